// SPDX-License-Identifier: Apache-2.0
#include "store/store_info.h"

#include <fmt/ostream.h>

#include <cmath>

namespace strielad {
namespace {

bool is_uniform(const Axis& a) {
  if (a.size() < 3) return true;
  const double d = a.values[1] - a.values[0];
  for (std::size_t i = 2; i < a.size(); ++i) {
    if (std::abs((a.values[i] - a.values[i - 1]) - d) > 1e-9 * std::abs(d) + 1e-12) return false;
  }
  return true;
}

std::uint64_t step_files_bytes(const Store& store) {
  std::uint64_t total = 0;
  for (std::uint32_t s = 0; s < store.step_count(); ++s) {
    if (store.has_step(s)) total += std::filesystem::file_size(store.step_path(s));
  }
  return total;
}

}  // namespace

void describe_store(const Store& store, std::ostream& out) {
  const auto& m = store.manifest();
  const auto& layout = store.octree();
  fmt::print(out, "store      {}\n", store.path().string());
  fmt::print(out, "state      {} (written by strielad {})\n", m.complete ? "complete" : "converting",
             m.tool_version);
  fmt::print(out, "store id   {:016x}\n", m.store_id);
  fmt::print(out, "grid       {} x {} x {} samples\n", m.x.size(), m.y.size(), m.z.size());
  for (const Axis* a : {&m.x, &m.y, &m.z}) {
    fmt::print(out, "  {:<9}{} ({}, {}): {} .. {}, {}, {}\n", a->name, a->size(),
               axis_kind_name(a->kind), a->units.empty() ? "no units" : a->units,
               a->values.front(), a->values.back(), a->descending() ? "descending" : "ascending",
               is_uniform(*a) ? "uniform" : "non-uniform");
  }
  std::size_t present = 0;
  for (std::uint32_t s = 0; s < store.step_count(); ++s) present += store.has_step(s);
  fmt::print(out, "time       {} steps ({} converted): {} .. {} {}{}\n", m.time.size(), present,
             m.time.values.front(), m.time.values.back(), m.time.units,
             m.time.calendar.empty() ? "" : " (" + m.time.calendar + ")");
  fmt::print(out, "variables  {}\n", m.variables.size());
  for (std::size_t i = 0; i < m.variables.size(); ++i) {
    const auto& v = m.variables[i];
    fmt::print(out, "  {:<9}{:<8} {:<12} {:<9} {}\n", v.name, dtype_name(v.dtype),
               v.units.empty() ? "-" : v.units, m.codec_of(i).predictor, v.long_name);
  }
  fmt::print(out, "octree     brick {}, {} levels, {} nodes per step, {:.1f}% sample overhead\n",
             m.brick, layout.level_count(), layout.node_count(),
             layout.overhead_fraction() * 100);
  for (std::size_t l = 0; l < layout.level_count(); ++l) {
    const auto& s = layout.level(l);
    fmt::print(out, "  level {}  {} x {} x {} nodes, stride {} x {} x {}\n", l, s.nodes[0],
               s.nodes[1], s.nodes[2], s.stride[0], s.stride[1], s.stride[2]);
  }
  const auto fpzip_text = [](const format::CodecSpec& c) {
    return c.fpzip ? std::string(", fpzip where it pays") : std::string();
  };
  fmt::print(out, "codec      blosc {} level {} shuffle {}, predictor {}{} (format version {})\n",
             m.codec.name, m.codec.level, m.codec.shuffle, m.codec.predictor, fpzip_text(m.codec),
             m.format_version);
  for (const auto& v : m.variables) {
    if (!v.codec) continue;
    fmt::print(out, "  {:<9}blosc {} level {} shuffle {}, predictor {}{}\n", v.name, v.codec->name,
               v.codec->level, v.codec->shuffle, v.codec->predictor, fpzip_text(*v.codec));
  }
  fmt::print(out, "sources    {} files\n", m.sources.size());
  fmt::print(out, "size       {:.1f} MB of step files\n", step_files_bytes(store) / 1e6);
  if (m.complete && m.summary.contains("ratio")) {
    fmt::print(out, "ratio      {:.2f} (input {:.1f} MB)\n", m.summary["ratio"].get<double>(),
               m.summary["input_bytes"].get<double>() / 1e6);
  }
}

nlohmann::json store_info_json(const Store& store) {
  nlohmann::json j = format::manifest_to_json(store.manifest());
  nlohmann::json present = nlohmann::json::array();
  for (std::uint32_t s = 0; s < store.step_count(); ++s) {
    if (store.has_step(s)) present.push_back(s);
  }
  j["converted_steps"] = present;
  j["step_files_bytes"] = step_files_bytes(store);
  j["octree"]["sample_overhead_percent"] = store.octree().overhead_fraction() * 100;
  return j;
}

}  // namespace strielad
