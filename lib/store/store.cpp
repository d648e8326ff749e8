// SPDX-License-Identifier: Apache-2.0
#include "store/store.h"

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

#include "core/checksum.h"
#include "core/direct_read_file.h"
#include "core/error.h"
#include "core/file_io.h"
#include "store/brick_cache.h"
#include "store/brick_codec.h"
#include "store/fpzip_chunk.h"
#include "store/zfp_chunk.h"

namespace strielad {

using format::BrickKind;
using format::IndexEntry;

struct Store::StepState {
  std::mutex mutex;
  bool opened = false;
  ReadOnlyFile file;
  std::unique_ptr<DirectReadFile> direct;  // chunk reads, when opened with direct_reads
  format::StepFooter footer;
  std::vector<format::SectionEntry> sections;
  std::vector<std::unique_ptr<const std::vector<IndexEntry>>> indexes;  // per section, lazy
};

std::shared_ptr<const Store> Store::open(const std::filesystem::path& dir,
                                         StoreOpenOptions options) {
  const auto manifest_path = dir / "MANIFEST";
  if (!std::filesystem::exists(manifest_path)) {
    throw make_error(ErrorCode::kNotFound, "{}: not a STRIELAD store (no MANIFEST file)",
                     dir.string());
  }
  format::Manifest manifest =
      format::decode_manifest(read_file_bytes(manifest_path), manifest_path.string());
  if (manifest.geometry) {
    // A GEOMETRY or geometry.bricks that the geometry does not call for (a missing one is
    // reported when it is read, naming the file).
    const auto stray = [&](std::string_view name, bool expected, std::string_view needs) {
      if (!expected && std::filesystem::exists(dir / name)) {
        throw make_error(ErrorCode::kCorrupt, "{}: present, but the store's geometry has no {}",
                         (dir / name).string(), needs);
      }
    };
    stray(format::kGeometryFileName, format::has_geometry_file(manifest),
          "curvilinear coordinates and no surface");
    stray(format::kGeometryBricksFileName, format::has_geometry_bricks(manifest),
          "time-invariant vertical field");
  }
  if (!manifest.complete && !options.allow_incomplete) {
    throw make_error(ErrorCode::kInvalidArgument,
                     "{}: conversion has not been finalized (state 'converting'); finish it by "
                     "re-running strielad-convert or 'strielad-convert finalize'",
                     dir.string());
  }
  std::shared_ptr<Store> store(new Store(dir, std::move(manifest)));
  store->direct_reads_ = options.direct_reads;
  return store;
}

Store::Store(std::filesystem::path dir, format::Manifest manifest)
    : dir_(std::move(dir)), manifest_(std::move(manifest)), octree_(manifest_.dims(), manifest_.brick) {
  steps_.reserve(step_count());
  for (std::size_t i = 0; i < step_count(); ++i) steps_.push_back(std::make_unique<StepState>());
  geometry_bricks_ = std::make_unique<StepState>();
}

Store::~Store() = default;

std::filesystem::path Store::step_path(std::uint32_t step) const {
  return dir_ / format::step_file_name(step);
}

std::filesystem::path Store::geometry_path() const { return dir_ / format::kGeometryFileName; }

std::filesystem::path Store::geometry_bricks_path() const {
  return dir_ / format::kGeometryBricksFileName;
}

std::string Store::describe_node(std::uint32_t variable, NodeId node) const {
  const NodeKey k = octree_.key(node);
  const bool field = variable == variable_count() && has_geometry_field();
  const std::string what =
      field ? std::string("geometry field")
            : fmt::format("variable '{}'", manifest_.variables.at(variable).name);
  return fmt::format("{} node {} (level {}, index {},{},{})", what, node, k.level, k.index[0],
                     k.index[1], k.index[2]);
}

bool Store::has_step(std::uint32_t step) const {
  return step < step_count() && std::filesystem::exists(step_path(step));
}

void Store::check_step(std::uint32_t step) const {
  if (step >= step_count()) {
    throw make_error(ErrorCode::kNotFound, "{}: time step {} does not exist (the store has {})",
                     dir_.string(), step, step_count());
  }
}

void Store::check_step_and_variable(std::uint32_t step, std::uint32_t variable) const {
  check_step(step);
  if (variable >= variable_count()) {
    throw make_error(ErrorCode::kNotFound, "{}: variable index {} does not exist (the store has {})",
                     dir_.string(), variable, variable_count());
  }
}

Store::StepState& Store::step_state(std::uint32_t step) const {
  StepState& s = *steps_.at(step);
  std::lock_guard lock(s.mutex);
  if (s.opened) return s;
  const auto path = step_path(step);
  if (!std::filesystem::exists(path)) {
    throw make_error(ErrorCode::kNotFound, "{}: time step {} not converted ({} is missing)",
                     dir_.string(), step, format::step_file_name(step));
  }
  open_step_file(s, path, step, format::step_section_count(manifest_));
  return s;
}

Store::StepState& Store::geometry_bricks_state() const {
  StepState& s = *geometry_bricks_;
  std::lock_guard lock(s.mutex);
  if (s.opened) return s;
  const auto path = geometry_bricks_path();
  if (!std::filesystem::exists(path)) {
    throw make_error(ErrorCode::kCorrupt,
                     "{}: missing; the store's vertical geometry field does not vary in time "
                     "and is stored there",
                     path.string());
  }
  open_step_file(s, path, format::kGeometryStep, 1);
  return s;
}

void Store::open_step_file(StepState& s, const std::filesystem::path& path, std::uint32_t step,
                           std::uint32_t sections) const {
  const std::string what = path.string();
  // Only time steps are recorded in the manifest (not geometry.bricks).
  const format::StepRecord* record =
      step != format::kGeometryStep && manifest_.complete && step < manifest_.steps.size()
          ? &manifest_.steps[step]
          : nullptr;
  ReadOnlyFile file(path);
  constexpr std::uint64_t kFixed = format::kStepHeaderSize + format::kStepFooterSize;
  if (file.size() < kFixed) {
    throw make_error(ErrorCode::kTruncated, "{}: file is {} bytes, shorter than header and footer",
                     what, file.size());
  }
  if (record && record->size != file.size()) {
    throw make_error(ErrorCode::kCorrupt, "{}: file is {} bytes but the manifest recorded {}", what,
                     file.size(), record->size);
  }
  std::vector<std::byte> header(format::kStepHeaderSize), footer_bytes(format::kStepFooterSize);
  file.read_at(0, header);
  file.read_at(file.size() - format::kStepFooterSize, footer_bytes);
  const format::StepHeader h = format::decode_step_header(header, what);
  const format::StepFooter f = format::decode_step_footer(footer_bytes, what);
  const auto expect = [&](std::uint64_t found, std::uint64_t expected, std::string_view field) {
    if (found != expected) {
      throw make_error(ErrorCode::kCorrupt, "{}: {} is {} but the manifest says {}", what, field,
                       found, expected);
    }
  };
  expect(h.store_id, manifest_.store_id, "header store_id");
  expect(f.store_id, manifest_.store_id, "footer store_id");
  expect(h.step, step, "header step");
  expect(f.step, step, "footer step");
  expect(h.variable_count, sections, "header variable_count");
  expect(f.variable_count, sections, "footer variable_count");
  expect(h.node_count, octree_.node_count(), "header node_count");
  expect(f.node_count, octree_.node_count(), "footer node_count");
  const std::uint64_t table_size = std::uint64_t{f.variable_count} * format::kSectionEntrySize;
  const std::uint64_t footer_offset = file.size() - format::kStepFooterSize;
  if (f.section_table_offset < format::kStepHeaderSize ||
      f.section_table_offset + table_size != footer_offset) {
    throw make_error(ErrorCode::kCorrupt,
                     "{}: section table at offset {} ({} bytes) does not end at the footer ({})",
                     what, f.section_table_offset, table_size, footer_offset);
  }
  std::vector<std::byte> table(table_size);
  file.read_at(f.section_table_offset, table);
  s.sections = format::decode_section_table(table, f.variable_count, f.node_count,
                                            f.section_table_checksum, format::kStepHeaderSize,
                                            f.section_table_offset, what);
  if (record && record->footer_checksum != checksum64(std::span(footer_bytes).first(48))) {
    throw make_error(ErrorCode::kCorrupt, "{}: footer differs from the one the manifest recorded",
                     what);
  }
  index_bytes_ += header.size() + footer_bytes.size() + table.size();
  s.footer = f;
  s.file = std::move(file);
  if (direct_reads_) s.direct = DirectReadFile::open(path);  // null: buffered after all
  s.indexes.resize(sections);
  s.opened = true;
}

std::span<const IndexEntry> Store::section_index(StepState& s, std::uint32_t section,
                                                 std::string_view label) const {
  std::lock_guard lock(s.mutex);
  auto& slot = s.indexes.at(section);
  if (!slot) {
    const format::SectionEntry& entry = s.sections[section];
    std::vector<std::byte> stored(entry.stored_size);
    s.file.read_at(entry.offset, stored);
    index_bytes_ += stored.size();
    // Chunks lie between the header and the first index section.
    std::uint64_t first_section = s.footer.section_table_offset;
    for (const auto& sec : s.sections) first_section = std::min(first_section, sec.offset);
    slot = std::make_unique<const std::vector<IndexEntry>>(format::decode_index_section(
        stored, entry, s.footer.node_count, format::kStepHeaderSize, first_section,
        fmt::format("{}: {}", s.file.path().string(), label)));
  }
  return *slot;
}

std::span<const IndexEntry> Store::index(std::uint32_t step, std::uint32_t variable) const {
  if (variable == variable_count() && has_geometry_field()) return geometry_index(step);
  check_step_and_variable(step, variable);
  return section_index(step_state(step), variable,
                       fmt::format("variable '{}'", manifest_.variables[variable].name));
}

const IndexEntry& Store::node_entry(std::uint32_t step, std::uint32_t variable, NodeId node) const {
  const auto entries = index(step, variable);
  if (node >= entries.size()) {
    throw make_error(ErrorCode::kNotFound, "{}: node {} does not exist (the octree has {} nodes)",
                     dir_.string(), node, entries.size());
  }
  return entries[node];
}

Brick Store::decode_brick(StepState& s, const IndexEntry& e, NodeId node, DType dtype,
                          const format::CodecSpec& codec,
                          const std::function<std::string()>& what) const {
  Brick b;
  b.node = node;
  b.box = octree_.level_box(octree_.key(node));
  for (int a = 0; a < 3; ++a) b.dims[a] = b.box.extent(a);
  b.dtype = dtype;
  b.kind = e.kind;
  b.constant = e.constant;
  if (e.kind != BrickKind::kData) return b;

  std::vector<std::byte> chunk(e.chunk_size);
  if (s.direct) {
    device_bytes_ += s.direct->read_at(e.chunk_offset, chunk);
  } else {
    s.file.read_at(e.chunk_offset, chunk);
  }
  chunks_read_ += 1;
  chunk_bytes_ += chunk.size();
  const std::uint64_t sum = checksum64(chunk);
  if (sum != e.chunk_checksum) {
    throw make_error(ErrorCode::kCorrupt, "{}: chunk checksum mismatch (stored {:016x}, computed {:016x})",
                     what(), e.chunk_checksum, sum);
  }
  b.bytes.resize(b.sample_count() * dtype_size(b.dtype));
  if (e.coding == format::ChunkCoding::kFpzip) {
    if (!codec.fpzip) {
      throw make_error(ErrorCode::kCorrupt,
                       "{}: chunk is coded with fpzip, but the codec does not allow it", what());
    }
    decompress_brick_fpzip(chunk, b.dtype, b.dims, b.bytes, what());
  } else if (e.coding == format::ChunkCoding::kZfp) {
    if (!codec.zfp) {
      throw make_error(ErrorCode::kCorrupt,
                       "{}: chunk is coded with zfp, but the codec is not lossy", what());
    }
    decompress_brick_zfp(chunk, b.dtype, b.dims, b.bytes, what());
  } else {
    decompress_brick(chunk, b.dtype, b.dims, codec, b.bytes, what());
  }
  return b;
}

Brick Store::read_brick(std::uint32_t step, std::uint32_t variable, NodeId node) const {
  if (variable == variable_count() && has_geometry_field()) return read_geometry_brick(step, node);
  const IndexEntry& e = node_entry(step, variable, node);
  StepState& s = step_state(step);
  return decode_brick(s, e, node, manifest_.variables[variable].dtype, manifest_.codec_of(variable),
                      [&] {
                        return fmt::format("{}: step {} {}", s.file.path().string(), step,
                                           describe_node(variable, node));
                      });
}

std::shared_ptr<const Brick> Store::read_brick(std::uint32_t step, std::uint32_t variable,
                                               NodeId node, BrickCache& cache) const {
  if (variable == variable_count() && has_geometry_field()) {
    return read_geometry_brick(step, node, cache);
  }
  const BrickKey key{this, step, variable, node};
  return cache.get_or_load(key, [&] { return read_brick(step, variable, node); });
}

bool Store::has_geometry_field() const {
  return manifest_.geometry &&
         manifest_.geometry->vertical.kind == format::VerticalGeometry::Kind::kField;
}

Store::StepState& Store::geometry_state(std::uint32_t step) const {
  if (!has_geometry_field()) {
    throw make_error(ErrorCode::kNotFound, "{}: the store has no vertical geometry field",
                     dir_.string());
  }
  check_step(step);
  return manifest_.geometry->vertical.varies_in_time ? step_state(step) : geometry_bricks_state();
}

std::span<const IndexEntry> Store::geometry_index(std::uint32_t step) const {
  StepState& s = geometry_state(step);
  const bool varies = manifest_.geometry->vertical.varies_in_time;
  return section_index(s, varies ? static_cast<std::uint32_t>(variable_count()) : 0,
                       "geometry field");
}

namespace {

// The index of the brick's first missing (NaN) sample, or its sample count when none is.
// T is float or double, U the unsigned integer of its size: a NaN's bits without the sign
// exceed the infinity's.
template <class T, class U>
std::size_t first_nan(const std::byte* bytes, std::size_t count) {
  static_assert(sizeof(T) == sizeof(U));
  constexpr U kMagnitude = ~U(0) >> 1;
  const U infinity = std::bit_cast<U>(std::numeric_limits<T>::infinity());
  std::size_t i = 0;
  // Blocks by an integer maximum (no branch per sample); a block with a NaN is searched
  // again sample by sample.
  constexpr std::size_t kBlock = 64;
  for (; i + kBlock <= count; i += kBlock) {
    U largest = 0;
    for (std::size_t j = 0; j < kBlock; ++j) {
      U bits;
      std::memcpy(&bits, bytes + (i + j) * sizeof(T), sizeof(T));
      bits &= kMagnitude;
      largest = bits > largest ? bits : largest;
    }
    if (largest > infinity) break;
  }
  for (; i < count; ++i) {
    U bits;
    std::memcpy(&bits, bytes + i * sizeof(T), sizeof(T));
    if ((bits & kMagnitude) > infinity) return i;
  }
  return count;
}

std::size_t first_missing_sample(const Brick& b) {
  if (b.kind != BrickKind::kData) return std::isnan(b.sample(0)) ? 0 : b.sample_count();
  return b.dtype == DType::kFloat32
             ? first_nan<float, std::uint32_t>(b.bytes.data(), b.sample_count())
             : first_nan<double, std::uint64_t>(b.bytes.data(), b.sample_count());
}

}  // namespace

Brick Store::read_geometry_brick(std::uint32_t step, NodeId node) const {
  const auto entries = geometry_index(step);
  if (node >= entries.size()) {
    throw make_error(ErrorCode::kNotFound, "{}: node {} does not exist (the octree has {} nodes)",
                     dir_.string(), node, entries.size());
  }
  const IndexEntry& e = entries[node];
  StepState& s = geometry_state(step);
  const auto& field = manifest_.geometry->vertical;
  // The brick's name, made only for an error.
  const auto what = [&] {
    return field.varies_in_time
               ? fmt::format("{}: step {} {}", s.file.path().string(), step,
                             describe_node(static_cast<std::uint32_t>(variable_count()), node))
               : fmt::format("{}: {}", s.file.path().string(),
                             describe_node(static_cast<std::uint32_t>(variable_count()), node));
  };
  // The field has no missing samples ("Geometry bricks").
  const std::uint64_t owned = octree_.owned_fine_box(octree_.key(node)).count();
  if (e.kind == BrickKind::kEmpty || e.valid_count != owned) {
    throw make_error(ErrorCode::kCorrupt,
                     "{}: a geometry brick must have every sample: it is {} with {} valid of the "
                     "{} samples the node owns",
                     what(), e.kind == BrickKind::kEmpty ? "empty" : "stored", e.valid_count, owned);
  }
  Brick b = decode_brick(s, e, node, field.dtype, field.codec, what);
  if (const std::size_t missing = first_missing_sample(b); missing < b.sample_count()) {
    throw make_error(ErrorCode::kCorrupt, "{}: sample {} of a geometry brick is missing", what(),
                     missing);
  }
  return b;
}

std::shared_ptr<const Brick> Store::read_geometry_brick(std::uint32_t step, NodeId node,
                                                        BrickCache& cache) const {
  const bool shared = has_geometry_field() && !manifest_.geometry->vertical.varies_in_time;
  if (shared) check_step(step);
  const BrickKey key{this, shared ? format::kGeometryStep : step,
                     static_cast<std::uint32_t>(variable_count()), node};
  return cache.get_or_load(key, [&] { return read_geometry_brick(step, node); });
}

std::shared_ptr<const format::HorizontalCoordinates> Store::horizontal_coordinates() const {
  if (!format::has_geometry_file(manifest_)) return nullptr;
  std::lock_guard lock(geometry_mutex_);
  if (coordinates_) return coordinates_;
  const auto path = geometry_path();
  const std::string what = path.string();
  if (!std::filesystem::exists(path)) {
    throw make_error(ErrorCode::kCorrupt,
                     "{}: missing; the store's geometry has {}, which this file holds", what,
                     format::is_curvilinear(manifest_) ? "curvilinear coordinates"
                         : "a surface height");
  }
  const std::vector<std::byte> bytes = read_file_bytes(path);
  index_bytes_ += bytes.size();
  format::GeometryFile file = format::decode_geometry_file(bytes, what);
  format::check_geometry_file_matches(file, manifest_, what);
  coordinates_ = std::make_shared<const format::HorizontalCoordinates>(std::move(file.coordinates));
  return coordinates_;
}

StoreReadCounters Store::counters() const {
  return StoreReadCounters{chunks_read_.load(), chunk_bytes_.load(), index_bytes_.load(),
                           device_bytes_.load()};
}

}  // namespace strielad
