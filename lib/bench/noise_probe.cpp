// SPDX-License-Identifier: Apache-2.0
#include "bench/noise_probe.h"

#include <cmath>

#include "bench/stopwatch.h"

namespace strielad::bench {

double noise_probe_seconds(std::uint64_t iterations) {
  const Stopwatch clock;
  std::uint64_t state = 0x9E3779B97F4A7C15ull;
  double acc = 1.0;
  for (std::uint64_t i = 0; i < iterations; ++i) {
    state ^= state << 13;
    state ^= state >> 7;
    state ^= state << 17;
    acc = acc * 0.999999 + double(state >> 40) * 1e-12;
  }
  const double seconds = clock.seconds();
  // Keeps the loop from being optimised away.
  volatile double sink = acc + double(state & 1);
  (void)sink;
  return seconds;
}

}  // namespace strielad::bench
