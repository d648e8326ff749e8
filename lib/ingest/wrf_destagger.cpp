// SPDX-License-Identifier: Apache-2.0
#include "ingest/wrf_destagger.h"

#include <string_view>

#include "core/error.h"

namespace strielad::ingest {
namespace {

bool ends_with_stag(const std::string& name) {
  constexpr std::string_view kSuffix = "_stag";
  return name.size() > kSuffix.size() &&
         std::string_view(name).substr(name.size() - kSuffix.size()) == kSuffix;
}

template <typename Out>
void destagger_any(std::span<const double> in, const Dims3& slab, StaggeredAxis axis,
                   std::span<Out> out) {
  const Dims3 ext = staggered_extent(slab, axis);
  if (in.size() != ext.count() || out.size() != slab.count()) {
    throw make_error(ErrorCode::kInternal, "destagger: {} staggered and {} mass samples for a {} x "
                     "{} x {} slab", in.size(), out.size(), slab.x, slab.y, slab.z);
  }
  // Offset (in staggered samples) of the second neighbour.
  const std::size_t step = axis == StaggeredAxis::kX   ? 1
                           : axis == StaggeredAxis::kY ? ext.x
                           : axis == StaggeredAxis::kZ ? ext.x * ext.y
                                                       : 0;
  std::size_t o = 0;
  for (std::size_t k = 0; k < slab.z; ++k) {
    for (std::size_t j = 0; j < slab.y; ++j) {
      const std::size_t row = (k * ext.y + j) * ext.x;
      for (std::size_t i = 0; i < slab.x; ++i, ++o) {
        const double a = in[row + i];
        out[o] = static_cast<Out>(step == 0 ? a : 0.5 * (a + in[row + i + step]));
      }
    }
  }
}

}  // namespace

std::optional<StaggeredAxis> staggered_axis(const std::array<std::string, 3>& names,
                                            const std::array<std::size_t, 3>& lengths,
                                            const Dims3& grid) {
  const std::array<std::size_t, 3> want{grid.z, grid.y, grid.x};
  constexpr std::array<StaggeredAxis, 3> kAxes{StaggeredAxis::kZ, StaggeredAxis::kY,
                                               StaggeredAxis::kX};
  StaggeredAxis found = StaggeredAxis::kNone;
  for (std::size_t d = 0; d < 3; ++d) {
    if (lengths[d] == want[d]) continue;
    if (lengths[d] != want[d] + 1 || !ends_with_stag(names[d]) || found != StaggeredAxis::kNone) {
      return std::nullopt;
    }
    found = kAxes[d];
  }
  return found;
}

Dims3 staggered_extent(const Dims3& slab, StaggeredAxis axis) {
  Dims3 e = slab;
  if (axis == StaggeredAxis::kX) ++e.x;
  if (axis == StaggeredAxis::kY) ++e.y;
  if (axis == StaggeredAxis::kZ) ++e.z;
  return e;
}

void destagger(std::span<const double> staggered, const Dims3& slab, StaggeredAxis axis,
               std::span<double> out) {
  destagger_any(staggered, slab, axis, out);
}

void destagger(std::span<const double> staggered, const Dims3& slab, StaggeredAxis axis,
               std::span<float> out) {
  destagger_any(staggered, slab, axis, out);
}

}  // namespace strielad::ingest
