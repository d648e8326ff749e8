// SPDX-License-Identifier: Apache-2.0
// Errors in the user's colour and transparency shader: driver logs rewritten to point at
// the user's file and line (Mesa and NVIDIA formats), broken shaders refused with the
// file, line and message while the last good shader keeps rendering (checked pixel by
// pixel), and ATTR_<name> defines from the scene's attribute names.
#include <cmath>
#include <string>

#include "render/shader_program.h"
#include "render_fixture.h"

namespace strielad::testing {
namespace {

// --- parse_info_log: no context needed ---

TEST(ParseInfoLog, AMesaPositionInTheUserCodeNamesTheFileLineAndColumn) {
  const auto d = render::parse_info_log("1:12(5): error: `foo' undeclared\n", "clouds.glsl",
                                        "built-in fragment shader");
  ASSERT_EQ(d.size(), 1u);
  EXPECT_EQ(d[0].message, "clouds.glsl:12:5: error: `foo' undeclared");
  EXPECT_EQ(d[0].user_line, 12);
}

TEST(ParseInfoLog, AnNvidiaPositionInTheUserCodeNamesTheFileAndLine) {
  const auto d = render::parse_info_log("1(7) : error C0000: syntax error", "clouds.glsl",
                                        "built-in fragment shader");
  ASSERT_EQ(d.size(), 1u);
  EXPECT_EQ(d[0].message, "clouds.glsl:7: error C0000: syntax error");
  EXPECT_EQ(d[0].user_line, 7);
}

TEST(ParseInfoLog, APositionInTheBuiltInPartNamesTheBuiltInStage) {
  const auto mesa = render::parse_info_log("0:40(3): error: `x' undeclared", "clouds.glsl",
                                           "built-in fragment shader");
  ASSERT_EQ(mesa.size(), 1u);
  EXPECT_EQ(mesa[0].message, "built-in fragment shader:40: error: `x' undeclared");
  EXPECT_EQ(mesa[0].user_line, 0);
  const auto nvidia = render::parse_info_log("0(40) : error C1008: undefined variable", "clouds.glsl",
                                             "built-in vertex shader");
  ASSERT_EQ(nvidia.size(), 1u);
  EXPECT_EQ(nvidia[0].message, "built-in vertex shader:40: error C1008: undefined variable");
  EXPECT_EQ(nvidia[0].user_line, 0);
}

TEST(ParseInfoLog, AUserLineNumberMeansUserCodeWhateverTheStringNumber) {
  const auto d = render::parse_info_log("0:100003(12): error: `foo' undeclared", "clouds.glsl",
                                        "built-in fragment shader");
  ASSERT_EQ(d.size(), 1u);
  EXPECT_EQ(d[0].message, "clouds.glsl:3:12: error: `foo' undeclared");
  EXPECT_EQ(d[0].user_line, 3);
}

TEST(ParseInfoLog, EveryLineOfALogIsOneDiagnosticInOrder) {
  const auto d = render::parse_info_log(
      "1:3(9): warning: unused variable\r\n\n   \n1:4(2): error: syntax error\nlinker gave up\n",
      "a.glsl", "built-in fragment shader");
  ASSERT_EQ(d.size(), 3u);
  EXPECT_EQ(d[0].message, "a.glsl:3:9: warning: unused variable");
  EXPECT_EQ(d[0].user_line, 3);
  EXPECT_EQ(d[1].message, "a.glsl:4:2: error: syntax error");
  EXPECT_EQ(d[1].user_line, 4);
  // A line without a position is kept as it is.
  EXPECT_EQ(d[2].message, "linker gave up");
  EXPECT_EQ(d[2].user_line, 0);
}

// --- set_user_shader / set_scene_layout on a real context ---

// color() and alpha() around the given body lines, so that line numbers are known: the
// body starts on line 3.
std::string shader_with_body(const std::string& body) {
  return "vec4 color(int id, float attributes[MAX_ATTRIBUTES], vec3 normal, vec3 sun,\n"  // 1
         "           vec3 position, vec3 view, float time) {\n"                          // 2
         + body +                                                                         // 3..
         "}\n"
         "float alpha(int id, float distance) { return 1.0; }\n";
}

class UserShaderTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { context_ = render::HeadlessContext::create().release(); }
  static void TearDownTestSuite() {
    delete context_;
    context_ = nullptr;
  }
  void SetUp() override { renderer_ = std::make_unique<render::VolumeRenderer>(); }

  static inline render::HeadlessContext* context_ = nullptr;
  std::unique_ptr<render::VolumeRenderer> renderer_;
};

TEST_F(UserShaderTest, ASyntaxErrorIsReportedAtItsLineAndTheOldShaderStays) {
  const std::string good = shader_with_body("  return vec4(1, 0, 0, 1);\n");
  ASSERT_TRUE(renderer_->set_user_shader(good, "good.glsl").ok);

  const auto update = renderer_->set_user_shader(
      shader_with_body("  vec4 c = vec4(1, 0, 0, 1) + ;\n  return c;\n"), "broken.glsl");
  EXPECT_FALSE(update.ok);
  EXPECT_EQ(update.error_line, 3);
  EXPECT_NE(update.error.find("broken.glsl:3"), std::string::npos) << update.error;
  EXPECT_NE(update.error.find("error"), std::string::npos) << update.error;
  EXPECT_FALSE(update.diagnostics.empty());
  EXPECT_EQ(renderer_->user_shader_source(), good);
  EXPECT_EQ(renderer_->user_shader_name(), "good.glsl");
}

TEST_F(UserShaderTest, ACallOfAnUndefinedFunctionIsReported) {
  const std::string before = renderer_->user_shader_source();
  const std::string before_name = renderer_->user_shader_name();
  const auto update = renderer_->set_user_shader(
      shader_with_body("  float x = no_such_function(1.0);\n  return vec4(x);\n"), "undefined.glsl");
  EXPECT_FALSE(update.ok);
  EXPECT_NE(update.error.find("error"), std::string::npos) << update.error;
  EXPECT_NE(update.error.find("no_such_function"), std::string::npos) << update.error;
  EXPECT_EQ(renderer_->user_shader_source(), before);
  EXPECT_EQ(renderer_->user_shader_name(), before_name);
}

TEST_F(UserShaderTest, AnErrorInsideAnExpressionNamesTheUserFileAndLine) {
  // Mesa 22.3 reports errors found inside expressions (undeclared names, undefined
  // functions) in source string 0, e.g. "0:100003(12): error: ..."; the user's line
  // numbers, from 100001, still tell them apart (render/shader_program.h).
  const auto undefined = renderer_->set_user_shader(
      shader_with_body("  float x = no_such_function(1.0);\n  return vec4(x);\n"), "undefined.glsl");
  EXPECT_FALSE(undefined.ok);
  EXPECT_EQ(undefined.error_line, 3);
  EXPECT_NE(undefined.error.find("undefined.glsl:3"), std::string::npos) << undefined.error;
  const auto undeclared = renderer_->set_user_shader(
      shader_with_body("  float x = foo;\n  return vec4(x);\n"), "undeclared.glsl");
  EXPECT_FALSE(undeclared.ok);
  EXPECT_EQ(undeclared.error_line, 3);
  EXPECT_NE(undeclared.error.find("undeclared.glsl:3"), std::string::npos) << undeclared.error;
}

TEST_F(UserShaderTest, AShaderWithoutAlphaIsRefused) {
  const std::string before = renderer_->user_shader_source();
  const auto update = renderer_->set_user_shader(
      "vec4 color(int id, float attributes[MAX_ATTRIBUTES], vec3 normal, vec3 sun,\n"
      "           vec3 position, vec3 view, float time) { return vec4(1); }\n",
      "no_alpha.glsl");
  EXPECT_FALSE(update.ok);
  EXPECT_NE(update.error.find("alpha"), std::string::npos) << update.error;
  EXPECT_EQ(renderer_->user_shader_source(), before);
}

TEST_F(UserShaderTest, AValidShaderIsAcceptedAndBecomesCurrent) {
  const std::string source = shader_with_body("  return vec4(normal * 0.5 + 0.5, 1.0);\n");
  ASSERT_NE(renderer_->user_shader_source(), source);
  const auto update = renderer_->set_user_shader(source, "normals.glsl");
  EXPECT_TRUE(update.ok) << update.error;
  EXPECT_TRUE(update.error.empty()) << update.error;
  EXPECT_EQ(update.error_line, 0);
  EXPECT_EQ(renderer_->user_shader_source(), source);
  EXPECT_EQ(renderer_->user_shader_name(), "normals.glsl");
}

TEST_F(UserShaderTest, AttributeNamesDefineAttrMacros) {
  const std::string uses_ta = shader_with_body("  return vec4(attributes[ATTR_ta], 0, 0, 1);\n");
  EXPECT_FALSE(renderer_->set_user_shader(uses_ta, "ta.glsl").ok) << "no attribute named ta yet";
  ASSERT_TRUE(renderer_->set_scene_layout({1}, {"qc", "ta"}).ok);
  const auto update = renderer_->set_user_shader(uses_ta, "ta.glsl");
  EXPECT_TRUE(update.ok) << update.error;
  EXPECT_EQ(renderer_->user_shader_name(), "ta.glsl");
}

TEST_F(UserShaderTest, AttrMacrosGiveTheAttributePosition) {
  ASSERT_TRUE(renderer_->set_scene_layout({1}, {"qc", "ta"}).ok);
  const std::string checks_index = shader_with_body(
      "#if ATTR_qc != 0 || ATTR_ta != 1\n"
      "#error wrong attribute index\n"
      "#endif\n"
      "  return vec4(1);\n");
  const auto update = renderer_->set_user_shader(checks_index, "index.glsl");
  EXPECT_TRUE(update.ok) << update.error;
}

TEST_F(UserShaderTest, AttributeNamesInvalidInGlslBecomeValidMacroNames) {
  ASSERT_TRUE(renderer_->set_scene_layout({1}, {"air-temp", "q.rain"}).ok);
  const auto update = renderer_->set_user_shader(
      shader_with_body("  return vec4(attributes[ATTR_air_temp], attributes[ATTR_q_rain], 0, 1);\n"),
      "names.glsl");
  EXPECT_TRUE(update.ok) << update.error;
}

// --- the last good shader keeps rendering ---

class UserShaderRenderTest : public RenderTest {};

TEST_F(UserShaderRenderTest, ABrokenShaderLeavesThePictureUnchanged) {
  const Vec3 eye{5.0, -320.0, 55.0}, target{5.0, 0.0, 55.0};
  Scene scene;
  scene.subvolumes = {sphere(1, "d1", 30.0)};
  const auto first = render(scene, eye, target, flat_shader("return 1.0;"));
  int red = 0;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) red += first.image.at(x, y)[0] > 128 ? 1 : 0;
  ASSERT_GT(red, 100) << "the sphere should cover part of the picture";

  const auto update = renderer_->set_user_shader("vec4 color(", "broken.glsl");
  ASSERT_FALSE(update.ok);
  const auto inputs = render::frame_inputs(*controller_, camera(eye, target));
  const auto again = render::render_complete_frame(*controller_, *renderer_, *target_, inputs);
  ASSERT_EQ(again.image.pixels.size(), first.image.pixels.size());
  EXPECT_TRUE(again.image.pixels == first.image.pixels) << "the picture changed";

  // The comparison can tell shaders apart: a green shader changes the picture.
  const auto green = renderer_->set_user_shader(
      "vec4 color(int id, float attributes[MAX_ATTRIBUTES], vec3 normal, vec3 sun,\n"
      "           vec3 position, vec3 view, float time) { return vec4(0, 1, 0, 1); }\n"
      "float alpha(int id, float distance) { return 1.0; }\n",
      "green.glsl");
  ASSERT_TRUE(green.ok) << green.error;
  const auto changed = render::render_complete_frame(*controller_, *renderer_, *target_, inputs);
  EXPECT_FALSE(changed.image.pixels == first.image.pixels);
}

}  // namespace
}  // namespace strielad::testing
