// SPDX-License-Identifier: Apache-2.0
// What every strielad-view run starts with: the server (in-process for a local store, or
// remote), the link thread, the first scene, and the user's shader text.
#pragma once

#include <memory>
#include <string>
#include <utility>

#include "scene/scene.h"
#include "serve/server.h"
#include "view/view_link.h"
#include "viewer_args.h"

namespace strielad::view_cmd {

struct ViewerSession {
  std::unique_ptr<serve::Server> server;  // in-process only; destroyed after the link
  std::unique_ptr<view::ViewLink> link;
  std::string dataset_name;
  Scene scene;
  std::string shader_name;   // the file, or "built-in clouds.glsl"
  std::string shader_source; // empty: the built-in one
};

// \error kNotFound / kInvalidInput naming the store, scene or shader file at fault;
// kIo when the server cannot be reached.
ViewerSession open_session(const ViewerArgs& args);

// The shader file's text. \error kNotFound / kIo naming the file.
std::string read_text_file(const std::string& path);

}  // namespace strielad::view_cmd
