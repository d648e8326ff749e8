// SPDX-License-Identifier: Apache-2.0
#include "grid/longitude_turns.h"

#include <algorithm>
#include <cmath>

namespace strielad {

std::vector<int> longitude_turns(double lo, double hi, double a, double b) {
  const double node_lo = std::min(a, b), node_hi = std::max(a, b);
  // [lo - 360 k, hi - 360 k] meets [node_lo, node_hi]: lo - 360 k <= node_hi and
  // hi - 360 k >= node_lo.
  const double first = std::ceil((lo - node_hi) / kFullTurn);
  const double last = std::floor((hi - node_lo) / kFullTurn);
  std::vector<int> turns;
  for (double k = first - 1; k <= last + 1; k += 1.0) {
    // The divisions above round; the test is exact.
    if (lo - kFullTurn * k <= node_hi && hi - kFullTurn * k >= node_lo) {
      turns.push_back(static_cast<int>(k));
    }
  }
  return turns;
}

}  // namespace strielad
