// SPDX-License-Identifier: Apache-2.0
#include "convert/converter.h"

#include <fmt/format.h>
#include <spdlog/spdlog.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <limits>
#include <atomic>
#include <chrono>

#include "convert/conversion_limits.h"
#include "convert/geometry_field_reader.h"
#include "convert/geometry_plan.h"
#include "convert/geometry_writer.h"
#include "convert/step_converter.h"
#include "core/checksum.h"
#include "core/error.h"
#include "core/file_io.h"
#include "core/version.h"
#include "format/geometry_file_format.h"
#include "octree/octree_layout.h"
#include "store/store.h"

namespace strielad::build {
namespace {

using nlohmann::json;

// Names the top-level parts of the plan that differ, for the refusal message: "'octree'
// differs", "'codec', 'octree' differ" (a new brick size can change the predictors that
// `auto` picks too).
std::string plan_difference(const format::Manifest& a, const format::Manifest& b) {
  const json pa = format::manifest_plan_json(a), pb = format::manifest_plan_json(b);
  std::vector<std::string> keys;
  for (const auto& [key, value] : pa.items()) {
    if (!pb.contains(key) || pb[key] != value) keys.push_back(fmt::format("'{}'", key));
  }
  for (const auto& [key, value] : pb.items()) {
    if (!pa.contains(key)) keys.push_back(fmt::format("'{}'", key));
  }
  if (keys.empty()) return "'store_id' differs";
  return fmt::format("{} differ{}", fmt::join(keys, ", "), keys.size() == 1 ? "s" : "");
}

void remove_stale_temporaries(const std::filesystem::path& store, std::uint32_t first,
                              std::uint32_t last) {
  const auto dir = store / "steps";
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    const std::string name = entry.path().filename().string();
    for (std::uint32_t s = first; s <= last; ++s) {
      const std::string prefix =
          std::filesystem::path(format::step_file_name(s)).filename().string() + ".tmp.";
      if (name.rfind(prefix, 0) == 0) {
        spdlog::info("removing {} left by an interrupted conversion", entry.path().string());
        std::filesystem::remove(entry.path());
      }
    }
  }
}

// True when the step file exists and its header, footer, tables and index sections are
// sound (chunks are checked by `verify`).
bool step_is_complete(const Store& store, std::uint32_t step) {
  if (!store.has_step(step)) return false;
  try {
    for (std::uint32_t v = 0; v < store.variable_count(); ++v) store.index(step, v);
    return true;
  } catch (const Error& e) {
    spdlog::warn("{}; converting step {} again", e.what(), step);
    return false;
  }
}

}  // namespace

json ConvertResult::to_json() const {
  return json{{"steps_converted", steps_converted},
              {"steps_skipped", steps_skipped},
              {"input_bytes", input_bytes},
              {"direct_input_bytes", direct_input_bytes},
              {"written_bytes", written_bytes},
              {"bricks", {{"empty", empty}, {"constant", constant}, {"data", data}}},
              {"lossy", {{"zfp_bricks", lossy}, {"fallback_bricks", lossy_fallback}}},
              {"seconds", seconds},
              {"input_mb_per_s", seconds > 0 ? double(input_bytes) / 1e6 / seconds : 0.0},
              {"finalized", finalized},
              {"codecs", codecs},
              {"summary", summary}};
}

namespace {

// The converter's codec rules: format::validate_codec plus predictor "auto".
void validate_convert_codec(const format::CodecSpec& codec, std::string_view what) {
  if (codec.predictor != kPredictorAuto && codec.predictor != format::kPredictorNone &&
      codec.predictor != format::kPredictorLorenzo3) {
    throw make_error(ErrorCode::kInvalidArgument,
                     "{}predictor '{}' is not one of auto, none, lorenzo3", what, codec.predictor);
  }
  format::CodecSpec blosc = codec;
  blosc.predictor = format::kPredictorNone;
  try {
    format::validate_codec(blosc);
  } catch (const Error& e) {
    throw make_error(ErrorCode::kInvalidArgument, "{}{}", what, e.what());
  }
}

bool same_blosc(const format::CodecSpec& a, const format::CodecSpec& b) {
  return a.name == b.name && a.level == b.level && a.shuffle == b.shuffle;
}

}  // namespace

std::pair<std::string, format::CodecSpec> parse_codec_for(std::string_view text,
                                                          std::string_view default_predictor) {
  const auto bad = [&] {
    return make_error(ErrorCode::kInvalidArgument,
                      "--codec-for: '{}' is not VARIABLE=CODEC:LEVEL:SHUFFLE[:PREDICTOR] "
                      "(e.g. clw=zstd:5:byte:none)",
                      text);
  };
  const auto eq = text.rfind('=');
  if (eq == std::string_view::npos || eq == 0) throw bad();
  std::vector<std::string> parts;
  std::string_view rest = text.substr(eq + 1);
  while (true) {
    const auto colon = rest.find(':');
    parts.emplace_back(rest.substr(0, colon));
    if (colon == std::string_view::npos) break;
    rest = rest.substr(colon + 1);
  }
  if (parts.size() < 3 || parts.size() > 4) throw bad();
  format::CodecSpec c;
  c.name = parts[0];
  const std::string& level = parts[1];
  if (level.size() != 1 || level[0] < '0' || level[0] > '9') throw bad();
  c.level = level[0] - '0';
  c.shuffle = parts[2];
  c.predictor = parts.size() == 4 ? parts[3] : std::string(default_predictor);
  std::string variable(text.substr(0, eq));
  validate_convert_codec(c, fmt::format("--codec-for {}: ", variable));
  return {std::move(variable), std::move(c)};
}

namespace {

// The codec options checked before anything is read: valid codecs, and --codec-for naming
// converted variables only.
void check_codec_options(const ingest::InputCatalog& catalog, const ConvertOptions& options) {
  validate_convert_codec(options.codec, "");
  for (const auto& [name, codec] : options.codec_for) {
    validate_convert_codec(codec, fmt::format("--codec-for {}: ", name));
    bool found = false;
    for (const auto& v : catalog.variables) found = found || v.name == name;
    if (!found) {
      std::string names;
      for (const auto& v : catalog.variables) {
        if (!names.empty()) names += ", ";
        names += v.name;
      }
      throw make_error(ErrorCode::kInvalidArgument,
                       "--codec-for names variable '{}', which is not converted (converted: {})",
                       name, names);
    }
  }
}

// The plan's grid, time, variables and sources, taken from the scanned inputs.
format::Manifest manifest_from_catalog(const ingest::InputCatalog& catalog,
                                       const ConvertOptions& options) {
  format::Manifest m;
  m.tool_version = kToolVersion;
  m.x = catalog.x;
  m.y = catalog.y;
  m.z = catalog.z;
  m.grid_mapping = catalog.grid_mapping;
  m.time = catalog.time;
  for (const auto& v : catalog.variables) {
    m.variables.push_back(format::StoreVariable{v.name, v.units, v.long_name, v.standard_name,
                                                v.store_type, v.source_type, v.fill_value,
                                                v.missing_value, v.valid_min, v.valid_max,
                                                v.scale_factor, v.add_offset});
  }
  m.brick = options.brick;
  m.nan_as_fill = options.scan.nan_as_fill;
  for (const auto& f : catalog.files) {
    m.sources.push_back(format::SourceRecord{f.path, f.size, f.header_checksum});
  }
  return m;
}

// Each variable's codec as the options ask for it (--codec-for, else --codec; --fpzip).
std::vector<format::CodecSpec> requested_codecs(const ingest::InputCatalog& catalog,
                                                const ConvertOptions& options) {
  std::vector<format::CodecSpec> codecs;
  for (std::size_t v = 0; v < catalog.variables.size(); ++v) {
    const auto own = options.codec_for.find(catalog.variables[v].name);
    codecs.push_back(own != options.codec_for.end() ? own->second : options.codec);
  }
  for (const std::string& name : options.fpzip) {
    bool found = false;
    for (std::size_t v = 0; v < codecs.size(); ++v) {
      if (name == "all" || catalog.variables[v].name == name) {
        codecs[v].fpzip = true;
        found = true;
      }
    }
    if (!found) {
      throw make_error(ErrorCode::kInvalidArgument,
                       "--fpzip names variable '{}', which is not converted", name);
    }
  }
  const std::vector<format::LossySpec> lossy = resolve_lossy(catalog, options.scan, options.lossy);
  for (std::size_t i = 0; i < lossy.size(); ++i) {
    const std::size_t v = catalog.variable_index(options.lossy[i].variable);
    if (codecs[v].fpzip) {
      throw make_error(ErrorCode::kInvalidArgument,
                       "--lossy and --fpzip both name variable '{}' (a variable is either lossy "
                       "or fpzip-coded)",
                       options.lossy[i].variable);
    }
    codecs[v].zfp = lossy[i];
    spdlog::info("lossy '{}': zfp within {} ({}:{})", options.lossy[i].variable,
                 lossy[i].tolerance, format::lossy_mode_name(lossy[i].mode), lossy[i].value);
  }
  return codecs;
}

// Predictor "auto" resolved from sample bricks of step 0. One variable at a time:
// measured, running them in parallel made it 4x slower (HDF5 under the netCDF lock, the
// same file opened several times).
void resolve_auto_predictors(const ingest::InputCatalog& catalog, const ConvertOptions& options,
                             const OctreeLayout& layout, std::vector<format::CodecSpec>& codecs,
                             std::vector<PredictorTrial>* trials) {
  std::vector<std::optional<PredictorTrial>> auto_trials(codecs.size());
  const auto started = std::chrono::steady_clock::now();
  for (std::size_t v = 0; v < codecs.size(); ++v) {
    if (codecs[v].predictor == kPredictorAuto) {
      auto_trials[v] = choose_predictor(catalog, options.scan, v, layout, codecs[v]);
    }
  }
  for (std::size_t v = 0; v < codecs.size(); ++v) {
    if (!auto_trials[v]) continue;
    PredictorTrial& t = *auto_trials[v];
    spdlog::info("predictor for '{}': {} (lorenzo3 {:+.1f}% on {} of {} sampled bricks with "
                 "data: {:.1f} KB without, {:.1f} KB with)",
                 t.variable, t.chosen, -100.0 * t.saving(), t.data_bricks, t.bricks_sampled,
                 t.bytes_none / 1e3, t.bytes_lorenzo3 / 1e3);
    codecs[v].predictor = t.chosen;
    if (trials) trials->push_back(std::move(t));
  }
  if (std::any_of(auto_trials.begin(), auto_trials.end(), [](const auto& t) { return t.has_value(); })) {
    spdlog::info("predictors chosen in {:.0f} ms",
                 std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - started)
                     .count());
  }
}

// Store-wide codec: the predictor most variables with the common Blosc settings use.
format::CodecSpec store_wide_codec(const format::CodecSpec& requested,
                                   const std::vector<format::CodecSpec>& codecs) {
  format::CodecSpec codec = requested;
  if (codec.predictor == kPredictorAuto) {
    std::size_t lorenzo3 = 0, none = 0;
    for (const auto& c : codecs) {
      if (!same_blosc(c, codec)) continue;
      (c.predictor == format::kPredictorLorenzo3 ? lorenzo3 : none) += 1;
    }
    codec.predictor = lorenzo3 > none ? format::kPredictorLorenzo3 : format::kPredictorNone;
  }
  return codec;
}

}  // namespace

format::Manifest plan_store(const ingest::InputCatalog& catalog, const ConvertOptions& options,
                            std::vector<PredictorTrial>* trials) {
  check_codec_options(catalog, options);
  format::Manifest m = manifest_from_catalog(catalog, options);
  const OctreeLayout layout(m.dims(), m.brick);  // validates dims and brick
  // Sizes before any data is read (the predictor trial reads bricks).
  for (const auto& v : catalog.variables) {
    check_brick_fits_chunk(layout, v.store_type, v.name);
    check_conversion_memory(layout, v.store_type, source_type_size(v.source_type),
                            options.threads, options.memory_limit, v.name);
  }
  std::vector<format::CodecSpec> codecs = requested_codecs(catalog, options);
  resolve_auto_predictors(catalog, options, layout, codecs, trials);
  m.codec = store_wide_codec(options.codec, codecs);
  for (std::size_t v = 0; v < codecs.size(); ++v) {
    if (!(codecs[v] == m.codec)) m.variables[v].codec = codecs[v];
  }
  m.geometry = plan_geometry(catalog, options.scan, m.codec);
  if (m.geometry && m.geometry->vertical.kind == format::VerticalGeometry::Kind::kField) {
    check_conversion_memory(layout, m.geometry->vertical.dtype, sizeof(double), options.threads,
                            options.memory_limit, "the grid geometry");
  }
  m.format_version = format::version_for_plan(m);
  m.store_id = format::compute_store_id(m);
  return m;
}

namespace {

// Each variable's codec for the result, with the trial that chose its predictor.
void report_codecs(const format::Manifest& plan, const std::vector<PredictorTrial>& trials,
                   ConvertResult& result) {
  for (std::size_t v = 0; v < plan.variables.size(); ++v) {
    const format::CodecSpec& c = plan.codec_of(v);
    json entry{{"name", c.name}, {"level", c.level}, {"shuffle", c.shuffle},
               {"predictor", c.predictor}, {"fpzip", c.fpzip}};
    if (c.zfp) entry["zfp"] = format::lossy_json(*c.zfp);
    for (const auto& t : trials) {
      if (t.variable == plan.variables[v].name) entry["auto"] = t.to_json();
    }
    result.codecs[plan.variables[v].name] = std::move(entry);
  }
}

// The store's MANIFEST written from the plan, or the one there checked to hold the same
// plan: returned when that store is already complete.
std::optional<format::Manifest> start_or_match_manifest(const std::filesystem::path& store_dir,
                                                        const format::Manifest& plan) {
  const auto manifest_path = store_dir / "MANIFEST";
  if (!std::filesystem::exists(manifest_path)) {
    write_file_atomically(manifest_path, format::encode_manifest(plan));
    return std::nullopt;
  }
  format::Manifest existing =
      format::decode_manifest(read_file_bytes(manifest_path), manifest_path.string());
  if (existing.store_id != plan.store_id) {
    throw make_error(ErrorCode::kAlreadyExists,
                     "{}: the store was started from different inputs or options (its {}); "
                     "convert into a new directory or delete it",
                     store_dir.string(), plan_difference(existing, plan));
  }
  if (existing.complete) return existing;
  return std::nullopt;
}

// Steps first..last that are not yet complete in the store; the others counted as skipped.
std::vector<std::uint32_t> steps_to_convert(const Store& store, std::uint32_t first,
                                            std::uint32_t last, ConvertResult& result) {
  std::vector<std::uint32_t> todo;
  for (std::uint32_t s = first; s <= last; ++s) {
    if (step_is_complete(store, s)) {
      ++result.steps_skipped;
    } else {
      todo.push_back(s);
    }
  }
  if (result.steps_skipped > 0) {
    spdlog::info("resuming: {} of {} steps already converted", result.steps_skipped,
                 last - first + 1);
  }
  return todo;
}

// The store's GEOMETRY file (a curvilinear grid's 2-D coordinates, the surface height) and
// geometry.bricks (a time-invariant
// vertical field), written before any step: GEOMETRY every run (a re-run finds the same
// bytes; other bytes are refused), geometry.bricks when it is absent (its store_id ties it
// to this plan; racing Slurm array tasks publish the same bytes or refuse other ones).
void write_geometry_files(const ingest::InputCatalog& catalog, const format::Manifest& plan,
                          const OctreeLayout& layout, const ConvertOptions& options) {
  if (!plan.geometry) return;
  ingest::SlabReader reader(catalog, options.scan);
  if (plan.geometry->surface || catalog.curvilinear) {
    format::GeometryFile file;
    file.store_id = plan.store_id;
    file.coordinates = curvilinear_coordinates(catalog);
    if (plan.geometry->surface) {
      std::vector<double> surface(plan.x.size() * plan.y.size());
      reader.read_surface(surface);
      file.coordinates.surface_m = std::move(surface);
    }
    write_geometry_file(options.store, file);
  }
  if (has_time_invariant_geometry(plan) &&
      !std::filesystem::exists(options.store / format::kGeometryBricksFileName)) {
    StepCounts c;
    publish_geometry_bricks(options.store, [&](const std::filesystem::path& candidate) {
      c = convert_geometry_bricks(plan, layout, reader, candidate);
    });
    spdlog::info("grid geometry: {} bricks ({} with data), {:.1f} MB", c.empty + c.constant + c.data,
                 c.data, static_cast<double>(c.file_bytes) / 1e6);
  }
}

void convert_steps(const ingest::InputCatalog& catalog, const format::Manifest& plan,
                   const OctreeLayout& layout, const ConvertOptions& options,
                   const std::vector<std::uint32_t>& todo, ConvertResult& result) {
  std::uint64_t bytes_per_step = 0;
  for (const auto& v : plan.variables) {
    bytes_per_step += plan.dims().count() * source_type_size(v.source_type);
  }
  const std::uint64_t total = bytes_per_step * todo.size();
  std::atomic<std::uint64_t> done{0};
  const ProgressFn progress = [&](std::uint64_t bytes) {
    done += bytes;
    if (options.progress) options.progress(done.load(), total);
  };

  ingest::SlabReader reader(catalog, options.scan);
  for (std::uint32_t s : todo) {
    const auto t0 = std::chrono::steady_clock::now();
    const StepCounts c =
        convert_step(plan, layout, reader, s, options.store / format::step_file_name(s), progress);
    const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    spdlog::debug("step {}: {:.1f} MB in, {:.1f} MB out, {:.2f} s", s, c.input_bytes / 1e6,
                  c.file_bytes / 1e6, secs);
    ++result.steps_converted;
    result.input_bytes += c.input_bytes;
    result.written_bytes += c.file_bytes;
    result.empty += c.empty;
    result.constant += c.constant;
    result.data += c.data;
    result.lossy += c.lossy;
    result.lossy_fallback += c.lossy_fallback;
  }
  result.direct_input_bytes = reader.direct_bytes();
}

}  // namespace

ConvertResult convert(const ConvertOptions& options) {
  const auto started = std::chrono::steady_clock::now();
  std::optional<tbb::global_control> limit;
  if (options.threads > 0) {
    limit.emplace(tbb::global_control::max_allowed_parallelism,
                  static_cast<std::size_t>(options.threads));
  }
  const ingest::InputCatalog catalog = ingest::scan_inputs(options.inputs, options.scan);
  std::vector<PredictorTrial> trials;
  format::Manifest plan = plan_store(catalog, options, &trials);
  const OctreeLayout layout(plan.dims(), plan.brick);
  const auto steps = static_cast<std::uint32_t>(plan.time.values.size());
  const std::uint32_t first = options.only_first.value_or(0);
  const std::uint32_t last = options.only_last.value_or(steps - 1);
  if (first > last || last >= steps) {
    throw make_error(ErrorCode::kInvalidArgument, "steps {}:{} are outside the store's 0:{}", first,
                     last, steps - 1);
  }

  std::filesystem::create_directories(options.store / "steps");
  ConvertResult result;
  report_codecs(plan, trials, result);
  if (auto existing = start_or_match_manifest(options.store, plan)) {
    spdlog::info("{} is already complete; nothing to do", options.store.string());
    result.steps_skipped = last - first + 1;
    result.finalized = true;
    result.summary = existing->summary;
    return result;
  }
  remove_stale_temporaries(options.store, first, last);
  write_geometry_files(catalog, plan, layout, options);

  const auto store = Store::open(options.store, StoreOpenOptions{.allow_incomplete = true});
  const std::vector<std::uint32_t> todo = steps_to_convert(*store, first, last, result);
  convert_steps(catalog, plan, layout, options, todo, result);
  if (format::has_lossy_codec(plan)) {
    const auto log = result.lossy_fallback > 0 ? spdlog::level::warn : spdlog::level::info;
    spdlog::log(log,
                "lossy: {} data bricks coded by zfp within the bound, {} kept lossless because "
                "zfp missed it",
                result.lossy, result.lossy_fallback);
  }
  result.seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();

  if (options.finalize) {
    bool all_present = true;
    for (std::uint32_t s = 0; s < steps && all_present; ++s) all_present = store->has_step(s);
    if (all_present) {
      result.summary = finalize_store(options.store);
      result.finalized = true;
    } else {
      spdlog::info("some steps are still missing; the store stays unfinalized");
    }
  }
  return result;
}

json finalize_store(const std::filesystem::path& dir) {
  const auto store = Store::open(dir, StoreOpenOptions{.allow_incomplete = true});
  format::Manifest m = store->manifest();
  if (m.complete) return m.summary;
  const OctreeLayout& layout = store->octree();
  std::vector<std::uint32_t> missing;
  for (std::uint32_t s = 0; s < store->step_count(); ++s) {
    if (!store->has_step(s)) missing.push_back(s);
  }
  if (!missing.empty()) {
    throw make_error(ErrorCode::kNotFound, "{}: cannot finalize: {} time steps not converted (first: {})",
                     dir.string(), missing.size(), missing.front());
  }
  std::uint64_t input_bytes = 0, store_bytes = 0, level0_chunks = 0, coarse_chunks = 0;
  json per_variable = json::object();
  for (std::uint32_t v = 0; v < store->variable_count(); ++v) {
    std::uint64_t counts[3] = {0, 0, 0}, chunk_bytes = 0;
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (std::uint32_t s = 0; s < store->step_count(); ++s) {
      const auto entries = store->index(s, v);
      // The root's exact range covers the whole step.
      if (const auto& root = entries[layout.root()]; root.has_valid_data()) {
        lo = std::min(lo, root.min);
        hi = std::max(hi, root.max);
      }
      for (NodeId n = 0; n < entries.size(); ++n) {
        const auto& e = entries[n];
        ++counts[static_cast<int>(e.kind)];
        chunk_bytes += e.chunk_size;
        (n < layout.level(0).node_count() ? level0_chunks : coarse_chunks) += e.chunk_size;
      }
    }
    const std::uint64_t raw = m.dims().count() * dtype_size(m.variables[v].dtype) * store->step_count();
    input_bytes += m.dims().count() * source_type_size(m.variables[v].source_type) * store->step_count();
    per_variable[m.variables[v].name] = json{
        {"raw_bytes", raw},
        {"chunk_bytes", chunk_bytes},
        {"ratio", chunk_bytes ? double(raw) / double(chunk_bytes) : 0.0},
        {"bricks", {{"empty", counts[0]}, {"constant", counts[1]}, {"data", counts[2]}}}};
    // The exact range of the valid data over all steps (null when nothing is valid):
    // what a viewer offers as the limits' range without reading the index.
    per_variable[m.variables[v].name]["min"] = lo <= hi ? json(lo) : json(nullptr);
    per_variable[m.variables[v].name]["max"] = lo <= hi ? json(hi) : json(nullptr);
  }
  for (std::uint32_t s = 0; s < store->step_count(); ++s) {
    const auto path = store->step_path(s);
    const auto size = std::filesystem::file_size(path);
    store_bytes += size;
    ReadOnlyFile file(path);
    std::vector<std::byte> footer(format::kStepFooterSize);
    file.read_at(size - footer.size(), footer);
    m.steps.push_back(format::StepRecord{s, format::step_file_name(s), size,
                                         checksum64(std::span(footer).first(48))});
  }
  m.summary = json{
      {"input_bytes", input_bytes},
      {"store_bytes", store_bytes},
      {"ratio", store_bytes ? double(input_bytes) / double(store_bytes) : 0.0},
      {"nodes_per_step", layout.node_count()},
      {"levels", layout.level_count()},
      {"octree_sample_overhead_percent", layout.overhead_fraction() * 100.0},
      {"octree_stored_overhead_percent",
       level0_chunks ? 100.0 * double(coarse_chunks) / double(level0_chunks) : 0.0},
      {"variables", per_variable},
  };
  m.complete = true;
  write_file_atomically(dir / "MANIFEST", format::encode_manifest(m));
  return m.summary;
}

}  // namespace strielad::build
