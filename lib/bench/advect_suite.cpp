// SPDX-License-Identifier: Apache-2.0
#include "bench/advect_suite.h"

#include <fmt/format.h>

#include <array>
#include <chrono>
#include <cmath>
#include <functional>
#include <map>
#include <numbers>
#include <span>

#include "advect/integrators.h"
#include "bench/latency_stats.h"
#include "bench/machine_info.h"
#include "synthetic/sample_atmosphere.h"
#include "synthetic/sample_grid.h"

namespace strielad::bench {
namespace {

using Clock = std::chrono::steady_clock;
using Formula = advect::WindFormula;
using Exact = std::function<Vec3(const Vec3& start, double t)>;

constexpr double kPi = std::numbers::pi;

std::vector<double> linspace(double a, double b, std::size_t n) {
  return advect::evenly_spaced(a, b, n);
}

advect::WindField sample(std::array<std::vector<double>, 3> axes, double t1, const Formula& f) {
  advect::WindGrid grid;
  grid.horizontal = advect::Horizontal::kMetres;
  grid.axes = std::move(axes);
  return advect::sample_wind(std::move(grid), 0, t1, f);
}

struct Flow {
  std::string name;
  advect::WindField field;
  double duration = 3600;
  std::vector<Vec3> starts;
  Exact exact;  // null: the reference is RK4 with a very small step
  std::vector<double> euler_steps, rk4_steps;
  // The adaptive methods' absolute tolerance: 1 mm in the axis units.
  Vec3 atol{1e-3, 1e-3, 1e-3};
};

constexpr double kDegree = kPi / 180;
constexpr double kReferenceStepS = 0.25;

// Distance in metres between two positions on the flow's grid (degrees: on the local
// tangent plane, which is exact enough for errors of kilometres and less).
double distance_m(const advect::WindGrid& grid, const Vec3& a, const Vec3& b) {
  if (grid.horizontal == advect::Horizontal::kMetres) {
    return std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);
  }
  const double cos_lat = std::cos(0.5 * (a[1] + b[1]) * kDegree);
  return std::hypot((a[0] - b[0]) * kDegree * advect::kEarthRadiusM * cos_lat,
                    (a[1] - b[1]) * kDegree * advect::kEarthRadiusM, a[2] - b[2]);
}

// The sample generator's wind (SampleAtmosphere: ua, va, wa, as `strielad-convert
// sample` writes them) at times 0 and t1 on its lon/lat/stretched-height grid of `dims`.
// Heights run top to bottom, as in the sample files; WindField takes descending axes.
advect::WindField generated_wind(Dims3 dims, std::uint64_t seed, double t1) {
  const synthetic::SampleGrid grid(dims);
  const std::size_t level = grid.level_size();
  std::array<advect::WindSlice, 2> slices;
  for (int s = 0; s < 2; ++s) {
    const synthetic::SampleAtmosphere atmosphere(grid, seed, s == 0 ? 0.0 : t1);
    const auto fill = [&](synthetic::SampleVariable variable, std::vector<float>& out) {
      out.resize(dims.count());
      for (std::size_t k = 0; k < dims.z; ++k) {
        atmosphere.fill_level(variable, k, std::span<float>(out).subspan(k * level, level));
      }
    };
    fill(synthetic::SampleVariable::kUa, slices[s].u);
    fill(synthetic::SampleVariable::kVa, slices[s].v);
    fill(synthetic::SampleVariable::kWa, slices[s].w);
  }
  advect::WindGrid wind_grid;
  wind_grid.axes = {grid.lon, grid.lat, grid.height};
  wind_grid.horizontal = advect::Horizontal::kDegrees;
  wind_grid.vertical = advect::Vertical::kMetres;
  return advect::WindField(std::move(wind_grid), 0, std::move(slices[0]), t1, std::move(slices[1]));
}

// Start points on a ring or a line inside the domain, the same for every method.
std::vector<Vec3> spread(int n, const std::function<Vec3(double u)>& at) {
  std::vector<Vec3> out;
  for (int i = 0; i < n; ++i) out.push_back(at((i + 0.5) / n));
  return out;
}

std::vector<Flow> make_flows(const AdvectSuiteOptions& o) {
  const int n = o.quick ? 2 : o.trajectories;
  std::vector<Flow> flows;
  {  // Solid-body rotation, one turn an hour: exact after one turn = the start.
    constexpr double omega = 2 * kPi / 3600;
    Flow f{"solid-body rotation (1 turn/h, 1 h)",
           sample({linspace(-40e3, 40e3, 41), linspace(-40e3, 40e3, 41), linspace(0, 1e3, 2)}, 7200,
                  [](double x, double y, double, double) { return Vec3{-omega * y, omega * x, 0}; }),
           3600,
           spread(n, [](double u) { return Vec3{(5 + 25 * u) * 1e3 * std::cos(7 * u), (5 + 25 * u) * 1e3 * std::sin(7 * u), 500}; }),
           [](const Vec3& s, double t) {
             const double a = omega * t;
             return Vec3{s[0] * std::cos(a) - s[1] * std::sin(a), s[0] * std::sin(a) + s[1] * std::cos(a), s[2]};
           },
           {60, 30, 15, 7.5, 3.75},
           {900, 600, 300, 120, 60, 30}};
    flows.push_back(std::move(f));
  }
  {  // Shear layer: u = s z, rising at w; x(t) = x0 + s (z0 t + w t^2 / 2).
    constexpr double shear = 0.01, rise = 0.5;
    Flow f{"shear layer (10 m/s per km, w 0.5 m/s, 1 h)",
           sample({linspace(0, 300e3, 31), linspace(0, 10e3, 3), linspace(0, 12e3, 25)}, 7200,
                  [](double, double, double z, double) { return Vec3{shear * z, 0, rise}; }),
           3600,
           spread(n, [](double u) { return Vec3{5e3 + 20e3 * u, 5e3, 500 + 2500 * u}; }),
           [](const Vec3& s, double t) {
             return Vec3{s[0] + shear * (s[2] * t + rise * t * t / 2), s[1], s[2] + rise * t};
           },
           {60, 30, 15, 7.5, 3.75},
           {900, 600, 300, 120, 60, 30}};
    flows.push_back(std::move(f));
  }
  for (const double k : {1.0, 10.0}) {  // Stiff: fast convergence to y = y0, slow in x.
    constexpr double slow = 1e-3, x0 = 50e3, y0 = 50e3;
    Flow f{fmt::format("stiff convergence (rates 1e-3 and {:g} /s, ratio {:.0e}, 1 h)", k, k / slow),
           sample({linspace(0, 100e3, 21), linspace(0, 100e3, 21), linspace(0, 1e3, 2)}, 7200,
                  [k](double x, double y, double, double) { return Vec3{-slow * (x - x0), -k * (y - y0), 0}; }),
           3600,
           spread(n, [](double u) { return Vec3{60e3 + 30e3 * u, 20e3 + 60e3 * u, 500}; }),
           [k](const Vec3& s, double t) {
             return Vec3{x0 + (s[0] - x0) * std::exp(-slow * t), y0 + (s[1] - y0) * std::exp(-k * t), s[2]};
           },
           {0.5 / k, 1.0 / k, 1.9 / k, 2.5 / k},
           {0.5 / k, 1.0 / k, 2.5 / k, 3.0 / k}};
    flows.push_back(std::move(f));
  }
  {  // Vortices drifting in time, sampled every 5 km: interpolation makes the field only
     // piecewise smooth, as real model output is. Reference: RK4 with 0.25 s steps.
    const auto wind = [](double x, double y, double z, double t) {
      const double L = 200e3, phase = 2 * kPi * t / 7200;
      const double u = 12 * std::sin(2 * kPi * y / L + phase) + 4 * std::cos(2 * kPi * (x + y) / (0.5 * L));
      const double v = 9 * std::cos(2 * kPi * x / L - phase) + 3 * std::sin(2 * kPi * (x - y) / (0.4 * L));
      const double w = 0.3 * std::sin(2 * kPi * x / L) * std::sin(kPi * z / 12e3);
      return Vec3{u, v, w};
    };
    Flow f{"drifting vortices on a 5 km grid (1 h, reference RK4 0.25 s)",
           sample({linspace(0, 400e3, 81), linspace(0, 400e3, 81), linspace(0, 12e3, 13)}, 7200, wind),
           3600,
           spread(n, [](double u) { return Vec3{120e3 + 160e3 * u, 280e3 - 160e3 * u, 3000 + 4000 * u}; }),
           nullptr,
           {60, 30, 15, 7.5, 3.75},
           {900, 600, 300, 120, 60, 30}};
    flows.push_back(std::move(f));
  }
  {  // The sample generator's wind between two outputs an hour apart, on a coarse view of
     // its grid (4.5-14.5 E, 47.5-54.5 N, 21 km to 20 m): jet, cyclone, noise and the
     // sharp updrafts of its clouds. Start points inside, away from the edges.
    const Dims3 dims = o.quick ? Dims3{41, 40, 20} : Dims3{143, 156, 60};
    Flow f{fmt::format("generated sample wind, {}x{}x{} lon/lat/height (1 h, reference RK4 0.25 s)",
                       dims.x, dims.y, dims.z),
           generated_wind(dims, 1, 3600),
           3600,
           spread(n, [](double u) { return Vec3{5.5 + 4.0 * u, 53.0 - 4.5 * u, 1500 + 7000 * u}; }),
           nullptr,
           {60, 30, 15, 7.5, 3.75},
           {900, 600, 300, 120, 60, 30, 15}};
    const double degree_m = kDegree * advect::kEarthRadiusM;
    f.atol = {1e-3 / degree_m, 1e-3 / degree_m, 1e-3};
    flows.push_back(std::move(f));
  }
  if (o.quick) {
    for (auto& f : flows) {
      f.euler_steps.resize(2);
      f.rk4_steps.resize(2);
    }
  }
  return flows;
}

struct Setting {
  advect::AdvectOptions options;
  std::string label;
};

AdvectRun run_setting(const Flow& flow, const std::vector<Vec3>& truth, const Setting& s, int repeat) {
  AdvectRun run;
  run.flow = flow.name;
  run.method = std::string(advect::method_name(s.options.method));
  run.setting = s.label;
  run.trajectories = static_cast<int>(flow.starts.size());
  std::vector<double> walls, errors;
  std::map<std::string, int> stops;
  for (int r = 0; r < repeat; ++r) {
    std::vector<advect::AdvectResult> results;
    const auto t0 = Clock::now();
    for (const auto& start : flow.starts) results.push_back(advect::advect(flow.field, start, 0, flow.duration, s.options));
    walls.push_back(std::chrono::duration<double, std::micro>(Clock::now() - t0).count());
    if (r > 0) continue;
    run.evaluations = 0;
    for (std::size_t i = 0; i < results.size(); ++i) {
      const auto& res = results[i];
      run.evaluations += res.evaluations;
      ++stops[std::string(advect::stop_name(res.stop))];
      if (res.stop == advect::Stop::kReached) {
        ++run.reached;
        errors.push_back(distance_m(flow.field.grid(), res.position, truth[i]));
      }
    }
  }
  run.wall_us = median(walls);
  const double nan = std::nan("");
  run.max_error_m = run.reached == run.trajectories && !errors.empty()
                        ? *std::max_element(errors.begin(), errors.end())
                        : nan;
  run.median_error_m = errors.empty() ? nan : median(errors);
  for (const auto& [name, count] : stops) {
    run.stops += (run.stops.empty() ? "" : ", ") + fmt::format("{} {}", count, name);
  }
  return run;
}

// The truth at the end time per start point: exact, or RK4 with very small steps. A
// start point whose reference trajectory leaves the domain (or meets fill) has no truth
// to compare with: it is left out of the flow, and the note says so.
std::vector<Vec3> end_positions(Flow& flow, std::string& note) {
  std::vector<Vec3> truth, kept;
  int left = 0;
  for (const auto& start : flow.starts) {
    if (flow.exact) {
      truth.push_back(flow.exact(start, flow.duration));
      kept.push_back(start);
      continue;
    }
    const auto ref = advect::advect(flow.field, start, 0, flow.duration,
                                    {.method = advect::Method::kRk4, .step_s = kReferenceStepS,
                                     .max_steps = 100'000'000});
    if (ref.stop != advect::Stop::kReached) {
      ++left;
      continue;
    }
    truth.push_back(ref.position);
    kept.push_back(start);
  }
  if (left > 0) {
    note = fmt::format("{} of {} start points left out: their reference trajectory stopped early "
                       "(left the domain or met fill)",
                       left, flow.starts.size());
  }
  flow.starts = std::move(kept);
  return truth;
}

std::vector<Setting> settings_for(const Flow& flow, bool quick) {
  std::vector<Setting> settings;
  for (const double h : flow.euler_steps) {
    settings.push_back({{.method = advect::Method::kEuler, .step_s = h, .max_steps = 100'000'000},
                        fmt::format("step {:g} s", h)});
  }
  for (const double h : flow.rk4_steps) {
    settings.push_back({{.method = advect::Method::kRk4, .step_s = h, .max_steps = 100'000'000},
                        fmt::format("step {:g} s", h)});
  }
  const std::vector<double> tolerances =
      quick ? std::vector<double>{1e-4, 1e-7}
            : std::vector<double>{1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10};
  for (const auto method : {advect::Method::kDopri5, advect::Method::kRosenbrock}) {
    for (const double rtol : tolerances) {
      advect::AdvectOptions a;
      a.method = method;
      a.rtol = rtol;
      a.atol = flow.atol;
      a.step_s = 60;
      settings.push_back({a, fmt::format("rtol {:.0e}", rtol)});
    }
  }
  return settings;
}

}  // namespace

AdvectSuiteReport run_advect_suite(const AdvectSuiteOptions& o) {
  const auto suite_start = Clock::now();
  AdvectSuiteReport report;
  report.options = o;
  const int repeat = o.quick ? 1 : std::max(o.repeat, 1);
  for (auto& flow : make_flows(o)) {
    AdvectFlowInfo info;
    info.name = flow.name;
    const std::vector<Vec3> truth = end_positions(flow, info.note);
    info.trajectories = static_cast<int>(flow.starts.size());
    report.flows.push_back(info);
    if (flow.starts.empty()) continue;
    for (const auto& s : settings_for(flow, o.quick)) {
      report.runs.push_back(run_setting(flow, truth, s, repeat));
    }
  }
  report.machine = machine_info("/tmp");
  report.seconds = std::chrono::duration<double>(Clock::now() - suite_start).count();
  if (!o.plot_png.empty()) report.plot_status = write_advect_plot(report, o.plot_png);
  return report;
}

std::vector<Table> advect_report_tables(const AdvectSuiteReport& report) {
  std::vector<Table> tables;
  std::vector<std::string> flows;
  for (const auto& info : report.flows) flows.push_back(info.name);
  for (std::size_t f = 0; f < flows.size(); ++f) {
    Table t;
    t.name = fmt::format("flow_{}", f + 1);
    t.title = flows[f];
    t.columns = {"method", "setting", "max error m", "median error m", "evaluations",
                 "wall us", "us per evaluation", "trajectories"};
    for (const auto& r : report.runs) {
      if (r.flow != flows[f]) continue;
      t.add({r.method, r.setting, std::isnan(r.max_error_m) ? Cell("-") : Cell(r.max_error_m, 4),
             std::isnan(r.median_error_m) ? Cell("-") : Cell(r.median_error_m, 4),
             Cell::integer(double(r.evaluations)), Cell(r.wall_us, 0),
             Cell(r.evaluations ? r.wall_us / double(r.evaluations) : 0.0, 3), r.stops});
    }
    t.notes.push_back("error: distance at the end time to the exact (or reference) position, over all start points; '-' when some stopped early (see trajectories)");
    if (!report.flows[f].note.empty()) t.notes.push_back(report.flows[f].note);
    tables.push_back(std::move(t));
  }
  // The cheapest setting per method that brings every trajectory within 1 m.
  Table best;
  best.name = "cheapest_within_1m";
  best.title = "Fewest field evaluations with every trajectory within 1 m of the truth";
  best.columns = {"flow", "euler", "rk4", "dopri5", "rosenbrock"};
  for (const auto& flow : flows) {
    std::vector<Cell> row{flow};
    for (const char* m : {"euler", "rk4", "dopri5", "rosenbrock"}) {
      const AdvectRun* pick = nullptr;
      for (const auto& r : report.runs) {
        if (r.flow == flow && r.method == m && !std::isnan(r.max_error_m) && r.max_error_m <= 1.0 &&
            (!pick || r.evaluations < pick->evaluations)) {
          pick = &r;
        }
      }
      row.push_back(pick ? Cell(fmt::format("{} evaluations ({})", pick->evaluations, pick->setting))
                         : Cell("not reached"));
    }
    best.add(std::move(row));
  }
  tables.push_back(std::move(best));
  return tables;
}

nlohmann::json advect_report_json(const AdvectSuiteReport& report, const std::vector<Table>& tables) {
  nlohmann::json runs = nlohmann::json::array();
  for (const auto& r : report.runs) {
    runs.push_back({{"flow", r.flow},
                    {"method", r.method},
                    {"setting", r.setting},
                    {"max_error_m", std::isnan(r.max_error_m) ? nlohmann::json(nullptr) : nlohmann::json(r.max_error_m)},
                    {"median_error_m", std::isnan(r.median_error_m) ? nlohmann::json(nullptr) : nlohmann::json(r.median_error_m)},
                    {"evaluations", r.evaluations},
                    {"wall_us", r.wall_us},
                    {"reached", r.reached},
                    {"trajectories", r.trajectories},
                    {"stops", r.stops}});
  }
  nlohmann::json t = nlohmann::json::array();
  for (const auto& table : tables) t.push_back(table_json(table));
  nlohmann::json flows = nlohmann::json::array();
  for (const auto& f : report.flows) {
    flows.push_back({{"name", f.name}, {"trajectories", f.trajectories}, {"note", f.note}});
  }
  return {{"suite", "advect"},
          {"command", report.options.command_line},
          {"options", {{"repeat", report.options.repeat}, {"trajectories", report.options.trajectories}, {"quick", report.options.quick}}},
          {"machine", report.machine},
          {"seconds", report.seconds},
          {"plot", report.plot_status},
          {"flows", flows},
          {"runs", runs},
          {"tables", t}};
}

}  // namespace strielad::bench
