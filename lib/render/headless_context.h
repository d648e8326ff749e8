// SPDX-License-Identifier: Apache-2.0
// An OpenGL 4.5 core context without a window, through EGL: the Mesa surfaceless
// platform first (no X server, no GPU needed: llvmpipe), else the default EGL display.
// Rendering goes to framebuffer objects. Used by strielad-view --offscreen, the view
// benchmark and the render tests.
#pragma once

#include <memory>
#include <string>

namespace strielad::render {

class HeadlessContext {
 public:
  // Creates the context and makes it current on the calling thread.
  // \error kUnsupported saying which EGL step failed (no EGL display, no OpenGL 4.3+
  // core context).
  static std::unique_ptr<HeadlessContext> create();
  ~HeadlessContext();
  HeadlessContext(const HeadlessContext&) = delete;
  HeadlessContext& operator=(const HeadlessContext&) = delete;

  void make_current();
  // "OpenGL 4.5 (Core Profile) Mesa 22.3.6 / llvmpipe (LLVM 15.0.6, 256 bits)".
  std::string description() const;

 private:
  HeadlessContext() = default;
  struct State;
  std::unique_ptr<State> state_;
};

// The GL_VERSION / GL_RENDERER strings of the current context.
std::string current_gl_description();

}  // namespace strielad::render
