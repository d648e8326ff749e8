// SPDX-License-Identifier: Apache-2.0
// GRIB model levels placed in pressure or height (generated files): IFS-like hybrid
// levels by their pv coefficients and lnsp, COSMO-like generalVerticalLayer levels by HHL
// with HSURF as the surface. The catalog finds them, SlabReader evaluates them (checked
// against the formulas computed here from the decoded messages), a conversion stores them
// (format 5); what cannot be placed is refused.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <mutex>
#include <string>
#include <vector>

#include "convert/converter.h"
#include "ingest/grib_catalog.h"
#include "ingest/grib_messages.h"
#include "ingest/grib_scan.h"
#include "ingest/slab_reader.h"
#include "store/store.h"
#include "support/expect_error.h"
#include "support/grib_fixture.h"
#include "support/temp_dir.h"

namespace strielad {
namespace {

using testing::GribFixtureMessage;

constexpr std::size_t kNi = 16, kNj = 31, kPlane = kNi * kNj;  // regular_ll_pl_grib2's grid
constexpr const char* kSample = "regular_ll_pl_grib2";

// Half levels 0 (top) .. 5 (surface): a in Pa, then b.
const std::vector<double> kPv{0, 2000, 5000, 6000, 3000, 0, 0, 0, 0.1, 0.4, 0.8, 1};

std::vector<double> field(double base, double per_sample) {
  std::vector<double> v(kPlane);
  for (std::size_t i = 0; i < kPlane; ++i) {
    v[i] = base + per_sample * static_cast<double>((i * 7) % 23);
  }
  return v;
}

GribFixtureMessage hybrid_t(long level, long step, const std::vector<double>& pv = kPv) {
  return {kSample,
          {{"typeOfLevel", std::string("hybrid")},
           {"level", level},
           {"NV", static_cast<long>(pv.size())},
           {"pv", pv},
           {"step", step},
           {"bitsPerValue", 16L}},
          field(280.0 - 10.0 * static_cast<double>(level), 0.25)};
}

GribFixtureMessage lnsp(long step) {
  std::vector<double> v = field(95000.0 + 100.0 * static_cast<double>(step), 300.0);
  for (double& x : v) x = std::log(x);
  return {kSample,
          {{"typeOfLevel", std::string("hybrid")},
           {"level", 1L},
           {"shortName", std::string("lnsp")},
           {"step", step},
           {"bitsPerValue", 24L}},
          v};
}

// t on hybrid levels 2, 3 and 5 of 5 (a subset: each keeps its own number), lnsp, steps
// 0 and 6 h.
std::vector<GribFixtureMessage> ifs_messages() {
  std::vector<GribFixtureMessage> m;
  for (const long step : {0L, 6L}) {
    for (const long level : {2L, 3L, 5L}) m.push_back(hybrid_t(level, step));
    m.push_back(lnsp(step));
  }
  return m;
}

std::vector<double> decoded(const std::filesystem::path& path,
                            const ingest::GribMessageSummary& m) {
  std::lock_guard lock(ingest::eccodes_mutex());
  return ingest::read_grib_message(path, m).double_array_key("values", path.string());
}

// The pv a message holds: GRIB keeps the coefficients as float32.
std::vector<double> decoded_pv(const std::filesystem::path& path,
                               const ingest::GribMessageSummary& m) {
  std::lock_guard lock(ingest::eccodes_mutex());
  return ingest::read_grib_message(path, m).double_array_key("pv", path.string());
}

const ingest::GribVariable& plane_named(const ingest::GribScan& scan, const std::string& name) {
  for (const auto& v : scan.planes) {
    if (v.short_name == name) return v;
  }
  throw make_error(ErrorCode::kNotFound, "no plane '{}'", name);
}

const ingest::GribVariable& variable_named(const ingest::GribScan& scan, const std::string& name) {
  for (const auto& v : scan.variables) {
    if (v.short_name == name) return v;
  }
  throw make_error(ErrorCode::kNotFound, "no variable '{}'", name);
}

build::ConvertOptions options(const std::filesystem::path& input,
                              const std::filesystem::path& store) {
  build::ConvertOptions o;
  o.inputs = {input};
  o.store = store;
  o.brick = 16;
  o.threads = 1;
  return o;
}

TEST(GribModelLevelsTest, HybridLevelsArePlacedByPressureFromPvAndLnsp) {
  const testing::TempDir dir;
  const auto path = dir / "ifs.grb2";
  testing::write_grib_file(path, ifs_messages());
  const ingest::InputCatalog c = ingest::grib_catalog({path}, {});
  ASSERT_EQ(c.variables.size(), 1u);
  EXPECT_EQ(c.variables[0].name, "t");
  EXPECT_EQ(c.z.values, (std::vector<double>{2, 3, 5}));
  ASSERT_EQ(c.time.size(), 2u);
  ASSERT_TRUE(c.vertical_geometry);
  const auto& g = *c.vertical_geometry;
  EXPECT_EQ(g.quantity, ingest::VerticalGeometrySource::Quantity::kPressure);
  EXPECT_EQ(g.formula, "atmosphere_hybrid_sigma_pressure_coordinate");
  EXPECT_EQ(g.terms,
            (std::map<std::string, std::string>{{"a", "pv"}, {"b", "pv"}, {"ps", "lnsp"}}));
  EXPECT_TRUE(g.varies_in_time);
  EXPECT_FALSE(c.surface);

  const ingest::GribScan scan = ingest::scan_grib_file(path);
  const ingest::GribVariable& ln = plane_named(scan, "lnsp");
  ASSERT_EQ(ln.times.size(), 2u);
  const std::vector<double> pv = decoded_pv(path, variable_named(scan, "t").messages[0][0]);
  ASSERT_EQ(pv.size(), kPv.size());
  for (std::size_t i = 0; i < pv.size(); ++i) EXPECT_NEAR(pv[i], kPv[i], 1e-6 * kPv[i]);
  ingest::SlabReader reader(c, {});
  const std::size_t n = pv.size() / 2 - 1;
  for (std::size_t step = 0; step < 2; ++step) {
    const std::vector<double> lnps = decoded(path, ln.messages[step][0]);
    std::vector<double> got(3 * kPlane);
    reader.read_vertical_geometry(step, 0, 3, got);
    for (std::size_t k = 0; k < 3; ++k) {
      const auto level = static_cast<std::size_t>(c.z.values[k]);
      for (std::size_t s = 0; s < kPlane; ++s) {
        const double ps = std::exp(lnps[s]);
        const double above = pv[level - 1] + pv[n + 1 + level - 1] * ps;
        const double below = pv[level] + pv[n + 1 + level] * ps;
        ASSERT_DOUBLE_EQ(got[k * kPlane + s], (above + below) / 2)
            << "step " << step << " level " << level << " sample " << s;
      }
    }
    // A slab in the middle gives the same levels.
    std::vector<double> one(kPlane);
    reader.read_vertical_geometry(step, 1, 2, one);
    for (std::size_t s = 0; s < kPlane; ++s) ASSERT_EQ(one[s], got[kPlane + s]);
  }
}

TEST(GribModelLevelsTest, HybridLevelsConvertToAStoreWithAPressureField) {
  const testing::TempDir dir;
  const auto path = dir / "ifs.grb2";
  testing::write_grib_file(path, ifs_messages());
  build::convert(options(path, dir / "store"));
  const auto store = Store::open(dir / "store");
  const auto& m = store->manifest();
  EXPECT_EQ(m.format_version, 5u);
  ASSERT_TRUE(m.geometry);
  EXPECT_EQ(m.geometry->vertical.kind, format::VerticalGeometry::Kind::kField);
  EXPECT_EQ(m.geometry->vertical.quantity, format::VerticalGeometry::Quantity::kPressure);
  EXPECT_EQ(m.geometry->vertical.formula, "atmosphere_hybrid_sigma_pressure_coordinate");
  EXPECT_EQ(m.geometry->vertical.sources, std::vector<std::string>{"lnsp"});
  EXPECT_TRUE(m.geometry->vertical.varies_in_time);
  EXPECT_EQ(m.variables.size(), 1u);
}

TEST(GribModelLevelsTest, NetcdfLevelOptionsAreRefusedRatherThanIgnored) {
  const testing::TempDir dir;
  const auto path = dir / "ifs.grb2";
  testing::write_grib_file(path, ifs_messages());
  build::ConvertOptions with_height = options(path, dir / "store");
  with_height.scan.height_var = "z";
  testing::expect_error([&] { build::convert(with_height); }, ErrorCode::kInvalidArgument,
                        {path.string(), "--height-var applies to netCDF input only"});
  build::ConvertOptions with_term = options(path, dir / "store");
  with_term.scan.formula_constants["P0"] = 100000;
  testing::expect_error([&] { build::convert(with_term); }, ErrorCode::kInvalidArgument,
                        {"--formula-term applies to netCDF input only"});
  EXPECT_FALSE(std::filesystem::exists(dir / "store"));
}

TEST(GribModelLevelsTest, SurfacePressureSpServesAsWellAsLnsp) {
  const testing::TempDir dir;
  std::vector<GribFixtureMessage> m;
  for (const long level : {1L, 4L}) m.push_back(hybrid_t(level, 0));
  m.push_back({kSample,
               {{"typeOfLevel", std::string("surface")}, {"shortName", std::string("sp")}},
               field(100000.0, 50.0)});
  testing::write_grib_file(dir / "sp.grb2", m);
  const ingest::InputCatalog c = ingest::grib_catalog({dir / "sp.grb2"}, {});
  ASSERT_TRUE(c.vertical_geometry);
  EXPECT_EQ(c.vertical_geometry->terms.at("ps"), "sp");
  const ingest::GribScan scan = ingest::scan_grib_file(dir / "sp.grb2");
  const std::vector<double> ps = decoded(dir / "sp.grb2", plane_named(scan, "sp").messages[0][0]);
  const std::vector<double> pv =
      decoded_pv(dir / "sp.grb2", variable_named(scan, "t").messages[0][0]);
  std::vector<double> got(2 * kPlane);
  ingest::SlabReader(c, {}).read_vertical_geometry(0, 0, 2, got);
  const std::size_t n = 5;
  for (std::size_t s = 0; s < kPlane; ++s) {
    // Level 1: half levels 0 and 1; level 4: half levels 3 and 4.
    EXPECT_DOUBLE_EQ(got[s], ((pv[0] + pv[n + 1] * ps[s]) + (pv[1] + pv[n + 2] * ps[s])) / 2);
    EXPECT_DOUBLE_EQ(got[kPlane + s],
                     ((pv[3] + pv[n + 4] * ps[s]) + (pv[4] + pv[n + 5] * ps[s])) / 2);
  }
}

TEST(GribModelLevelsTest, SurfaceGeopotentialBecomesTheSurfaceHeight) {
  const testing::TempDir dir;
  const auto path = dir / "ifs.grb2";
  auto m = ifs_messages();
  m.push_back({kSample,
               {{"typeOfLevel", std::string("surface")},
                {"shortName", std::string("z")},
                {"bitsPerValue", 24L}},
               field(500.0, 900.0)});
  testing::write_grib_file(path, m);
  const ingest::InputCatalog c = ingest::grib_catalog({path}, {});
  ASSERT_TRUE(c.surface);
  EXPECT_EQ(c.surface->variable, "z");
  const ingest::GribScan scan = ingest::scan_grib_file(path);
  const std::vector<double> z = decoded(path, plane_named(scan, "z").messages[0][0]);
  std::vector<double> got(kPlane);
  ingest::SlabReader(c, {}).read_surface(got);
  for (std::size_t s = 0; s < kPlane; ++s) EXPECT_DOUBLE_EQ(got[s], z[s] / 9.80665) << s;
}

TEST(GribModelLevelsTest, LnspMissingAtOneStepIsRefusedNamingTheStep) {
  const testing::TempDir dir;
  auto m = ifs_messages();
  m.pop_back();  // lnsp at 6 h
  testing::write_grib_file(dir / "ifs.grb2", m);
  testing::expect_error([&] { ingest::grib_catalog({dir / "ifs.grb2"}, {}); },
                        ErrorCode::kInvalidInput, {"'lnsp'", "time step 1"});
}

TEST(GribModelLevelsTest, HybridLevelsWithPvButNoSurfacePressureAreRefused) {
  const testing::TempDir dir;
  std::vector<GribFixtureMessage> m;
  for (const long level : {2L, 3L}) m.push_back(hybrid_t(level, 0));
  testing::write_grib_file(dir / "t.grb2", m);
  testing::expect_error([&] { ingest::grib_catalog({dir / "t.grb2"}, {}); },
                        ErrorCode::kInvalidInput, {"'lnsp'", "'sp'"});
}

TEST(GribModelLevelsTest, DifferentPvInOneSetIsRefusedNamingBothMessages) {
  const testing::TempDir dir;
  auto m = ifs_messages();
  std::vector<double> other = kPv;
  other[2] = 5100;
  m[2] = hybrid_t(5, 0, other);
  testing::write_grib_file(dir / "ifs.grb2", m);
  const ingest::GribScan scan = ingest::scan_grib_file(dir / "ifs.grb2");
  const auto& t = variable_named(scan, "t");
  const std::string first = fmt::format("byte {} ", t.messages[0][0].offset);
  const std::string second = fmt::format("byte {} ", t.messages[0][2].offset);
  testing::expect_error([&] { ingest::grib_catalog({dir / "ifs.grb2"}, {}); },
                        ErrorCode::kInvalidInput,
                        {"different hybrid level coefficients", first, second});
}

TEST(GribModelLevelsTest, LevelBeyondThePvIsRefused) {
  const testing::TempDir dir;
  std::vector<GribFixtureMessage> m{hybrid_t(4, 0), hybrid_t(6, 0), lnsp(0)};
  testing::write_grib_file(dir / "ifs.grb2", m);
  testing::expect_error([&] { ingest::grib_catalog({dir / "ifs.grb2"}, {}); },
                        ErrorCode::kInvalidInput, {"hybrid level 6", "1 .. 5"});
}

// COSMO: t on layers 1..3, HHL on half levels 1..4 (top down), HSURF.
std::vector<GribFixtureMessage> cosmo_messages() {
  std::vector<GribFixtureMessage> m;
  for (long k = 1; k <= 3; ++k) {
    m.push_back({kSample,
                 {{"centre", 78L},
                  {"typeOfLevel", std::string("generalVerticalLayer")},
                  {"scaleFactorOfFirstFixedSurface", 0L},
                  {"scaledValueOfFirstFixedSurface", k},
                  {"scaleFactorOfSecondFixedSurface", 0L},
                  {"scaledValueOfSecondFixedSurface", k + 1},
                  {"bitsPerValue", 16L}},
                 field(230.0 + 15.0 * static_cast<double>(k), 0.5)});
  }
  for (long k = 1; k <= 4; ++k) {
    m.push_back({kSample,
                 {{"centre", 78L},
                  {"discipline", 0L},
                  {"parameterCategory", 3L},
                  {"parameterNumber", 6L},
                  {"typeOfLevel", std::string("generalVertical")},
                  {"typeOfSecondFixedSurface", 101L},
                  {"scaleFactorOfFirstFixedSurface", 0L},
                  {"scaledValueOfFirstFixedSurface", k},
                  {"bitsPerValue", 24L}},
                 field(14000.0 - 3500.0 * static_cast<double>(k), 20.0)});
  }
  m.push_back({kSample,
               {{"centre", 78L},
                {"discipline", 0L},
                {"parameterCategory", 3L},
                {"parameterNumber", 6L},
                {"typeOfLevel", std::string("surface")},
                {"typeOfSecondFixedSurface", 101L},
                {"scaledValueOfFirstFixedSurface", 0L},
                {"bitsPerValue", 24L}},
               field(0.0, 20.0)});
  return m;
}

TEST(GribModelLevelsTest, CosmoLayersArePlacedBetweenTheirHalfLevelHeights) {
  const testing::TempDir dir;
  const auto path = dir / "cosmo.grb2";
  testing::write_grib_file(path, cosmo_messages());
  const ingest::InputCatalog c = ingest::grib_catalog({path}, {});
  ASSERT_EQ(c.variables.size(), 1u);  // HHL places the levels: not a variable
  EXPECT_EQ(c.variables[0].name, "t");
  EXPECT_EQ(c.z.values, (std::vector<double>{1, 2, 3}));
  ASSERT_TRUE(c.vertical_geometry);
  EXPECT_EQ(c.vertical_geometry->quantity, ingest::VerticalGeometrySource::Quantity::kHeight);
  EXPECT_EQ(c.vertical_geometry->formula, "variable");
  EXPECT_EQ(c.vertical_geometry->sources, std::vector<std::string>{"HHL"});
  EXPECT_FALSE(c.vertical_geometry->varies_in_time);
  ASSERT_TRUE(c.surface);
  EXPECT_EQ(c.surface->variable, "HSURF");

  const ingest::GribScan scan = ingest::scan_grib_file(path);
  const ingest::GribVariable& hhl = variable_named(scan, "HHL");
  ASSERT_EQ(hhl.z.values, (std::vector<double>{1, 2, 3, 4}));
  std::vector<std::vector<double>> half;
  for (std::size_t k = 0; k < 4; ++k) half.push_back(decoded(path, hhl.messages[0][k]));
  ingest::SlabReader reader(c, {});
  std::vector<double> got(3 * kPlane);
  reader.read_vertical_geometry(0, 0, 3, got);
  for (std::size_t k = 0; k < 3; ++k) {
    for (std::size_t s = 0; s < kPlane; ++s) {
      ASSERT_EQ(got[k * kPlane + s], 0.5 * (half[k][s] + half[k + 1][s]))
          << "layer " << k + 1 << " sample " << s;
    }
  }
  std::vector<double> surface(kPlane);
  reader.read_surface(surface);
  const std::vector<double> hsurf = decoded(path, plane_named(scan, "HSURF").messages[0][0]);
  EXPECT_EQ(surface, hsurf);
}

TEST(GribModelLevelsTest, CosmoLayersConvertToAStoreWithAHeightField) {
  const testing::TempDir dir;
  const auto path = dir / "cosmo.grb2";
  testing::write_grib_file(path, cosmo_messages());
  build::convert(options(path, dir / "store"));
  const auto store = Store::open(dir / "store");
  const auto& m = store->manifest();
  EXPECT_EQ(m.format_version, 5u);
  ASSERT_TRUE(m.geometry);
  EXPECT_EQ(m.geometry->vertical.quantity, format::VerticalGeometry::Quantity::kHeight);
  EXPECT_EQ(m.geometry->vertical.sources, std::vector<std::string>{"HHL"});
  EXPECT_FALSE(m.geometry->vertical.varies_in_time);
  ASSERT_TRUE(m.geometry->surface);
  EXPECT_EQ(m.geometry->surface->variable, "HSURF");
}

TEST(GribModelLevelsTest, CosmoLayerWithoutItsLowerHalfLevelIsRefused) {
  const testing::TempDir dir;
  auto m = cosmo_messages();
  m.erase(m.begin() + 6);  // HHL half level 4
  testing::write_grib_file(dir / "cosmo.grb2", m);
  testing::expect_error([&] { ingest::grib_catalog({dir / "cosmo.grb2"}, {}); },
                        ErrorCode::kInvalidInput, {"HHL has no half level 4"});
}

}  // namespace
}  // namespace strielad
