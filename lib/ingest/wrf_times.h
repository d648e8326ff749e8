// SPDX-License-Identifier: Apache-2.0
// WRF's time coordinate: the character variable Times(Time, DateStrLen) holds one
// "YYYY-MM-DD_hh:mm:ss" per step. It becomes a CF time coordinate "seconds since <the
// first Times>" (calendar standard), so that each file carries its own reference and
// ingest/time_reconciliation.h merges files of consecutive steps.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "ingest/file_scan.h"

namespace strielad::ingest {

// `times`: the steps' date strings as stored (trailing blanks or NULs allowed).
// \error kInvalidInput naming `what` and the step for a string that is not
// "YYYY-MM-DD_hh:mm:ss" (an impossible date included), or steps that do not increase.
TimeCoordinate wrf_time_coordinate(const std::vector<std::string>& times, std::string_view what);

}  // namespace strielad::ingest
