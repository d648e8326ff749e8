// SPDX-License-Identifier: Apache-2.0
#include "robust/case_runner.h"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <functional>
#include <new>

#include "convert/converter.h"
#include "core/error.h"
#include "robust/advect_check.h"
#include "robust/case_netcdf.h"
#include "robust/case_reference.h"
#include "robust/extract_checks.h"
#include "robust/store_checks.h"
#include "store/store.h"
#include "store/store_verifier.h"

namespace strielad::robust {
namespace {

using Clock = std::chrono::steady_clock;

std::string describe(const StageFindings& f) {
  if (f.ok()) return f.refusal ? *f.refusal : f.summary;
  std::string text = fmt::format("{} problem{}: {}", f.problem_count, f.problem_count == 1 ? "" : "s",
                                 fmt::join(f.problems, "; "));
  if (f.problem_count > f.problems.size()) text += "; ...";
  return text;
}

// Runs one stage, turning whatever it throws into an outcome.
StageResult run_stage(Stage stage, const std::function<StageFindings()>& body) {
  StageResult r;
  r.stage = stage;
  const auto started = Clock::now();
  try {
    const StageFindings f = body();
    r.outcome = !f.ok() ? Outcome::kFailed : f.refusal ? Outcome::kClearError : Outcome::kOk;
    r.detail = describe(f);
  } catch (const Error& e) {
    r.outcome = e.code() == ErrorCode::kInternal ? Outcome::kFailed : Outcome::kClearError;
    r.detail = e.code() == ErrorCode::kInternal ? fmt::format("internal error: {}", e.what())
                                                : std::string(e.what());
  } catch (const std::bad_alloc&) {
    r.outcome = Outcome::kFailed;
    r.detail = "out of memory (std::bad_alloc): an allocation the input's size should have "
               "prevented";
  } catch (const std::exception& e) {
    r.outcome = Outcome::kFailed;
    r.detail = fmt::format("not a strielad::Error: {}", e.what());
  }
  r.seconds = std::chrono::duration<double>(Clock::now() - started).count();
  return r;
}

void judge(StageResult& r, const Expectation& expected) {
  r.expected = expected;
  r.as_expected = r.outcome == expected.outcome &&
                  (expected.outcome != Outcome::kClearError ||
                   r.detail.find(expected.message_part) != std::string::npos);
}

}  // namespace

bool CaseReport::as_expected() const {
  for (const auto& s : stages) {
    if (!s.as_expected) return false;
  }
  return true;
}

std::vector<std::string> CaseReport::deviations() const {
  std::vector<std::string> out;
  for (const auto& s : stages) {
    if (s.as_expected) continue;
    std::string want(outcome_name(s.expected.outcome));
    if (!s.expected.message_part.empty()) want += fmt::format(" ('{}')", s.expected.message_part);
    out.push_back(fmt::format("{}: expected {}, got {}: {}", stage_name(s.stage), want,
                              outcome_name(s.outcome), s.detail));
  }
  return out;
}

CaseReport run_case(const ExtremeCase& c, const RunOptions& options) {
  const auto started = Clock::now();
  CaseReport report;
  report.name = c.name;
  report.extreme = c.extreme;
  report.expected_text = c.expected_text;
  const std::filesystem::path dir = options.work_dir / c.name;
  const std::filesystem::path input = dir / "input.nc";
  const std::filesystem::path store_dir = dir / "store";
  std::error_code ec;
  std::filesystem::remove_all(dir, ec);
  std::filesystem::create_directories(dir);
  spdlog::debug("robustness case {} in {}", c.name, dir.string());

  std::shared_ptr<const Store> store;
  const std::vector<std::vector<double>> level0 = reference_level0(c);
  const auto with_store = [&](Stage stage, const std::function<StageFindings()>& body) {
    if (!store) {
      StageResult r;
      r.stage = stage;
      r.detail = "no store";
      return r;
    }
    return run_stage(stage, body);
  };

  report.stages.push_back(run_stage(Stage::kConvert, [&] {
    write_case_netcdf(c, input);
    build::ConvertOptions o;
    o.inputs = {input};
    o.store = store_dir;
    o.brick = c.brick;
    o.threads = options.threads;
    o.scan.nan_as_fill = c.nan_as_fill;
    o.memory_limit = c.memory_limit;
    const build::ConvertResult result = build::convert(o);
    StageFindings f;
    if (!result.finalized) f.problem("the store was not finalized");
    store = Store::open(store_dir);
    f.summary = fmt::format("{} steps, bricks: {} empty, {} constant, {} data; {} bytes",
                            result.steps_converted, result.empty, result.constant, result.data,
                            result.written_bytes);
    return f;
  }));
  report.stages.push_back(with_store(Stage::kVerify, [&] {
    const VerifyReport v = verify_store(store_dir);
    StageFindings f;
    for (const auto& p : v.problems) f.problem("{}", p);
    f.summary = fmt::format("{} bricks of {} steps verified", v.bricks_checked, v.steps_checked);
    return f;
  }));
  report.stages.push_back(
      with_store(Stage::kStatistics, [&] { return check_statistics(*store, level0); }));
  report.stages.push_back(
      with_store(Stage::kLevels, [&] { return check_levels(c, *store, level0); }));
  report.stages.push_back(
      with_store(Stage::kExtract, [&] { return check_extraction(c, *store, options.threads); }));
  report.stages.push_back(with_store(Stage::kServe, [&] {
    return check_server(c, dir, store_dir.filename().string(), options.threads,
                        options.server_timeout);
  }));
  report.stages.push_back(with_store(Stage::kAdvect, [&] { return check_advection(*store); }));

  for (auto& stage : report.stages) judge(stage, c.expectation(stage.stage));
  store.reset();
  if (!options.keep_files) std::filesystem::remove_all(dir, ec);
  report.seconds = std::chrono::duration<double>(Clock::now() - started).count();
  return report;
}

}  // namespace strielad::robust
