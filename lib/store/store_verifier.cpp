// SPDX-License-Identifier: Apache-2.0
#include "store/store_verifier.h"

#include <cmath>

#include "core/error.h"
#include "store/store.h"

namespace strielad {
namespace {

// Level-0 bricks cover exactly the samples their statistics describe: recompute them. A
// zfp chunk's samples are within `tolerance` of those the statistics were taken from
// (formats/store.md, "zfp chunks (version 6)"), so its range may be that much wider.
std::string check_level0_stats(const Brick& b, const format::IndexEntry& e, double tolerance) {
  double mn = NAN, mx = NAN;
  for (std::size_t i = 0; i < b.sample_count(); ++i) {
    const double v = b.sample(i);
    if (std::isnan(v)) continue;
    if (std::isnan(mn) || v < mn) mn = v;
    if (std::isnan(mx) || v > mx) mx = v;
  }
  const bool same = (std::isnan(mn) && std::isnan(e.min)) || (mn == e.min && mx == e.max);
  if (e.coding == format::ChunkCoding::kZfp && !std::isnan(mn) && !std::isnan(e.min)) {
    if (std::abs(mn - e.min) > tolerance || std::abs(mx - e.max) > tolerance) {
      return fmt::format("recorded range [{}, {}] and the data's [{}, {}] differ by more than the "
                         "lossy tolerance {}",
                         e.min, e.max, mn, mx, tolerance);
    }
    return {};
  }
  if (!same) {
    return fmt::format("recorded range [{}, {}] differs from the data's [{}, {}]", e.min, e.max, mn,
                       mx);
  }
  return {};
}

// Every brick of one index (a variable's or the geometry field's) decodes, and level-0
// statistics match the data (within `tolerance` for zfp chunks). `read` reads node n;
// `describe` names its file and node.
template <typename ReadBrick, typename Describe>
void check_bricks(std::span<const format::IndexEntry> entries, NodeId level0_end,
                  const ReadBrick& read, const Describe& describe, VerifyReport& report,
                  double tolerance = 0) {
  for (NodeId n = 0; n < entries.size(); ++n) {
    try {
      const Brick b = read(n);
      ++report.bricks_checked;
      report.chunk_bytes_checked += entries[n].chunk_size;
      if (n < level0_end) {
        const std::string why = check_level0_stats(b, entries[n], tolerance);
        if (!why.empty()) report.problems.push_back(fmt::format("{}: {}", describe(n), why));
      }
    } catch (const Error& e) {
      report.problems.push_back(e.what());
    }
  }
}

// The GEOMETRY file and, for a time-invariant vertical field, geometry.bricks.
void check_static_geometry(const Store& store, NodeId level0_end, VerifyReport& report) {
  try {
    store.horizontal_coordinates();
  } catch (const Error& e) {
    report.problems.push_back(e.what());
  }
  if (!store.has_geometry_field() || store.manifest().geometry->vertical.varies_in_time ||
      store.step_count() == 0) {
    return;
  }
  std::span<const format::IndexEntry> entries;
  try {
    entries = store.geometry_index(0);
  } catch (const Error& e) {
    report.problems.push_back(e.what());
    return;
  }
  const auto field = static_cast<std::uint32_t>(store.variable_count());
  check_bricks(
      entries, level0_end, [&](NodeId n) { return store.read_geometry_brick(0, n); },
      [&](NodeId n) {
        return fmt::format("{}: {}", store.geometry_bricks_path().string(),
                           store.describe_node(field, n));
      },
      report);
}

}  // namespace

nlohmann::json VerifyReport::to_json() const {
  return nlohmann::json{{"ok", ok()},
                        {"steps_checked", steps_checked},
                        {"bricks_checked", bricks_checked},
                        {"chunk_bytes_checked", chunk_bytes_checked},
                        {"problems", problems}};
}

VerifyReport verify_store(const std::filesystem::path& dir,
                          const std::function<void(std::uint64_t, std::uint64_t)>& progress) {
  VerifyReport report;
  std::shared_ptr<const Store> store;
  try {
    store = Store::open(dir, StoreOpenOptions{.allow_incomplete = true});
  } catch (const Error& e) {
    report.problems.push_back(e.what());
    return report;
  }
  if (!store->manifest().complete) {
    report.problems.push_back(fmt::format("{}: conversion not finalized (state 'converting')",
                                          dir.string()));
  }
  const OctreeLayout& layout = store->octree();
  const NodeId level0_end = static_cast<NodeId>(layout.level(0).node_count());
  check_static_geometry(*store, level0_end, report);
  const bool field_per_step =
      store->has_geometry_field() && store->manifest().geometry->vertical.varies_in_time;
  for (std::uint32_t s = 0; s < store->step_count(); ++s) {
    if (progress) progress(s, store->step_count());
    if (!store->has_step(s)) {
      report.problems.push_back(fmt::format("{}: time step {} not converted ({} is missing)",
                                            dir.string(), s, format::step_file_name(s)));
      continue;
    }
    ++report.steps_checked;
    const auto describe = [&](std::uint32_t v) {
      return [&store, s, v](NodeId n) {
        return fmt::format("{}: {}", store->step_path(s).string(), store->describe_node(v, n));
      };
    };
    bool damaged = false;
    for (std::uint32_t v = 0; v < store->variable_count(); ++v) {
      std::span<const format::IndexEntry> entries;
      try {
        entries = store->index(s, v);
      } catch (const Error& e) {
        report.problems.push_back(e.what());
        damaged = true;  // the step's structure is damaged; its other sections would repeat it
        break;
      }
      const auto& zfp = store->manifest().codec_of(v).zfp;
      check_bricks(
          entries, level0_end, [&](NodeId n) { return store->read_brick(s, v, n); }, describe(v),
          report, zfp ? zfp->tolerance : 0.0);
    }
    if (!field_per_step || damaged) continue;
    std::span<const format::IndexEntry> entries;
    try {
      entries = store->geometry_index(s);
    } catch (const Error& e) {
      report.problems.push_back(e.what());
      continue;
    }
    check_bricks(
        entries, level0_end, [&](NodeId n) { return store->read_geometry_brick(s, n); },
        describe(static_cast<std::uint32_t>(store->variable_count())), report);
  }
  if (progress) progress(store->step_count(), store->step_count());
  return report;
}

}  // namespace strielad
