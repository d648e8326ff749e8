// SPDX-License-Identifier: Apache-2.0
// What strielad-view chose by itself, logged at start (docs/view.md, "Defaults for any
// domain"): the scene when no --scene is given (its canonical JSON, formats/scene.md, so
// that it can be saved, edited and given back with --scene), the vertical exaggeration
// and the rule that gave it, and how the sun is placed.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "scene/scene.h"

namespace strielad::view {

struct ViewChoices {
  std::optional<Scene> default_scene;  // set when the viewer picked the scene
  std::string exaggeration;            // "10 for a 700 x 778 km domain ..." or "25 (--exaggeration)"
  std::string sun;                     // view::describe_sun, or the fixed light's origin
};

// The log lines, in order: "default scene (no --scene): {...}" (only with a default
// scene), "vertical exaggeration ...", "sun: ...".
// \error as scene_to_json for an invalid default scene.
std::vector<std::string> view_choice_lines(const ViewChoices& choices);

// Logs view_choice_lines at level info.
void log_view_choices(const ViewChoices& choices);

}  // namespace strielad::view
