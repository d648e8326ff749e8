// SPDX-License-Identifier: Apache-2.0
#include "bench/proc_io.h"

#include <fcntl.h>
#include <unistd.h>

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

namespace strielad::bench {

std::optional<ProcIo> read_proc_io() {
  std::FILE* f = std::fopen("/proc/self/io", "r");
  if (!f) return std::nullopt;
  ProcIo io;
  char key[64];
  unsigned long long value = 0;
  int found = 0;
  while (std::fscanf(f, "%63[^:]: %llu\n", key, &value) == 2) {
    if (std::strcmp(key, "rchar") == 0) io.rchar = value, ++found;
    if (std::strcmp(key, "read_bytes") == 0) io.read_bytes = value, ++found;
    if (std::strcmp(key, "write_bytes") == 0) io.write_bytes = value, ++found;
  }
  std::fclose(f);
  if (found < 3) return std::nullopt;
  return io;
}

bool proc_io_counts_disk_reads(const char* dir) {
  if (!read_proc_io()) return false;
  const std::string path =
      (std::filesystem::path(dir) / ("proc-io-probe." + std::to_string(::getpid()))).string();
  const int fd = ::open(path.c_str(), O_RDWR | O_CREAT | O_TRUNC | O_CLOEXEC, 0600);
  if (fd < 0) return false;
  std::vector<char> buf(1 << 20, 'x');
  bool ok = ::write(fd, buf.data(), buf.size()) == static_cast<ssize_t>(buf.size()) &&
            ::fsync(fd) == 0 && ::posix_fadvise(fd, 0, 0, POSIX_FADV_DONTNEED) == 0;
  std::uint64_t delta = 0;
  if (ok) {
    const auto before = read_proc_io();
    ok = ::pread(fd, buf.data(), 65536, 4096 * 7) == 65536;
    const auto after = read_proc_io();
    if (before && after) delta = after->read_bytes - before->read_bytes;
  }
  ::close(fd);
  ::unlink(path.c_str());
  return ok && delta > 0;
}

}  // namespace strielad::bench
