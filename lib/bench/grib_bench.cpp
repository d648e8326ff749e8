// SPDX-License-Identifier: Apache-2.0
#include "bench/grib_bench.h"

#include <fmt/format.h>
#include <spdlog/spdlog.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

#include "bench/cpu_time.h"
#include "bench/latency_stats.h"
#include "bench/machine_info.h"
#include "bench/process_runner.h"
#include "bench/stopwatch.h"
#include "convert/converter.h"
#include "core/error.h"
#include "store/level_samples.h"
#include "store/store.h"
#include "synthetic/grib_sample_writer.h"
#include "synthetic/sample_dataset.h"

namespace strielad::bench {
namespace {

namespace fs = std::filesystem;

void remove_quietly(const fs::path& p) {
  std::error_code ec;
  fs::remove_all(p, ec);
}

std::vector<fs::path> paths_of(const synthetic::SampleResult& r) {
  std::vector<fs::path> out;
  for (const auto& f : r.files) out.push_back(f.path);
  return out;
}

std::string read_text(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

struct Inputs {
  fs::path grib, netcdf;
  double seconds = 0;
  bool reused = false;
};

// The GRIB2 and NetCDF samples of one step, reused when the stamp says they were made
// with the same grid and packing.
Inputs ensure_inputs(const GribBenchOptions& o) {
  const fs::path dir = o.work / "input";
  const std::string stamp = fmt::format("{}x{}x{} bits {} seed 1 steps 1 grib model levels\n",
                                        o.dims.x, o.dims.y, o.dims.z, o.grib_bits);
  Inputs in{dir / "grib" / "sample_t000.grib2", dir / "netcdf" / "sample_t000.nc"};
  if (fs::exists(in.grib) && fs::exists(in.netcdf) && read_text(dir / "stamp") == stamp) {
    in.reused = true;
    return in;
  }
  remove_quietly(dir);
  const Stopwatch clock;
  synthetic::SampleSpec spec;
  spec.dims = o.dims;
  spec.steps = 1;
  const auto netcdf = synthetic::write_sample_dataset(spec, dir / "netcdf");
  spec.format = synthetic::SampleFormat::kGrib2;
  spec.grib_bits = o.grib_bits;
  spec.grib_levels = synthetic::GribLevelKind::kModelLevel;
  const auto grib = synthetic::write_sample_dataset(spec, dir / "grib");
  in.grib = paths_of(grib).front();
  in.netcdf = paths_of(netcdf).front();
  write_text_file(dir / "stamp", stamp);
  in.seconds = clock.seconds();
  return in;
}

struct Timed {
  double seconds = 0, cpu = 0;
  std::uint64_t store_bytes = 0;
};

Timed convert_once(const fs::path& input, const fs::path& store, const GribBenchOptions& o) {
  remove_quietly(store);
  build::ConvertOptions co;
  co.inputs = {input};
  co.store = store;
  co.brick = o.brick;
  co.threads = o.threads;
  const double cpu0 = process_cpu_seconds();
  const Stopwatch clock;
  const build::ConvertResult r = build::convert(co);
  return {clock.seconds(), process_cpu_seconds() - cpu0, r.written_bytes};
}

void record(ContenderRuns& c, const Timed& t) {
  c.seconds.push_back(t.seconds);
  c.cpu_seconds.push_back(t.cpu);
  c.output_bytes = t.store_bytes;
}

// For every index of `from`, the index of the value within `tol` in `to`; empty when one
// is not there.
std::vector<std::size_t> match_axis(const std::vector<double>& from, const std::vector<double>& to,
                                    double tol) {
  std::vector<std::size_t> map;
  if (from.size() != to.size()) return map;
  for (const double v : from) {
    const auto it =
        std::find_if(to.begin(), to.end(), [&](double w) { return std::abs(v - w) <= tol; });
    if (it == to.end()) return {};
    map.push_back(static_cast<std::size_t>(it - to.begin()));
  }
  return map;
}

ContenderRuns contender(std::string name, std::string command, std::uint64_t input_bytes) {
  ContenderRuns c;
  c.name = std::move(name);
  c.command = std::move(command);
  c.input_bytes = input_bytes;
  return c;
}

double sample_mb(std::uint64_t bytes) { return static_cast<double>(bytes) / 1e6; }

}  // namespace

GribBenchOptions quick_grib_options(GribBenchOptions o) {
  o.dims = {48, 40, 10};
  o.repeat = 1;
  return o;
}

StoreDifference compare_stores_level0(const fs::path& a, const fs::path& b,
                                      const std::function<std::string(const std::string&)>&
                                          name_in_b) {
  StoreDifference d;
  const auto sa = Store::open(a);
  const auto sb = Store::open(b);
  const auto& ma = sa->manifest();
  const auto& mb = sb->manifest();
  const auto mx = match_axis(ma.x.values, mb.x.values, 1e-4);
  const auto my = match_axis(ma.y.values, mb.y.values, 1e-4);
  auto mz = match_axis(ma.z.values, mb.z.values, 1e-6);
  if (mz.empty() && ma.z.size() == mb.z.size()) {
    for (std::size_t k = 0; k < ma.z.size(); ++k) mz.push_back(k);
  }
  if (mx.empty() || my.empty() || mz.empty()) {
    d.problem = fmt::format("the grids differ ({}x{}x{} and {}x{}x{}, or other coordinates)",
                            ma.x.size(), ma.y.size(), ma.z.size(), mb.x.size(), mb.y.size(),
                            mb.z.size());
    return d;
  }
  const std::size_t nx = ma.x.size(), ny = ma.y.size(), nz = ma.z.size();
  for (std::size_t v = 0; v < ma.variables.size(); ++v) {
    const std::string other = name_in_b(ma.variables[v].name);
    const auto it = std::find_if(mb.variables.begin(), mb.variables.end(),
                                 [&](const auto& w) { return w.name == other; });
    if (it == mb.variables.end()) {
      d.problem = fmt::format("{} has no variable {} (for {})", b.string(), other,
                              ma.variables[v].name);
      return d;
    }
    const auto vb = static_cast<std::uint32_t>(it - mb.variables.begin());
    const std::uint32_t steps = static_cast<std::uint32_t>(std::min(ma.time.size(), mb.time.size()));
    for (std::uint32_t t = 0; t < steps; ++t) {
      const auto la = read_level_samples<float>(*sa, t, static_cast<std::uint32_t>(v), 0);
      const auto lb = read_level_samples<float>(*sb, t, vb, 0);
      for (std::size_t k = 0; k < nz; ++k) {
        float lo = INFINITY, hi = -INFINITY;
        double level_max = 0;
        for (std::size_t j = 0; j < ny; ++j) {
          for (std::size_t i = 0; i < nx; ++i) {
            const float x = la.values[(k * ny + j) * nx + i];
            const float y = lb.values[(mz[k] * ny + my[j]) * nx + mx[i]];
            ++d.samples;
            if (std::isnan(x) != std::isnan(y)) {
              ++d.missing_mismatches;
              continue;
            }
            if (std::isnan(x)) continue;
            lo = std::min(lo, x);
            hi = std::max(hi, x);
            level_max = std::max(level_max, std::abs(static_cast<double>(x) - y));
          }
        }
        d.max_abs_difference = std::max(d.max_abs_difference, level_max);
        if (hi > lo) {
          d.max_relative_difference =
              std::max(d.max_relative_difference, level_max / (static_cast<double>(hi) - lo));
        }
      }
    }
    ++d.variables;
  }
  return d;
}

GribBenchReport run_grib_bench(const GribBenchOptions& o) {
  const Stopwatch total;
  GribBenchReport r;
  r.options = o;
  fs::create_directories(o.work);
  const Inputs in = ensure_inputs(o);
  r.generate_seconds = in.seconds;
  r.reused_input = in.reused;
  r.grib_bytes = fs::file_size(in.grib);
  r.netcdf_bytes = fs::file_size(in.netcdf);
  r.samples = static_cast<std::uint64_t>(o.dims.x) * o.dims.y * o.dims.z *
              synthetic::all_sample_variable_names().size();
  const int threads = o.threads > 0 ? o.threads : static_cast<int>(::sysconf(_SC_NPROCESSORS_ONLN));

  const fs::path store_a = o.work / "store_a", store_b = o.work / "store_b",
                 store_c = o.work / "store_c", b_netcdf = o.work / "grib_to_netcdf.nc",
                 b_log = o.work / "grib_to_netcdf.log";
  const std::string convert_what = fmt::format("build::convert in process, brick {}, threads {}",
                                               o.brick, threads);
  ContenderRuns a =
      contender("A: strielad-convert GRIB2", convert_what + " of " + in.grib.string(), r.grib_bytes);
  const std::vector<std::string> argv{"grib_to_netcdf", "-D", "NC_FLOAT", "-o",
                                      b_netcdf.string(), in.grib.string()};
  ContenderRuns b1 = contender("B: grib_to_netcdf", shell_command(argv), r.grib_bytes);
  ContenderRuns b2 = contender("B: strielad-convert its NetCDF",
                               convert_what + " of " + b_netcdf.string(), 0);
  ContenderRuns b = contender("B: total", "grib_to_netcdf, then strielad-convert", r.grib_bytes);
  ContenderRuns c = contender("C: strielad-convert NetCDF (reference)",
                              convert_what + " of " + in.netcdf.string(), r.netcdf_bytes);
  const auto program = find_program("grib_to_netcdf");
  if (program) {
    r.grib_to_netcdf = program->string();
  } else {
    r.b_failure = "grib_to_netcdf not found on PATH (Debian: libeccodes-tools)";
  }

  for (int round = 0; round < o.repeat; ++round) {
    spdlog::info("grib bench: round {} of {}", round + 1, o.repeat);
    a.max_resident_before = std::max(a.max_resident_before, evict_inputs({in.grib}));
    record(a, convert_once(in.grib, store_a, o));

    if (r.b_failure.empty()) {
      b1.max_resident_before = std::max(b1.max_resident_before, evict_inputs({in.grib}));
      remove_quietly(b_netcdf);
      const ProcessResult p = run_process(argv, b_log);
      if (p.exit_status != 0) {
        r.b_failure = fmt::format("'{}' failed with status {}: {}", shell_command(argv),
                                  p.exit_status, p.output_tail);
        spdlog::warn("grib bench: {}", r.b_failure);
      } else {
        b1.seconds.push_back(p.seconds);
        b1.cpu_seconds.push_back(p.cpu_seconds);
        r.b_netcdf_bytes = fs::file_size(b_netcdf);
        b1.output_bytes = r.b_netcdf_bytes;
        b2.input_bytes = r.b_netcdf_bytes;
        try {
          const Timed t = convert_once(b_netcdf, store_b, o);
          record(b2, t);
          b.seconds.push_back(p.seconds + t.seconds);
          b.cpu_seconds.push_back(p.cpu_seconds + t.cpu);
          b.output_bytes = t.store_bytes;
        } catch (const Error& e) {
          r.b_failure = fmt::format("strielad-convert of grib_to_netcdf's output: {}", e.what());
          spdlog::warn("grib bench: {}", r.b_failure);
        }
      }
    }

    c.max_resident_before = std::max(c.max_resident_before, evict_inputs({in.netcdf}));
    record(c, convert_once(in.netcdf, store_c, o));
  }
  if (r.b_failure.empty() && !b.seconds.empty()) {
    r.a_vs_b = compare_stores_level0(store_a, store_b, [](const std::string& n) { return n; });
  } else {
    r.a_vs_b.problem = "B did not run";
  }
  std::map<std::string, std::string> sample_names;
  for (const auto& info : synthetic::sample_variable_table()) {
    sample_names[std::string(synthetic::grib_parameter(info.id).short_name)] = info.name;
  }
  r.a_vs_c = compare_stores_level0(store_a, store_c, [&](const std::string& n) {
    const auto it = sample_names.find(n);
    return it == sample_names.end() ? n : it->second;
  });
  r.contenders = {a, b1, b2, b, c};
  r.seconds = total.seconds();
  return r;
}

std::vector<Table> grib_tables(const GribBenchReport& r) {
  Table t{"grib",
          fmt::format("GRIB2 conversion, {}x{}x{}, 8 variables, 1 step, {} round(s); medians "
                      "(min-max)",
                      r.options.dims.x, r.options.dims.y, r.options.dims.z, r.options.repeat),
          {"contender", "seconds", "min", "max", "input MB", "input MB/s", "Msamples/s",
           "CPU s", "store MB"},
          {},
          {}};
  for (const auto& c : r.contenders) {
    if (c.seconds.empty()) continue;
    const bool is_store = c.name.find("convert") != std::string::npos ||
                          c.name.find("total") != std::string::npos;
    t.add({c.name, Cell(c.median_seconds(), 2), Cell(c.min_seconds(), 2),
           Cell(c.max_seconds(), 2), Cell(sample_mb(c.input_bytes), 1),
           Cell(c.median_mb_per_s(), 1),
           Cell(static_cast<double>(r.samples) / c.median_seconds() / 1e6, 1),
           Cell(c.median_cpu_seconds(), 2),
           is_store ? Cell(sample_mb(c.output_bytes), 1) : Cell("-")});
  }
  t.notes.push_back(fmt::format(
      "Inputs: GRIB2 {:.1f} MB ({}-bit simple packing, hybrid level numbers), NetCDF-4 "
      "float32 {:.1f} MB; every contender starts with its input evicted from the page cache; "
      "B's NetCDF file ({:.1f} MB) is read as grib_to_netcdf left it",
      sample_mb(r.grib_bytes), r.options.grib_bits, sample_mb(r.netcdf_bytes),
      sample_mb(r.b_netcdf_bytes)));
  for (const auto& c : r.contenders) {
    if (c.max_resident_before > 0.01) {
      t.notes.push_back(fmt::format("{}: up to {:.0f}% of the input stayed cached", c.name,
                                    100 * c.max_resident_before));
    }
  }
  if (!r.b_failure.empty()) t.notes.push_back("B: " + r.b_failure);

  Table check{"grib_check", "Level-0 samples of the stores compared",
              {"pair", "variables", "samples", "missing mismatches", "max |difference|",
               "max difference / level range", "equal"},
              {},
              {}};
  const auto add = [&](const char* name, const StoreDifference& d) {
    check.add({name, Cell::integer(static_cast<double>(d.variables)),
               Cell::integer(static_cast<double>(d.samples)),
               Cell::integer(static_cast<double>(d.missing_mismatches)),
               Cell(d.max_abs_difference, 6), Cell(d.max_relative_difference, 7),
               d.problem.empty() ? (d.equal() ? "yes" : "no") : d.problem});
  };
  add("A vs B", r.a_vs_b);
  add("A vs C (GRIB packing)", r.a_vs_c);
  return {t, check};
}

nlohmann::json grib_json(const GribBenchReport& r, const std::vector<Table>& tables) {
  nlohmann::json out = {
      {"suite", "grib"},
      {"command", r.options.command_line},
      {"dims", {r.options.dims.x, r.options.dims.y, r.options.dims.z}},
      {"repeat", r.options.repeat},
      {"grib_bits", r.options.grib_bits},
      {"grib_bytes", r.grib_bytes},
      {"netcdf_bytes", r.netcdf_bytes},
      {"grib_to_netcdf_bytes", r.b_netcdf_bytes},
      {"grib_to_netcdf", r.grib_to_netcdf},
      {"b_failure", r.b_failure},
      {"generate_seconds", r.generate_seconds},
      {"reused_input", r.reused_input},
      {"a_equals_b", r.a_vs_b.equal()},
      {"seconds", r.seconds},
      {"machine", machine_info(r.options.work)},
  };
  nlohmann::json contenders = nlohmann::json::array();
  for (const auto& c : r.contenders) {
    contenders.push_back({{"name", c.name},
                          {"command", c.command},
                          {"input_bytes", c.input_bytes},
                          {"output_bytes", c.output_bytes},
                          {"seconds", c.seconds},
                          {"cpu_seconds", c.cpu_seconds}});
  }
  out["contenders"] = contenders;
  nlohmann::json t = nlohmann::json::array();
  for (const auto& table : tables) t.push_back(table_json(table));
  out["tables"] = t;
  return out;
}

}  // namespace strielad::bench
