// SPDX-License-Identifier: Apache-2.0
#include "robust/case_reference.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "grid/axis.h"

namespace strielad::robust {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The value as the store type holds it.
double to_store_type(long double v, bool is_double) {
  return is_double ? static_cast<double>(v) : static_cast<double>(static_cast<float>(v));
}

// Distance from |x| to the next representable value of the store type, at x's rounding.
double ulp(long double x, bool is_double) {
  if (is_double) {
    const double d = std::fabs(static_cast<double>(x));
    return std::nextafter(d, std::numeric_limits<double>::infinity()) - d;
  }
  const float f = std::fabs(static_cast<float>(x));
  return static_cast<double>(std::nextafter(f, std::numeric_limits<float>::infinity())) -
         static_cast<double>(f);
}

// Neumaier's compensated sum in long double.
struct CompensatedSum {
  long double sum = 0, compensation = 0, magnitude = 0;
  std::size_t count = 0;
  void add(long double v) {
    const long double t = sum + v;
    compensation += std::fabs(sum) >= std::fabs(v) ? (sum - t) + v : (v - t) + sum;
    sum = t;
    magnitude += std::fabs(v);
    ++count;
  }
  long double value() const { return sum + compensation; }
};

}  // namespace

bool stores_double(const ExtremeCase& c) { return c.input.type == SourceType::kDouble; }

std::vector<std::vector<double>> reference_level0(const ExtremeCase& c) {
  const CaseInput& in = c.input;
  std::vector<std::vector<double>> steps;
  if (in.values.empty()) return steps;
  const bool is_double = stores_double(c);
  const std::size_t n = c.samples_per_step();
  // Attributes as the ingest reads them: the fill in the variable's type, scale and offset
  // from float attributes.
  const auto as_source = [&](double v) {
    switch (in.type) {
      case SourceType::kFloat: return static_cast<double>(static_cast<float>(v));
      case SourceType::kDouble: return v;
      case SourceType::kShortPacked: return static_cast<double>(static_cast<short>(std::lround(v)));
    }
    return v;
  };
  const double scale = static_cast<float>(in.scale_factor.value_or(1.0));
  const double offset = static_cast<float>(in.add_offset.value_or(0.0));
  for (std::size_t t = 0; t < c.steps(); ++t) {
    std::vector<double> level0(n);
    for (std::size_t i = 0; i < n; ++i) {
      const double raw = as_source(in.values[t * n + i]);
      const bool fill = in.fill_value && raw == as_source(*in.fill_value);
      if (fill || !std::isfinite(raw)) {
        level0[i] = kNaN;
      } else if (in.type == SourceType::kShortPacked) {
        const double unpacked = to_store_type(raw * scale + offset, false);
        level0[i] = std::isfinite(unpacked) ? unpacked : kNaN;
      } else {
        level0[i] = to_store_type(raw, is_double);
      }
    }
    // Longitudes round the Earth: the store repeats the first meridian at the end.
    if (longitudes_close_the_circle(in.lon)) {
      const std::size_t nx = in.lon.size();
      std::vector<double> closed;
      closed.reserve(n / nx * (nx + 1));
      for (std::size_t row = 0; row < n / nx; ++row) {
        closed.insert(closed.end(), level0.begin() + static_cast<std::ptrdiff_t>(row * nx),
                      level0.begin() + static_cast<std::ptrdiff_t>((row + 1) * nx));
        closed.push_back(level0[row * nx]);
      }
      level0 = std::move(closed);
    }
    steps.push_back(std::move(level0));
  }
  return steps;
}

std::vector<NodeReference> reference_node_stats(const OctreeLayout& layout,
                                                const std::vector<double>& level0) {
  const Dims3 g = layout.grid();
  const auto at = [&](std::size_t x, std::size_t y, std::size_t z) {
    return level0[(z * g.y + y) * g.x + x];
  };
  std::vector<NodeReference> out(layout.node_count());
  for (NodeId n = 0; n < layout.node_count(); ++n) {
    const NodeKey key = layout.key(n);
    NodeReference& r = out[n];
    r.min = r.max = kNaN;
    const IndexBox box = layout.fine_box(key);
    for (std::size_t z = box.lo[2]; z <= box.hi[2]; ++z)
      for (std::size_t y = box.lo[1]; y <= box.hi[1]; ++y)
        for (std::size_t x = box.lo[0]; x <= box.hi[0]; ++x) {
          const double v = at(x, y, z);
          if (std::isnan(v)) continue;
          if (std::isnan(r.min) || v < r.min) r.min = v;
          if (std::isnan(r.max) || v > r.max) r.max = v;
        }
    const IndexBox owned = layout.owned_fine_box(key);
    for (std::size_t z = owned.lo[2]; z <= owned.hi[2]; ++z)
      for (std::size_t y = owned.lo[1]; y <= owned.hi[1]; ++y)
        for (std::size_t x = owned.lo[0]; x <= owned.hi[0]; ++x) {
          r.valid_count += std::isnan(at(x, y, z)) ? 0 : 1;
        }
  }
  return out;
}

void widen_to_level_samples(std::vector<NodeReference>& stats, const OctreeLayout& layout,
                            std::size_t level, const std::vector<double>& values) {
  const LevelShape& shape = layout.level(level);
  for (NodeId n = shape.first_node; n < shape.first_node + shape.node_count(); ++n) {
    NodeReference& r = stats[n];
    const IndexBox box = layout.level_box(layout.key(n));
    for (std::size_t z = box.lo[2]; z <= box.hi[2]; ++z)
      for (std::size_t y = box.lo[1]; y <= box.hi[1]; ++y)
        for (std::size_t x = box.lo[0]; x <= box.hi[0]; ++x) {
          const double v = values[(z * shape.samples[1] + y) * shape.samples[0] + x];
          if (std::isnan(v)) continue;
          if (std::isnan(r.min) || v < r.min) r.min = v;
          if (std::isnan(r.max) || v > r.max) r.max = v;
        }
  }
}

double mean_tolerance(long double exact, long double sum_abs, std::size_t count, bool is_double) {
  const long double k = static_cast<long double>(count);
  const long double accumulation = (k + 1) * std::ldexp(1.0L, -53) * sum_abs / k;
  return ulp(exact, is_double) / 2 + static_cast<double>(accumulation);
}

CoarseReference reference_downsample(const OctreeLayout& layout, std::size_t fine_level,
                                     const std::vector<double>& fine, bool is_double) {
  const LevelShape& f = layout.level(fine_level);
  const LevelShape& c = layout.level(fine_level + 1);
  std::array<bool, 3> halved{};
  for (int a = 0; a < 3; ++a) halved[a] = c.stride[a] != f.stride[a];
  const auto fine_at = [&](std::size_t x, std::size_t y, std::size_t z) {
    return fine[(z * f.samples[1] + y) * f.samples[0] + x];
  };
  CoarseReference out;
  const std::size_t count = c.samples[0] * c.samples[1] * c.samples[2];
  out.values.assign(count, kNaN);
  out.exact.assign(count, kNaN);
  out.tolerance.assign(count, 0.0);
  out.fallback.assign(count, 0);
  std::size_t i = 0;
  for (std::size_t cz = 0; cz < c.samples[2]; ++cz)
    for (std::size_t cy = 0; cy < c.samples[1]; ++cy)
      for (std::size_t cx = 0; cx < c.samples[0]; ++cx, ++i) {
        const std::array<std::size_t, 3> cc{cx, cy, cz};
        std::array<std::size_t, 3> centre{}, lo{}, hi{};
        for (int a = 0; a < 3; ++a) {
          centre[a] = halved[a] ? std::min(2 * cc[a], f.samples[a] - 1) : cc[a];
          lo[a] = halved[a] && centre[a] > 0 ? centre[a] - 1 : centre[a];
          hi[a] = halved[a] ? std::min(centre[a] + 1, f.samples[a] - 1) : centre[a];
        }
        const double v = fine_at(centre[0], centre[1], centre[2]);
        if (!std::isnan(v)) {
          out.values[i] = v;
          out.exact[i] = v;
          continue;
        }
        out.fallback[i] = 1;
        CompensatedSum sum;
        for (std::size_t z = lo[2]; z <= hi[2]; ++z)
          for (std::size_t y = lo[1]; y <= hi[1]; ++y)
            for (std::size_t x = lo[0]; x <= hi[0]; ++x) {
              const double w = fine_at(x, y, z);
              if (!std::isnan(w)) sum.add(w);
            }
        if (sum.count == 0) continue;
        const long double mean = sum.value() / static_cast<long double>(sum.count);
        out.values[i] = to_store_type(mean, is_double);
        out.exact[i] = mean;
        out.tolerance[i] = mean_tolerance(mean, sum.magnitude, sum.count, is_double);
      }
  return out;
}

}  // namespace strielad::robust
