// SPDX-License-Identifier: Apache-2.0
// A fuzz smoke test for compilers without libFuzzer: feeds every file under the given
// directories (the target's kept corpus and crash reproducers), each seed, and
// deterministic mutations of the seeds (bit flips, byte overwrites, truncations,
// insertions, splices) to the target for a bounded time. A crash or sanitizer report
// fails the test.
//   <target> [SECONDS [DIR...]]   |   <target> --write-seeds DIR
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <string>

#include "fuzz/fuzz_target.h"

int main(int argc, char** argv) {
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
      LLVMFuzzerTestOneInput(bytes.data(), bytes.size());
      ++runs;
    }
  }
  for (const auto& s : seeds) {
    LLVMFuzzerTestOneInput(s.data(), s.size());
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
      LLVMFuzzerTestOneInput(in.data(), in.size());
      ++runs;
    }
  }
  std::printf("%zu inputs (kept files, %zu seeds and their mutations), no crash\n", runs,
              seeds.size());
  return 0;
}
