// SPDX-License-Identifier: Apache-2.0
#include "store/store_verifier.h"

#include <cmath>

#include "core/error.h"
#include "store/store.h"

namespace strielad {
namespace {

// Level-0 bricks cover exactly the samples their statistics describe: recompute them.
std::string check_level0_stats(const Brick& b, const format::IndexEntry& e) {
  double mn = NAN, mx = NAN;
  for (std::size_t i = 0; i < b.sample_count(); ++i) {
    const double v = b.sample(i);
    if (std::isnan(v)) continue;
    if (std::isnan(mn) || v < mn) mn = v;
    if (std::isnan(mx) || v > mx) mx = v;
  }
  const bool same = (std::isnan(mn) && std::isnan(e.min)) || (mn == e.min && mx == e.max);
  if (!same) {
    return fmt::format("recorded range [{}, {}] differs from the data's [{}, {}]", e.min, e.max, mn,
                       mx);
  }
  return {};
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
  for (std::uint32_t s = 0; s < store->step_count(); ++s) {
    if (progress) progress(s, store->step_count());
    if (!store->has_step(s)) {
      report.problems.push_back(fmt::format("{}: time step {} not converted ({} is missing)",
                                            dir.string(), s, format::step_file_name(s)));
      continue;
    }
    ++report.steps_checked;
    for (std::uint32_t v = 0; v < store->variable_count(); ++v) {
      std::span<const format::IndexEntry> entries;
      try {
        entries = store->index(s, v);
      } catch (const Error& e) {
        report.problems.push_back(e.what());
        break;  // the step's structure is damaged; its other variables would repeat it
      }
      for (NodeId n = 0; n < entries.size(); ++n) {
        try {
          const Brick b = store->read_brick(s, v, n);
          ++report.bricks_checked;
          report.chunk_bytes_checked += entries[n].chunk_size;
          if (n < level0_end) {
            const std::string why = check_level0_stats(b, entries[n]);
            if (!why.empty()) {
              report.problems.push_back(fmt::format("{}: {}: {}", store->step_path(s).string(),
                                                    store->describe_node(v, n), why));
            }
          }
        } catch (const Error& e) {
          report.problems.push_back(e.what());
        }
      }
    }
  }
  if (progress) progress(store->step_count(), store->step_count());
  return report;
}

}  // namespace strielad
