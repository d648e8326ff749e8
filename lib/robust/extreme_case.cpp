// SPDX-License-Identifier: Apache-2.0
#include "robust/extreme_case.h"

#include <algorithm>

namespace strielad::robust {

std::string_view stage_name(Stage stage) {
  switch (stage) {
    case Stage::kConvert: return "convert";
    case Stage::kVerify: return "verify";
    case Stage::kStatistics: return "statistics";
    case Stage::kLevels: return "levels";
    case Stage::kExtract: return "extract";
    case Stage::kServe: return "serve";
    case Stage::kAdvect: return "advect";
  }
  return "unknown";
}

std::string_view outcome_name(Outcome outcome) {
  switch (outcome) {
    case Outcome::kOk: return "ok";
    case Outcome::kClearError: return "clear error";
    case Outcome::kFailed: return "FAILED";
    case Outcome::kNotRun: return "not run";
  }
  return "unknown";
}

Expectation ExtremeCase::expectation(Stage stage) const {
  if (const auto it = expected.find(stage); it != expected.end()) return it->second;
  // After a stage that is expected to refuse, the ones that need its result do not run.
  for (Stage earlier : kStages) {
    if (earlier == stage) break;
    const auto it = expected.find(earlier);
    if (it == expected.end() || it->second.outcome != Outcome::kClearError) continue;
    // A refused conversion leaves no store; a refusal later on stops only that stage.
    if (earlier == Stage::kConvert) return {Outcome::kNotRun, {}};
  }
  return {Outcome::kOk, {}};
}

}  // namespace strielad::robust
