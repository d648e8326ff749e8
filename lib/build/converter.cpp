// SPDX-License-Identifier: Apache-2.0
#include "build/converter.h"

#include <spdlog/spdlog.h>
#include <tbb/global_control.h>

#include <atomic>
#include <chrono>

#include "build/step_converter.h"
#include "core/checksum.h"
#include "core/error.h"
#include "core/file_io.h"
#include "core/version.h"
#include "octree/octree_layout.h"
#include "store/store.h"

namespace strielad::build {
namespace {

using nlohmann::json;

// Names the first top-level part of the plan that differs, for the refusal message.
std::string plan_difference(const format::Manifest& a, const format::Manifest& b) {
  const json pa = format::manifest_plan_json(a), pb = format::manifest_plan_json(b);
  for (const auto& [key, value] : pa.items()) {
    if (!pb.contains(key) || pb[key] != value) return key;
  }
  return "unknown";
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
              {"written_bytes", written_bytes},
              {"bricks", {{"empty", empty}, {"constant", constant}, {"data", data}}},
              {"seconds", seconds},
              {"input_mb_per_s", seconds > 0 ? double(input_bytes) / 1e6 / seconds : 0.0},
              {"finalized", finalized},
              {"summary", summary}};
}

format::Manifest plan_store(const ingest::InputCatalog& catalog, const ConvertOptions& options) {
  format::validate_codec(options.codec);
  format::Manifest m;
  m.tool_version = kToolVersion;
  m.x = catalog.x;
  m.y = catalog.y;
  m.z = catalog.z;
  m.time = catalog.time;
  for (const auto& v : catalog.variables) {
    m.variables.push_back(format::StoreVariable{v.name, v.units, v.long_name, v.standard_name,
                                                v.store_type, v.source_type, v.fill_value,
                                                v.missing_value, v.valid_min, v.valid_max,
                                                v.scale_factor, v.add_offset});
  }
  m.brick = options.brick;
  m.codec = options.codec;
  m.nan_as_fill = options.scan.nan_as_fill;
  for (const auto& f : catalog.files) {
    m.sources.push_back(format::SourceRecord{f.path, f.size, f.header_checksum});
  }
  const OctreeLayout layout(m.dims(), m.brick);  // validates dims and brick
  m.store_id = format::compute_store_id(m);
  return m;
}

ConvertResult convert(const ConvertOptions& options) {
  const auto started = std::chrono::steady_clock::now();
  std::optional<tbb::global_control> limit;
  if (options.threads > 0) {
    limit.emplace(tbb::global_control::max_allowed_parallelism,
                  static_cast<std::size_t>(options.threads));
  }
  const ingest::InputCatalog catalog = ingest::scan_inputs(options.inputs, options.scan);
  format::Manifest plan = plan_store(catalog, options);
  const OctreeLayout layout(plan.dims(), plan.brick);
  const auto steps = static_cast<std::uint32_t>(plan.time.values.size());
  const std::uint32_t first = options.only_first.value_or(0);
  const std::uint32_t last = options.only_last.value_or(steps - 1);
  if (first > last || last >= steps) {
    throw make_error(ErrorCode::kInvalidArgument, "steps {}:{} are outside the store's 0:{}", first,
                     last, steps - 1);
  }

  std::filesystem::create_directories(options.store / "steps");
  const auto manifest_path = options.store / "MANIFEST";
  ConvertResult result;
  if (std::filesystem::exists(manifest_path)) {
    const format::Manifest existing =
        format::decode_manifest(read_file_bytes(manifest_path), manifest_path.string());
    if (existing.store_id != plan.store_id) {
      throw make_error(ErrorCode::kAlreadyExists,
                       "{}: the store was started from different inputs or options (its '{}' "
                       "differs); convert into a new directory or delete it",
                       options.store.string(), plan_difference(existing, plan));
    }
    if (existing.complete) {
      spdlog::info("{} is already complete; nothing to do", options.store.string());
      result.steps_skipped = last - first + 1;
      result.finalized = true;
      result.summary = existing.summary;
      return result;
    }
  } else {
    write_file_atomically(manifest_path, format::encode_manifest(plan));
  }
  remove_stale_temporaries(options.store, first, last);

  const auto store = Store::open(options.store, StoreOpenOptions{.allow_incomplete = true});
  std::vector<std::uint32_t> todo;
  for (std::uint32_t s = first; s <= last; ++s) {
    if (step_is_complete(*store, s)) {
      ++result.steps_skipped;
    } else {
      todo.push_back(s);
    }
  }
  if (result.steps_skipped > 0) {
    spdlog::info("resuming: {} of {} steps already converted", result.steps_skipped,
                 last - first + 1);
  }
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
    for (std::uint32_t s = 0; s < store->step_count(); ++s) {
      const auto entries = store->index(s, v);
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
