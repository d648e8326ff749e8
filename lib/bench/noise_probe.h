// SPDX-License-Identifier: Apache-2.0
// A noise probe for benchmark reports: a fixed amount of single-threaded CPU work (a
// dependent chain of integer and floating-point operations on a few registers, no memory
// traffic), timed. On an otherwise idle core it takes the same time every run, so the
// spread of repeated probes over a long benchmark run states how much other load on a
// shared machine slowed it.
#pragma once

#include <cstdint>

namespace strielad::bench {

// Wall seconds of one probe of `iterations` steps (about 60 ms at the default on a
// 3 GHz core).
double noise_probe_seconds(std::uint64_t iterations = 50'000'000);

}  // namespace strielad::bench
