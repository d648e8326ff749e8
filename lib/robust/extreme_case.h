// SPDX-License-Identifier: Apache-2.0
// One extreme input of the robustness matrix ("Stability on stiff and extreme cases";
// docs/robustness.md): a small CF-NetCDF grid with one variable "f" whose values,
// axes or size are extreme, the limits a scene puts on it, and the outcome expected of
// every stage (conversion, verification, statistics, coarse levels, extraction, the
// server, advection). Plain data: extreme_cases.h lists the cases, case_runner.h runs one.
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace strielad::robust {

// The stages a case goes through, in order.
enum class Stage { kConvert, kVerify, kStatistics, kLevels, kExtract, kServe, kAdvect };
inline constexpr std::array<Stage, 7> kStages{Stage::kConvert,    Stage::kVerify,
                                              Stage::kStatistics, Stage::kLevels,
                                              Stage::kExtract,    Stage::kServe,
                                              Stage::kAdvect};
std::string_view stage_name(Stage stage);

enum class Outcome {
  kOk,          // ran and every check passed
  kClearError,  // refused with a strielad::Error (not kInternal) whose message says why
  kFailed,      // a check failed, or a crash-like error (kInternal, a foreign exception)
  kNotRun,      // an earlier stage ended the case (e.g. conversion refused the input)
};
std::string_view outcome_name(Outcome outcome);

struct Expectation {
  Outcome outcome = Outcome::kOk;
  std::string message_part;  // kClearError: text the error message must contain
};

// How the variable is stored in the NetCDF file.
enum class SourceType { kFloat, kDouble, kShortPacked };

struct CaseInput {
  // Coordinates as written: lon (degrees_east), lat (degrees_north), z (height in m,
  // positive up; ascending or descending as given), time (seconds since 2020-01-01).
  std::vector<double> lon, lat, z;
  std::vector<double> time{0.0, 3600.0};
  SourceType type = SourceType::kFloat;
  // Values (t, z, y, x), x fastest, in the file's type (packed integers for
  // kShortPacked); empty: the variable is declared but never written (huge grids).
  std::vector<double> values;
  // The vertical axis as integer hPa (NC_INT "plev", positive down) instead of height in
  // metres: z holds the pressures.
  bool integer_pressure_levels = false;
  std::optional<double> fill_value;             // _FillValue
  std::optional<double> scale_factor, add_offset;  // kShortPacked: float attributes
};

struct ExtremeCase {
  std::string name;     // short, unique, e.g. "denormals"
  std::string extreme;  // what is extreme about the input, one line
  CaseInput input;
  bool nan_as_fill = false;
  std::uint32_t brick = 4;
  // ConvertOptions::memory_limit (0: this machine's memory).
  std::uint64_t memory_limit = 0;
  // One sub-volume per entry, each one limit on "f" (absent bound = open); every mesh
  // carries "f" as attribute.
  struct Limit {
    std::optional<double> min, max;
  };
  std::vector<Limit> limits;
  // Optional extra sub-volume: a longitude domain [lo, hi] without limits.
  std::optional<std::array<double, 2>> lon_domain;
  // Further sub-volumes (ids 200, 201, ...): a domain box over any of the axes (x, y, z in
  // the case's coordinates; absent = unbounded), with the first limit or without limits.
  struct DomainBox {
    std::array<std::optional<std::array<double, 2>>, 3> ranges;
    bool with_limit = false;
  };
  std::vector<DomainBox> domains;
  // Also check each sub-volume's seamless union per level: closed and consistently
  // oriented, its volume equal to the VTK table-clip pipeline's on the same nodes.
  bool check_unions = false;
  // Stages not listed are expected kOk (kNotRun after an expected error).
  std::map<Stage, Expectation> expected;
  // What should happen and why, for the table and docs/robustness.md.
  std::string expected_text;

  Expectation expectation(Stage stage) const;
  std::size_t nx() const { return input.lon.size(); }
  std::size_t ny() const { return input.lat.size(); }
  std::size_t nz() const { return input.z.size(); }
  std::size_t steps() const { return input.time.size(); }
  std::size_t samples_per_step() const { return nx() * ny() * nz(); }
};

}  // namespace strielad::robust
