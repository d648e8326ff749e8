// SPDX-License-Identifier: Apache-2.0
#include "convert/level_sampler.h"

#include <tbb/parallel_for.h>

#include <cmath>
#include <limits>

namespace strielad::build {

template <typename T>
void downsample_planes(const PlaneBlock<T>& fine, std::array<bool, 3> halved,
                       std::vector<T>& coarse, std::array<std::size_t, 3> cd, std::size_t cz_begin,
                       std::size_t cz_end) {
  const std::size_t fnx = fine.dims[0], fny = fine.dims[1], fnz = fine.z_total;
  const std::size_t fine_n[3] = {fnx, fny, fnz};
  tbb::parallel_for(cz_begin, cz_end, [&](std::size_t cz) {
    const std::size_t fz = fine_center(cz, halved[2], fnz);
    for (std::size_t cy = 0; cy < cd[1]; ++cy) {
      const std::size_t fy = fine_center(cy, halved[1], fny);
      T* out = coarse.data() + (cz * cd[1] + cy) * cd[0];
      for (std::size_t cx = 0; cx < cd[0]; ++cx) {
        const std::size_t fx = fine_center(cx, halved[0], fnx);
        const T centre = fine.at(fx, fy, fz);
        if (!std::isnan(centre)) {
          out[cx] = centre;
          continue;
        }
        // Fall back to the mean of the valid neighbours along the halved axes.
        const std::size_t c[3] = {fx, fy, fz};
        std::size_t lo[3], hi[3];
        for (int a = 0; a < 3; ++a) {
          lo[a] = (halved[a] && c[a] > 0) ? c[a] - 1 : c[a];
          hi[a] = (halved[a] && c[a] + 1 < fine_n[a]) ? c[a] + 1 : c[a];
        }
        // `scale` 1 first; a sum beyond the double range (float64 data near its maximum)
        // is taken again on values scaled by 2^-5, exactly, which 27 values cannot overflow.
        double mean = 0;
        std::size_t count = 0;
        for (const double scale : {1.0, 1.0 / 32}) {
          double sum = 0;
          count = 0;
          for (std::size_t z = lo[2]; z <= hi[2]; ++z)
            for (std::size_t y = lo[1]; y <= hi[1]; ++y)
              for (std::size_t x = lo[0]; x <= hi[0]; ++x) {
                const T v = fine.at(x, y, z);
                if (!std::isnan(v)) {
                  sum += static_cast<double>(v) * scale;
                  ++count;
                }
              }
          mean = count ? sum / static_cast<double>(count) / scale : 0.0;
          if (std::isfinite(sum)) break;
        }
        out[cx] = count ? static_cast<T>(mean) : std::numeric_limits<T>::quiet_NaN();
      }
    }
  });
}

template void downsample_planes<float>(const PlaneBlock<float>&, std::array<bool, 3>,
                                       std::vector<float>&, std::array<std::size_t, 3>, std::size_t,
                                       std::size_t);
template void downsample_planes<double>(const PlaneBlock<double>&, std::array<bool, 3>,
                                        std::vector<double>&, std::array<std::size_t, 3>,
                                        std::size_t, std::size_t);

}  // namespace strielad::build
