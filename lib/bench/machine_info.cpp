// SPDX-License-Identifier: Apache-2.0
#include "bench/machine_info.h"

#include <blosc.h>
#include <netcdf.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <sys/utsname.h>
#include <unistd.h>
#include <zstd.h>

#include <fmt/format.h>
#include <tbb/version.h>

#include <cstdlib>
#include <fstream>
#include <string>
#include <thread>

#include "core/version.h"

namespace strielad::bench {
namespace {

std::string first_line_with(const char* file, const std::string& key) {
  std::ifstream in(file);
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind(key, 0) == 0) {
      const auto colon = line.find(':');
      std::string v = colon == std::string::npos ? line : line.substr(colon + 1);
      const auto start = v.find_first_not_of(" \t");
      return start == std::string::npos ? "" : v.substr(start);
    }
  }
  return "unknown";
}

std::string read_trimmed(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::string s;
  std::getline(in, s);
  return s.empty() ? "unknown" : s;
}

// Block device holding `dir`: name, whether the kernel calls it rotational, free space.
nlohmann::json storage_of(const std::filesystem::path& dir) {
  nlohmann::json j = {{"path", dir.string()}};
  struct stat st {};
  if (::stat(dir.c_str(), &st) == 0) {
    const auto sys = std::filesystem::path(
        fmt::format("/sys/dev/block/{}:{}", major(st.st_dev), minor(st.st_dev)));
    std::error_code ec;
    auto real = std::filesystem::canonical(sys, ec);
    if (!ec) {
      j["device"] = real.filename().string();
      auto queue = real / "queue";
      if (!std::filesystem::exists(queue)) queue = real.parent_path() / "queue";  // partition
      j["rotational"] = read_trimmed(queue / "rotational");
      j["read_ahead_kb"] = read_trimmed(queue / "read_ahead_kb");
    }
  }
  std::error_code ec;
  const auto space = std::filesystem::space(dir, ec);
  if (!ec) j["free_gb"] = static_cast<double>(space.available) / 1e9;
  return j;
}

}  // namespace

double load_average_1min() {
  double load[1] = {0};
  return ::getloadavg(load, 1) == 1 ? load[0] : -1;
}

nlohmann::json machine_info(const std::filesystem::path& work_dir) {
  struct utsname u {};
  ::uname(&u);
  const std::string mem = first_line_with("/proc/meminfo", "MemTotal");
  return nlohmann::json{
      {"cpu", first_line_with("/proc/cpuinfo", "model name")},
      {"cores", std::thread::hardware_concurrency()},
      {"memory", mem},
      {"kernel", fmt::format("{} {}", u.sysname, u.release)},
      {"storage", storage_of(work_dir)},
      {"compiler", fmt::format("gcc-compatible {}", __VERSION__)},
      {"strielad", std::string(kToolVersion)},
      {"netcdf", nc_inq_libvers()},
      {"blosc", blosc_get_version_string()},
      {"zstd", ZSTD_versionString()},
      {"tbb", TBB_VERSION_STRING},
      {"page_size", ::sysconf(_SC_PAGESIZE)},
      {"load_average_1min", load_average_1min()},
  };
}

}  // namespace strielad::bench
