// SPDX-License-Identifier: Apache-2.0
// Prints each variable of a store with the value range of its root node at step 0,
// from the index and from the decoded root brick: a C++ user's first program.
#include <cmath>
#include <cstdio>
#include <exception>

#include "core/error.h"
#include "store/store.h"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: store_summary STORE\n");
    return 2;
  }
  try {
    const auto store = strielad::Store::open(argv[1]);
    const auto root = store->octree().root();
    for (std::uint32_t v = 0; v < store->variable_count(); ++v) {
      const auto& entry = store->node_entry(0, v, root);
      const auto brick = store->read_brick(0, v, root);
      double lo = INFINITY, hi = -INFINITY;
      for (std::size_t i = 0; i < brick.sample_count(); ++i) {
        const double value = brick.sample(i);
        if (!std::isnan(value)) {
          lo = std::fmin(lo, value);
          hi = std::fmax(hi, value);
        }
      }
      std::printf("%s index [%g, %g] brick [%g, %g]\n",
                  store->manifest().variables[v].name.c_str(), entry.min, entry.max, lo, hi);
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "store_summary: %s\n", e.what());
    return 1;
  }
  return 0;
}
