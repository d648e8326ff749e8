// SPDX-License-Identifier: Apache-2.0
// Compiling and linking GLSL programs whose stages are a built-in part followed by
// user code, with compiler messages pointing at the user's file and line.
//
// Each stage's source is two GLSL source strings: the built-in part (source string 0)
// and, when a stage includes user code, "#line 100001 1" and the user's text (source
// string 1). Compiler logs name a position as "string:line": Mesa writes
// "1:100012(5): error: ...", NVIDIA "1(100012) : error ...". Mesa 22.3 names string 0
// for errors found inside expressions, so user code is recognized by its line numbers
// (above kUserLineOffset) as well as by string 1: such positions are rewritten to
// "NAME:12:5:" (NAME is the user file), other positions to "built-in <stage>:LINE:".
#pragma once

#include <epoxy/gl.h>

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "render/gl_handles.h"

namespace strielad::render {

// User code is numbered from kUserLineOffset + 1 (the built-in parts are far shorter).
inline constexpr int kUserLineOffset = 100000;

struct StageSource {
  GLenum stage = GL_VERTEX_SHADER;
  std::string builtin;           // starts with #version
  std::optional<std::string> user;  // user code appended as source string 1
};

struct ShaderDiagnostic {
  std::string message;  // one line, e.g. "clouds.glsl:12:5: error: `foo' undeclared"
  int user_line = 0;    // line in the user's code, 0 when the message is not about it
};

struct CompileResult {
  GlProgram program;  // empty when compiling or linking failed
  std::vector<ShaderDiagnostic> diagnostics;  // errors (and warnings) in log order
  bool ok() const { return static_cast<bool>(program); }
  // The first error (or first diagnostic) as one line, empty when there is none.
  std::string first_error() const;
};

// Compiles every stage and links them. Never throws for bad GLSL: that is a result.
CompileResult compile_program(const std::vector<StageSource>& stages,
                              const std::string& user_name);

// A program of built-in vertex and fragment code only. Its GLSL failing to compile is a
// bug: throws kInternal, "WHAT program: first error".
GlProgram compile_builtin_program(const std::string& vertex, const std::string& fragment,
                                  std::string_view what);

// Splits a driver's info log into diagnostics, rewriting positions as described above
// (exposed for tests: driver logs differ).
std::vector<ShaderDiagnostic> parse_info_log(const std::string& log, const std::string& user_name,
                                             const std::string& builtin_name);

}  // namespace strielad::render
