// SPDX-License-Identifier: Apache-2.0
// WRF history files (the WRF-like sample of synthetic/wrf_like_file.h) read without the
// curvilinear path: the Lambert conformal mapping places every mass point where the
// file's XLAT/XLONG and PROJ's own cs2cs put it; U, V and W are destaggered onto the
// mass points as the mean of their two neighbours; Times become seconds since the first
// one; files of one step each merge; a perturbed XLAT, or one that moves between steps,
// is refused naming the deviation.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <netcdf.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <string>
#include <vector>

#include "ingest/box_reader.h"
#include "ingest/input_catalog.h"
#include "ingest/slab_reader.h"
#include "ingest/wrf_destagger.h"
#include "ingest/wrf_times.h"
#include "support/cs2cs.h"
#include "support/expect_error.h"
#include "support/netcdf_fixture.h"
#include "support/temp_dir.h"
#include "synthetic/model_like_files.h"
#include "synthetic/wrf_grid.h"

namespace strielad::ingest {
namespace {

using strielad::testing::expect_error;

constexpr Dims3 kDims{14, 11, 6};
constexpr double kStepSeconds = 1800;

std::vector<std::filesystem::path> write_wrf(const std::filesystem::path& dir, std::size_t steps,
                                             bool file_per_step) {
  synthetic::SampleSpec s;
  s.dims = kDims;
  s.steps = steps;
  s.step_seconds = kStepSeconds;
  s.file_per_step = file_per_step;
  std::vector<std::filesystem::path> paths;
  for (const auto& f :
       synthetic::write_model_like_dataset(s, synthetic::SampleModel::kWrf, dir).files) {
    paths.push_back(f.path);
  }
  return paths;
}

float global_float(const std::filesystem::path& file, const char* name) {
  int nc = 0;
  float v = 0;
  EXPECT_EQ(nc_open(file.c_str(), NC_NOWRITE, &nc), NC_NOERR);
  EXPECT_EQ(nc_get_att_float(nc, NC_GLOBAL, name, &v), NC_NOERR);
  nc_close(nc);
  return v;
}

// Adds `delta` to XLAT at (step, j, i) of `file`, in place.
void perturb_xlat(const std::filesystem::path& file, std::size_t step, std::size_t j, std::size_t i,
                  float delta) {
  int nc = 0, var = 0;
  ASSERT_EQ(nc_open(file.c_str(), NC_WRITE, &nc), NC_NOERR);
  ASSERT_EQ(nc_inq_varid(nc, "XLAT", &var), NC_NOERR);
  const std::size_t index[3] = {step, j, i};
  float v = 0;
  ASSERT_EQ(nc_get_var1_float(nc, var, index, &v), NC_NOERR);
  v += delta;
  ASSERT_EQ(nc_put_var1_float(nc, var, index, &v), NC_NOERR);
  ASSERT_EQ(nc_close(nc), NC_NOERR);
}

// Sets global attribute `name` of `file` to `value` (float, or int for MAP_PROJ).
void set_global(const std::filesystem::path& file, const char* name, double value) {
  int nc = 0;
  ASSERT_EQ(nc_open(file.c_str(), NC_WRITE, &nc), NC_NOERR);
  ASSERT_EQ(nc_redef(nc), NC_NOERR);
  if (std::string(name) == "MAP_PROJ") {
    const int v = static_cast<int>(value);
    ASSERT_EQ(nc_put_att_int(nc, NC_GLOBAL, name, NC_INT, 1, &v), NC_NOERR);
  } else {
    const float v = static_cast<float>(value);
    ASSERT_EQ(nc_put_att_float(nc, NC_GLOBAL, name, NC_FLOAT, 1, &v), NC_NOERR);
  }
  ASSERT_EQ(nc_close(nc), NC_NOERR);
}

TEST(WrfInputTest, LambertMappingPlacesEveryMassPointOnXlatXlong) {
  const testing::TempDir dir;
  const auto files = write_wrf(dir.path(), 1, false);
  const InputCatalog c = scan_inputs(files, {});
  ASSERT_TRUE(c.grid_mapping);
  EXPECT_EQ(c.grid_mapping->name, "lambert_conformal_conic");
  EXPECT_EQ(c.grid_mapping->attributes.at("earth_radius"), 6370000.0);
  EXPECT_EQ(c.x.kind, AxisKind::kProjectionX);
  EXPECT_EQ(c.y.kind, AxisKind::kProjectionY);
  EXPECT_EQ(c.x.units, "m");
  ASSERT_EQ(c.dims(), kDims);
  EXPECT_EQ(c.z.kind, AxisKind::kModelLevel);
  EXPECT_EQ(c.z.name, "bottom_top");
  EXPECT_EQ(c.z.values.front(), 0.0);
  EXPECT_EQ(c.z.values.back(), static_cast<double>(kDims.z - 1));
  // DX and DY steps, exactly.
  const double dx = global_float(files[0], "DX"), dy = global_float(files[0], "DY");
  for (std::size_t i = 1; i < c.x.size(); ++i)
    EXPECT_NEAR(c.x.values[i] - c.x.values[i - 1], dx, 1e-6);
  for (std::size_t j = 1; j < c.y.size(); ++j)
    EXPECT_NEAR(c.y.values[j] - c.y.values[j - 1], dy, 1e-6);

  // The axes through PROJ's cs2cs with the projection written out here, against the
  // file's float XLAT/XLONG and the generator's exact positions (double).
  const testing::NetcdfValues xlat = testing::read_netcdf_variable(files[0], "XLAT"),
                              xlong = testing::read_netcdf_variable(files[0], "XLONG");
  const synthetic::WrfGrid exact = synthetic::wrf_grid(kDims.x, kDims.y);
  if (!testing::have_cs2cs()) GTEST_SKIP() << "cs2cs (proj-bin) not installed";
  const std::string lcc =
      fmt::format("+proj=lcc +lat_1=30 +lat_2=60 +lat_0={} +lon_0={} +R=6370000 +units=m",
                  static_cast<double>(global_float(files[0], "MOAD_CEN_LAT")),
                  static_cast<double>(global_float(files[0], "STAND_LON")));
  std::vector<std::array<double, 2>> points;
  for (std::size_t j = 0; j < c.y.size(); ++j) {
    for (std::size_t i = 0; i < c.x.size(); ++i) points.push_back({c.x.values[i], c.y.values[j]});
  }
  const auto lonlat = testing::cs2cs(lcc, "+proj=longlat +R=6370000", points);
  ASSERT_TRUE(lonlat);
  ASSERT_EQ(lonlat->size(), points.size());
  double worst_file = 0, worst_exact = 0;
  for (std::size_t p = 0; p < points.size(); ++p) {
    worst_file = std::max({worst_file, std::abs((*lonlat)[p][0] - xlong.values[p]),
                           std::abs((*lonlat)[p][1] - xlat.values[p])});
    worst_exact = std::max({worst_exact, std::abs((*lonlat)[p][0] - exact.lon[p]),
                            std::abs((*lonlat)[p][1] - exact.lat[p])});
  }
  // float32 XLAT/XLONG near 50 N: half an ulp is 2e-6 degrees; cs2cs prints 6 decimals
  // of a degree in its default format (the tool's rounding: 5e-7 more).
  EXPECT_LT(worst_file, 5e-6);
  EXPECT_LT(worst_exact, 5e-6);
}

TEST(WrfInputTest, StaggeredWindsAreTheMeanOfTheirTwoNeighbours) {
  const testing::TempDir dir;
  const auto files = write_wrf(dir.path(), 2, false);
  ScanOptions o;
  o.variables = {"U", "V", "W", "T"};
  const InputCatalog c = scan_inputs(files, o);
  SlabReader reader(c, o);
  const std::size_t nx = kDims.x, ny = kDims.y, plane = nx * ny;
  const std::size_t z0 = 1, z1 = 4, step = 1;
  for (const char* name : {"U", "V", "W", "T"}) {
    const testing::NetcdfValues file = testing::read_netcdf_variable(files[0], name);
    ASSERT_EQ(file.shape.size(), 4u);
    const std::size_t fz = file.shape[1], fy = file.shape[2], fx = file.shape[3];
    const auto at = [&](std::size_t k, std::size_t j, std::size_t i) {
      return file.values[((step * fz + k) * fy + j) * fx + i];
    };
    std::vector<double> got((z1 - z0) * plane);
    std::vector<float> got_f((z1 - z0) * plane);
    reader.read(c.variable_index(name), step, z0, z1, std::span<double>(got));
    reader.read(c.variable_index(name), step, z0, z1, std::span<float>(got_f));
    for (std::size_t k = z0; k < z1; ++k) {
      for (std::size_t j = 0; j < ny; ++j) {
        for (std::size_t i = 0; i < nx; ++i) {
          double want = at(k, j, i);
          if (fx == nx + 1) want = 0.5 * (at(k, j, i) + at(k, j, i + 1));
          if (fy == ny + 1) want = 0.5 * (at(k, j, i) + at(k, j + 1, i));
          if (fz == kDims.z + 1) want = 0.5 * (at(k, j, i) + at(k + 1, j, i));
          const std::size_t s = (k - z0) * plane + j * nx + i;
          ASSERT_EQ(got[s], want) << name << " k " << k << " j " << j << " i " << i;
          ASSERT_EQ(got_f[s], static_cast<float>(want)) << name << " k " << k << " j " << j;
        }
      }
    }
    // The box reader (predictor trials) destaggers the same way.
    build::BoxReader box_reader(c, o, c.variable_index(name), step);
    const IndexBox box{{2, 3, z0}, {nx - 1, ny - 1, z1 - 1}};
    std::vector<double> in_box(box.count());
    box_reader.read(box, std::span<double>(in_box));
    std::size_t b = 0;
    for (std::size_t k = box.lo[2]; k <= box.hi[2]; ++k) {
      for (std::size_t j = box.lo[1]; j <= box.hi[1]; ++j) {
        for (std::size_t i = box.lo[0]; i <= box.hi[0]; ++i, ++b) {
          ASSERT_EQ(in_box[b], got[(k - z0) * plane + j * nx + i]) << name << " box " << b;
        }
      }
    }
  }
}

TEST(WrfInputTest, ThetaIsTPlus300Kelvin) {
  const testing::TempDir dir;
  const auto files = write_wrf(dir.path(), 2, false);
  ScanOptions o;
  o.variables = {"theta", "T"};  // T asked for by name: converted as it is
  const InputCatalog c = scan_inputs(files, o);
  EXPECT_EQ(c.variables[c.variable_index("T")].long_name,
            "perturbation potential temperature theta-t0");
  EXPECT_EQ(c.variables[c.variable_index("T")].value_offset, 0.0);
  const testing::NetcdfValues t = testing::read_netcdf_variable(files[0], "T");
  const std::size_t plane = kDims.x * kDims.y, level = kDims.z * plane;
  ASSERT_EQ(t.values.size(), 2 * level);
  SlabReader reader(c, o);
  const std::size_t theta = c.variable_index("theta");
  for (std::size_t step = 0; step < 2; ++step) {
    std::vector<double> got(level), perturbation(level);
    std::vector<float> got_f(level);
    reader.read(theta, step, 0, kDims.z, std::span<double>(got));
    reader.read(theta, step, 0, kDims.z, std::span<float>(got_f));
    reader.read(c.variable_index("T"), step, 0, kDims.z, std::span<double>(perturbation));
    for (std::size_t s = 0; s < level; ++s) {
      const double want = t.values[step * level + s] + 300.0;
      ASSERT_EQ(got[s], want) << "step " << step << " sample " << s;
      ASSERT_EQ(got_f[s], static_cast<float>(want)) << "step " << step << " sample " << s;
      ASSERT_EQ(perturbation[s], t.values[step * level + s]) << "step " << step << " sample " << s;
    }
    // The box reader (predictor trials) adds the same 300 K.
    build::BoxReader box_reader(c, o, theta, step);
    const IndexBox box{{1, 2, 1}, {kDims.x - 2, kDims.y - 1, kDims.z - 2}};
    std::vector<double> in_box(box.count());
    box_reader.read(box, std::span<double>(in_box));
    std::size_t b = 0;
    for (std::size_t k = box.lo[2]; k <= box.hi[2]; ++k) {
      for (std::size_t j = box.lo[1]; j <= box.hi[1]; ++j) {
        for (std::size_t i = box.lo[0]; i <= box.hi[0]; ++i, ++b) {
          ASSERT_EQ(in_box[b], got[k * plane + j * kDims.x + i]) << "box sample " << b;
        }
      }
    }
  }
}

TEST(WrfInputTest, DestaggerTakesTheMeanInDouble) {
  // Two samples whose float sum overflows: the mean is computed in double.
  const std::vector<double> in{3e38, 3e38, 1.0, 2.0};
  std::vector<float> out(2);
  destagger(in, Dims3{1, 2, 1}, StaggeredAxis::kX, std::span<float>(out));
  EXPECT_EQ(out[0], 3e38f);
  EXPECT_EQ(out[1], 1.5f);
  EXPECT_FALSE(staggered_axis({"bottom_top", "south_north", "west_east"}, {2, 3, 5},
                              Dims3{4, 3, 2}));  // one longer but not *_stag
  EXPECT_EQ(
      staggered_axis({"bottom_top", "south_north", "west_east_stag"}, {2, 3, 5}, Dims3{4, 3, 2}),
      StaggeredAxis::kX);
}

TEST(WrfInputTest, DefaultSelectionSkipsGeometrySourcesAndPlanes) {
  const testing::TempDir dir;
  const InputCatalog c = scan_inputs(write_wrf(dir.path(), 1, false), {});
  std::vector<std::string> names;
  for (const auto& v : c.variables) names.push_back(v.name);
  // T is offered as the potential temperature theta = T + 300 K, in its place.
  EXPECT_EQ(names,
            (std::vector<std::string>{"U", "V", "W", "theta", "P", "PB", "QVAPOR", "QCLOUD"}));
  const VariableMeta& theta = c.variables[c.variable_index("theta")];
  EXPECT_EQ(theta.units, "K");
  EXPECT_EQ(theta.long_name, "potential temperature (T + 300 K)");
  EXPECT_EQ(theta.standard_name, "air_potential_temperature");
  EXPECT_EQ(theta.source_variable, "T");
  EXPECT_EQ(theta.value_offset, 300.0);
  EXPECT_EQ(theta.store_type, DType::kFloat32);
  ASSERT_TRUE(c.vertical_geometry);
  EXPECT_EQ(c.vertical_geometry->sources, (std::vector<std::string>{"PH", "PHB"}));
  EXPECT_TRUE(c.vertical_geometry->varies_in_time);
  EXPECT_EQ(c.vertical_geometry->geopotential_gravity, 9.81);
  ASSERT_TRUE(c.surface);
  EXPECT_EQ(c.surface->variable, "HGT");
}

TEST(WrfInputTest, TimesBecomeSecondsSinceTheFirst) {
  const testing::TempDir dir;
  const InputCatalog c = scan_inputs(write_wrf(dir.path(), 3, false), {});
  EXPECT_EQ(c.time.units, "seconds since 2013-04-26 12:00:00");
  EXPECT_EQ(c.time.calendar, "standard");
  EXPECT_EQ(c.time.values, (std::vector<double>{0, kStepSeconds, 2 * kStepSeconds}));

  const TimeCoordinate t = wrf_time_coordinate(
      {"2016-02-28_23:00:00", "2016-02-29_01:30:00", std::string("2016-03-01_00:00:00\0", 20)},
      "f");
  EXPECT_EQ(t.units, "seconds since 2016-02-28 23:00:00");
  EXPECT_EQ(t.values, (std::vector<double>{0, 9000, 90000}));
  expect_error([] { wrf_time_coordinate({"2015-02-29_00:00:00"}, "f"); }, ErrorCode::kInvalidInput,
               {"f: Times of step 0", "2015-02-29_00:00:00"});
  expect_error(
      [] {
        wrf_time_coordinate({"2015-02-01_00:00:00", "2015-01-01_00:00:00"}, "f");
      },
      ErrorCode::kInvalidInput, {"step 1", "does not follow"});
}

TEST(WrfInputTest, OneFilePerStepMerges) {
  const testing::TempDir dir;
  const auto files = write_wrf(dir.path(), 2, true);
  ASSERT_EQ(files.size(), 2u);
  const InputCatalog c = scan_inputs(files, {});
  EXPECT_EQ(c.time.units, "seconds since 2013-04-26 12:00:00");
  EXPECT_EQ(c.time.values, (std::vector<double>{0, kStepSeconds}));
  const std::size_t t = c.variable_index("theta");
  EXPECT_EQ(c.locations[t][0].file, 0u);
  EXPECT_EQ(c.locations[t][1].file, 1u);
  EXPECT_EQ(c.locations[t][1].time_in_file, 0u);
}

TEST(WrfInputTest, PerturbedXlatIsRefusedNamingTheDeviation) {
  const testing::TempDir dir;
  const auto files = write_wrf(dir.path(), 1, false);
  perturb_xlat(files[0], 0, 5, 7, 0.01f);  // about 1.1 km north
  const std::string message = expect_error(
      [&] { scan_inputs(files, {}); }, ErrorCode::kInvalidInput,
      {files[0].filename().string(), "mass point (west_east 7, south_north 5) at step 0",
       "m from where MAP_PROJ 1"});
  // The deviation itself: about 1100 m.
  const auto at = message.find(") is ");
  ASSERT_NE(at, std::string::npos);
  const double deviation = std::stod(message.substr(at + 5));
  EXPECT_GT(deviation, 1000);
  EXPECT_LT(deviation, 1200);
}

TEST(WrfInputTest, XlatMovingBetweenStepsIsRefused) {
  const testing::TempDir dir;
  const auto files = write_wrf(dir.path(), 2, false);
  for (std::size_t j = 0; j < kDims.y; ++j) {
    for (std::size_t i = 0; i < kDims.x; ++i) perturb_xlat(files[0], 1, j, i, 0.05f);
  }
  expect_error([&] { scan_inputs(files, {}); }, ErrorCode::kInvalidInput,
               {"at step 1", "moving nest"});
}

TEST(WrfInputTest, AttributesThatDoNotDescribeTheGridAreRefused) {
  const testing::TempDir dir;
  const auto files = write_wrf(dir.path(), 1, false);
  set_global(files[0], "TRUELAT2", 45.0);  // another cone: the points no longer fit
  expect_error([&] { scan_inputs(files, {}); }, ErrorCode::kInvalidInput,
               {"XLAT/XLONG of mass point", "m from where MAP_PROJ 1", "inconsistent attributes"});
}

TEST(WrfInputTest, RotatedLatitudeLongitudeIsUnsupported) {
  const testing::TempDir dir;
  const auto files = write_wrf(dir.path(), 1, false);
  set_global(files[0], "MAP_PROJ", 6);
  set_global(files[0], "POLE_LAT", 40.0);
  expect_error([&] { scan_inputs(files, {}); }, ErrorCode::kUnsupported,
               {"MAP_PROJ 6 with POLE_LAT 40", "rotated"});
  // POLE_LAT 90: a regular latitude/longitude grid, which this Lambert grid is not.
  set_global(files[0], "POLE_LAT", 90.0);
  expect_error([&] { scan_inputs(files, {}); }, ErrorCode::kInvalidInput,
               {"degrees from where MAP_PROJ 6"});
}

// Replaces XLONG and XLAT of a one-step file by `lonlat` (ny x nx, x fastest).
void write_lonlat(const std::filesystem::path& file,
                  const std::vector<std::array<double, 2>>& lonlat) {
  int nc = 0, lon = 0, lat = 0;
  ASSERT_EQ(nc_open(file.c_str(), NC_WRITE, &nc), NC_NOERR);
  ASSERT_EQ(nc_inq_varid(nc, "XLONG", &lon), NC_NOERR);
  ASSERT_EQ(nc_inq_varid(nc, "XLAT", &lat), NC_NOERR);
  std::vector<float> lons, lats;
  for (const auto& p : lonlat) {
    lons.push_back(static_cast<float>(p[0]));
    lats.push_back(static_cast<float>(p[1]));
  }
  ASSERT_EQ(nc_put_var_float(nc, lon, lons.data()), NC_NOERR);
  ASSERT_EQ(nc_put_var_float(nc, lat, lats.data()), NC_NOERR);
  ASSERT_EQ(nc_close(nc), NC_NOERR);
}

struct OtherProjection {
  int map_proj;
  double truelat1, stand_lon;
  std::string proj;  // written here by hand, as WRF defines the projection
  std::string mapping;
  double x0, y0;
};

// Polar stereographic and Mercator grids (XLAT/XLONG from PROJ's cs2cs) are placed on
// axes that step by DX, DY from where cs2cs puts mass point (0, 0).
TEST(WrfInputTest, PolarStereographicAndMercatorGridsArePlaced) {
  if (!testing::have_cs2cs()) GTEST_SKIP() << "cs2cs (proj-bin) not installed";
  constexpr double kDx = 20000;
  const std::vector<OtherProjection> cases{
      {2, 60, -100, "+proj=stere +lat_0=90 +lat_ts=60 +lon_0=-100 +R=6370000 +units=m",
       "polar_stereographic", -130000, -4000000},
      {3, 30, 10, "+proj=merc +lat_ts=30 +lon_0=10 +R=6370000 +units=m", "mercator", -60000,
       4800000}};
  for (const OtherProjection& p : cases) {
    const testing::TempDir dir;
    const auto files = write_wrf(dir.path(), 1, false);
    std::vector<std::array<double, 2>> points;
    for (std::size_t j = 0; j < kDims.y; ++j) {
      for (std::size_t i = 0; i < kDims.x; ++i) {
        points.push_back(
            {p.x0 + static_cast<double>(i) * kDx, p.y0 + static_cast<double>(j) * kDx});
      }
    }
    const auto lonlat = testing::cs2cs(p.proj, "+proj=longlat +R=6370000", points);
    ASSERT_TRUE(lonlat);
    write_lonlat(files[0], *lonlat);
    set_global(files[0], "MAP_PROJ", p.map_proj);
    set_global(files[0], "TRUELAT1", p.truelat1);
    set_global(files[0], "STAND_LON", p.stand_lon);
    set_global(files[0], "DX", kDx);
    set_global(files[0], "DY", kDx);
    const InputCatalog c = scan_inputs(files, {});
    ASSERT_TRUE(c.grid_mapping) << p.mapping;
    EXPECT_EQ(c.grid_mapping->name, p.mapping);
    for (std::size_t i = 0; i < kDims.x; ++i) {
      EXPECT_NEAR(c.x.values[i], p.x0 + static_cast<double>(i) * kDx, 0.5) << p.mapping << " " << i;
    }
    for (std::size_t j = 0; j < kDims.y; ++j) {
      EXPECT_NEAR(c.y.values[j], p.y0 + static_cast<double>(j) * kDx, 0.5) << p.mapping << " " << j;
    }
  }
}

// MAP_PROJ 6 with POLE_LAT 90: longitude and latitude axes stepping DX / (R pi / 180).
TEST(WrfInputTest, RegularLatitudeLongitudeGridHasGeographicAxes) {
  const testing::TempDir dir;
  const auto files = write_wrf(dir.path(), 1, false);
  constexpr double kStep = 0.25, kLon0 = 5.0, kLat0 = 40.0;
  std::vector<std::array<double, 2>> lonlat;
  for (std::size_t j = 0; j < kDims.y; ++j) {
    for (std::size_t i = 0; i < kDims.x; ++i) {
      lonlat.push_back(
          {kLon0 + static_cast<double>(i) * kStep, kLat0 + static_cast<double>(j) * kStep});
    }
  }
  write_lonlat(files[0], lonlat);
  set_global(files[0], "MAP_PROJ", 6);
  const double dx = kStep * 6370000.0 * std::numbers::pi / 180.0;
  set_global(files[0], "DX", dx);
  set_global(files[0], "DY", dx);
  const InputCatalog c = scan_inputs(files, {});
  EXPECT_FALSE(c.grid_mapping);
  EXPECT_EQ(c.x.kind, AxisKind::kLongitude);
  EXPECT_EQ(c.y.kind, AxisKind::kLatitude);
  // DX is a float attribute: its rounding moves the last column by up to 1e-6 degrees.
  for (std::size_t i = 0; i < kDims.x; ++i) {
    EXPECT_NEAR(c.x.values[i], kLon0 + static_cast<double>(i) * kStep, 2e-6) << i;
  }
  for (std::size_t j = 0; j < kDims.y; ++j) {
    EXPECT_NEAR(c.y.values[j], kLat0 + static_cast<double>(j) * kStep, 2e-6) << j;
  }
}

}  // namespace
}  // namespace strielad::ingest
