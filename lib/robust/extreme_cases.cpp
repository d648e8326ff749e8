// SPDX-License-Identifier: Apache-2.0
#include "robust/extreme_cases.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>

#include "core/error.h"

namespace strielad::robust {
namespace {

constexpr double kFill = -9999.0;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kFloatMax = std::numeric_limits<float>::max();
constexpr double kFloatDenormMin = std::numeric_limits<float>::denorm_min();
// The largest float32 subnormal: just below the smallest normal.
const double kFloatDenormMax = std::nextafter(std::numeric_limits<float>::min(), 0.0f);
constexpr std::uint64_t kGiB = std::uint64_t{1} << 30;

std::vector<double> linspace(double first, double last, std::size_t n) {
  std::vector<double> v(n);
  for (std::size_t i = 0; i < n; ++i) {
    v[i] = n == 1 ? first : first + (last - first) * double(i) / double(n - 1);
  }
  return v;
}

// The default small grid: 13 x 11 x 9 samples (3 x 3 x 2 bricks of 4 cells, 3 levels),
// lon 5..6.2 E, lat 47..48 N, height 0..4000 m, two steps an hour apart.
// `degrees`: the horizontal spacing (huge grids use a finer one, so that latitudes stay
// within +-90 and longitudes within one turn).
CaseInput small_grid(std::size_t nx = 13, std::size_t ny = 11, std::size_t nz = 9,
                     double degrees = 0.1) {
  CaseInput in;
  in.lon = linspace(5.0, 5.0 + degrees * double(nx - 1), nx);
  in.lat = linspace(47.0, 47.0 + degrees * double(ny - 1), ny);
  in.z = linspace(0.0, 500.0 * double(nz - 1), nz);
  return in;
}

using ValueFn = std::function<double(std::size_t t, std::size_t k, std::size_t j, std::size_t i)>;

void set_values(CaseInput& in, const ValueFn& f) {
  in.values.clear();
  for (std::size_t t = 0; t < in.time.size(); ++t)
    for (std::size_t k = 0; k < in.z.size(); ++k)
      for (std::size_t j = 0; j < in.lat.size(); ++j)
        for (std::size_t i = 0; i < in.lon.size(); ++i) in.values.push_back(f(t, k, j, i));
}

// A smooth field between about -1 and 2.2 that moves a little between the steps.
double smooth(std::size_t t, std::size_t k, std::size_t j, std::size_t i) {
  return std::sin(0.5 * double(i) + 0.2 * double(t)) * std::cos(0.4 * double(j)) + 0.15 * double(k);
}

ExtremeCase::Limit at_least(double v) { return {v, std::nullopt}; }
ExtremeCase::Limit at_most(double v) { return {std::nullopt, v}; }
ExtremeCase::Limit between(double lo, double hi) { return {lo, hi}; }

Expectation clear_error(std::string part) { return {Outcome::kClearError, std::move(part)}; }

// Fill at a scattered eighth of the samples, so that coarse samples fall back to means.
bool scattered_fill(std::size_t k, std::size_t j, std::size_t i) {
  return (i * 7 + j * 3 + k * 5) % 8 == 0;
}

std::vector<ExtremeCase> value_cases() {
  std::vector<ExtremeCase> cases;
  {
    ExtremeCase c;
    c.name = "baseline";
    c.extreme = "nothing: a smooth float field (checks the harness)";
    c.input = small_grid();
    set_values(c.input, smooth);
    c.limits = {at_least(0.5), at_most(0.0)};
    c.expected_text = "every stage ok";
    cases.push_back(std::move(c));
  }
  {
    ExtremeCase c;
    c.name = "tiny-and-huge";
    c.extreme = "1e-30, 1e30, -1e30 and 1 in every brick, fill between them";
    c.input = small_grid();
    c.input.fill_value = kFill;
    set_values(c.input, [](std::size_t t, std::size_t k, std::size_t j, std::size_t i) {
      if (scattered_fill(k, j, i)) return kFill;
      constexpr double kValues[4] = {1e-30, 1e30, -1e30, 1.0};
      return kValues[(i + 2 * j + 3 * k + t) % 4];
    });
    c.limits = {at_least(1.0), at_most(1e-30), between(-1e29, 1e29)};
    c.expected_text =
        "ok: exact float ranges; coarse fill falls back to double means within the documented "
        "bound; surfaces between 1e-30 and 1e30 closed, no zero-area triangles";
    cases.push_back(std::move(c));
  }
  {
    ExtremeCase c;
    c.name = "huge-wind";
    c.extreme = "1e30 .. 3e30 everywhere, no fill: a wind of 1e30 m/s";
    c.input = small_grid();
    set_values(c.input, [](std::size_t t, std::size_t k, std::size_t j, std::size_t i) {
      return 1e30 * (2.0 + smooth(t, k, j, i) / 2.2);
    });
    c.limits = {at_least(2e30)};
    c.expected_text =
        "ok: every trajectory leaves the grid in its first step and stops there, flagged, "
        "inside the grid at a finite position (steps halved towards the boundary)";
    cases.push_back(std::move(c));
  }
  {
    ExtremeCase c;
    c.name = "float-range-limits";
    c.extreme = "+-3.4028235e38 (float32 max) side by side, fill between them";
    c.input = small_grid();
    c.input.fill_value = kFill;
    set_values(c.input, [](std::size_t t, std::size_t k, std::size_t j, std::size_t i) {
      if (scattered_fill(k, j, i)) return kFill;
      return (i + j + k + t) % 3 == 0 ? -kFloatMax : kFloatMax;
    });
    c.limits = {at_least(0.0), at_least(3e38), at_most(-kFloatMax)};
    c.expected_text =
        "ok: means of float32 maxima stay finite (summed in double); the field's gradient "
        "(7e38 per cell) gives unit normals; attributes finite";
    cases.push_back(std::move(c));
  }
  {
    ExtremeCase c;
    c.name = "denormals";
    c.extreme = "float32 subnormals (1.4e-45 .. 1.18e-38), +0 and -0";
    c.input = small_grid();
    c.input.fill_value = kFill;
    set_values(c.input, [](std::size_t t, std::size_t k, std::size_t j, std::size_t i) {
      if (scattered_fill(k, j, i)) return kFill;
      const double values[5] = {0.0, -0.0, kFloatDenormMin, 1e-40, kFloatDenormMax};
      return values[(i + j + 2 * k + t) % 5];
    });
    c.limits = {at_least(1e-41), between(kFloatDenormMin, 1e-40), at_most(0.0)};
    c.expected_text =
        "ok: subnormals kept bit for bit, ranges exact, thresholds between subnormals honoured; "
        "wind of 1e-40 m/s leaves points where they are";
    cases.push_back(std::move(c));
  }
  {
    ExtremeCase c;
    c.name = "float64-beyond-float32";
    c.extreme = "float64 data: +-1e300, 1e-300 and 1.5e308 (near the float64 maximum) next to fill";
    c.input = small_grid();
    c.input.type = SourceType::kDouble;
    c.input.fill_value = kFill;
    set_values(c.input, [](std::size_t t, std::size_t k, std::size_t j, std::size_t i) {
      if (scattered_fill(k, j, i)) return kFill;
      constexpr double kValues[4] = {1.5e308, 1e300, -1e300, 1e-300};
      return kValues[(i + j + k + t) % 4];
    });
    c.limits = {at_least(1.0), at_most(-1.0)};
    c.expected_text =
        "ok: stored exactly as float64 with exact ranges; coarse means of 1.5e308 pairs do not "
        "overflow; extraction (float32) clamps beyond +-3.4e38, so regions and attributes stay "
        "finite; wind beyond float32 is missing for advection";
    cases.push_back(std::move(c));
  }
  {
    ExtremeCase c;
    c.name = "packed-overflow";
    c.extreme = "short packed with scale_factor 1e36: unpacks beyond float32";
    c.input = small_grid();
    c.input.type = SourceType::kShortPacked;
    c.input.scale_factor = 1e36;
    c.input.add_offset = 0.0;
    c.input.fill_value = -32767;
    set_values(c.input, [](std::size_t, std::size_t k, std::size_t j, std::size_t i) {
      return double((int(i * 37 + j * 11 + k * 5) % 2000) - 1000);
    });
    c.limits = {at_least(0.0)};
    c.expected[Stage::kConvert] = clear_error("beyond the range of float32");
    c.expected_text =
        "conversion refuses, naming file, variable, step and sample: the store may hold only "
        "finite values";
    cases.push_back(std::move(c));
  }
  return cases;
}

std::vector<ExtremeCase> missing_data_cases() {
  std::vector<ExtremeCase> cases;
  {
    ExtremeCase c;
    c.name = "all-fill-bricks";
    c.extreme = "whole bricks (and at step 1 a whole level-1 node) of _FillValue";
    c.input = small_grid();
    c.input.fill_value = kFill;
    set_values(c.input, [](std::size_t t, std::size_t k, std::size_t j, std::size_t i) {
      if (i <= 4 && j <= 4) return kFill;               // level-0 bricks (0, 0, *)
      if (t == 1 && i >= 8 && j >= 4) return kFill;     // more at step 1
      return smooth(t, k, j, i);
    });
    c.limits = {at_least(0.5), at_most(2.0)};
    c.expected_text =
        "ok: empty bricks store nothing, their ranges are NaN with valid count 0, coarse "
        "samples over them stay missing; skipped as no-data; trajectories stop flagged "
        "'missing wind'";
    cases.push_back(std::move(c));
  }
  {
    ExtremeCase c;
    c.name = "all-fill-variable";
    c.extreme = "every sample of every step is _FillValue";
    c.input = small_grid();
    c.input.fill_value = kFill;
    set_values(c.input, [](std::size_t, std::size_t, std::size_t, std::size_t) { return kFill; });
    c.limits = {at_least(0.0)};
    c.expected_text =
        "ok: every node empty, summary min/max null; every node skipped (no data); every "
        "trajectory stops at once, flagged";
    cases.push_back(std::move(c));
  }
  {
    ExtremeCase c;
    c.name = "nan-inf-refused";
    c.extreme = "NaN, +Inf and -Inf in the data, not declared missing";
    c.input = small_grid();
    set_values(c.input, [](std::size_t t, std::size_t k, std::size_t j, std::size_t i) {
      if (t == 0 && k == 1 && j == 2 && i == 3) return kNaN;
      if (k == 2 && j == 5 && i == 6) return kInf;
      if (k == 6 && j == 1 && i == 9) return -kInf;
      return smooth(t, k, j, i);
    });
    c.limits = {at_least(0.5)};
    c.expected[Stage::kConvert] = clear_error(
        "variable 'f' time step 0: sample (lon 3, lat 2, level 1) is NaN; pass --nan-as-fill");
    c.expected_text = "conversion refuses, naming file, variable, step and sample position";
    cases.push_back(std::move(c));
  }
  {
    ExtremeCase c;
    c.name = "nan-inf-as-fill";
    c.extreme = "NaN, +-Inf and _FillValue in the data, converted with --nan-as-fill";
    c.input = small_grid();
    c.input.fill_value = kFill;
    c.nan_as_fill = true;
    set_values(c.input, [](std::size_t t, std::size_t k, std::size_t j, std::size_t i) {
      if ((i + 3 * j + k) % 11 == 0) return kNaN;
      if ((2 * i + j + 5 * k + t) % 13 == 0) return (i % 2 ? kInf : -kInf);
      if ((i + j + k) % 17 == 0) return kFill;
      return smooth(t, k, j, i);
    });
    c.limits = {at_least(0.5), at_most(1.0)};
    c.expected_text =
        "ok: NaN/Inf become missing like fill; ranges and counts ignore them; meshes close "
        "half-way to missing samples; attributes NaN only next to missing samples; trajectories "
        "stop flagged 'missing wind'";
    cases.push_back(std::move(c));
  }
  return cases;
}

std::vector<ExtremeCase> threshold_cases() {
  std::vector<ExtremeCase> cases;
  const ValueFn integers = [](std::size_t t, std::size_t k, std::size_t j, std::size_t i) {
    return double((i + j + k + t) % 5);
  };
  {
    ExtremeCase c;
    c.name = "thresholds-at-samples";
    c.extreme = "integer field 0..4, limits exactly at sample values";
    c.input = small_grid();
    set_values(c.input, integers);
    c.limits = {at_least(2.0), at_most(2.0), between(2.0, 3.0), at_least(4.0)};
    c.expected_text =
        "ok: samples equal to a bound are inside; nodes whose range only touches a bound are "
        "extracted, not skipped; no zero-area triangles where surfaces pass through samples";
    cases.push_back(std::move(c));
  }
  {
    ExtremeCase c;
    c.name = "lo-equals-hi";
    c.extreme = "limit min = max = 2 on an integer field with a constant block of 2; a lon "
                "domain [5.5, 5.5]";
    c.input = small_grid();
    set_values(c.input, [&](std::size_t t, std::size_t k, std::size_t j, std::size_t i) {
      if (i <= 4 && j <= 4) return 2.0;  // constant level-0 bricks (0, 0, *)
      return integers(t, k, j, i);
    });
    c.limits = {between(2.0, 2.0)};
    c.lon_domain = {5.5, 5.5};
    c.expected_text =
        "ok: the constant block of exactly 2 is inside (whole-brick boxes); elsewhere the "
        "region has no volume, so no triangles; the zero-width domain gives none at all";
    cases.push_back(std::move(c));
  }
  {
    ExtremeCase c;
    c.name = "constant-field";
    c.extreme = "273.15 everywhere (float32: 273.149993896484375)";
    c.input = small_grid();
    set_values(c.input, [](std::size_t, std::size_t, std::size_t, std::size_t) { return 273.15; });
    const double stored = static_cast<double>(static_cast<float>(273.15));
    c.limits = {at_least(stored), at_least(273.15), at_most(273.15), at_least(300.0)};
    c.expected_text =
        "ok: every brick constant (no chunk); a bound at the stored float value keeps the "
        "whole grid (closed boxes), one 6e-6 above it drops every node by value range";
    cases.push_back(std::move(c));
  }
  return cases;
}

std::vector<ExtremeCase> axis_cases() {
  std::vector<ExtremeCase> cases;
  {
    ExtremeCase c;
    c.name = "spacing-1-to-1000";
    c.extreme = "every axis has neighbouring spacings in the ratio 1:1000";
    c.input = small_grid();
    auto stretched = [](double first, double small, std::size_t n) {
      std::vector<double> v{first};
      for (std::size_t i = 1; i < n; ++i) v.push_back(v.back() + (i % 4 == 1 ? small : 1000 * small));
      return v;
    };
    c.input.lon = stretched(5.0, 1e-4, 13);
    c.input.lat = stretched(47.0, 1e-4, 11);
    c.input.z = stretched(0.0, 1.0, 9);
    set_values(c.input, smooth);
    c.limits = {at_least(0.5), at_most(0.0)};
    c.expected_text =
        "ok: axes kept exactly; normals from the gradient divided by the real spacing stay unit "
        "length; meshes closed";
    cases.push_back(std::move(c));
  }
  {
    ExtremeCase c;
    c.name = "descending-axes";
    c.extreme = "lon, lat and height all stored descending (an odd number of flips)";
    c.input = small_grid();
    std::reverse(c.input.lon.begin(), c.input.lon.end());
    std::reverse(c.input.lat.begin(), c.input.lat.end());
    std::reverse(c.input.z.begin(), c.input.z.end());
    set_values(c.input, smooth);
    c.limits = {at_least(0.5), at_most(0.0)};
    c.lon_domain = {5.3, 5.9};
    c.expected_text =
        "ok: kept descending; triangles still counter-clockwise seen from outside (positive "
        "enclosed volume); domain ranges given ascending; advection on descending axes";
    cases.push_back(std::move(c));
  }
  {
    ExtremeCase c;
    c.name = "one-cell-thick";
    c.extreme = "two height levels: one cell thick";
    c.input = small_grid(13, 11, 2);
    set_values(c.input, smooth);
    c.limits = {at_least(0.2)};
    c.expected_text = "ok: one-cell-thick meshes, closed by grid-edge faces above and below";
    cases.push_back(std::move(c));
  }
  {
    ExtremeCase c;
    c.name = "minimal-2x2x2";
    c.extreme = "the smallest grid: 2 x 2 x 2 samples, one node";
    c.input = small_grid(2, 2, 2);
    set_values(c.input, [](std::size_t t, std::size_t k, std::size_t j, std::size_t i) {
      return double(i + 2 * j + 4 * k) + 0.5 * double(t);
    });
    c.limits = {at_least(3.5)};
    c.expected_text = "ok: a single root node that is also the only leaf";
    cases.push_back(std::move(c));
  }
  {
    ExtremeCase c;
    c.name = "single-level";
    c.extreme = "one height level: a 2-D field, no cells along z";
    c.input = small_grid(13, 11, 1);
    set_values(c.input, smooth);
    c.limits = {at_least(0.5)};
    c.expected[Stage::kAdvect] = clear_error("axis z has 1 values");
    c.expected_text =
        "converts and reads back exactly; no cell has volume, so every node is empty or "
        "skipped (like a domain with lo = hi), without reading bricks; advection refuses: "
        "a wind field needs two samples along every axis";
    cases.push_back(std::move(c));
  }
  {
    ExtremeCase c;
    c.name = "lon-across-0";
    c.extreme = "longitudes -0.6 .. 0.6 (crossing the prime meridian)";
    c.input = small_grid();
    c.input.lon = linspace(-0.6, 0.6, 13);
    set_values(c.input, smooth);
    c.limits = {at_least(0.5)};
    c.lon_domain = {-0.25, 0.25};
    c.expected_text = "ok: an ordinary ascending axis";
    cases.push_back(std::move(c));
  }
  {
    ExtremeCase c;
    c.name = "lon-across-180";
    c.extreme = "longitudes 179.4 .. 180.6 written continuously (past 180)";
    c.input = small_grid();
    c.input.lon = linspace(179.4, 180.6, 13);
    set_values(c.input, smooth);
    c.limits = {at_least(0.5)};
    c.lon_domain = {179.8, 180.3};
    c.expected_text = "ok: longitudes above 180 are kept as written";
    cases.push_back(std::move(c));
  }
  {
    ExtremeCase c;
    c.name = "lon-wrapped-at-180";
    c.extreme = "longitudes 179.4 .. 180, -179.9 .. -179.4 (wrapped at the antimeridian)";
    c.input = small_grid();
    c.input.lon = linspace(179.4, 180.6, 13);
    for (double& lon : c.input.lon) {
      if (lon > 180.05) lon -= 360.0;
    }
    set_values(c.input, smooth);
    c.limits = {at_least(0.5)};
    c.lon_domain = {179.8, 180.3};
    c.expected_text =
        "ok: the ingest unwraps the axis (adds 360 after the jump, logged) to 179.4 .. 180.6, "
        "as if written continuously; scene domains use the unwrapped values";
    cases.push_back(std::move(c));
  }
  return cases;
}

// A domain box on one axis [v[i], v[j]] (bounds exactly on samples), with or without the
// case's limit.
ExtremeCase::DomainBox on_samples(int axis, const std::vector<double>& v, std::size_t i,
                                  std::size_t j, bool with_limit) {
  ExtremeCase::DomainBox box;
  box.ranges[axis] = std::array<double, 2>{std::min(v[i], v[j]), std::max(v[i], v[j])};
  box.with_limit = with_limit;
  return box;
}

// Boxes whose bounds are sample coordinates (round numbers on a 2.5-degree grid,
// integer pressure levels), on every axis, from a node face to a node face, from a sample
// inside a node to a node face and between two samples inside nodes; with and without a
// limit; and one over all three axes.
void boxes_on_samples(ExtremeCase& c) {
  const std::array<const std::vector<double>*, 3> axes{&c.input.lon, &c.input.lat, &c.input.z};
  for (int a = 0; a < 3; ++a) {
    const auto& v = *axes[a];
    const std::size_t b = c.brick, n = v.size();
    for (bool limit : {false, true}) {
      if (n > 2 * b) c.domains.push_back(on_samples(a, v, b, 2 * b, limit));
      if (n > b + 2) c.domains.push_back(on_samples(a, v, 1, b, limit));
      if (n > 4) c.domains.push_back(on_samples(a, v, 1, n - 2, limit));
    }
  }
  ExtremeCase::DomainBox all;
  for (int a = 0; a < 3; ++a) {
    const auto& v = *axes[a];
    all.ranges[a] = std::array<double, 2>{std::min(v[1], v[v.size() - 2]), std::max(v[1], v[v.size() - 2])};
  }
  all.with_limit = true;
  c.domains.push_back(all);
  c.check_unions = true;
}

std::vector<ExtremeCase> box_cases() {
  std::vector<ExtremeCase> cases;
  {
    ExtremeCase c;
    c.name = "box-on-samples";
    c.extreme = "domain boxes with bounds exactly on samples (node faces and inside nodes) on "
                "a non-uniform ascending lon, a descending lat and a descending non-uniform "
                "height axis";
    c.input = small_grid();
    for (std::size_t i = 0; i < c.input.lon.size(); ++i) c.input.lon[i] = 5.0 + 0.1 * double(i) + 0.004 * double(i * i);
    std::reverse(c.input.lat.begin(), c.input.lat.end());
    for (std::size_t k = 0; k < c.input.z.size(); ++k) c.input.z[k] = 30.0 * double(k * k) + 10.0 * double(k);
    std::reverse(c.input.z.begin(), c.input.z.end());
    set_values(c.input, smooth);
    c.limits = {at_least(0.5)};
    boxes_on_samples(c);
    c.expected_text =
        "ok: every sub-volume's seamless union is closed at every level (a bound on a node "
        "face makes that face a domain-box face; a limit meeting a bound on a sample plane "
        "meets it at the edge crossing), boxes exact, volumes VTK's";
    cases.push_back(std::move(c));
  }
  {
    ExtremeCase c;
    c.name = "box-on-integer-hpa";
    c.extreme = "the same boxes on integer pressure levels in hPa (NC_INT, descending)";
    c.input = small_grid();
    c.input.integer_pressure_levels = true;
    c.input.z = {1000, 925, 850, 700, 600, 500, 400, 300, 250};
    set_values(c.input, smooth);
    c.limits = {at_least(0.5)};
    boxes_on_samples(c);
    c.expected_text = "ok: as box-on-samples, on the pressure axis as stored";
    cases.push_back(std::move(c));
  }
  {
    ExtremeCase c;
    c.name = "lon-range-across-seam";
    c.extreme = "a global grid 0 .. 337.5 E every 22.5 degrees (periodic) with longitude "
                "ranges across its seam in three conventions, on samples and between them";
    c.input = small_grid(16, 11, 9);
    c.input.lon = linspace(0.0, 337.5, 16);
    c.input.lat = linspace(-25.0, 25.0, 11);
    set_values(c.input, smooth);
    c.limits = {at_least(0.5)};
    for (const auto& range : {std::array<double, 2>{-45, 45}, std::array<double, 2>{315, 405},
                              std::array<double, 2>{-400, -300}, std::array<double, 2>{300, 380}}) {
      for (bool limit : {false, true}) {
        ExtremeCase::DomainBox box;
        box.ranges[0] = range;
        box.with_limit = limit;
        c.domains.push_back(box);
      }
    }
    c.check_unions = true;
    c.expected_text =
        "ok: the converter repeats the first meridian at 360 (the cell across the seam is "
        "kept); each range comes out in its own convention, continuous across the seam, "
        "its union closed at every level, volumes VTK's";
    cases.push_back(std::move(c));
  }
  return cases;
}

std::vector<ExtremeCase> size_cases() {
  std::vector<ExtremeCase> cases;
  {
    ExtremeCase c;
    c.name = "2^31-cells";
    c.extreme = "2048 x 2048 x 512 samples (2^31) declared, never written; 1 GiB memory limit";
    c.input = small_grid(2048, 2048, 512, 1e-3);
    c.input.time = {0.0};
    c.input.fill_value = kFill;
    c.brick = 24;
    c.memory_limit = kGiB;
    c.limits = {at_least(0.0)};
    c.expected[Stage::kConvert] = clear_error("GB of memory to convert");
    c.expected_text =
        "refused before anything is read or allocated, with the memory it would need (about "
        "5 GB with 2 threads, streamed one brick layer at a time); without the limit it "
        "converts";
    cases.push_back(std::move(c));
  }
  {
    ExtremeCase c;
    c.name = "2^32-cells-one-level";
    c.extreme = "65536 x 65536 x 1 samples (2^32) declared, never written; 8 GiB memory limit";
    c.input = small_grid(65536, 65536, 1, 1e-4);
    c.input.time = {0.0};
    c.input.fill_value = kFill;
    c.brick = 24;
    c.memory_limit = 8 * kGiB;
    c.limits = {at_least(0.0)};
    c.expected[Stage::kConvert] = clear_error("GB of memory to convert");
    c.expected_text =
        "refused before anything is read or allocated: one level of 2^32 float32 samples is "
        "17 GB per slab, about 113 GB with 2 threads";
    cases.push_back(std::move(c));
  }
  {
    ExtremeCase c;
    c.name = "brick-1024";
    c.extreme = "1025^3 samples declared, brick 1024: one brick of 4.3 GB";
    c.input = small_grid(1025, 1025, 1025, 1e-3);
    c.input.time = {0.0};
    c.input.fill_value = kFill;
    c.brick = 1024;
    c.limits = {at_least(0.0)};
    c.expected[Stage::kConvert] = clear_error("more than a Blosc chunk can hold");
    c.expected_text =
        "refused when planned: a brick must fit one Blosc chunk (2 GiB); the message names the "
        "largest brick size that fits";
    cases.push_back(std::move(c));
  }
  return cases;
}

}  // namespace

std::vector<ExtremeCase> extreme_cases() {
  std::vector<ExtremeCase> all;
  for (auto group : {value_cases(), missing_data_cases(), threshold_cases(), axis_cases(),
                     box_cases(), size_cases()}) {
    for (auto& c : group) all.push_back(std::move(c));
  }
  return all;
}

ExtremeCase extreme_case(std::string_view name) {
  std::vector<std::string> names;
  for (auto& c : extreme_cases()) {
    if (c.name == name) return c;
    names.push_back(c.name);
  }
  throw make_error(ErrorCode::kNotFound, "no robustness case '{}' (cases: {})", name,
                   fmt::join(names, ", "));
}

}  // namespace strielad::robust
