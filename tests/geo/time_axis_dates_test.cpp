// SPDX-License-Identifier: Apache-2.0
// Dates beside raw time values (lib/geo/time_axis_dates.h): the time axes of real files
// no one here wrote (libncarg-data, read with the netCDF C API), their dates against
// Python's datetime and cftime 1.6.2, the one reason an axis without dates gives, and the
// time step object of the --json outputs.
#include <gtest/gtest.h>
#include <netcdf.h>

#include <filesystem>
#include <string>
#include <tuple>
#include <vector>

#include "core/error.h"
#include "geo/time_axis_dates.h"
#include "support/temp_dir.h"

namespace strielad::geo {
namespace {

// A text attribute of `varid`, NC_CHAR or NC_STRING; "" when absent.
std::string text_attribute(int ncid, int varid, const char* name) {
  nc_type type = 0;
  std::size_t length = 0;
  if (nc_inq_att(ncid, varid, name, &type, &length) != NC_NOERR) return "";
  if (type == NC_STRING) {
    char* value = nullptr;
    EXPECT_EQ(nc_get_att_string(ncid, varid, name, &value), NC_NOERR);
    std::string text = value ? value : "";
    nc_free_string(1, &value);
    return text;
  }
  std::string text(length, '\0');
  EXPECT_EQ(nc_get_att_text(ncid, varid, name, text.data()), NC_NOERR);
  while (!text.empty() && text.back() == '\0') text.pop_back();  // some files count the NUL
  return text;
}

// The time coordinate `name` of a libncarg-data file as a TimeAxis.
TimeAxis read_time_axis(const std::string& file, const char* name) {
  TimeAxis axis;
  int ncid = 0, varid = 0, dimid = 0;
  const auto path = testing::ncarg_file(file);
  if (nc_open(path.c_str(), NC_NOWRITE, &ncid) != NC_NOERR) return axis;
  EXPECT_EQ(nc_inq_varid(ncid, name, &varid), NC_NOERR) << file;
  EXPECT_EQ(nc_inq_vardimid(ncid, varid, &dimid), NC_NOERR);
  std::size_t n = 0;
  EXPECT_EQ(nc_inq_dimlen(ncid, dimid, &n), NC_NOERR);
  axis.name = name;
  axis.units = text_attribute(ncid, varid, "units");
  axis.calendar = text_attribute(ncid, varid, "calendar");
  axis.values.resize(n);
  EXPECT_EQ(nc_get_var_double(ncid, varid, axis.values.data()), NC_NOERR);
  nc_close(ncid);
  return axis;
}

bool have_ncarg_data() { return std::filesystem::exists(testing::ncarg_file("cdf/contour.cdf")); }

TEST(TimeAxisDatesTest, RealFilesGiveTheDatesOfIndependentReferences) {
  if (!have_ncarg_data()) GTEST_SKIP() << "libncarg-data not installed";
  // "days since 1949-12-01 00:00:00", proleptic_gregorian, 20500.5: Python's
  // datetime(1949, 12, 1) + timedelta(days=20500.5) is 2006-01-16 12:00:00.
  const TimeAxis tas = read_time_axis("nug/tas_rotated_grid_EUR11.nc", "time");
  ASSERT_EQ(tas.values, std::vector<double>{20500.5});
  const TimeAxisDates tas_dates(tas);
  EXPECT_TRUE(tas_dates.has_dates());
  EXPECT_EQ(tas_dates.date(tas.values[0]).text, "2006-01-16T12:00:00Z");
  // "hours since 2001-01-01 00:00:00", standard, 0.
  const TimeAxis echam = read_time_axis("nug/rectilinear_grid_3D.nc", "time");
  EXPECT_EQ(TimeAxisDates(echam).date(echam.values.at(0)).text, "2001-01-01T00:00:00Z");
  // "days since 0049-09-01 00:00:00" without a calendar: standard, so the Julian calendar
  // in the year 49 (cftime: 0049-12-17, 0049-12-18).
  const TimeAxis hybrid = read_time_axis("cdf/vinth2p.nc", "time");
  ASSERT_EQ(hybrid.values, (std::vector<double>{107, 108}));
  EXPECT_EQ(TimeAxisDates(hybrid).date(107).text, "0049-12-17T00:00:00Z");
  EXPECT_EQ(TimeAxisDates(hybrid).date(108).text, "0049-12-18T00:00:00Z");
}

TEST(TimeAxisDatesTest, RealFilesWithoutDatesSayWhyInsteadOfAWrongDate) {
  if (!have_ncarg_data()) GTEST_SKIP() << "libncarg-data not installed";
  // cdf/contour.cdf: forecast times in plain "hours", no reference date.
  const TimeAxis frtime = read_time_axis("cdf/contour.cdf", "frtime");
  ASSERT_EQ(frtime.units, "hours");
  const TimeAxisDates contour(frtime);
  EXPECT_FALSE(contour.has_dates());
  EXPECT_NE(contour.why_not().find("'hours': no reference date"), std::string::npos)
      << contour.why_not();
  const TimeDate d = contour.date(6);
  EXPECT_FALSE(d.ok());
  EXPECT_EQ(d.text, "");
  EXPECT_EQ(d.why_not, contour.why_not());
  // cdf/nc4uvt.nc: "Month".
  const TimeAxis month = read_time_axis("cdf/nc4uvt.nc", "time");
  ASSERT_EQ(month.units, "Month");
  EXPECT_NE(TimeAxisDates(month).why_not().find("'Month': no reference date"), std::string::npos);
}

TEST(TimeAxisDatesTest, EveryCalendarAndEveryReasonForNoDates) {
  const auto axis = [](std::string units, std::string calendar) {
    return TimeAxis{"time", std::move(units), std::move(calendar), {0}};
  };
  EXPECT_EQ(TimeAxisDates(axis("hours since 1900-01-01", "noleap")).date(973356).text,
            "2011-02-11T12:00:00Z");
  EXPECT_EQ(TimeAxisDates(axis("hours since 1900-01-01", "360_day")).date(973356).text,
            "2012-08-27T12:00:00Z");
  for (const auto& [units, calendar, reason] :
       std::vector<std::tuple<std::string, std::string, std::string>>{
           {"months since 2000-01-01", "360_day", "not a fixed length of time"},
           {"years since 2000-01-01", "standard", "not a fixed length of time"},
           {"days since 2000-01-01", "none", "calendar 'none'"},
           {"days since 2000-01-01", "mayan", "calendar 'mayan' is not a CF calendar"},
           {"days since 2000-01-01", "noleap_365", "calendar 'noleap_365'"},
           {"", "", "no units"},
           {"furlongs since 2000-01-01", "", "unknown unit 'furlongs'"}}) {
    const TimeAxisDates dates(axis(units, calendar));
    EXPECT_FALSE(dates.has_dates()) << units << " " << calendar;
    EXPECT_NE(dates.why_not().find(reason), std::string::npos) << dates.why_not();
    EXPECT_EQ(dates.date(0).why_not, dates.why_not());
  }
  // An axis with dates whose one value has none.
  const TimeAxisDates days(axis("days since 2000-01-01", ""));
  EXPECT_TRUE(days.date(1).ok());
  EXPECT_FALSE(days.date(1e300).ok());
  EXPECT_NE(days.date(1e300).why_not.find("too far"), std::string::npos);
}

TEST(TimeAxisDatesTest, TimeStepJsonHasTheDateOrWhyNot) {
  const TimeAxis t{"time", "days since 1949-12-01 00:00:00", "proleptic_gregorian", {0, 20500.5}};
  const auto j = time_step_json(t, 1);
  EXPECT_EQ(j["step"], 1);
  EXPECT_EQ(j["value"], 20500.5);
  EXPECT_EQ(j["units"], "days since 1949-12-01 00:00:00");
  EXPECT_EQ(j["calendar"], "proleptic_gregorian");
  EXPECT_EQ(j["date"], "2006-01-16T12:00:00Z");
  EXPECT_FALSE(j.contains("date_error"));

  const TimeAxis hours{"frtime", "hours", "", {0, 6}};
  const auto k = time_step_json(hours, 1);
  EXPECT_EQ(k["value"], 6);
  EXPECT_TRUE(k["date"].is_null());
  EXPECT_NE(k["date_error"].get<std::string>().find("no reference date"), std::string::npos);
  EXPECT_THROW(time_step_json(hours, 2), Error);
}

}  // namespace
}  // namespace strielad::geo
