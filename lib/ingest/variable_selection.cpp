// SPDX-License-Identifier: Apache-2.0
#include "ingest/variable_selection.h"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <set>

#include "core/error.h"
#include "ingest/grid_compare.h"

namespace strielad::ingest {
namespace {

std::string files_text(const std::vector<ScannedFile>& files) {
  if (files.size() == 1) return files.front().source.path;
  return fmt::format("any of the {} input files ({} ...)", files.size(),
                     files.front().source.path);
}

std::vector<std::string> available_variables(const std::vector<ScannedFile>& files) {
  std::vector<std::string> names;
  std::set<std::string> seen;
  for (const auto& f : files) {
    for (const auto& v : f.variables) {
      if (v.auxiliary) continue;
      if (seen.insert(v.name).second) names.push_back(v.name);
    }
  }
  return names;
}

std::string normalized(std::string name) {
  while (!name.empty() && name.front() == '/') name.erase(name.begin());
  return name;
}

std::vector<std::string> select_requested(const std::vector<ScannedFile>& files,
                                          const std::vector<std::string>& requested) {
  std::vector<std::string> out;
  std::set<std::string> seen;
  for (const auto& raw : requested) {
    std::string name = normalized(raw);
    if (name.empty()) {
      throw make_error(ErrorCode::kInvalidArgument, "empty variable name requested");
    }
    if (!seen.insert(name).second) {
      throw make_error(ErrorCode::kInvalidArgument, "variable '{}' is requested twice", name);
    }
    bool found = false;
    for (const auto& f : files) found = found || f.find(name) != nullptr;
    if (!found) {
      const auto available = available_variables(files);
      throw make_error(ErrorCode::kNotFound,
                       "variable '{}' not found in {}; available variables: {}", name,
                       files_text(files),
                       available.empty() ? std::string("(none)") : fmt::format("{}", fmt::join(available, ", ")));
    }
    out.push_back(std::move(name));
  }
  return out;
}

std::vector<std::string> select_default(const std::vector<ScannedFile>& files,
                                        const std::vector<std::string>& geometry_sources) {
  std::vector<std::string> out;
  std::set<std::string> selected, skipped, logged;
  const ScannedVariable* reference = nullptr;
  const ScannedFile* reference_file = nullptr;
  std::optional<Error> first_invalid, first_unstructured;

  for (const auto& f : files) {
    for (const auto& v : f.variables) {
      if (selected.count(v.name) || skipped.count(v.name)) continue;
      if (v.auxiliary) {
        if (logged.insert(v.name).second) {
          spdlog::debug("{}: '{}' is a coordinate or auxiliary variable: not converted",
                        f.source.path, v.name);
        }
        continue;
      }
      if (std::find(geometry_sources.begin(), geometry_sources.end(), v.name) !=
          geometry_sources.end()) {
        if (logged.insert(v.name).second) {
          spdlog::info("{}: '{}' places the levels (the grid geometry): not converted as data "
                       "(name it in --vars to convert it too)",
                       f.source.path, v.name);
        }
        continue;
      }
      switch (v.klass) {
        case VariableClass::kGrid3D:
          if (!v.not_by_default.empty()) {
            if (logged.insert(v.name).second) {
              spdlog::info("{}: '{}' {} (name it in --vars to convert it too)", f.source.path,
                           v.name, v.not_by_default);
            }
            continue;
          }
          if (reference == nullptr) {
            reference = &v;
            reference_file = &f;
          } else if (auto d = grid_difference(v.x, v.y, v.z, reference->x, reference->y,
                                              reference->z,
                                              fmt::format("variable '{}'", reference->name))) {
            spdlog::info("{}: skipping variable '{}': it is not on the grid of variable '{}' "
                         "({}): {}",
                         f.source.path, v.name, reference->name, reference_file->source.path,
                         *d);
            skipped.insert(v.name);
            continue;
          }
          selected.insert(v.name);
          out.push_back(v.name);
          break;
        case VariableClass::kNotGridded:
          if (logged.insert(v.name).second) spdlog::info("skipping: {}", v.problem->what());
          break;
        case VariableClass::kUnstructured:
          if (!first_unstructured) first_unstructured = v.problem;
          if (logged.insert(v.name).second) spdlog::warn("skipping: {}", v.problem->what());
          break;
        case VariableClass::kInvalid:
          if (!first_invalid) first_invalid = v.problem;
          if (logged.insert(v.name).second) spdlog::warn("skipping: {}", v.problem->what());
          break;
      }
    }
  }
  if (out.empty()) {
    if (first_invalid) throw *first_invalid;
    if (first_unstructured) throw *first_unstructured;
    const auto available = available_variables(files);
    throw make_error(ErrorCode::kNotFound,
                     "no 3D variable (vertical, lat, lon, optionally with time) found in {}; "
                     "variables: {}",
                     files_text(files),
                     available.empty() ? std::string("(none)") : fmt::format("{}", fmt::join(available, ", ")));
  }
  return out;
}

}  // namespace

std::vector<std::string> select_variables(const std::vector<ScannedFile>& files,
                                          const std::vector<std::string>& requested,
                                          const std::vector<std::string>& geometry_sources) {
  return requested.empty() ? select_default(files, geometry_sources)
                           : select_requested(files, requested);
}

}  // namespace strielad::ingest
