// SPDX-License-Identifier: Apache-2.0
// The viewer's default vertical exaggeration (lib/view/default_exaggeration.h): it follows
// the domain's extents, so the paper's grid keeps 10, a global grid gets enough to show
// depth, a small deep domain stays at true scale, and domains without depth get the
// fixed default.
#include <gtest/gtest.h>

#include <cmath>

#include "lod/lod_test_grids.h"
#include "view/default_exaggeration.h"

namespace strielad::view {
namespace {

using lod::testing::linspace;

// A global grid like a 2.5-degree forecast: 144 x 73 points, 26 pressure levels from
// 1000 to 10 hPa.
format::Manifest global_manifest(std::size_t levels = 26) {
  format::Manifest m;
  m.x = Axis{"lon", AxisKind::kLongitude, "degrees_east", "longitude", "", "", linspace(0, 357.5, 144)};
  m.y = Axis{"lat", AxisKind::kLatitude, "degrees_north", "latitude", "", "", linspace(90, -90, 73)};
  m.z = Axis{"plev", AxisKind::kPressure, "Pa", "", "", "down", linspace(100000, 1000, levels)};
  m.time = TimeAxis{"time", "hours since 2024-06-21 00:00:00", "standard", {12}};
  m.brick = 16;
  return m;
}

double default_for(const format::Manifest& m, double frame_exaggeration = 10.0) {
  const lod::WorldFrame frame(m, {.vertical_exaggeration = frame_exaggeration});
  return default_vertical_exaggeration(domain_extent(frame));
}

TEST(DefaultExaggerationTest, PaperGridKeepsTen) {
  const lod::WorldFrame frame(lod::testing::paper_manifest());
  const auto e = domain_extent(frame);
  EXPECT_NEAR(e.width_km, 700, 5);
  EXPECT_NEAR(e.length_km, 778, 5);
  EXPECT_NEAR(e.depth_km, 20.98, 0.01);
  EXPECT_EQ(default_vertical_exaggeration(e), lod::kDefaultVerticalExaggeration);
}

TEST(DefaultExaggerationTest, GlobalGridShowsDepth) {
  const auto m = global_manifest();
  const lod::WorldFrame frame(m);
  const auto e = domain_extent(frame);
  EXPECT_NEAR(e.width_km, 39753, 10);
  EXPECT_NEAR(e.length_km, 20015, 10);
  EXPECT_NEAR(e.depth_km, 30.9, 0.2);  // 10 hPa in the standard atmosphere, less 1000 hPa's 111 m
  const double chosen = default_vertical_exaggeration(e);
  EXPECT_EQ(chosen, 200);
  // The exaggerated depth is a sizeable part of the domain's horizontal size, as the
  // paper's 210 of 738 km: not a sheet.
  const double share = chosen * e.depth_km / std::sqrt(e.width_km * e.length_km);
  EXPECT_GT(share, 0.15);
  EXPECT_LT(share, 0.5);
}

TEST(DefaultExaggerationTest, DoesNotDependOnTheFramesOwnExaggeration) {
  EXPECT_EQ(default_for(global_manifest(), 1.0), default_for(global_manifest(), 37.0));
  EXPECT_EQ(default_for(lod::testing::small_manifest(), 1.0), 10);
}

TEST(DefaultExaggerationTest, WiderDomainsOfTheSameDepthGetMore) {
  double previous = 0;
  for (const double km : {50.0, 200.0, 700.0, 3000.0, 12000.0, 40000.0}) {
    const double e = default_vertical_exaggeration({km, km, 21.0});
    EXPECT_GE(e, previous) << km;
    previous = e;
  }
  EXPECT_GE(previous, 200);
}

TEST(DefaultExaggerationTest, RoundedToOneTwoFive) {
  EXPECT_EQ(default_vertical_exaggeration({739, 739, 21}), 10);   // 9.85
  EXPECT_EQ(default_vertical_exaggeration({1500, 1500, 21}), 20);  // 20.0
  EXPECT_EQ(default_vertical_exaggeration({300, 300, 21}), 5);    // 4.0
  EXPECT_EQ(default_vertical_exaggeration({200, 200, 21}), 2);    // 2.67 (below 3.16)
}

TEST(DefaultExaggerationTest, SmallDeepDomainStaysAtTrueScale) {
  // A large-eddy simulation 10 km wide and 5 km deep: 0.56 would flatten it.
  EXPECT_EQ(default_vertical_exaggeration({10, 10, 5}), kMinDefaultExaggeration);
}

TEST(DefaultExaggerationTest, ShallowDomainIsBounded) {
  EXPECT_EQ(default_vertical_exaggeration({40000, 20000, 0.01}), kMaxDefaultExaggeration);
}

TEST(DefaultExaggerationTest, DomainWithoutDepthGetsTheFixedDefault) {
  EXPECT_EQ(default_for(global_manifest(1)), lod::kDefaultVerticalExaggeration);
  EXPECT_EQ(default_vertical_exaggeration({0, 700, 21}), lod::kDefaultVerticalExaggeration);
  EXPECT_EQ(default_vertical_exaggeration({700, 700, NAN}), lod::kDefaultVerticalExaggeration);
}

TEST(DefaultExaggerationTest, DescriptionGivesTheRuleAndItsNumbers) {
  const std::string text = describe_default_exaggeration({39753, 20015, 30.9});
  EXPECT_EQ(text.rfind("200 for a 39753 x 20015 km domain 30.9 km deep", 0), 0u) << text;
  EXPECT_NE(text.find("0.28 x horizontal size / depth = 256"), std::string::npos) << text;
  EXPECT_NE(describe_default_exaggeration({10, 10, 5}).find("within 1..1000"), std::string::npos);
  EXPECT_NE(describe_default_exaggeration({0, 0, 5}).find("fixed default"), std::string::npos);
}

}  // namespace
}  // namespace strielad::view
