// SPDX-License-Identifier: Apache-2.0
#include "readback/vtp_declared_sizes.h"

#include <algorithm>
#include <charconv>
#include <cstdint>
#include <optional>
#include <string_view>

#include "core/error.h"

namespace strielad::vtp {
namespace {

// The value of attribute `name` in the element text `tag` ("<DataArray a="1" ...>").
std::optional<std::string_view> attribute(std::string_view tag, std::string_view name) {
  for (std::size_t at = tag.find(name); at != std::string_view::npos; at = tag.find(name, at + 1)) {
    const bool starts = at > 0 && (tag[at - 1] == ' ' || tag[at - 1] == '\t' || tag[at - 1] == '\n' ||
                                   tag[at - 1] == '\r');
    std::size_t p = at + name.size();
    while (p < tag.size() && (tag[p] == ' ' || tag[p] == '\t' || tag[p] == '\n' || tag[p] == '\r')) ++p;
    if (!starts || p >= tag.size() || tag[p] != '=') continue;
    ++p;
    while (p < tag.size() && (tag[p] == ' ' || tag[p] == '\t' || tag[p] == '\n' || tag[p] == '\r')) ++p;
    if (p >= tag.size() || (tag[p] != '"' && tag[p] != '\'')) continue;
    const auto end = tag.find(tag[p], p + 1);
    if (end == std::string_view::npos) return std::nullopt;
    return tag.substr(p + 1, end - p - 1);
  }
  return std::nullopt;
}

// A declared count: digits (VTK reads them as 64-bit integers); a sign, anything else or
// an overflow counts as "too large" (VTK would reject or misread it later).
double count(std::string_view tag, std::string_view name, double if_missing) {
  const auto text = attribute(tag, name);
  if (!text) return if_missing;
  std::string_view t = *text;
  while (!t.empty() && (t.front() == ' ' || t.front() == '+')) t.remove_prefix(1);
  std::uint64_t v = 0;
  const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
  if (ec != std::errc() || t.empty()) return t.empty() || t.front() == '-' ? 0 : 1e300;
  return double(v);
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
  for (const char* known : {"Int8", "UInt8", "Int16", "UInt16", "Int32", "UInt32", "Int64", "UInt64",
                            "Float32", "Float64", "String", "Char"}) {
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

// Checks one file's declared sizes against what its bytes can hold.
class DeclaredSizeCheck {
 public:
  DeclaredSizeCheck(std::span<const char> file, const std::string& what)
      : text_(file.data(), file.size()),
        what_(what),
        limit_(kMaxExpansion * double(file.size()) + double(1 << 20)) {
    // The XML part ends where raw appended data begins (after "<AppendedData ...>_").
    const auto appended = text_.find("<AppendedData");
    xml_ = text_.substr(0, appended);
    appended_start_ = text_.size();
    if (const auto file_tag_at = xml_.find("<VTKFile"); file_tag_at != std::string_view::npos) {
      const auto tag = xml_.substr(file_tag_at, xml_.find('>', file_tag_at) - file_tag_at);
      if (attribute(tag, "header_type") == "UInt64") header_bytes_ = 8;
      compressed_ = attribute(tag, "compressor").has_value();
    }
    if (appended != std::string_view::npos) {
      const auto close = text_.find('>', appended);
      const auto tag = text_.substr(appended, close - appended);
      raw_appended_ = attribute(tag, "encoding") == "raw";
      const auto underscore = close == std::string_view::npos ? close : text_.find('_', close);
      if (underscore != std::string_view::npos) appended_start_ = underscore + 1;
    }
  }

  void run() const {
    double points = 0, cells = 0;  // of the current piece
    double verts = 0, lines = 0, strips = 0, polys = 0;
    double tuples = 0;  // of the arrays in the current section
    constexpr auto npos = std::string_view::npos;
    for (std::size_t at = xml_.find('<'); at != npos; at = xml_.find('<', at + 1)) {
      const auto close = xml_.find('>', at);
      const auto tag = xml_.substr(at, close == npos ? close : close - at);
      const auto name_end = tag.find_first_of(" \t\r\n/>", 1);
      const std::string_view name = tag.substr(1, name_end == npos ? name_end : name_end - 1);
      if (name == "Piece") {
        points = count(tag, "NumberOfPoints", 0);
        verts = count(tag, "NumberOfVerts", 0);
        lines = count(tag, "NumberOfLines", 0);
        strips = count(tag, "NumberOfStrips", 0);
        polys = count(tag, "NumberOfPolys", 0);
        cells = verts + lines + strips + polys;
        if (points * 3 > limit_) refuse("Piece NumberOfPoints", points * 3);
        if (cells > limit_) refuse("Piece cell counts", cells);
      } else if (name == "PointData" || name == "Points") {
        tuples = points;
      } else if (name == "CellData") {
        tuples = cells;
      } else if (name == "Verts" || name == "Lines" || name == "Strips" || name == "Polys") {
        // The section's own cells: an empty section's arrays hold no values whatever the
        // other sections hold. (Its connectivity holds more than one value per cell; the
        // limit below is far above that.)
        tuples = name == "Verts"    ? verts
                 : name == "Lines"  ? lines
                 : name == "Strips" ? strips
                                    : polys;
      } else if (name == "FieldData") {
        tuples = 0;
      } else if (name == "DataArray" || name == "Array") {
        check_array(tag, name, close, tuples);
      }
    }
  }

 private:
  [[noreturn]] void refuse(std::string_view element, double values) const {
    throw make_error(ErrorCode::kInvalidInput,
                     "{}: not a readable VTK XML PolyData file: {} declares {:.4g} values, more "
                     "than its {} bytes can hold",
                     what_, element, values, text_.size());
  }

  // An array element `tag` ending at `close`, in a section whose arrays hold `tuples`.
  void check_array(std::string_view tag, std::string_view name, std::size_t close,
                   double tuples) const {
    // VTK 9.1 dereferences the null array it makes for a FieldData array of an unknown
    // type: only its type names pass.
    const auto type = attribute(tag, "type");
    if (!type || !known_type(*type)) {
      throw make_error(ErrorCode::kInvalidInput,
                       "{}: not a readable VTK XML PolyData file: {} of type '{}' (not a VTK XML "
                       "data type)",
                       what_, name, type ? *type : "");
    }
    const double n =
        count(tag, "NumberOfTuples", tuples) * std::max(1.0, count(tag, "NumberOfComponents", 1));
    if (n > limit_) refuse(name, n);
    // VTK 9.1 reads an array of any other format as appended data whenever the file has
    // some (a mistyped "appunded" reached its compressed reader unchecked): only its
    // format names pass.
    const auto format = attribute(tag, "format");
    if (format && *format != "ascii" && *format != "binary" && *format != "appended") {
      throw make_error(ErrorCode::kInvalidInput,
                       "{}: not a readable VTK XML PolyData file: {} '{}' of format '{}' (not "
                       "ascii, binary or appended)",
                       what_, name, attribute(tag, "Name").value_or(""), *format);
    }
    if (!compressed_ || !format) return;
    if (const auto start = compressed_start(tag, *format, close)) {
      check_compressed_header(name, n, *start);
    }
  }

  // The compressed header of an appended or binary array; nothing where VTK refuses the
  // array itself (an offset beyond the data, a short header) or for other formats.
  std::optional<CompressedStart> compressed_start(std::string_view tag, std::string_view format,
                                                  std::size_t close) const {
    const std::size_t header = 3 * header_bytes_;
    CompressedStart start;
    if (format == "appended" && raw_appended_) {
      const double offset = count(tag, "offset", 0);
      const std::size_t appended_bytes = text_.size() - std::min(text_.size(), appended_start_);
      if (offset >= double(appended_bytes)) return std::nullopt;  // VTK refuses
      const std::size_t p = appended_start_ + std::size_t(offset);
      if (text_.size() - p < header) return std::nullopt;  // VTK refuses a short header
      start.words = std::string(text_.substr(p, header));
      start.room = text_.size() - p - header;
    } else if (format == "binary" && close != std::string_view::npos) {
      const std::string_view body = xml_.substr(close + 1, xml_.find('<', close) - close - 1);
      start.words = decode_base64_prefix(body, header);
      if (start.words.size() < header) return std::nullopt;
      start.room = body.size();
    } else {
      return std::nullopt;
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
  std::string_view xml_;
  const std::string& what_;
  double limit_;
  std::size_t header_bytes_ = 4;  // header_type UInt32 (VTK's default) or UInt64
  bool compressed_ = false;
  bool raw_appended_ = false;
  std::size_t appended_start_ = 0;
};

}  // namespace

void check_declared_sizes(std::span<const char> file, const std::string& what) {
  DeclaredSizeCheck(file, what).run();
}

}  // namespace strielad::vtp
