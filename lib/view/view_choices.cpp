// SPDX-License-Identifier: Apache-2.0
#include "view/view_choices.h"

#include <spdlog/spdlog.h>

namespace strielad::view {

std::vector<std::string> view_choice_lines(const ViewChoices& choices) {
  std::vector<std::string> lines;
  if (choices.default_scene) {
    lines.push_back("default scene (no --scene): " + scene_to_json(*choices.default_scene));
  }
  lines.push_back("vertical exaggeration " + choices.exaggeration);
  lines.push_back("sun: " + choices.sun);
  return lines;
}

void log_view_choices(const ViewChoices& choices) {
  for (const auto& line : view_choice_lines(choices)) spdlog::info("{}", line);
}

}  // namespace strielad::view
