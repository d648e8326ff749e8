// SPDX-License-Identifier: Apache-2.0
#include "robust/store_checks.h"

#include <bit>
#include <cmath>
#include <limits>

#include "robust/case_reference.h"
#include "store/level_samples.h"

namespace strielad::robust {
namespace {

bool same_value(double a, double b) {
  return (std::isnan(a) && std::isnan(b)) ||
         std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

// min/max compare as numbers (the index keeps -0 and +0 apart no more than the data).
bool same_number(double a, double b) { return (std::isnan(a) && std::isnan(b)) || a == b; }

}  // namespace

StageFindings check_statistics(const Store& store, const std::vector<std::vector<double>>& level0) {
  StageFindings f;
  const OctreeLayout& layout = store.octree();
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  std::uint64_t valid_total = 0;
  for (std::uint32_t step = 0; step < store.step_count(); ++step) {
    const auto entries = store.index(step, 0);
    std::vector<NodeReference> ref = reference_node_stats(layout, level0.at(step));
    for (std::size_t level = 1; level < layout.level_count(); ++level) {
      widen_to_level_samples(ref, layout, level, read_level_samples<double>(store, step, 0, level).values);
    }
    for (NodeId n = 0; n < entries.size(); ++n) {
      const auto& e = entries[n];
      const auto& r = ref[n];
      if (!same_number(e.min, r.min) || !same_number(e.max, r.max) || e.valid_count != r.valid_count) {
        f.problem("step {} node {}: range [{}, {}] with {} valid, the input has [{}, {}] with {}",
                  step, n, e.min, e.max, e.valid_count, r.min, r.max, r.valid_count);
      }
    }
    std::uint64_t valid = 0;
    for (double v : level0[step]) {
      if (std::isnan(v)) continue;
      ++valid;
      lo = std::min(lo, v);
      hi = std::max(hi, v);
    }
    if (entries[layout.root()].valid_count != valid) {
      f.problem("step {}: the root counts {} valid samples, the input has {}", step,
                entries[layout.root()].valid_count, valid);
    }
    valid_total += valid;
  }
  const auto& summary = store.manifest().summary;
  const auto& var = summary.at("variables").at("f");
  if (valid_total == 0) {
    if (!var.at("min").is_null() || !var.at("max").is_null()) {
      f.problem("summary range {} .. {} for a variable without valid data", var.at("min").dump(),
                var.at("max").dump());
    }
  } else if (!var.at("min").is_number() || !var.at("max").is_number() ||
             var.at("min").get<double>() != lo || var.at("max").get<double>() != hi) {
    f.problem("summary range {} .. {}, the input's is {} .. {}", var.at("min").dump(),
              var.at("max").dump(), lo, hi);
  }
  f.summary = fmt::format("{} nodes x {} steps exact; {} valid samples; range {} .. {}",
                          layout.node_count(), store.step_count(), valid_total,
                          valid_total ? fmt::format("{}", lo) : "none",
                          valid_total ? fmt::format("{}", hi) : "none");
  return f;
}

StageFindings check_levels(const ExtremeCase& c, const Store& store,
                           const std::vector<std::vector<double>>& level0) {
  StageFindings f;
  const OctreeLayout& layout = store.octree();
  const bool is_double = stores_double(c);
  std::uint64_t exact = 0, means = 0;
  double worst = 0;  // largest error / bound of a fallback mean
  for (std::uint32_t step = 0; step < store.step_count(); ++step) {
    LevelSamples<double> fine = read_level_samples<double>(store, step, 0, 0);
    if (fine.shared_mismatches) {
      f.problem("step {} level 0: {} shared samples differ between bricks", step,
                fine.shared_mismatches);
    }
    for (std::size_t i = 0; i < fine.values.size(); ++i) {
      if (!same_value(fine.values[i], level0.at(step)[i])) {
        f.problem("step {} level 0 sample {}: stored {}, input {}", step, i, fine.values[i],
                  level0[step][i]);
      }
    }
    exact += fine.values.size();
    for (std::size_t level = 0; level + 1 < layout.level_count(); ++level) {
      const CoarseReference ref = reference_downsample(layout, level, fine.values, is_double);
      LevelSamples<double> coarse = read_level_samples<double>(store, step, 0, level + 1);
      if (coarse.shared_mismatches) {
        f.problem("step {} level {}: {} shared samples differ between bricks", step, level + 1,
                  coarse.shared_mismatches);
      }
      for (std::size_t i = 0; i < coarse.values.size(); ++i) {
        const double got = coarse.values[i];
        if (!ref.fallback[i]) {
          ++exact;
          if (!same_value(got, ref.values[i])) {
            f.problem("step {} level {} sample {}: stored {}, the centre sample is {}", step,
                      level + 1, i, got, ref.values[i]);
          }
          continue;
        }
        ++means;
        if (std::isnan(got) != std::isnan(ref.values[i])) {
          f.problem("step {} level {} sample {}: stored {}, reference mean {}", step, level + 1, i,
                    got, ref.values[i]);
          continue;
        }
        if (std::isnan(got)) continue;
        const long double error = std::fabs(static_cast<long double>(got) - ref.exact[i]);
        if (!(error <= ref.tolerance[i]) || !std::isfinite(got)) {
          f.problem("step {} level {} sample {}: stored mean {} is {} from the exact {}, bound {}",
                    step, level + 1, i, got, static_cast<double>(error),
                    static_cast<double>(ref.exact[i]), ref.tolerance[i]);
        } else if (ref.tolerance[i] > 0) {
          worst = std::max(worst, static_cast<double>(error / ref.tolerance[i]));
        }
      }
      fine = std::move(coarse);
    }
  }
  f.summary = fmt::format("{} levels x {} steps: {} samples bit-exact, {} fallback means within "
                          "the bound (worst {:.2f} of it)",
                          layout.level_count(), store.step_count(), exact, means, worst);
  return f;
}

}  // namespace strielad::robust
