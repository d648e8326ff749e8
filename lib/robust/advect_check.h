// SPDX-License-Identifier: Apache-2.0
// The advection stage of a robustness case: the case's variable read back from the store
// at level 0 at steps 0 and 1 and used as all three wind components (m/s on degree and
// metre axes), then points advected from step 0 to step 1 by every integrator from the
// centre, a corner, a sample, near the far corner and from outside the grid.
#pragma once

#include "robust/stage_findings.h"
#include "store/store.h"

namespace strielad::robust {

// Every trajectory must end with finite position and time within [t0, t1]; reached ones
// at t1; stopped ones flagged and still inside the grid (a start outside stops at once
// as "left the domain"). A wind field the grid cannot hold (an axis of one sample) is a
// refusal.
StageFindings check_advection(const Store& store);

}  // namespace strielad::robust
