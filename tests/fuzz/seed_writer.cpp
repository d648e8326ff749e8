// SPDX-License-Identifier: Apache-2.0
// Linked into every <name>_libfuzzer binary: `<name>_libfuzzer --write-seeds DIR` writes
// the target's seeds (strielad_fuzz_seeds) as DIR/seed-<i> and exits, so that a libFuzzer
// run starts from valid encodings (scripts/fuzz.sh). libFuzzer ignores flags that start
// with "--" and calls this before it reads any input.
#include <cstdio>
#include <cstdlib>
#include <string>

#include "fuzz/fuzz_target.h"

extern "C" int LLVMFuzzerInitialize(int* argc, char*** argv) {
  for (int i = 1; i + 1 < *argc; ++i) {
    if (std::string((*argv)[i]) != "--write-seeds") continue;
    const auto seeds = strielad_fuzz_seeds();
    for (std::size_t s = 0; s < seeds.size(); ++s) {
      const std::string path = std::string((*argv)[i + 1]) + "/seed-" + std::to_string(s);
      FILE* f = std::fopen(path.c_str(), "wb");
      if (f == nullptr || std::fwrite(seeds[s].data(), 1, seeds[s].size(), f) != seeds[s].size()) {
        std::fprintf(stderr, "error: cannot write %s\n", path.c_str());
        std::exit(1);
      }
      std::fclose(f);
    }
    std::printf("%zu seeds written to %s\n", seeds.size(), (*argv)[i + 1]);
    std::exit(0);
  }
  return 0;
}
