// SPDX-License-Identifier: Apache-2.0
// What the viewer chose by itself goes to the log at level info (lib/view/view_choices.h):
// the default scene as canonical JSON that parses back to it, the vertical exaggeration
// with its rule, and the sun's rule.
#include <gtest/gtest.h>
#include <spdlog/sinks/ostream_sink.h>
#include <spdlog/spdlog.h>

#include <sstream>

#include "lod/lod_test_grids.h"
#include "view/default_exaggeration.h"
#include "view/default_scene.h"
#include "view/view_choices.h"

namespace strielad::view {
namespace {

ViewChoices sample_choices() {
  auto m = lod::testing::small_manifest();
  for (const char* name : {"clw", "cli", "ta"}) {
    format::StoreVariable v;
    v.name = name;
    m.variables.push_back(v);
  }
  return {.default_scene = default_scene(m),
          .exaggeration = describe_default_exaggeration({700, 778, 21}),
          .sun = "the true sun over the domain centre (51.00 N, 9.50 E), 35.2 degrees up"};
}

TEST(ViewChoicesTest, DefaultSceneIsLoggedAsCanonicalJson) {
  const auto choices = sample_choices();
  const auto lines = view_choice_lines(choices);
  ASSERT_EQ(lines.size(), 3u);
  const std::string prefix = "default scene (no --scene): ";
  ASSERT_EQ(lines[0].rfind(prefix, 0), 0u) << lines[0];
  const std::string json = lines[0].substr(prefix.size());
  EXPECT_EQ(json, scene_to_json(*choices.default_scene));
  EXPECT_EQ(parse_scene(json, "logged scene"), *choices.default_scene);  // can be given back
  EXPECT_NE(json.find("\"cloud water\""), std::string::npos) << json;
  EXPECT_EQ(lines[1], "vertical exaggeration 10 for a 700 x 778 km domain 21 km deep (0.28 x "
                      "horizontal size / depth = 9.84, rounded to 1-2-5)");
  EXPECT_EQ(lines[2], "sun: the true sun over the domain centre (51.00 N, 9.50 E), 35.2 degrees up");
}

TEST(ViewChoicesTest, GivenSceneIsNotRepeated) {
  auto choices = sample_choices();
  choices.default_scene.reset();
  const auto lines = view_choice_lines(choices);
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_EQ(lines[0].rfind("vertical exaggeration", 0), 0u);
}

TEST(ViewChoicesTest, LoggedAtLevelInfo) {
  std::ostringstream out;
  auto sink = std::make_shared<spdlog::sinks::ostream_sink_mt>(out);
  sink->set_pattern("%l %v");
  const auto previous = spdlog::default_logger();
  spdlog::set_default_logger(std::make_shared<spdlog::logger>("test", sink));
  spdlog::set_level(spdlog::level::info);
  log_view_choices(sample_choices());
  spdlog::set_default_logger(previous);
  const std::string text = out.str();
  EXPECT_NE(text.find("info default scene (no --scene): {"), std::string::npos) << text;
  EXPECT_NE(text.find("info vertical exaggeration 10 for a 700 x 778 km domain"), std::string::npos);
  EXPECT_NE(text.find("info sun: the true sun over the domain centre"), std::string::npos);
}

}  // namespace
}  // namespace strielad::view
