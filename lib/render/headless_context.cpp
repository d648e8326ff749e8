// SPDX-License-Identifier: Apache-2.0
#include "render/headless_context.h"

#include <epoxy/egl.h>
#include <epoxy/gl.h>

#include <fmt/format.h>

#include "core/error.h"

namespace strielad::render {

struct HeadlessContext::State {
  EGLDisplay display = EGL_NO_DISPLAY;
  EGLContext context = EGL_NO_CONTEXT;
};

namespace {

EGLDisplay open_display() {
  if (epoxy_has_egl_extension(EGL_NO_DISPLAY, "EGL_MESA_platform_surfaceless") &&
      epoxy_has_egl_extension(EGL_NO_DISPLAY, "EGL_EXT_platform_base")) {
    EGLDisplay display =
        eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    if (display != EGL_NO_DISPLAY && eglInitialize(display, nullptr, nullptr)) return display;
  }
  EGLDisplay display = eglGetDisplay(EGL_DEFAULT_DISPLAY);
  if (display != EGL_NO_DISPLAY && eglInitialize(display, nullptr, nullptr)) return display;
  return EGL_NO_DISPLAY;
}

}  // namespace

std::unique_ptr<HeadlessContext> HeadlessContext::create() {
  auto context = std::unique_ptr<HeadlessContext>(new HeadlessContext());
  context->state_ = std::make_unique<State>();
  State& s = *context->state_;
  s.display = open_display();
  if (s.display == EGL_NO_DISPLAY) {
    throw make_error(ErrorCode::kUnsupported,
                     "headless OpenGL: no EGL display (install Mesa's EGL: libegl-mesa0)");
  }
  if (!eglBindAPI(EGL_OPENGL_API)) {
    throw make_error(ErrorCode::kUnsupported, "headless OpenGL: EGL cannot bind OpenGL");
  }
  const EGLint config_attributes[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
  EGLConfig config = nullptr;
  EGLint configs = 0;
  // Surfaceless contexts need no config; with KHR_no_config_context pass none.
  const bool no_config = epoxy_has_egl_extension(s.display, "EGL_KHR_no_config_context");
  if (!no_config && (!eglChooseConfig(s.display, config_attributes, &config, 1, &configs) ||
                     configs == 0)) {
    throw make_error(ErrorCode::kUnsupported, "headless OpenGL: no EGL config for OpenGL");
  }
  const EGLint context_attributes[] = {EGL_CONTEXT_MAJOR_VERSION, 4,
                                       EGL_CONTEXT_MINOR_VERSION, 5,
                                       EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                       EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
  s.context = eglCreateContext(s.display, no_config ? EGL_NO_CONFIG_KHR : config,
                               EGL_NO_CONTEXT, context_attributes);
  if (s.context == EGL_NO_CONTEXT) {
    throw make_error(ErrorCode::kUnsupported,
                     "headless OpenGL: no OpenGL 4.5 core context (EGL error {:#x})",
                     eglGetError());
  }
  context->make_current();
  return context;
}

HeadlessContext::~HeadlessContext() {
  if (!state_) return;
  if (state_->display != EGL_NO_DISPLAY) {
    eglMakeCurrent(state_->display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    if (state_->context != EGL_NO_CONTEXT) eglDestroyContext(state_->display, state_->context);
    eglTerminate(state_->display);
  }
}

void HeadlessContext::make_current() {
  if (!eglMakeCurrent(state_->display, EGL_NO_SURFACE, EGL_NO_SURFACE, state_->context)) {
    throw make_error(ErrorCode::kUnsupported,
                     "headless OpenGL: cannot make the context current (EGL error {:#x})",
                     eglGetError());
  }
}

std::string HeadlessContext::description() const { return current_gl_description(); }

std::string current_gl_description() {
  const auto* version = reinterpret_cast<const char*>(glGetString(GL_VERSION));
  const auto* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  return fmt::format("OpenGL {} / {}", version ? version : "?", renderer ? renderer : "?");
}

}  // namespace strielad::render
