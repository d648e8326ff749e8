// SPDX-License-Identifier: Apache-2.0
#include "convert/geometry_writer.h"

#include <algorithm>
#include <system_error>

#include "convert/step_writer.h"
#include "core/error.h"
#include "core/file_io.h"
#include "format/manifest.h"

namespace strielad::build {
namespace {

// Publishes the complete file `candidate` (a temporary sibling of `path`) as `path` when
// there is none, else checks that the one there has the same bytes. The candidate is
// removed either way.
bool publish_or_compare(const std::filesystem::path& candidate, const std::filesystem::path& path) {
  struct RemoveCandidate {
    const std::filesystem::path& path;
    ~RemoveCandidate() {
      std::error_code ignored;
      std::filesystem::remove(path, ignored);
    }
  } remove_candidate{candidate};
  if (!std::filesystem::exists(path)) {
    // Two writers racing here publish the same bytes.
    std::filesystem::rename(candidate, path);
    fsync_directory(path.parent_path());
    return true;
  }
  const std::vector<std::byte> found = read_file_bytes(path);
  const std::vector<std::byte> wanted = read_file_bytes(candidate);
  if (found != wanted) {
    throw make_error(ErrorCode::kCorrupt,
                     "{}: exists but differs from the file this conversion writes ({} bytes, "
                     "{} expected): it belongs to another plan or is damaged; remove the store "
                     "or convert into a new one",
                     path.string(), found.size(), wanted.size());
  }
  return false;
}

}  // namespace

bool write_geometry_file(const std::filesystem::path& store, const format::GeometryFile& file) {
  const std::filesystem::path path = store / format::kGeometryFileName;
  const std::vector<std::byte> bytes = format::encode_geometry_file(file);
  if (std::filesystem::exists(path)) {
    if (read_file_bytes(path) != bytes) {
      throw make_error(ErrorCode::kCorrupt,
                       "{}: exists but differs from the file this conversion writes: it belongs "
                       "to another plan or is damaged; remove the store or convert into a new one",
                       path.string());
    }
    return false;
  }
  write_file_atomically(path, bytes);
  return true;
}

bool publish_geometry_bricks(const std::filesystem::path& store,
                             const std::function<void(const std::filesystem::path&)>& write) {
  const std::filesystem::path path = store / format::kGeometryBricksFileName;
  // The whole file is written beside the final one first, so a re-run can compare bytes.
  const std::filesystem::path candidate = temporary_sibling(path);
  write(candidate);
  return publish_or_compare(candidate, path);
}

bool write_geometry_bricks(const std::filesystem::path& store, std::uint64_t store_id,
                           std::vector<EncodedBrick> bricks) {
  format::StepHeader header;
  header.store_id = store_id;
  header.step = format::kGeometryStep;
  header.variable_count = 1;
  header.node_count = static_cast<std::uint32_t>(bricks.size());
  return publish_geometry_bricks(store, [&](const std::filesystem::path& candidate) {
    StepWriter writer(candidate, header);
    for (NodeId n = 0; n < bricks.size(); ++n) writer.add_brick(0, n, std::move(bricks[n]));
    writer.commit();
  });
}

}  // namespace strielad::build
