// SPDX-License-Identifier: Apache-2.0
// This process's I/O counters from /proc/self/io (task I/O accounting). read_bytes counts
// bytes the process caused to be fetched from the block device (page-cache misses,
// including read-ahead), which is what "bytes read from disk" means in the benchmarks.
#pragma once

#include <cstdint>
#include <optional>

namespace strielad::bench {

struct ProcIo {
  std::uint64_t rchar = 0;       // bytes passed to read()/pread() (cache hits included)
  std::uint64_t read_bytes = 0;  // bytes read from the storage layer
  std::uint64_t write_bytes = 0;
};

// Empty when /proc/self/io is missing or unreadable (kernel without task I/O accounting).
std::optional<ProcIo> read_proc_io();

// Whether read_bytes moves: reads `probe_bytes` of an evicted scratch file in `dir` and
// checks the counter grew. False when the counters are unavailable or stay at zero.
bool proc_io_counts_disk_reads(const char* dir);

}  // namespace strielad::bench
