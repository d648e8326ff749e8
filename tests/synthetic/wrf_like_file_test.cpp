// SPDX-License-Identifier: Apache-2.0
// The WRF-like sample (--model wrf) read back with netCDF: WRF's dimensions, global and
// variable attributes, Times and XTIME, XLAT/XLONG against PROJ's own cs2cs for the
// Lambert conformal grid the global attributes describe, staggered points between
// their mass neighbours, and geopotential levels that start on HGT and rise.
#include <gtest/gtest.h>
#include <netcdf.h>

#include <algorithm>
#include <cfloat>
#include <cmath>

#include "core/error.h"
#include "sample_test_util.h"
#include "support/cs2cs.h"
#include "synthetic/model_like_files.h"
#include "synthetic/sample_args.h"
#include "synthetic/sample_grid.h"
#include "synthetic/wrf_like_file.h"

namespace strielad::testing {
namespace {

using synthetic::SampleModel;

constexpr Dims3 kDims{40, 36, 30};
constexpr std::size_t kNx = kDims.x, kNy = kDims.y, kNz = kDims.z;

struct WrfSample {
  TempDir dir;
  synthetic::SampleResult result;
  WrfSample(std::size_t steps, bool single_file, int deflate = 0) {
    synthetic::SampleSpec spec;
    spec.dims = kDims;
    spec.steps = steps;
    spec.file_per_step = !single_file;
    spec.step_seconds = 1800;
    spec.deflate = deflate;
    result = synthetic::write_model_like_dataset(spec, SampleModel::kWrf, dir.path());
  }
  const std::filesystem::path& file(std::size_t i = 0) const { return result.files.at(i).path; }
};

// One shared two-step file: the tests only read it.
const WrfSample& two_steps() {
  static const WrfSample sample(2, true);
  return sample;
}

double number_att(const NcFile& f, const std::string& var, const char* name, nc_type expected) {
  const int v = var.empty() ? NC_GLOBAL : f.varid(var);
  std::lock_guard lock(ingest::netcdf_mutex());
  nc_type type = NC_NAT;
  std::size_t len = 0;
  ingest::nc_check(nc_inq_att(f.id(), v, name, &type, &len), name);
  EXPECT_EQ(type, expected) << var << ":" << name;
  EXPECT_EQ(len, 1u) << var << ":" << name;
  double value = 0;
  ingest::nc_check(nc_get_att_double(f.id(), v, name, &value), name);
  return value;
}

std::vector<std::string> times(const NcFile& f) {
  const std::size_t n = f.dim_length("Time"), len = f.dim_length("DateStrLen");
  std::string text(n * len, '\0');
  const int v = f.varid("Times");
  {
    std::lock_guard lock(ingest::netcdf_mutex());
    ingest::nc_check(nc_get_var_text(f.id(), v, text.data()), "Times");
  }
  std::vector<std::string> out;
  for (std::size_t t = 0; t < n; ++t) out.push_back(text.substr(t * len, len));
  return out;
}

nc_type var_type(const NcFile& f, const std::string& var) {
  const int v = f.varid(var);
  std::lock_guard lock(ingest::netcdf_mutex());
  nc_type type = NC_NAT;
  ingest::nc_check(nc_inq_vartype(f.id(), v, &type), var);
  return type;
}

int file_format(const NcFile& f) {
  std::lock_guard lock(ingest::netcdf_mutex());
  int format = 0;
  ingest::nc_check(nc_inq_format(f.id(), &format), "format");
  return format;
}

TEST(WrfLikeFileTest, ParsesTheModelName) {
  EXPECT_EQ(synthetic::parse_sample_model("wrf"), SampleModel::kWrf);
  EXPECT_EQ(synthetic::sample_model_name(SampleModel::kWrf), "wrf");
  EXPECT_THROW(synthetic::parse_sample_model("WRF"), Error);
  EXPECT_EQ(synthetic::model_sample_variable_names(SampleModel::kWrf),
            (std::vector<std::string>{"U", "V", "W", "PH", "PHB", "T", "P", "PB", "QVAPOR",
                                      "QCLOUD"}));
}

TEST(WrfLikeFileTest, DimensionsAndGlobalAttributesAreWrfs) {
  const WrfSample& s = two_steps();
  ASSERT_EQ(s.result.files.size(), 1u);
  EXPECT_EQ(s.file().filename(), "wrfout_d01_2013-04-26_12:00:00");
  const NcFile f(s.file());
  EXPECT_EQ(file_format(f), NC_FORMAT_64BIT_OFFSET) << "WRF's default io_form";
  {
    std::lock_guard lock(ingest::netcdf_mutex());
    int unlimited = -1, time = -1;
    ingest::nc_check(nc_inq_unlimdim(f.id(), &unlimited), "unlimited");
    ingest::nc_check(nc_inq_dimid(f.id(), "Time", &time), "Time");
    EXPECT_EQ(unlimited, time);
  }
  EXPECT_EQ(f.dim_length("Time"), 2u);
  EXPECT_EQ(f.dim_length("DateStrLen"), 19u);
  EXPECT_EQ(f.dim_length("west_east"), kNx);
  EXPECT_EQ(f.dim_length("south_north"), kNy);
  EXPECT_EQ(f.dim_length("bottom_top"), kNz);
  EXPECT_EQ(f.dim_length("west_east_stag"), kNx + 1);
  EXPECT_EQ(f.dim_length("south_north_stag"), kNy + 1);
  EXPECT_EQ(f.dim_length("bottom_top_stag"), kNz + 1);

  EXPECT_EQ(f.text_att("", "TITLE"), " OUTPUT FROM WRF V4.4 MODEL");
  EXPECT_EQ(f.text_att("", "SIMULATION_START_DATE"), "2013-04-26_12:00:00");
  EXPECT_EQ(f.text_att("", "START_DATE"), "2013-04-26_12:00:00");
  EXPECT_EQ(number_att(f, "", "MAP_PROJ", NC_INT), 1);
  EXPECT_EQ(number_att(f, "", "WEST-EAST_GRID_DIMENSION", NC_INT), kNx + 1);
  EXPECT_EQ(number_att(f, "", "SOUTH-NORTH_GRID_DIMENSION", NC_INT), kNy + 1);
  EXPECT_EQ(number_att(f, "", "BOTTOM-TOP_GRID_DIMENSION", NC_INT), kNz + 1);
  EXPECT_EQ(number_att(f, "", "TRUELAT1", NC_FLOAT), 30.0);
  EXPECT_EQ(number_att(f, "", "TRUELAT2", NC_FLOAT), 60.0);
  EXPECT_EQ(number_att(f, "", "POLE_LAT", NC_FLOAT), 90.0);
  EXPECT_EQ(number_att(f, "", "POLE_LON", NC_FLOAT), 0.0);
  EXPECT_NEAR(number_att(f, "", "CEN_LAT", NC_FLOAT), 51.0, 1e-5);
  EXPECT_NEAR(number_att(f, "", "CEN_LON", NC_FLOAT), 9.5, 1e-5);
  EXPECT_NEAR(number_att(f, "", "STAND_LON", NC_FLOAT), 9.5, 1e-5);
  EXPECT_NEAR(number_att(f, "", "MOAD_CEN_LAT", NC_FLOAT), 51.0, 1e-5);
  // The grid spans about the sample's 10 x 7 degrees over Germany.
  const double dx = number_att(f, "", "DX", NC_FLOAT), dy = number_att(f, "", "DY", NC_FLOAT);
  EXPECT_NEAR(dx * (kNx - 1), 700e3, 30e3);
  EXPECT_NEAR(dy * (kNy - 1), 778e3, 30e3);
}

struct VariableShape {
  const char* name;
  std::vector<std::string> dims;
  const char* memory_order;
  const char* stagger;
  const char* coordinates;  // nullptr: none
  const char* units;
};

TEST(WrfLikeFileTest, VariablesHaveWrfsDimensionsAndAttributes) {
  const NcFile f(two_steps().file());
  const std::vector<std::string> xyz{"Time", "bottom_top", "south_north", "west_east"};
  const std::vector<std::string> xyz_w{"Time", "bottom_top_stag", "south_north", "west_east"};
  const std::vector<std::string> xy{"Time", "south_north", "west_east"};
  const char* mass = "XLONG XLAT XTIME";
  const std::vector<VariableShape> shapes{
      {"XLAT", xy, "XY ", "", "XLONG XLAT", "degree_north"},
      {"XLONG", xy, "XY ", "", "XLONG XLAT", "degree_east"},
      {"XLAT_U", {"Time", "south_north", "west_east_stag"}, "XY ", "X", "XLONG_U XLAT_U", "degree_north"},
      {"XLONG_U", {"Time", "south_north", "west_east_stag"}, "XY ", "X", "XLONG_U XLAT_U", "degree_east"},
      {"XLAT_V", {"Time", "south_north_stag", "west_east"}, "XY ", "Y", "XLONG_V XLAT_V", "degree_north"},
      {"XLONG_V", {"Time", "south_north_stag", "west_east"}, "XY ", "Y", "XLONG_V XLAT_V", "degree_east"},
      {"XTIME", {"Time"}, "0  ", "", nullptr, "minutes since 2013-04-26 12:00:00"},
      {"ZNU", {"Time", "bottom_top"}, "Z  ", "", nullptr, ""},
      {"ZNW", {"Time", "bottom_top_stag"}, "Z  ", "Z", nullptr, ""},
      {"HGT", xy, "XY ", "", mass, "m"},
      {"PHB", xyz_w, "XYZ", "Z", mass, "m2 s-2"},
      {"PH", xyz_w, "XYZ", "Z", mass, "m2 s-2"},
      {"W", xyz_w, "XYZ", "Z", mass, "m s-1"},
      {"PB", xyz, "XYZ", "", mass, "Pa"},
      {"P", xyz, "XYZ", "", mass, "Pa"},
      {"T", xyz, "XYZ", "", mass, "K"},
      {"QVAPOR", xyz, "XYZ", "", mass, "kg kg-1"},
      {"QCLOUD", xyz, "XYZ", "", mass, "kg kg-1"},
      {"U", {"Time", "bottom_top", "south_north", "west_east_stag"}, "XYZ", "X", "XLONG_U XLAT_U XTIME", "m s-1"},
      {"V", {"Time", "bottom_top", "south_north_stag", "west_east"}, "XYZ", "Y", "XLONG_V XLAT_V XTIME", "m s-1"},
  };
  for (const VariableShape& v : shapes) {
    SCOPED_TRACE(v.name);
    EXPECT_EQ(f.dim_names(v.name), v.dims);
    EXPECT_EQ(var_type(f, v.name), NC_FLOAT);
    EXPECT_EQ(number_att(f, v.name, "FieldType", NC_INT), 104);
    EXPECT_EQ(f.text_att(v.name, "MemoryOrder"), v.memory_order);
    EXPECT_EQ(f.text_att(v.name, "stagger"), v.stagger);
    EXPECT_EQ(f.text_att(v.name, "units"), v.units);
    EXPECT_FALSE(f.text_att(v.name, "description").empty());
    if (v.coordinates != nullptr) {
      EXPECT_EQ(f.text_att(v.name, "coordinates"), v.coordinates);
    } else {
      EXPECT_FALSE(f.has_att(v.name, "coordinates"));
    }
  }
  EXPECT_EQ(f.dim_names("Times"), (std::vector<std::string>{"Time", "DateStrLen"}));
  EXPECT_EQ(var_type(f, "Times"), NC_CHAR);
}

TEST(WrfLikeFileTest, TimesAndXtimeCountFromTheSimulationStart) {
  const WrfSample single(3, true);
  const NcFile f(single.file());
  EXPECT_EQ(times(f), (std::vector<std::string>{"2013-04-26_12:00:00", "2013-04-26_12:30:00",
                                                "2013-04-26_13:00:00"}));
  EXPECT_EQ(f.floats("XTIME"), (std::vector<float>{0.0f, 30.0f, 60.0f}));

  const WrfSample split(3, false);
  ASSERT_EQ(split.result.files.size(), 3u);
  EXPECT_EQ(split.file(1).filename(), "wrfout_d01_2013-04-26_12:30:00");
  EXPECT_EQ(split.file(2).filename(), "wrfout_d01_2013-04-26_13:00:00");
  const NcFile second(split.file(1));
  EXPECT_EQ(times(second), std::vector<std::string>{"2013-04-26_12:30:00"});
  EXPECT_EQ(second.floats("XTIME"), std::vector<float>{30.0f});
  EXPECT_EQ(second.text_att("", "SIMULATION_START_DATE"), "2013-04-26_12:00:00");

  EXPECT_EQ(synthetic::wrf_date_string(12 * 3600.0), "2013-04-27_00:00:00");
  EXPECT_EQ(synthetic::wrf_date_string(5 * 86400.0 + 61.4), "2013-05-01_12:01:01");
}

TEST(WrfLikeFileTest, LatitudesAndLongitudesAgreeWithCs2cs) {
  if (!have_cs2cs()) GTEST_SKIP() << "cs2cs (proj-bin) missing";
  const NcFile f(two_steps().file());
  const double dx = number_att(f, "", "DX", NC_FLOAT), dy = number_att(f, "", "DY", NC_FLOAT);
  const double lat_0 = number_att(f, "", "CEN_LAT", NC_FLOAT);
  const double lon_0 = number_att(f, "", "STAND_LON", NC_FLOAT);
  const std::string lcc = fmt::format(
      "+proj=lcc +lat_1=30 +lat_2=60 +lat_0={} +lon_0={} +R=6370000 +units=m", lat_0, lon_0);
  // (i, j) of mass points; U points at i - 1/2, V points at j - 1/2.
  const std::vector<std::array<std::size_t, 2>> picks{
      {0, 0}, {kNx - 1, 0}, {0, kNy - 1}, {kNx - 1, kNy - 1}, {kNx / 2, kNy / 2}, {7, 29}};
  const auto check = [&](const char* lat_name, const char* lon_name, std::size_t row_length,
                         double di, double dj) {
    SCOPED_TRACE(lat_name);
    const std::vector<float> lat = f.floats(lat_name), lon = f.floats(lon_name);
    std::vector<std::array<double, 2>> xy;
    for (const auto& [i, j] : picks) {
      xy.push_back({(static_cast<double>(i) + di - (kNx - 1) / 2.0) * dx,
                    (static_cast<double>(j) + dj - (kNy - 1) / 2.0) * dy});
    }
    const auto expected = cs2cs(lcc, "+proj=longlat +R=6370000", xy);
    ASSERT_TRUE(expected);
    ASSERT_EQ(expected->size(), picks.size());
    for (std::size_t p = 0; p < picks.size(); ++p) {
      const std::size_t c = picks[p][1] * row_length + picks[p][0];
      EXPECT_NEAR(lon[c], (*expected)[p][0], 2e-5) << p;  // float in the file
      EXPECT_NEAR(lat[c], (*expected)[p][1], 2e-5) << p;
    }
  };
  check("XLAT", "XLONG", kNx, 0.0, 0.0);
  check("XLAT_U", "XLONG_U", kNx + 1, -0.5, 0.0);
  check("XLAT_V", "XLONG_V", kNx, 0.0, -0.5);
  // The second Time holds the same positions.
  const std::vector<float> lat = f.floats("XLAT");
  EXPECT_TRUE(std::equal(lat.begin(), lat.begin() + kNx * kNy, lat.begin() + kNx * kNy));
}

TEST(WrfLikeFileTest, StaggeredPointsLieBetweenTheirMassNeighbours) {
  const NcFile f(two_steps().file());
  const std::vector<float> lat = f.floats("XLAT"), lon = f.floats("XLONG");
  const std::vector<float> lat_u = f.floats("XLAT_U"), lon_u = f.floats("XLONG_U");
  const std::vector<float> lat_v = f.floats("XLAT_V"), lon_v = f.floats("XLONG_V");
  const auto between = [](float v, float a, float b) {
    return v > std::min(a, b) && v < std::max(a, b);
  };
  for (std::size_t j = 0; j < kNy; ++j) {
    for (std::size_t i = 1; i < kNx; ++i) {
      const std::size_t u = j * (kNx + 1) + i, west = j * kNx + i - 1, east = j * kNx + i;
      ASSERT_TRUE(between(lon_u[u], lon[west], lon[east])) << "U " << i << "," << j;
      // A row is a straight line across the conic's circular parallels: its latitude
      // peaks or dips at the central meridian, so allow the sag of half a cell (~1e-4).
      ASSERT_LE(lat_u[u], std::max(lat[west], lat[east]) + 2e-4f) << "U " << i << "," << j;
      ASSERT_GE(lat_u[u], std::min(lat[west], lat[east]) - 2e-4f) << "U " << i << "," << j;
    }
  }
  for (std::size_t j = 1; j < kNy; ++j) {
    for (std::size_t i = 0; i < kNx; ++i) {
      const std::size_t v = j * kNx + i, south = (j - 1) * kNx + i, north = j * kNx + i;
      ASSERT_TRUE(between(lat_v[v], lat[south], lat[north])) << "V " << i << "," << j;
      ASSERT_LE(lon_v[v], std::max(lon[south], lon[north]) + 1e-5f) << "V " << i << "," << j;
      ASSERT_GE(lon_v[v], std::min(lon[south], lon[north]) - 1e-5f) << "V " << i << "," << j;
    }
  }
  // The outer staggered points lie outside the mass points.
  EXPECT_LT(lon_u[0], lon[0]);
  EXPECT_GT(lon_u[kNx], lon[kNx - 1]);
  EXPECT_LT(lat_v[0], lat[0]);
  EXPECT_GT(lat_v[kNy * kNx], lat[(kNy - 1) * kNx]);
}

TEST(WrfLikeFileTest, GeopotentialLevelsStartOnTheTerrainAndRise) {
  const NcFile f(two_steps().file());
  constexpr std::size_t kColumns = kNx * kNy, kW = (kNz + 1) * kColumns;
  const std::vector<float> ph = f.floats("PH"), phb = f.floats("PHB"), hgt = f.floats("HGT");
  const std::vector<float> znw = f.floats("ZNW"), znu = f.floats("ZNU");
  ASSERT_EQ(ph.size(), 2 * kW);
  EXPECT_EQ(znw[0], 1.0f);
  EXPECT_EQ(znw[kNz], 0.0f);
  for (std::size_t k = 0; k < kNz; ++k) {
    ASSERT_LT(znw[k + 1], znw[k]) << k;
    ASSERT_LT(znu[k], znw[k]) << k;
    ASSERT_GT(znu[k], znw[k + 1]) << k;
  }
  const auto [low, high] = std::minmax_element(hgt.begin(), hgt.begin() + kColumns);
  EXPECT_EQ(*low, 0.0f) << "the North Sea";
  EXPECT_GT(*high, 1500.0f) << "the Alps";
  double ph_change = 0;
  for (std::size_t t = 0; t < 2; ++t) {
    for (std::size_t c = 0; c < kColumns; ++c) {
      const auto z = [&](std::size_t k) {
        const std::size_t at = t * kW + k * kColumns + c;
        return (static_cast<double>(ph[at]) + phb[at]) / synthetic::kWrfGravity;
      };
      const float ground = hgt[t * kColumns + c];
      ASSERT_NEAR(z(0), ground, 4 * FLT_EPSILON * std::max(1.0f, ground)) << "column " << c;
      for (std::size_t k = 0; k < kNz; ++k) {
        ASSERT_GT(z(k + 1), z(k)) << "t " << t << " column " << c << " level " << k;
      }
      EXPECT_NEAR(z(kNz), synthetic::kModelTop, 25.0) << "about flat at the top";
      for (std::size_t k = 0; k <= kNz; ++k) {
        const std::size_t at = t * kW + k * kColumns + c;
        ASSERT_LE(std::fabs(ph[at]), 20.0 * synthetic::kWrfGravity + 1);
        if (t == 1) ph_change = std::max(ph_change, std::fabs(double(ph[at]) - ph[at - kW]));
      }
    }
  }
  EXPECT_GT(ph_change, 1.0) << "PH varies in time";
  // Terrain-following near the ground: the lowest mass level over the mountains is far
  // above the one over the sea.
  const std::size_t lo = low - hgt.begin(), hi = high - hgt.begin();
  const auto z1 = [&](std::size_t c) { return (ph[kColumns + c] + phb[kColumns + c]) / 9.81; };
  EXPECT_GT(z1(hi) - z1(lo), 0.9 * (*high - *low));
}

TEST(WrfLikeFileTest, AtmosphereIsPlausible) {
  const NcFile f(two_steps().file());
  constexpr std::size_t kColumns = kNx * kNy;
  const std::vector<float> p = f.floats("P"), pb = f.floats("PB"), t = f.floats("T");
  const std::vector<float> qv = f.floats("QVAPOR"), qc = f.floats("QCLOUD");
  const std::vector<float> u = f.floats("U"), v = f.floats("V"), w = f.floats("W");
  for (std::size_t c = 0; c < kColumns; ++c) {
    for (std::size_t k = 0; k < kNz; ++k) {
      const std::size_t at = k * kColumns + c;
      const double pressure = double(p[at]) + pb[at], theta = t[at] + 300.0;
      ASSERT_GT(pressure, 3000.0);
      ASSERT_LT(pressure, 105000.0);
      ASSERT_LT(std::fabs(p[at]), 3000.0f) << "a perturbation";
      ASSERT_GT(theta, 270.0);
      ASSERT_LT(theta, 600.0);
      ASSERT_GT(qv[at], 0.0f);
      ASSERT_LT(qv[at], 0.02f);
      if (k + 1 < kNz) {
        ASSERT_LT(p[at + kColumns] + pb[at + kColumns], pressure) << "pressure falls upward";
        ASSERT_GT(t[at + kColumns] + 300.0 + 0.5, theta) << "stable";
      }
    }
  }
  const double cloudy = nonzero_fraction(qc);
  EXPECT_GT(cloudy, 0.0) << "a cloud blob";
  EXPECT_LT(cloudy, 0.2) << "mostly clear";
  for (const auto* field : {&u, &v, &w}) {
    for (const float x : *field) ASSERT_LT(std::fabs(x), 80.0f);
  }
  EXPECT_GT(*std::max_element(u.begin(), u.end()), 10.0f) << "the westerly";
}

TEST(WrfLikeFileTest, DeflateWritesNetcdf4AndTheSameValues) {
  const WrfSample packed(1, true, 4), plain(1, true);
  const NcFile a(packed.file()), b(plain.file());
  EXPECT_EQ(file_format(a), NC_FORMAT_NETCDF4);
  for (const char* name : {"U", "PH", "QCLOUD", "XLAT_V"}) {
    EXPECT_EQ(a.floats(name), b.floats(name)) << name;
  }
}

}  // namespace
}  // namespace strielad::testing
