// SPDX-License-Identifier: Apache-2.0
#include "support/geometry_store.h"

#include <cmath>
#include <functional>
#include <vector>

#include "convert/brick_encoder.h"
#include "convert/geometry_writer.h"
#include "convert/step_writer.h"
#include "core/checksum.h"
#include "core/file_io.h"
#include "octree/octree_layout.h"

namespace strielad::testing {
namespace {

using Sample = std::function<double(std::size_t, std::size_t, std::size_t)>;

// Every node's brick of the level-0 field `at`, in node-id order. Coarse samples are
// level-0 samples (nothing is missing); a node's range covers its level-0 box.
template <typename T>
std::vector<build::EncodedBrick> encode_all_nodes(const OctreeLayout& layout, const Sample& at,
                                                  const format::CodecSpec& codec) {
  std::vector<build::EncodedBrick> out;
  for (std::size_t l = 0; l < layout.level_count(); ++l) {
    const LevelShape& shape = layout.level(l);
    const auto& n = shape.samples;
    std::vector<T> level(n[0] * n[1] * n[2]);
    for (std::size_t z = 0; z < n[2]; ++z) {
      for (std::size_t y = 0; y < n[1]; ++y) {
        for (std::size_t x = 0; x < n[0]; ++x) {
          level[(z * n[1] + y) * n[0] + x] =
              static_cast<T>(at(layout.fine_index(l, 0, x), layout.fine_index(l, 1, y),
                                layout.fine_index(l, 2, z)));
        }
      }
    }
    const build::PlaneBlock<T> block{level.data(), n, 0, n[2]};
    for (NodeId id = shape.first_node; id < shape.first_node + shape.node_count(); ++id) {
      const NodeKey key = layout.key(id);
      const IndexBox box = layout.level_box(key);
      if (l == 0) {
        const IndexBox owned = layout.owned_fine_box(key);
        out.push_back(build::encode_brick(block, box, &owned, {}, codec));
        continue;
      }
      build::NodeStats stats;
      const IndexBox fine = layout.fine_box(key);
      for (std::size_t z = fine.lo[2]; z <= fine.hi[2]; ++z) {
        for (std::size_t y = fine.lo[1]; y <= fine.hi[1]; ++y) {
          for (std::size_t x = fine.lo[0]; x <= fine.hi[0]; ++x) {
            const double v = static_cast<T>(at(x, y, z));
            stats.min = std::isnan(stats.min) ? v : std::min(stats.min, v);
            stats.max = std::isnan(stats.max) ? v : std::max(stats.max, v);
          }
        }
      }
      stats.valid_count = layout.owned_fine_box(key).count();
      out.push_back(build::encode_brick(block, box, nullptr, stats, codec));
    }
  }
  return out;
}

Axis index_axis(const std::string& name, std::size_t n) {
  Axis a{name, AxisKind::kIndex, "1", "", "", "", {}};
  for (std::size_t i = 0; i < n; ++i) a.values.push_back(double(i));
  return a;
}

Axis ramp_axis(const std::string& name, AxisKind kind, const std::string& units, double first,
               double step, std::size_t n) {
  Axis a{name, kind, units, "", "", "", {}};
  for (std::size_t i = 0; i < n; ++i) a.values.push_back(first + step * double(i));
  return a;
}

format::CodecSpec field_codec() {
  format::CodecSpec c;
  c.predictor = std::string(format::kPredictorLorenzo3);  // unlike the variable's codec
  c.level = 5;
  return c;
}

format::Manifest geometry_manifest(const GeometryStoreSpec& spec) {
  format::Manifest m;
  m.tool_version = "test";
  if (spec.curvilinear) {
    m.x = index_axis("x", spec.nx);
    m.y = index_axis("y", spec.ny);
  } else {
    m.x = ramp_axis("lon", AxisKind::kLongitude, "degrees_east", 10, 0.5, spec.nx);
    m.y = ramp_axis("lat", AxisKind::kLatitude, "degrees_north", 45, 0.5, spec.ny);
  }
  m.z = ramp_axis("level", AxisKind::kModelLevel, "1", 1, 1, spec.nz);
  m.time = TimeAxis{"time", "hours since 2000-01-01", "standard", {}};
  for (std::size_t s = 0; s < spec.steps; ++s) m.time.values.push_back(double(s));
  format::StoreVariable v;
  v.name = "ta";
  v.units = "K";
  m.variables.push_back(v);
  m.brick = spec.brick;
  format::GridGeometry g;
  if (spec.curvilinear) {
    g.horizontal.kind = format::HorizontalGeometry::Kind::kCurvilinear;
    g.horizontal.lon_variable = "XLONG";
    g.horizontal.lat_variable = "XLAT";
    g.horizontal.coordinates_checksum =
        format::coordinates_checksum(geometry_store_coordinates(spec));
  }
  if (spec.field != GeometryField::kNone) {
    g.vertical.kind = format::VerticalGeometry::Kind::kField;
    g.vertical.units = "m";
    g.vertical.formula = "atmosphere_hybrid_height_coordinate";
    g.vertical.terms = {{"a", "a"}, {"b", "b"}, {"orog", "topography_c"}};
    g.vertical.varies_in_time = spec.field == GeometryField::kVarying;
    g.vertical.dtype = DType::kFloat64;
    g.vertical.codec = field_codec();
  }
  if (spec.surface) g.surface = format::SurfaceGeometry{"topography_c", "m"};
  m.geometry = g;
  m.format_version = format::version_for_plan(m);
  m.store_id = format::compute_store_id(m);
  return m;
}

}  // namespace

double geometry_store_value(std::size_t x, std::size_t y, std::size_t z, std::size_t step) {
  return double(x) + 10.0 * double(y) + 100.0 * double(z) + 1000.0 * double(step);
}

double geometry_store_height(const GeometryStoreSpec& spec, std::size_t x, std::size_t y,
                             std::size_t z, std::size_t step) {
  const double time_part = spec.field == GeometryField::kVarying ? 7.0 * double(step) : 0.0;
  return 100.0 + 10.0 * double(x) + 5.0 * double(y) + 250.0 * double(z) + time_part;
}

format::HorizontalCoordinates geometry_store_coordinates(const GeometryStoreSpec& spec) {
  format::HorizontalCoordinates c;
  c.nx = static_cast<std::uint32_t>(spec.nx);
  c.ny = static_cast<std::uint32_t>(spec.ny);
  std::vector<double> surface;
  for (std::size_t j = 0; j < spec.ny; ++j) {
    for (std::size_t i = 0; i < spec.nx; ++i) {
      if (spec.curvilinear) {
        c.lon.push_back(10.0 + 0.5 * double(i) + 0.125 * double(j));
        c.lat.push_back(45.0 + 0.5 * double(j) - 0.0625 * double(i));
      }
      surface.push_back(100.0 + 10.0 * double(i) + 5.0 * double(j));
    }
  }
  if (spec.surface) c.surface_m = std::move(surface);
  return c;
}

format::Manifest write_geometry_store(const std::filesystem::path& dir,
                                      const GeometryStoreSpec& spec) {
  format::Manifest m = geometry_manifest(spec);
  std::filesystem::create_directories(dir / "steps");
  const OctreeLayout layout(m.dims(), m.brick);
  const auto node_count = static_cast<std::uint32_t>(layout.node_count());
  if (format::has_geometry_file(m)) {
    build::write_geometry_file(dir,
                               format::GeometryFile{m.store_id, geometry_store_coordinates(spec)});
  }
  const auto height_at = [&](std::size_t step) -> Sample {
    return [&spec, step](std::size_t x, std::size_t y, std::size_t z) {
      return geometry_store_height(spec, x, y, z, step);
    };
  };
  if (format::has_geometry_bricks(m)) {
    build::write_geometry_bricks(
        dir, m.store_id,
        encode_all_nodes<double>(layout, height_at(0), m.geometry->vertical.codec));
  }
  const std::uint32_t sections = format::step_section_count(m);
  for (std::uint32_t s = 0; s < spec.steps; ++s) {
    const auto path = dir / format::step_file_name(s);
    build::StepWriter writer(path, format::StepHeader{m.store_id, s, sections, node_count});
    const Sample value = [s](std::size_t x, std::size_t y, std::size_t z) {
      return geometry_store_value(x, y, z, s);
    };
    auto bricks = encode_all_nodes<float>(layout, value, m.codec);
    for (NodeId n = 0; n < node_count; ++n) writer.add_brick(0, n, std::move(bricks[n]));
    if (sections > m.variables.size()) {
      auto field = encode_all_nodes<double>(layout, height_at(s), m.geometry->vertical.codec);
      for (NodeId n = 0; n < node_count; ++n) writer.add_brick(1, n, std::move(field[n]));
    }
    writer.commit();
    const auto size = std::filesystem::file_size(path);
    ReadOnlyFile file(path);
    std::vector<std::byte> footer(format::kStepFooterSize);
    file.read_at(size - footer.size(), footer);
    m.steps.push_back(format::StepRecord{s, format::step_file_name(s), size,
                                         checksum64(std::span(footer).first(48))});
  }
  m.complete = true;
  write_file_atomically(dir / "MANIFEST", format::encode_manifest(m));
  return m;
}

}  // namespace strielad::testing
