// SPDX-License-Identifier: Apache-2.0
// The statistics and levels stages of a robustness case: what a converted store holds,
// against the reference computed from the input (robust/case_reference.h).
#pragma once

#include <vector>

#include "robust/extreme_case.h"
#include "robust/stage_findings.h"
#include "store/store.h"

namespace strielad::robust {

// Every node's min, max and valid count at every step equal the input's (exactly: min
// and max are values of the data, counts are integers; above level 0 the range also
// covers the node's own samples as stored), the root's valid count is the
// number of valid input samples, and the manifest summary's range is the input's (null
// when nothing is valid).
StageFindings check_statistics(const Store& store, const std::vector<std::vector<double>>& level0);

// Level 0 equals the input bit for bit (NaN where missing); every coarser level equals
// the reference sub-sampling of the level below as stored: bit for bit where a valid
// centre sample is taken, within the documented bound where a mean of neighbours stands
// in for fill; bricks agree on the samples they share.
StageFindings check_levels(const ExtremeCase& c, const Store& store,
                           const std::vector<std::vector<double>>& level0);

}  // namespace strielad::robust
