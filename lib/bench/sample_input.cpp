// SPDX-License-Identifier: Apache-2.0
#include "bench/sample_input.h"

#include <fmt/ranges.h>
#include <nlohmann/json.hpp>
#include <spdlog/spdlog.h>

#include <fstream>

#include "bench/stopwatch.h"
#include "convert/converter.h"
#include "core/error.h"
#include "bench/table_writer.h"
#include "synthetic/sample_dataset.h"

namespace strielad::bench {
namespace {

constexpr const char* kStampName = "bench-input.json";

nlohmann::json stamp_of(const SampleInputSpec& spec, const synthetic::SampleResult* result) {
  nlohmann::json j = {{"dims", {spec.dims.x, spec.dims.y, spec.dims.z}},
                      {"steps", spec.steps},
                      {"variables", spec.variables},
                      {"seed", spec.seed}};
  if (result) {
    nlohmann::json files = nlohmann::json::array();
    for (const auto& f : result->files) {
      files.push_back({{"name", f.path.filename().string()}, {"bytes", f.bytes}});
    }
    j["files"] = files;
  }
  return j;
}

// The files of an earlier run when its stamp matches and every file has its size.
std::optional<SampleInput> reusable(const SampleInputSpec& spec, const std::filesystem::path& dir) {
  std::ifstream in(dir / kStampName);
  if (!in) return std::nullopt;
  nlohmann::json stamp;
  try {
    stamp = nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception&) {
    return std::nullopt;
  }
  nlohmann::json expected = stamp_of(spec, nullptr);
  for (const auto& [key, value] : expected.items()) {
    if (!stamp.contains(key) || stamp[key] != value) return std::nullopt;
  }
  if (!stamp.contains("files")) return std::nullopt;
  SampleInput input;
  input.reused = true;
  for (const auto& f : stamp["files"]) {
    const auto path = dir / f.at("name").get<std::string>();
    std::error_code ec;
    const auto size = std::filesystem::file_size(path, ec);
    if (ec || size != f.at("bytes").get<std::uint64_t>()) return std::nullopt;
    input.files.push_back(path);
    input.bytes += size;
  }
  return input;
}

}  // namespace

SampleInput ensure_sample_input(const SampleInputSpec& spec, const std::filesystem::path& dir) {
  if (auto input = reusable(spec, dir)) {
    spdlog::info("bench: reusing the sample input in {} ({:.1f} MB)", dir.string(),
                 static_cast<double>(input->bytes) / 1e6);
    return *input;
  }
  synthetic::SampleSpec s;
  s.dims = spec.dims;
  s.steps = spec.steps;
  s.seed = spec.seed;
  s.variables = spec.variables;
  s.file_per_step = true;
  s.deflate = 0;
  std::error_code ec;
  std::filesystem::remove(dir / kStampName, ec);
  spdlog::info("bench: generating the sample input {}x{}x{} x {} step(s), variables {} in {}",
               spec.dims.x, spec.dims.y, spec.dims.z, spec.steps, fmt::join(spec.variables, ","),
               dir.string());
  const Stopwatch clock;
  const synthetic::SampleResult result = synthetic::write_sample_dataset(s, dir);
  SampleInput input;
  input.generate_seconds = clock.seconds();
  for (const auto& f : result.files) {
    input.files.push_back(f.path);
    input.bytes += f.bytes;
  }
  write_text_file(dir / kStampName, stamp_of(spec, &result).dump(2) + "\n");
  spdlog::info("bench: generated {:.1f} MB in {:.1f} s", static_cast<double>(input.bytes) / 1e6,
               input.generate_seconds);
  return input;
}

void convert_sample_store(const SampleInput& input, const std::vector<std::string>& variables,
                          std::uint32_t brick, int threads, const std::filesystem::path& dir) {
  build::ConvertOptions co;
  co.inputs = input.files;
  co.store = dir;
  co.scan.variables = variables;
  co.brick = brick;
  co.threads = threads;
  try {
    build::convert(co);
  } catch (const Error& e) {
    spdlog::info("bench: starting {} over ({})", dir.string(), e.what());
    std::filesystem::remove_all(dir);
    build::convert(co);
  }
}

}  // namespace strielad::bench
