// SPDX-License-Identifier: Apache-2.0
#include "render/shader_program.h"

#include <fmt/format.h>

#include <regex>
#include <sstream>

#include "core/error.h"

namespace strielad::render {
namespace {

std::string stage_name(GLenum stage) {
  switch (stage) {
    case GL_VERTEX_SHADER: return "vertex shader";
    case GL_FRAGMENT_SHADER: return "fragment shader";
    case GL_GEOMETRY_SHADER: return "geometry shader";
    case GL_COMPUTE_SHADER: return "compute shader";
    default: return "shader";
  }
}

// The info log of a shader (glGetShaderiv/glGetShaderInfoLog) or a program
// (glGetProgramiv/glGetProgramInfoLog).
template <typename GetIv, typename GetLog>
std::string info_log(GLuint object, GetIv get_iv, GetLog get_log) {
  GLint length = 0;
  get_iv(object, GL_INFO_LOG_LENGTH, &length);
  std::string log(static_cast<std::size_t>(std::max(length, 1)), '\0');
  get_log(object, length, nullptr, log.data());
  log.resize(log.find('\0') == std::string::npos ? log.size() : log.find('\0'));
  return log;
}

}  // namespace

std::string CompileResult::first_error() const {
  for (const auto& d : diagnostics) {
    if (d.message.find("error") != std::string::npos) return d.message;
  }
  return diagnostics.empty() ? std::string() : diagnostics.front().message;
}

std::vector<ShaderDiagnostic> parse_info_log(const std::string& log, const std::string& user_name,
                                             const std::string& builtin_name) {
  static const std::regex mesa(R"(^\s*(\d+):(\d+)\((\d+)\):\s*(.*)$)");
  static const std::regex nvidia(R"(^\s*(\d+)\((\d+)\)\s*:\s*(.*)$)");
  std::vector<ShaderDiagnostic> out;
  std::istringstream lines(log);
  std::string line;
  while (std::getline(lines, line)) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.find_first_not_of(" \t") == std::string::npos) continue;
    std::smatch m;
    int string_number = -1, line_number = 0, column = 0;
    std::string text;
    if (std::regex_match(line, m, mesa)) {
      string_number = std::stoi(m[1]);
      line_number = std::stoi(m[2]);
      column = std::stoi(m[3]);
      text = m[4];
    } else if (std::regex_match(line, m, nvidia)) {
      string_number = std::stoi(m[1]);
      line_number = std::stoi(m[2]);
      text = m[3];
    }
    ShaderDiagnostic d;
    if (line_number > kUserLineOffset) {
      // User code, whatever string the driver names (Mesa names string 0 for errors
      // found inside expressions).
      string_number = 1;
      line_number -= kUserLineOffset;
    }
    if (string_number == 1) {
      d.user_line = line_number;
      d.message = column > 0 ? fmt::format("{}:{}:{}: {}", user_name, line_number, column, text)
                             : fmt::format("{}:{}: {}", user_name, line_number, text);
    } else if (string_number == 0) {
      d.message = fmt::format("{}:{}: {}", builtin_name, line_number, text);
    } else {
      d.message = line;
    }
    out.push_back(std::move(d));
  }
  return out;
}

CompileResult compile_program(const std::vector<StageSource>& stages,
                              const std::string& user_name) {
  CompileResult result;
  GlProgram program(glCreateProgram());
  std::vector<GlShader> shaders;
  bool failed = false;
  for (const auto& stage : stages) {
    GlShader shader(glCreateShader(stage.stage));
    const std::string user =
        stage.user ? fmt::format("#line {} 1\n", kUserLineOffset + 1) + *stage.user + "\n"
                   : std::string();
    const char* sources[2] = {stage.builtin.c_str(), user.c_str()};
    glShaderSource(shader.get(), stage.user ? 2 : 1, sources, nullptr);
    glCompileShader(shader.get());
    GLint status = GL_FALSE;
    glGetShaderiv(shader.get(), GL_COMPILE_STATUS, &status);
    auto diagnostics = parse_info_log(info_log(shader.get(), glGetShaderiv, glGetShaderInfoLog), user_name,
                                      "built-in " + stage_name(stage.stage));
    result.diagnostics.insert(result.diagnostics.end(), diagnostics.begin(), diagnostics.end());
    if (status != GL_TRUE) {
      failed = true;
      if (diagnostics.empty()) {
        result.diagnostics.push_back({stage_name(stage.stage) + ": compilation failed", 0});
      }
      continue;
    }
    glAttachShader(program.get(), shader.get());
    shaders.push_back(std::move(shader));
  }
  if (failed) return result;
  glLinkProgram(program.get());
  GLint linked = GL_FALSE;
  glGetProgramiv(program.get(), GL_LINK_STATUS, &linked);
  if (linked != GL_TRUE) {
    auto diagnostics = parse_info_log(info_log(program.get(), glGetProgramiv, glGetProgramInfoLog), user_name, "link");
    if (diagnostics.empty()) diagnostics.push_back({"linking failed", 0});
    for (auto& d : diagnostics) d.message = "link: " + d.message;
    result.diagnostics.insert(result.diagnostics.end(), diagnostics.begin(), diagnostics.end());
    return result;
  }
  for (const auto& shader : shaders) glDetachShader(program.get(), shader.get());
  result.program = std::move(program);
  return result;
}

GlProgram compile_builtin_program(const std::string& vertex, const std::string& fragment,
                                  std::string_view what) {
  auto result = compile_program({{GL_VERTEX_SHADER, vertex, std::nullopt},
                                 {GL_FRAGMENT_SHADER, fragment, std::nullopt}},
                                "built-in");
  if (!result.ok()) {
    throw make_error(ErrorCode::kInternal, "{} program: {}", what, result.first_error());
  }
  return std::move(result.program);
}

}  // namespace strielad::render
