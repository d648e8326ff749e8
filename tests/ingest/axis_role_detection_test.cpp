// SPDX-License-Identifier: Apache-2.0
// Which dimension is lon/lat/vertical/time, from CF/COARDS metadata, and what kind of
// vertical coordinate it is.
#include <gtest/gtest.h>

#include "ingest/cf_axis_detection.h"

namespace strielad::ingest {
namespace {

using R = DimensionRole;

CoordinateAttributes named(std::string name) {
  CoordinateAttributes c;
  c.name = std::move(name);
  return c;
}

TEST(AxisRoleDetectionTest, AxisAttributeWins) {
  auto c = named("lat");  // the name says latitude, the axis attribute says otherwise
  c.axis = "Z";
  EXPECT_EQ(detect_dimension_role(c, false), R::kVertical);
  c.axis = "t";
  EXPECT_EQ(detect_dimension_role(c, false), R::kTime);
  c.axis = "X";
  EXPECT_EQ(detect_dimension_role(c, false), R::kLongitude);
}

TEST(AxisRoleDetectionTest, StandardNames) {
  auto c = named("a");
  c.standard_name = "latitude";
  EXPECT_EQ(detect_dimension_role(c, false), R::kLatitude);
  c.standard_name = "atmosphere_hybrid_sigma_pressure_coordinate";
  EXPECT_EQ(detect_dimension_role(c, false), R::kVertical);
  c.standard_name = "model_level_number";
  EXPECT_EQ(detect_dimension_role(c, false), R::kVertical);
  c.standard_name = "air_pressure";
  EXPECT_EQ(detect_dimension_role(c, false), R::kVertical);
  c.standard_name = "time";
  EXPECT_EQ(detect_dimension_role(c, false), R::kTime);
}

TEST(AxisRoleDetectionTest, Units) {
  auto c = named("a");
  for (const char* u : {"degrees_east", "degree_E", "degreesE"}) {
    c.units = u;
    EXPECT_EQ(detect_dimension_role(c, false), R::kLongitude) << u;
  }
  c.units = "degrees_north";
  EXPECT_EQ(detect_dimension_role(c, false), R::kLatitude);
  c.units = "days since 1850-01-01";
  EXPECT_EQ(detect_dimension_role(c, false), R::kTime);
  for (const char* u : {"Pa", "hPa", "mbar", "millibars", "km", "m"}) {
    c.units = u;
    EXPECT_EQ(detect_dimension_role(c, false), R::kVertical) << u;
  }
  c.units = "K";
  EXPECT_EQ(detect_dimension_role(c, false), R::kUnknown);
}

TEST(AxisRoleDetectionTest, PositiveAttributeMeansVertical) {
  auto c = named("a");
  c.units = "1";
  c.positive = "down";
  EXPECT_EQ(detect_dimension_role(c, false), R::kVertical);
}

TEST(AxisRoleDetectionTest, NamesAndUnlimited) {
  EXPECT_EQ(detect_dimension_role(named("longitude"), false), R::kLongitude);
  EXPECT_EQ(detect_dimension_role(named("lat"), false), R::kLatitude);
  EXPECT_EQ(detect_dimension_role(named("frtime"), false), R::kTime);
  EXPECT_EQ(detect_dimension_role(named("plev"), false), R::kVertical);
  EXPECT_EQ(detect_dimension_role(named("lev_2"), false), R::kVertical);
  EXPECT_EQ(detect_dimension_role(named("height"), false), R::kVertical);
  EXPECT_EQ(detect_dimension_role(named("record"), true), R::kTime);
  EXPECT_EQ(detect_dimension_role(named("record"), false), R::kUnknown);
}

TEST(AxisRoleDetectionTest, VerticalKinds) {
  auto c = named("lev");
  c.units = "hPa";
  EXPECT_EQ(detect_vertical_kind(c), AxisKind::kPressure);
  c.units = "millibars";
  EXPECT_EQ(detect_vertical_kind(c), AxisKind::kPressure);
  c.units = "m";
  EXPECT_EQ(detect_vertical_kind(c), AxisKind::kHeight);
  c.units = "km";
  EXPECT_EQ(detect_vertical_kind(c), AxisKind::kHeight);
  c.units = "";
  c.standard_name = "altitude";
  EXPECT_EQ(detect_vertical_kind(c), AxisKind::kHeight);
  c.standard_name = "atmosphere_sigma_coordinate";
  EXPECT_EQ(detect_vertical_kind(c), AxisKind::kModelLevel);
  c.standard_name = "air_pressure";
  EXPECT_EQ(detect_vertical_kind(c), AxisKind::kPressure);
  c = named("lev");
  c.units = "1";
  c.has_formula_terms = true;
  EXPECT_EQ(detect_vertical_kind(c), AxisKind::kModelLevel);
  c = named("lev");
  c.standard_name = "height";  // formula_terms: model levels, whatever else it says
  c.units = "m";
  c.has_formula_terms = true;
  EXPECT_EQ(detect_vertical_kind(c), AxisKind::kModelLevel);
  c.standard_name = "air_pressure";
  c.units = "Pa";
  EXPECT_EQ(detect_vertical_kind(c), AxisKind::kModelLevel);
  c = named("lev");
  c.units = "hybrid_sigma_pressure";
  EXPECT_EQ(detect_vertical_kind(c), AxisKind::kModelLevel);
  c = named("theta");
  c.units = "K";
  EXPECT_EQ(detect_vertical_kind(c), AxisKind::kOther);
}

}  // namespace
}  // namespace strielad::ingest
