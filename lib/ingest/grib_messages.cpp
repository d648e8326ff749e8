// SPDX-License-Identifier: Apache-2.0
#include "ingest/grib_messages.h"

#include <eccodes.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <memory>

#include "core/checksum.h"
#include "core/error.h"
#include "core/file_io.h"
#include "core/io_error.h"
#include "ingest/eccodes_call.h"

namespace strielad::ingest {
namespace {

struct FileCloser {
  void operator()(std::FILE* file) const { std::fclose(file); }
};

GribMessageSummary summarise(const GribHandle& message, const std::string& where) {
  GribMessageSummary s;
  off_t offset = 0;
  std::size_t size = 0;
  eccodes_check(codes_get_message_offset(message.get(), &offset), where);
  eccodes_check(codes_get_message_size(message.get(), &size), where);
  s.offset = static_cast<std::uint64_t>(offset);
  s.size = size;
  s.edition = message.long_key("edition");
  s.short_name = message.string_key("shortName");
  s.type_of_level = message.string_key("typeOfLevel");
  s.level = message.long_key("level");
  s.level_value = static_cast<double>(s.level);
  if (s.edition == 2) {
    const auto scaled = message.double_key("scaledValueOfFirstFixedSurface");
    const auto factor = message.double_key("scaleFactorOfFirstFixedSurface");
    if (scaled && factor) {
      const double si = *scaled * std::pow(10.0, -*factor);  // Pa, m or a number
      s.level_value = s.type_of_level == "isobaricInhPa" ? si / 100.0 : si;
    }
  }
  s.grid_type = message.string_key("gridType");
  s.name = message.string_key("name");
  s.units = message.string_key("units");
  s.grid_md5 = message.string_key("md5GridSection");
  s.validity_date = message.long_key("validityDate");
  s.validity_time = message.long_key("validityTime");
  s.number_of_values = message.long_key("numberOfValues");
  if (message.long_key("PVPresent") != 0) {
    const std::vector<double> pv = message.double_array_key("pv", where);
    s.pv_size = pv.size();
    s.pv_checksum = checksum64(std::as_bytes(std::span(pv)));
  }
  take_eccodes_log();  // a key some messages lack is not an error of the message
  return s;
}

}  // namespace

std::vector<GribMessageSummary> list_grib_messages(const std::filesystem::path& path) {
  const std::string name = path.string();
  std::lock_guard lock(eccodes_mutex());
  take_eccodes_log();
  std::unique_ptr<std::FILE, FileCloser> file(std::fopen(name.c_str(), "rb"));
  if (!file) throw io_error("open", path, errno);
  std::vector<GribMessageSummary> messages;
  for (;;) {
    const long before = std::ftell(file.get());
    int status = 0;
    GribHandle message(
        codes_handle_new_from_file(codes_context_get_default(), file.get(), PRODUCT_GRIB, &status));
    const std::string where =
        fmt::format("{}: GRIB message {} (after byte {})", name, messages.size() + 1, before);
    if (!message) {
      eccodes_check(status, where);
      const std::string log = take_eccodes_log();
      if (!log.empty()) throw make_error(ErrorCode::kInvalidInput, "{}: {}", where, log);
      break;  // end of file
    }
    const std::string log = take_eccodes_log();
    if (!log.empty()) throw make_error(ErrorCode::kInvalidInput, "{}: {}", where, log);
    messages.push_back(summarise(message, where));
  }
  if (messages.empty()) {
    throw make_error(ErrorCode::kInvalidInput, "{}: no GRIB message in the file", name);
  }
  return messages;
}

GribHandle decode_grib_message(std::span<const std::byte> bytes, std::string_view what) {
  take_eccodes_log();
  GribHandle message(
      codes_handle_new_from_message_copy(codes_context_get_default(), bytes.data(), bytes.size()));
  const std::string log = take_eccodes_log();
  if (!message || !log.empty()) {
    throw make_error(ErrorCode::kInvalidInput, "{}: {}", what,
                     log.empty() ? "ecCodes cannot decode it" : log);
  }
  return message;
}

GribHandle read_grib_message(const std::filesystem::path& path, const GribMessageSummary& summary) {
  const ReadOnlyFile file(path);
  std::vector<std::byte> bytes(static_cast<std::size_t>(summary.size));
  file.read_at(summary.offset, bytes);
  return decode_grib_message(
      bytes, fmt::format("{}: GRIB message at byte {}", path.string(), summary.offset));
}

}  // namespace strielad::ingest
