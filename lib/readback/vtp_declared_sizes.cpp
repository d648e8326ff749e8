// SPDX-License-Identifier: Apache-2.0
#include "readback/vtp_declared_sizes.h"

#include <algorithm>
#include <charconv>
#include <cstdint>
#include <optional>
#include <set>
#include <sstream>
#include <string_view>

#include <vtkNew.h>
#include <vtkType.h>
#include <vtkXMLDataElement.h>
#include <vtkXMLDataParser.h>

#include "core/error.h"
#include "export/vtk_error_capture.h"

namespace strielad::vtp {
namespace {

// A declared count: digits (VTK reads them as 64-bit integers); a sign, anything else or
// an overflow counts as "too large" (VTK would reject or misread it later).
double count(vtkXMLDataElement* element, const char* name, double if_missing) {
  const char* value = element->GetAttribute(name);
  if (value == nullptr) return if_missing;
  std::string_view t = value;
  while (!t.empty() && (t.front() == ' ' || t.front() == '+')) t.remove_prefix(1);
  std::uint64_t v = 0;
  const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
  if (ec != std::errc() || t.empty()) return t.empty() || t.front() == '-' ? 0 : 1e300;
  return double(v);
}

// The value of attribute `name`, if the element has it.
std::optional<std::string_view> attribute(vtkXMLDataElement* element, const char* name) {
  const char* value = element->GetAttribute(name);
  if (value == nullptr) return std::nullopt;
  return std::string_view(value);
}

std::uint64_t little_endian(const unsigned char* p, std::size_t bytes) {
  std::uint64_t v = 0;
  for (std::size_t i = bytes; i-- > 0;) v = v << 8 | p[i];
  return v;
}

int base64_value(char c) {
  if (c >= 'A' && c <= 'Z') return c - 'A';
  if (c >= 'a' && c <= 'z') return c - 'a' + 26;
  if (c >= '0' && c <= '9') return c - '0' + 52;
  if (c == '+') return 62;
  if (c == '/') return 63;
  return -1;
}

// The first `bytes` bytes of base64 text (whitespace skipped); fewer if it ends first.
std::string decode_base64_prefix(std::string_view text, std::size_t bytes) {
  std::string out;
  std::uint32_t bits = 0;
  int nbits = 0;
  for (char c : text) {
    const int v = base64_value(c);
    if (v < 0) {
      if (c == '=' || c == '<') break;
      continue;
    }
    bits = bits << 6 | std::uint32_t(v);
    nbits += 6;
    if (nbits >= 8) {
      nbits -= 8;
      out.push_back(char((bits >> nbits) & 0xff));
      if (out.size() == bytes) break;
    }
  }
  return out;
}

bool known_type(std::string_view type) {
  for (const char* known : {"Int8", "UInt8", "Int16", "UInt16", "Int32", "UInt32", "Int64",
                            "UInt64", "Float32", "Float64", "String", "Char"}) {
    if (type == known) return true;
  }
  return false;
}

// The first bytes of a compressed array (block count, block size, last block size, then
// one compressed size per block), and how many bytes follow them.
struct CompressedStart {
  std::string words;
  std::size_t room = 0;
};

// The element counts of the piece being checked, and how many tuples the arrays of the
// current section hold.
struct Section {
  double points = 0, verts = 0, lines = 0, strips = 0, polys = 0;
  double tuples = 0;
  // Inside FieldData, PointData or CellData, whose every child VTK makes an array of
  // (VTK 9.1 dereferences the null array it makes for a FieldData child without a known
  // type, whatever the child's name).
  bool children_are_arrays = false;
};

// Checks one file's declared sizes against what its bytes can hold, on the element tree
// VTK's own XML parser builds from them: every element and attribute exactly as
// vtkXMLPolyDataReader will see it (a text scan disagreed with expat about quotes inside
// attribute values, comments and entities).
class DeclaredSizeCheck {
 public:
  DeclaredSizeCheck(std::span<const char> file, const std::string& what)
      : text_(file.data(), file.size()),
        what_(what),
        limit_(kMaxExpansion * double(file.size()) + double(1 << 20)) {}

  void run() {
    vtkNew<vtk_support::ErrorCapture> errors;
    vtkNew<vtkXMLDataParser> parser;
    errors->watch(parser);
    std::istringstream stream(std::string(text_), std::ios::in | std::ios::binary);
    parser->SetStream(&stream);
    const int parsed = parser->Parse();
    vtkXMLDataElement* root = parser->GetRootElement();
    if (!parsed || errors->failed() || root == nullptr) {
      throw make_error(ErrorCode::kInvalidInput, "{}: not a readable VTK XML PolyData file: {}",
                       what_, errors->failed() ? errors->message() : "not XML");
    }
    if (attribute(root, "header_type") == "UInt64") header_bytes_ = 8;
    compressed_ = root->GetAttribute("compressor") != nullptr;
    for (int i = 0; i < root->GetNumberOfNestedElements(); ++i) {
      vtkXMLDataElement* nested = root->GetNestedElement(i);
      if (std::string_view(nested->GetName()) == "AppendedData") {
        has_appended_ = true;
        raw_appended_ = attribute(nested, "encoding") == "raw";
        appended_start_ = std::size_t(std::clamp<vtkTypeInt64>(parser->GetAppendedDataPosition(), 0,
                                                               vtkTypeInt64(text_.size())));
      }
    }
    Section section;
    walk(root, section);
  }

 private:
  // Checks `element` and everything nested in it; `section` is what its parent declared.
  void walk(vtkXMLDataElement* element, Section section) const {
    const std::string_view name = element->GetName() != nullptr ? element->GetName() : "";
    const bool array = section.children_are_arrays || name == "DataArray" || name == "Array";
    section.children_are_arrays = name == "FieldData" || name == "PointData" || name == "CellData";
    if (array) {
      check_array(element, name, section.tuples);
    } else if (name == "Piece") {
      section.points = count(element, "NumberOfPoints", 0);
      section.verts = count(element, "NumberOfVerts", 0);
      section.lines = count(element, "NumberOfLines", 0);
      section.strips = count(element, "NumberOfStrips", 0);
      section.polys = count(element, "NumberOfPolys", 0);
      const double cells = section.verts + section.lines + section.strips + section.polys;
      if (section.points * 3 > limit_) refuse("Piece NumberOfPoints", section.points * 3);
      if (cells > limit_) refuse("Piece cell counts", cells);
    } else if (name == "PointData" || name == "Points") {
      section.tuples = section.points;
    } else if (name == "CellData") {
      section.tuples = section.verts + section.lines + section.strips + section.polys;
    } else if (name == "Verts" || name == "Lines" || name == "Strips" || name == "Polys") {
      // The section's own cells: an empty section's arrays hold no values whatever the
      // other sections hold. (Its connectivity holds more than one value per cell; the
      // limit below is far above that.)
      section.tuples = name == "Verts"    ? section.verts
                       : name == "Lines"  ? section.lines
                       : name == "Strips" ? section.strips
                                          : section.polys;
    } else if (name == "FieldData") {
      section.tuples = 0;
    }
    if (section.children_are_arrays) check_array_names(element, name);
    for (int i = 0; i < element->GetNumberOfNestedElements(); ++i) {
      walk(element->GetNestedElement(i), section);
    }
  }

  // The arrays of a FieldData, PointData or CellData element: each named, no name twice
  // (VTK 9.1 keeps one array per name, then reads the section's elements by index into
  // the arrays it kept, and dereferences null past the last).
  void check_array_names(vtkXMLDataElement* section, std::string_view name) const {
    std::set<std::string_view> seen;
    for (int i = 0; i < section->GetNumberOfNestedElements(); ++i) {
      const char* array = section->GetNestedElement(i)->GetAttribute("Name");
      if (array == nullptr || *array == '\0') {
        throw make_error(ErrorCode::kInvalidInput,
                         "{}: not a readable VTK XML PolyData file: {} array {} has no Name", what_,
                         name, i);
      }
      if (!seen.insert(array).second) {
        throw make_error(ErrorCode::kInvalidInput,
                         "{}: not a readable VTK XML PolyData file: {} has two arrays named '{}'",
                         what_, name, array);
      }
    }
  }

  [[noreturn]] void refuse(std::string_view element, double values) const {
    throw make_error(ErrorCode::kInvalidInput,
                     "{}: not a readable VTK XML PolyData file: {} declares {:.4g} values, more "
                     "than its {} bytes can hold",
                     what_, element, values, text_.size());
  }

  // An array element in a section whose arrays hold `tuples`.
  void check_array(vtkXMLDataElement* element, std::string_view name, double tuples) const {
    // VTK 9.1 dereferences the null array it makes for a FieldData array of a missing or
    // unknown type: only its type names pass.
    const auto type = attribute(element, "type");
    if (!type || !known_type(*type)) {
      throw make_error(ErrorCode::kInvalidInput,
                       "{}: not a readable VTK XML PolyData file: {} '{}' of type '{}' (not a VTK "
                       "XML data type)",
                       what_, name, attribute(element, "Name").value_or(""), type.value_or(""));
    }
    // VTK 9.1 returns no array for a component count below 1, leaking the one it made.
    if (const auto components = attribute(element, "NumberOfComponents");
        components && !(count(element, "NumberOfComponents", 0) >= 1)) {
      throw make_error(ErrorCode::kInvalidInput,
                       "{}: not a readable VTK XML PolyData file: {} '{}' has NumberOfComponents "
                       "'{}' (not a positive integer)",
                       what_, name, attribute(element, "Name").value_or(""), *components);
    }
    const double n = count(element, "NumberOfTuples", tuples) *
                     std::max(1.0, count(element, "NumberOfComponents", 1));
    if (n > limit_) refuse(name, n);
    // VTK 9.1 reads an array of any other format as appended data whenever the file has
    // some (a mistyped "appunded" reached its compressed reader unchecked): only its
    // format names pass.
    const auto format = attribute(element, "format");
    if (format && *format != "ascii" && *format != "binary" && *format != "appended") {
      throw make_error(ErrorCode::kInvalidInput,
                       "{}: not a readable VTK XML PolyData file: {} '{}' of format '{}' (not "
                       "ascii, binary or appended)",
                       what_, name, attribute(element, "Name").value_or(""), *format);
    }
    if (!compressed_) return;
    // VTK reads any array with an offset as appended data whatever its format says (a
    // misspelt "fozmat" too), an array of format binary inline; ascii has no header.
    const bool appended = element->GetAttribute("offset") != nullptr;
    if (!appended && format != "binary") return;
    if (const auto start = compressed_start(element, appended)) {
      check_compressed_header(name, n, *start);
    }
  }

  // The compressed header of an appended (raw or base64) or inline binary array; nothing
  // where VTK refuses the array itself (an offset beyond the data, a short header).
  std::optional<CompressedStart> compressed_start(vtkXMLDataElement* element, bool appended) const {
    const std::size_t header = 3 * header_bytes_;
    CompressedStart start;
    if (appended) {
      if (!has_appended_) return std::nullopt;  // VTK finds no data to read
      const double offset = count(element, "offset", 0);
      const std::size_t appended_bytes = text_.size() - std::min(text_.size(), appended_start_);
      if (offset >= double(appended_bytes)) return std::nullopt;  // VTK refuses
      const std::size_t p = appended_start_ + std::size_t(offset);
      if (raw_appended_) {
        if (text_.size() - p < header) return std::nullopt;  // VTK refuses a short header
        start.words = std::string(text_.substr(p, header));
        start.room = text_.size() - p - header;
      } else {  // base64: the offset counts encoded characters
        start.words = decode_base64_prefix(text_.substr(p), header);
        if (start.words.size() < header) return std::nullopt;
        start.room = text_.size() - p;
      }
    } else {
      const std::string_view body =
          element->GetCharacterData() != nullptr ? element->GetCharacterData() : "";
      start.words = decode_base64_prefix(body, header);
      if (start.words.size() < header) return std::nullopt;
      start.room = body.size();
    }
    return start;
  }

  // VTK allocates by the first three words of the compressed header.
  void check_compressed_header(std::string_view name, double n,
                               const CompressedStart& start) const {
    const auto* words = reinterpret_cast<const unsigned char*>(start.words.data());
    const auto word = [&](std::size_t i) {
      return little_endian(words + i * header_bytes_, header_bytes_);
    };
    const std::uint64_t blocks = word(0), block_size = word(1), last_block_size = word(2);
    // VTK 9.1 dereferences a null block table when an array with values has no blocks.
    if (blocks == 0 && n > 0) {
      throw make_error(ErrorCode::kInvalidInput,
                       "{}: not a readable VTK XML PolyData file: {} declares {:.4g} values in "
                       "a compressed header of 0 blocks",
                       what_, name, n);
    }
    // VTK 9.1 divides by the block size (SIGFPE when it is 0) and takes a last block
    // larger than the others as more data than it allocated.
    if (blocks > 0 && (block_size == 0 || last_block_size > block_size)) {
      throw make_error(ErrorCode::kInvalidInput,
                       "{}: not a readable VTK XML PolyData file: {}'s compressed header has {} "
                       "blocks of {} bytes, the last of {}",
                       what_, name, blocks, block_size, last_block_size);
    }
    if (double(blocks) * double(header_bytes_) > double(start.room) ||
        double(block_size) > limit_ || double(last_block_size) > limit_ ||
        double(blocks) * double(block_size) > limit_) {
      refuse(fmt::format("{}'s compressed header ({} blocks of {} bytes, the last {})", name,
                         blocks, block_size, last_block_size),
             double(blocks) * double(block_size));
    }
  }

  std::string_view text_;
  const std::string& what_;
  double limit_;
  std::size_t header_bytes_ = 4;  // header_type UInt32 (VTK's default) or UInt64
  bool compressed_ = false;
  bool has_appended_ = false;
  bool raw_appended_ = false;
  std::size_t appended_start_ = 0;
};

}  // namespace

void check_declared_sizes(std::span<const char> file, const std::string& what) {
  DeclaredSizeCheck(file, what).run();
}

}  // namespace strielad::vtp
