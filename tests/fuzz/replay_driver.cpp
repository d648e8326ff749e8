// SPDX-License-Identifier: Apache-2.0
// A fuzz smoke test for compilers without libFuzzer: feeds every file under the given
// directories (the target's kept corpus and crash reproducers), each seed, and
// deterministic mutations of the seeds (bit flips, byte overwrites, truncations,
// insertions, splices) to the target for a bounded time. A crash or sanitizer report
// fails the test; on a fatal signal the input at fault is written to
// ./replay-crash-<target> (its path printed) before the process dies.
//   <target> [SECONDS [DIR...]]   |   <target> --write-seeds DIR
#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstring>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <string>

#include "fuzz/fuzz_target.h"

namespace {

// The input being run, for the fatal-signal handler (which may only make
// async-signal-safe calls: open, write, close, signal, raise).
const std::uint8_t* g_input = nullptr;
std::size_t g_input_size = 0;
char g_crash_path[512] = "replay-crash";

void write_all(int fd, const void* data, std::size_t size) {
  const char* p = static_cast<const char*>(data);
  while (size > 0) {
    const ssize_t n = ::write(fd, p, size);
    if (n <= 0) return;
    p += n;
    size -= static_cast<std::size_t>(n);
  }
}

extern "C" void save_input_and_die(int sig) {
  const int fd = ::open(g_crash_path, O_WRONLY | O_CREAT | O_TRUNC, 0644);
  if (fd >= 0) {
    if (g_input != nullptr) write_all(fd, g_input, g_input_size);
    ::close(fd);
  }
  static const char kText[] = "fatal signal; the input at fault is in ";
  write_all(2, kText, sizeof kText - 1);
  write_all(2, g_crash_path, std::strlen(g_crash_path));
  write_all(2, "\n", 1);
  std::signal(sig, SIG_DFL);
  std::raise(sig);
}

int run_one(const std::uint8_t* data, std::size_t size) {
  g_input = data;
  g_input_size = size;
  return LLVMFuzzerTestOneInput(data, size);
}

}  // namespace

int main(int argc, char** argv) {
  {
    std::string name = std::filesystem::path(argv[0]).filename().string();
    std::snprintf(g_crash_path, sizeof g_crash_path, "replay-crash-%s", name.c_str());
    for (int sig : {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT}) std::signal(sig, save_input_and_die);
  }
  const auto seeds = strielad_fuzz_seeds();
  if (argc > 2 && std::string(argv[1]) == "--write-seeds") {  // a corpus for libFuzzer
    for (std::size_t i = 0; i < seeds.size(); ++i) {
      const std::string path = std::string(argv[2]) + "/seed-" + std::to_string(i);
      if (FILE* f = std::fopen(path.c_str(), "wb")) {
        std::fwrite(seeds[i].data(), 1, seeds[i].size(), f);
        std::fclose(f);
      }
    }
    return 0;
  }
  const double seconds = argc > 1 ? std::atof(argv[1]) : 5.0;
  std::mt19937_64 rng(12345);
  std::size_t runs = 0;
  for (int a = 2; a < argc; ++a) {
    std::error_code ec;
    if (!std::filesystem::is_directory(argv[a], ec)) continue;
    std::vector<std::filesystem::path> files;
    for (const auto& e : std::filesystem::recursive_directory_iterator(argv[a])) {
      if (e.is_regular_file()) files.push_back(e.path());
    }
    std::sort(files.begin(), files.end());
    for (const auto& path : files) {
      std::ifstream in(path, std::ios::binary);
      const std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(in)),
                                            std::istreambuf_iterator<char>());
      run_one(bytes.data(), bytes.size());
      ++runs;
    }
  }
  for (const auto& s : seeds) {
    run_one(s.data(), s.size());
    ++runs;
  }
  const auto until = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  while (std::chrono::steady_clock::now() < until) {
    for (int batch = 0; batch < 64; ++batch) {
      std::vector<std::uint8_t> in = seeds[rng() % seeds.size()];
      const int edits = 1 + static_cast<int>(rng() % 4);
      for (int e = 0; e < edits && !in.empty(); ++e) {
        const std::size_t at = rng() % in.size();
        switch (rng() % 5) {
          case 0: in[at] ^= static_cast<std::uint8_t>(1u << (rng() % 8)); break;
          case 1: in[at] = static_cast<std::uint8_t>(rng()); break;
          case 2: in.resize(at); break;
          case 3: in.insert(in.begin() + static_cast<long>(at), static_cast<std::uint8_t>(rng())); break;
          case 4: {
            const auto& other = seeds[rng() % seeds.size()];
            const std::size_t from = rng() % other.size();
            for (std::size_t i = 0; i < 8 && at + i < in.size() && from + i < other.size(); ++i) {
              in[at + i] = other[from + i];
            }
            break;
          }
        }
      }
      run_one(in.data(), in.size());
      ++runs;
    }
  }
  std::printf("%zu inputs (kept files, %zu seeds and their mutations), no crash\n", runs,
              seeds.size());
  return 0;
}
