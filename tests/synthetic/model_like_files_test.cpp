// SPDX-License-Identifier: Apache-2.0
// The model-like samples (--model icon, icon-cf, sigma-pressure) read back with netCDF:
// dimensions and CF attributes, terrain-following levels that sit on the terrain at
// the bottom and are flat at the top, formulas consistent with the fields, surface
// pressure that varies in time and with the terrain, values that follow the true height.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "sample_test_util.h"
#include "synthetic/model_like_files.h"
#include "synthetic/sample_args.h"
#include "synthetic/sample_grid.h"
#include "synthetic/sample_terrain.h"

namespace strielad::testing {
namespace {

using synthetic::SampleModel;

constexpr Dims3 kDims{40, 36, 30};

struct ModelSample {
  TempDir dir;
  synthetic::SampleResult result;
  ModelSample(SampleModel model, std::size_t steps, bool single_file, bool z_mc = false) {
    synthetic::SampleSpec spec;
    spec.dims = kDims;
    spec.steps = steps;
    spec.file_per_step = !single_file;
    spec.step_seconds = 1800;
    result = synthetic::write_model_like_dataset(spec, model, dir.path(), {.write_z_mc = z_mc});
  }
  const std::filesystem::path& file(std::size_t i = 0) const { return result.files.at(i).path; }
};

std::size_t at(std::size_t k, std::size_t c) { return k * kDims.x * kDims.y + c; }
constexpr std::size_t kColumns = kDims.x * kDims.y;

// Columns of the lowest and the highest terrain.
std::pair<std::size_t, std::size_t> lowest_and_highest(const std::vector<float>& surface) {
  const auto [lo, hi] = std::minmax_element(surface.begin(), surface.end());
  return {static_cast<std::size_t>(lo - surface.begin()),
          static_cast<std::size_t>(hi - surface.begin())};
}

TEST(ModelLikeFilesTest, ParsesModelNames) {
  EXPECT_EQ(synthetic::parse_sample_model("sample"), SampleModel::kSample);
  EXPECT_EQ(synthetic::parse_sample_model("icon"), SampleModel::kIcon);
  EXPECT_EQ(synthetic::parse_sample_model(" icon-cf"), SampleModel::kIconCf);
  EXPECT_EQ(synthetic::parse_sample_model("sigma-pressure"), SampleModel::kSigmaPressure);
  EXPECT_THROW(synthetic::parse_sample_model("ICON"), Error);
  EXPECT_THROW(synthetic::parse_sample_model(""), Error);
  synthetic::SampleSpec spec;
  spec.dims = Dims3{4, 4, 3};
  TempDir dir;
  EXPECT_THROW(synthetic::write_model_like_dataset(spec, SampleModel::kSample, dir.path()), Error);
}

TEST(ModelLikeFilesTest, TerrainOnTheLonLatGridHasMountainsAndSea) {
  const synthetic::SampleGrid grid(kDims);
  const std::vector<float> h = synthetic::sample_terrain_heights(grid.lon, grid.lat, 1);
  ASSERT_EQ(h.size(), kColumns);
  const auto [lo, hi] = std::minmax_element(h.begin(), h.end());
  EXPECT_EQ(*lo, 0.0f) << "the North Sea in the north-west corner";
  EXPECT_EQ(h[(kDims.y - 1) * kDims.x], 0.0f);
  EXPECT_GT(*hi, 1500.0f) << "the Alps in the south";
  EXPECT_LT(*hi, 5000.0f);
  EXPECT_NE(synthetic::sample_terrain_heights(grid.lon, grid.lat, 2), h) << "seeded detail";
}

TEST(ModelLikeFilesTest, IconHasHalfLevelHeightsOnTheTerrain) {
  const ModelSample s(SampleModel::kIcon, 2, true);
  ASSERT_EQ(s.result.files.size(), 1u);
  EXPECT_EQ(s.file().filename(), "icon.nc");
  const NcFile f(s.file());
  EXPECT_EQ(f.dim_length("time"), 2u);
  EXPECT_EQ(f.dim_length("height"), kDims.z);
  EXPECT_EQ(f.dim_length("height_2"), kDims.z + 1);
  EXPECT_EQ(f.dim_length("lat"), kDims.y);
  EXPECT_EQ(f.dim_length("lon"), kDims.x);
  EXPECT_FALSE(f.has_var("z_mc")) << "not unless asked";

  const std::vector<double> height = f.doubles("height"), height_2 = f.doubles("height_2");
  for (std::size_t k = 0; k < height_2.size(); ++k) {
    EXPECT_EQ(height_2[k], static_cast<double>(k + 1));
    if (k < height.size()) {
      EXPECT_EQ(height[k], static_cast<double>(k + 1));
    }
  }
  for (const char* axis : {"height", "height_2"}) {
    EXPECT_EQ(f.text_att(axis, "positive"), "down");
    EXPECT_EQ(f.text_att(axis, "axis"), "Z");
  }
  EXPECT_EQ(f.text_att("time", "units"), "day as %Y%m%d.%f");
  EXPECT_EQ(f.text_att("time", "calendar"), "proleptic_gregorian");
  const std::vector<double> time = f.doubles("time");
  EXPECT_DOUBLE_EQ(time[0], 20130426.5);
  EXPECT_NEAR(time[1], 20130426.5 + 1800.0 / 86400.0, 1e-8);
  EXPECT_EQ(f.text_att("lat", "units"), "degrees_north");
  EXPECT_EQ(f.text_att("lon", "units"), "degrees_east");

  EXPECT_EQ(f.dim_names("z_ifc"), (std::vector<std::string>{"height_2", "lat", "lon"}));
  EXPECT_EQ(f.dim_names("topography_c"), (std::vector<std::string>{"lat", "lon"}));
  EXPECT_EQ(f.text_att("z_ifc", "units"), "m");
  EXPECT_EQ(f.text_att("topography_c", "standard_name"), "surface_altitude");
  const std::vector<float> z_ifc = f.floats("z_ifc"), topo = f.floats("topography_c");
  for (std::size_t c = 0; c < kColumns; ++c) {
    EXPECT_EQ(z_ifc[at(kDims.z, c)], topo[c]) << "lowest half level on the ground, column " << c;
    EXPECT_EQ(z_ifc[at(0, c)], static_cast<float>(synthetic::kModelTop)) << "flat top";
    for (std::size_t k = 0; k < kDims.z; ++k) {
      ASSERT_GT(z_ifc[at(k, c)], z_ifc[at(k + 1, c)]) << "column " << c << " level " << k;
    }
  }
  const auto [low, high] = lowest_and_highest(topo);
  EXPECT_GT(topo[high] - topo[low], 1000.0f);
  EXPECT_GT(z_ifc[at(kDims.z - 1, high)] - z_ifc[at(kDims.z - 1, low)], 900.0f)
      << "terrain-following near the ground";

  for (const char* name : {"temp", "qc", "u", "v", "w"}) {
    EXPECT_EQ(f.dim_names(name), (std::vector<std::string>{"time", "height", "lat", "lon"}))
        << name;
    EXPECT_TRUE(f.has_att(name, "units")) << name;
    EXPECT_TRUE(f.has_att(name, "standard_name")) << name;
  }
  // Temperature falls with the true height: along every column below the tropopause,
  // and from the lowlands to the mountains on the lowest level.
  const std::vector<float> temp = f.step("temp", 0);
  for (std::size_t c = 0; c < kColumns; ++c) {
    for (std::size_t k = 0; k + 1 < kDims.z; ++k) {
      if (z_ifc[at(k, c)] < 10500.0f) {
        ASSERT_LT(temp[at(k, c)], temp[at(k + 1, c)]) << "column " << c << " level " << k;
      }
    }
  }
  const float lowest = temp[at(kDims.z - 1, low)], highest = temp[at(kDims.z - 1, high)];
  EXPECT_LT(highest, lowest - 0.002f * (topo[high] - topo[low]));
  for (const float t : temp) {
    EXPECT_GT(t, 190.0f);
    EXPECT_LT(t, 310.0f);
  }
  const std::vector<float> qc = f.floats("qc");
  const double cloudy = nonzero_fraction(qc);
  EXPECT_GT(cloudy, 0.0) << "a cloud";
  EXPECT_LT(cloudy, 0.1) << "mostly clear";
  EXPECT_LE(*std::max_element(qc.begin(), qc.end()), 2e-3f);
  EXPECT_GE(*std::min_element(qc.begin(), qc.end()), 0.0f);
}

TEST(ModelLikeFilesTest, IconZMcOnlyWhenAskedAndMidwayBetweenHalfLevels) {
  const ModelSample s(SampleModel::kIcon, 1, false, true);
  EXPECT_EQ(s.file().filename(), "icon_t000.nc");
  const NcFile f(s.file());
  EXPECT_EQ(f.dim_names("z_mc"), (std::vector<std::string>{"height", "lat", "lon"}));
  const std::vector<float> z_mc = f.floats("z_mc"), z_ifc = f.floats("z_ifc");
  for (std::size_t k = 0; k < kDims.z; ++k) {
    for (std::size_t c = 0; c < kColumns; c += 7) {
      EXPECT_NEAR(z_mc[at(k, c)], 0.5f * (z_ifc[at(k, c)] + z_ifc[at(k + 1, c)]),
                  1e-6f * z_ifc[at(k, c)] + 1e-3f);
    }
  }
}

TEST(ModelLikeFilesTest, IconCfIsHybridHeightWithTheSameFields) {
  const ModelSample icon(SampleModel::kIcon, 2, false, true);
  const ModelSample cf(SampleModel::kIconCf, 2, false);
  ASSERT_EQ(cf.result.files.size(), 2u);
  EXPECT_EQ(cf.file(1).filename(), "icon_cf_t001.nc");
  const NcFile f(cf.file(1)), g(icon.file(1));
  EXPECT_FALSE(f.has_var("z_ifc"));
  EXPECT_EQ(f.dim_length("lev"), kDims.z);
  EXPECT_EQ(f.text_att("lev", "standard_name"), "atmosphere_hybrid_height_coordinate");
  EXPECT_EQ(f.text_att("lev", "units"), "m");
  EXPECT_EQ(f.text_att("lev", "formula_terms"), "a: lev b: b orog: orog");
  EXPECT_EQ(f.text_att("time", "units"), "seconds since 2013-04-26 12:00:00");
  EXPECT_EQ(f.doubles("time"), std::vector<double>{1800.0});
  EXPECT_EQ(f.dim_names("b"), std::vector<std::string>{"lev"});
  EXPECT_EQ(f.text_att("orog", "standard_name"), "surface_altitude");

  const std::vector<double> a = f.doubles("lev"), b = f.doubles("b");
  const std::vector<float> orog = f.floats("orog");
  EXPECT_EQ(orog, g.floats("topography_c"));
  const std::vector<float> z_mc = g.floats("z_mc");
  for (std::size_t k = 0; k < kDims.z; ++k) {
    if (k + 1 < kDims.z) {
      EXPECT_GT(a[k], a[k + 1]) << "top first";
      EXPECT_LT(b[k], b[k + 1]);
    }
    EXPECT_GT(b[k], 0.0);
    EXPECT_LT(b[k], 1.0);
    for (std::size_t c = 0; c < kColumns; ++c) {
      const double z = a[k] + b[k] * orog[c];
      ASSERT_NEAR(z, z_mc[at(k, c)], 1e-6 * z + 1e-3) << "a + b * orog is ICON's z_mc";
    }
  }
  for (const char* name : {"temp", "qc", "u", "v", "w"}) {
    EXPECT_EQ(f.dim_names(name), (std::vector<std::string>{"time", "lev", "lat", "lon"}));
    EXPECT_EQ(f.floats(name), g.floats(name)) << name << ": the same fields as icon";
  }
}

TEST(ModelLikeFilesTest, SigmaPressureHasSurfacePressureVaryingInTimeAndWithTerrain) {
  const ModelSample s(SampleModel::kSigmaPressure, 3, true);
  EXPECT_EQ(s.file().filename(), "sigma_pressure.nc");
  const NcFile f(s.file());
  EXPECT_EQ(f.dim_length("time"), 3u);
  EXPECT_EQ(f.doubles("time"), (std::vector<double>{0.0, 1800.0, 3600.0}));
  EXPECT_EQ(f.text_att("lev", "standard_name"), "atmosphere_hybrid_sigma_pressure_coordinate");
  EXPECT_EQ(f.text_att("lev", "formula_terms"), "ap: hyam b: hybm ps: ps");
  EXPECT_EQ(f.text_att("lev", "positive"), "down");
  EXPECT_EQ(f.text_att("hyam", "units"), "Pa");
  EXPECT_EQ(f.text_att("ps", "units"), "Pa");
  EXPECT_EQ(f.text_att("ps", "standard_name"), "surface_air_pressure");
  EXPECT_EQ(f.dim_names("ps"), (std::vector<std::string>{"time", "lat", "lon"}));
  EXPECT_EQ(f.dim_names("orog"), (std::vector<std::string>{"lat", "lon"}));
  for (const char* name : {"t", "q", "u", "v"}) {
    EXPECT_EQ(f.dim_names(name), (std::vector<std::string>{"time", "lev", "lat", "lon"}));
  }

  const std::vector<double> hyam = f.doubles("hyam"), hybm = f.doubles("hybm"),
                            lev = f.doubles("lev");
  const std::vector<float> ps = f.floats("ps"), orog = f.floats("orog");
  EXPECT_NE(std::vector<float>(ps.begin(), ps.begin() + kColumns),
            std::vector<float>(ps.end() - kColumns, ps.end()))
      << "ps varies in time";
  const auto [low, high] = lowest_and_highest(orog);
  EXPECT_LT(ps[high], ps[low] - 10000.0f) << "lower over the mountains";
  for (const float p : ps) {
    EXPECT_GT(p, 50000.0f);
    EXPECT_LT(p, 106000.0f);
  }
  for (std::size_t k = 0; k < kDims.z; ++k) {
    EXPECT_NEAR(lev[k], hyam[k] / 101325.0 + hybm[k], 1e-12);
    if (k + 1 < kDims.z) {
      EXPECT_LT(lev[k], lev[k + 1]) << "top to bottom";
    }
  }
  const std::vector<float> t = f.floats("t"), q = f.floats("q");
  for (std::size_t step = 0; step < 3; ++step) {
    for (std::size_t c = 0; c < kColumns; ++c) {
      const double surface = ps[step * kColumns + c];
      for (std::size_t k = 0; k + 1 < kDims.z; ++k) {
        ASSERT_LT(hyam[k] + hybm[k] * surface, hyam[k + 1] + hybm[k + 1] * surface);
      }
      EXPECT_LT(hyam[kDims.z - 1] + hybm[kDims.z - 1] * surface, surface);
    }
  }
  for (std::size_t i = 0; i < t.size(); ++i) {
    ASSERT_GT(t[i], 190.0f);
    ASSERT_LT(t[i], 310.0f);
    ASSERT_GT(q[i], 0.0f);
    ASSERT_LT(q[i], 0.03f);
  }
  // The lowest level is warmer in the lowlands than over the mountains.
  const std::size_t bottom = (kDims.z - 1) * kColumns;
  EXPECT_GT(t[bottom + low], t[bottom + high] + 5.0f);
}

TEST(ModelLikeFilesTest, SameSeedGivesTheSameFiles) {
  const ModelSample a(SampleModel::kSigmaPressure, 1, true), b(SampleModel::kSigmaPressure, 1, true);
  const NcFile fa(a.file()), fb(b.file());
  for (const char* name : {"t", "q", "u", "v", "ps", "orog"}) {
    EXPECT_EQ(fa.floats(name), fb.floats(name)) << name;
  }
}

}  // namespace
}  // namespace strielad::testing
