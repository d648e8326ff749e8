// SPDX-License-Identifier: Apache-2.0
// The viewer panel's time text (lib/view/simulation_time.h, step_time_text): the raw
// value with its units, then the date in the store's calendar, or why there is none.
// Dates from Python's datetime and cftime 1.6.2 (see tests/geo/cf_dates_test.cpp).
#include <gtest/gtest.h>

#include "format/manifest.h"
#include "view/simulation_time.h"

namespace strielad::view {
namespace {

format::Manifest manifest_with_time(TimeAxis time) {
  format::Manifest m;
  m.time = std::move(time);
  return m;
}

TEST(StepTimeTextTest, RawValueThenTheDateInTheStoresCalendar) {
  const auto m = manifest_with_time(
      {"time", "days since 1949-12-01 00:00:00", "proleptic_gregorian", {0, 20500.5}});
  EXPECT_EQ(step_time_text(m, 1),
            "time = 20500.5 days since 1949-12-01 00:00:00\n"
            "2006-01-16T12:00:00Z, proleptic_gregorian calendar");
  const auto noleap = manifest_with_time({"t", "hours since 1900-01-01", "noleap", {973356}});
  EXPECT_EQ(step_time_text(noleap, 0),
            "t = 973356 hours since 1900-01-01\n2011-02-11T12:00:00Z, noleap calendar");
  const auto unnamed = manifest_with_time({"time", "hours since 2001-01-01", "", {0, 1234567}});
  EXPECT_EQ(step_time_text(unnamed, 1),
            "time = 1234567 hours since 2001-01-01\n2141-11-03T07:00:00Z, standard calendar");
}

TEST(StepTimeTextTest, NoDateSaysWhy) {
  const auto m = manifest_with_time({"frtime", "hours", "", {0, 6, 12}});
  const std::string text = step_time_text(m, 1);
  EXPECT_EQ(text.substr(0, text.find('\n')), "frtime = 6 hours");
  EXPECT_EQ(text.substr(text.find('\n') + 1, 44), "no date: time units 'hours': no reference da");
  const auto months = manifest_with_time({"time", "months since 2000-01-01", "360_day", {3}});
  EXPECT_NE(step_time_text(months, 0).find("\nno date: time units 'months since 2000-01-01': "
                                           "months and years are not a fixed length of time"),
            std::string::npos)
      << step_time_text(months, 0);
}

TEST(StepTimeTextTest, NoTextForAStepOutsideTheStore) {
  const auto m = manifest_with_time({"time", "hours since 2001-01-01", "", {0}});
  EXPECT_EQ(step_time_text(m, 1), "");
}

}  // namespace
}  // namespace strielad::view
