// SPDX-License-Identifier: Apache-2.0
#include "bench/targets.h"

namespace strielad::bench {

Table targets_table(std::string title, const std::vector<Target>& targets,
                    std::vector<std::string> notes) {
  Table t{"targets", std::move(title), {"target", "measured", "met"}, {}, std::move(notes)};
  for (const auto& g : targets) {
    t.add({g.name, g.measured, g.evaluated ? (g.met ? "yes" : "NO") : "not measured"});
  }
  return t;
}

nlohmann::json targets_json(const std::vector<Target>& targets) {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& t : targets) {
    out.push_back({{"name", t.name}, {"measured", t.measured}, {"met", t.met}, {"evaluated", t.evaluated}});
  }
  return out;
}

}  // namespace strielad::bench
