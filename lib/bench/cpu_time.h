// SPDX-License-Identifier: Apache-2.0
// CPU seconds (user + system) used by this process, all threads, and by a waited-for
// child: on a shared machine CPU time varies less than wall time, so the benchmarks
// report both.
#pragma once

#include <sys/resource.h>

namespace strielad::bench {

inline double cpu_seconds(const struct rusage& u) {
  return static_cast<double>(u.ru_utime.tv_sec + u.ru_stime.tv_sec) +
         static_cast<double>(u.ru_utime.tv_usec + u.ru_stime.tv_usec) / 1e6;
}

// User + system seconds of this process so far (all threads).
inline double process_cpu_seconds() {
  struct rusage u {};
  ::getrusage(RUSAGE_SELF, &u);
  return cpu_seconds(u);
}

}  // namespace strielad::bench
