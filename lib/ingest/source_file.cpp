// SPDX-License-Identifier: Apache-2.0
#include "ingest/source_file.h"

#include <algorithm>
#include <vector>

#include "core/checksum.h"
#include "core/error.h"
#include "core/file_io.h"

namespace strielad::ingest {

std::string absolute_path_string(const std::filesystem::path& path) {
  std::error_code ec;
  auto absolute = std::filesystem::absolute(path, ec);
  if (ec) absolute = path;
  return absolute.lexically_normal().string();
}

SourceFile describe_source_file(const std::filesystem::path& path) {
  SourceFile source;
  source.path = absolute_path_string(path);
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) {
    throw make_error(ErrorCode::kNotFound, "{}: no such file", source.path);
  }
  if (std::filesystem::is_directory(path, ec)) {
    throw make_error(ErrorCode::kInvalidInput, "{}: is a directory, not a netCDF file",
                     source.path);
  }
  const ReadOnlyFile file(path);
  source.size = file.size();
  std::vector<std::byte> head(
      static_cast<std::size_t>(std::min<std::uint64_t>(source.size, kHeaderChecksumBytes)));
  file.read_at(0, head);
  source.header_checksum = checksum64(head);
  return source;
}

}  // namespace strielad::ingest
