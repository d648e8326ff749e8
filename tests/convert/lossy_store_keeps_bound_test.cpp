// SPDX-License-Identifier: Apache-2.0
// strielad-convert --lossy (store format version 6, zfp chunks): every valid sample of every
// brick of every level reads back within the variable's bound of what the lossless store
// holds, missing samples stay missing, lossless variables stay bit for bit; the index keeps
// the original min/max/valid counts; the manifest records mode and tolerance (rel resolved
// against the variable's range); bricks zfp cannot keep within the bound (1e30 next to
// ordinary values) are counted and stored losslessly; real model output (libncarg-data)
// keeps the bound too; bad requests name --lossy.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <fstream>

#include "convert/converter.h"
#include "store/store.h"
#include "store/store_verifier.h"
#include "support/expect_error.h"
#include "support/netcdf_fixture.h"
#include "support/temp_dir.h"
#include "synthetic/sample_dataset.h"

namespace strielad {
namespace {

using testing::expect_error;
using testing::TempDir;

build::ConvertOptions options(const std::vector<std::filesystem::path>& inputs,
                              const std::filesystem::path& store, std::uint32_t brick) {
  build::ConvertOptions o;
  o.inputs = inputs;
  o.store = store;
  o.brick = brick;
  o.threads = 2;
  return o;
}

struct BoundCheck {
  std::size_t zfp_chunks = 0, samples = 0;
  double max_error = 0;
};

// Every brick of every step and level of `lossy` against `exact`: the same kind and index
// statistics, missing where missing, within `bound[v]` (0: bit for bit) elsewhere.
void expect_bound_on_every_brick(const Store& exact, const Store& lossy,
                                 const std::vector<double>& bound, BoundCheck& check) {
  for (std::uint32_t v = 0; v < exact.variable_count(); ++v) {
    const std::string& name = exact.manifest().variables[v].name;
    for (std::uint32_t t = 0; t < exact.step_count(); ++t) {
      const auto ee = exact.index(t, v);
      const auto le = lossy.index(t, v);
      EXPECT_EQ(ee.size(), le.size());
      for (NodeId n = 0; n < ee.size(); ++n) {
        EXPECT_EQ(ee[n].kind, le[n].kind) << name << " node " << n;
        EXPECT_EQ(ee[n].valid_count, le[n].valid_count) << name << " node " << n;
        EXPECT_TRUE(std::memcmp(&ee[n].min, &le[n].min, 8) == 0 &&
                    std::memcmp(&ee[n].max, &le[n].max, 8) == 0)
            << name << " node " << n << ": index range is not the original's";
        check.zfp_chunks += le[n].coding == format::ChunkCoding::kZfp ? 1 : 0;
        if (bound[v] == 0) {
          EXPECT_NE(le[n].coding, format::ChunkCoding::kZfp) << name;
        }
        const Brick a = exact.read_brick(t, v, n), b = lossy.read_brick(t, v, n);
        for (std::size_t i = 0; i < a.sample_count(); ++i) {
          const double x = a.sample(i), y = b.sample(i);
          ++check.samples;
          if (std::isnan(x)) {
            ASSERT_TRUE(std::isnan(y)) << name << " step " << t << " node " << n << " sample " << i;
            continue;
          }
          ASSERT_TRUE(std::isfinite(y)) << name << " node " << n << " sample " << i;
          const double e = std::abs(x - y);
          ASSERT_LE(e, bound[v]) << name << " step " << t << " node " << n << " sample " << i
                                 << ": " << x << " read as " << y;
          check.max_error = std::max(check.max_error, e);
        }
      }
    }
  }
}

class LossySampleStoreTest : public ::testing::Test {
 protected:
  void SetUp() override {
    synthetic::SampleSpec spec;
    spec.dims = {48, 40, 20};
    spec.steps = 2;
    spec.variables = {"clw", "ta", "qr"};
    for (const auto& f : synthetic::write_sample_dataset(spec, dir_ / "input").files) {
      inputs_.push_back(f.path);
    }
    build::convert(options(inputs_, dir_ / "plain", 12));
    auto o = options(inputs_, dir_ / "lossy", 12);
    o.lossy = build::parse_lossy("ta=abs:0.05,clw=rel:1e-3");
    result_ = build::convert(o);
  }
  TempDir dir_;
  std::vector<std::filesystem::path> inputs_;
  build::ConvertResult result_;
};

TEST_F(LossySampleStoreTest, BoundHoldsOnEveryBrickAndIndexRangesStayOriginal) {
  const auto plain = Store::open(dir_ / "plain");
  const auto lossy = Store::open(dir_ / "lossy");
  const auto& m = lossy->manifest();
  const format::LossySpec* clw = &*m.codec_of(m.variable_index("clw")).zfp;
  std::vector<double> bound(m.variables.size(), 0.0);
  bound[m.variable_index("ta")] = 0.05;
  bound[m.variable_index("clw")] = clw->tolerance;
  BoundCheck check;
  expect_bound_on_every_brick(*plain, *lossy, bound, check);
  EXPECT_GT(check.zfp_chunks, 0u);
  EXPECT_GT(check.max_error, 0.0);  // it is lossy
  EXPECT_EQ(result_.lossy, check.zfp_chunks);
  std::uint64_t plain_bytes = 0, lossy_bytes = 0;
  const std::uint32_t ta = static_cast<std::uint32_t>(m.variable_index("ta"));
  for (std::uint32_t t = 0; t < 2; ++t) {
    for (const auto& e : plain->index(t, ta)) plain_bytes += e.chunk_size;
    for (const auto& e : lossy->index(t, ta)) lossy_bytes += e.chunk_size;
  }
  EXPECT_LT(lossy_bytes * 4, plain_bytes * 3) << "temperature within 0.05 K is not 25% smaller ("
                                          << result_.lossy << " zfp, " << result_.lossy_fallback
                                          << " fallback bricks)";
  const VerifyReport report = verify_store(dir_ / "lossy");
  EXPECT_TRUE(report.ok()) << (report.problems.empty() ? "" : report.problems.front());
}

TEST_F(LossySampleStoreTest, ManifestRecordsModeAndToleranceAndOnlyLossyStoresAreVersion6) {
  const auto plain = Store::open(dir_ / "plain");
  const auto lossy = Store::open(dir_ / "lossy");
  EXPECT_EQ(plain->manifest().format_version, 2u);
  EXPECT_EQ(lossy->manifest().format_version, format::kManifestVersionLossy);
  const auto& m = lossy->manifest();
  EXPECT_FALSE(m.codec.zfp.has_value());
  EXPECT_FALSE(m.codec_of(m.variable_index("qr")).zfp.has_value());
  const format::LossySpec ta = *m.codec_of(m.variable_index("ta")).zfp;
  EXPECT_EQ(ta, (format::LossySpec{format::LossyMode::kAbsolute, 0.05, 0.05}));
  const format::LossySpec clw = *m.codec_of(m.variable_index("clw")).zfp;
  EXPECT_EQ(clw.mode, format::LossyMode::kRelative);
  EXPECT_EQ(clw.value, 1e-3);
  const auto& range = plain->manifest().summary["variables"]["clw"];
  EXPECT_DOUBLE_EQ(clw.tolerance, 1e-3 * (range["max"].get<double>() - range["min"].get<double>()));
  EXPECT_EQ(result_.codecs["ta"]["zfp"]["tolerance"].get<double>(), 0.05);
  EXPECT_EQ(result_.to_json()["lossy"]["fallback_bricks"].get<std::uint64_t>(), result_.lossy_fallback);
}

TEST_F(LossySampleStoreTest, BadRequestsNameTheFlag) {
  auto o = options(inputs_, dir_ / "other", 12);
  o.lossy = build::parse_lossy("nosuch=abs:1");
  expect_error([&] { build::convert(o); }, ErrorCode::kInvalidArgument, {"--lossy", "'nosuch'"});
  o.lossy = build::parse_lossy("ta=abs:1,ta=rel:0.1");
  expect_error([&] { build::convert(o); }, ErrorCode::kInvalidArgument, {"--lossy", "twice"});
  o.lossy = build::parse_lossy("ta=abs:1");
  o.fpzip = {"ta"};
  expect_error([&] { build::convert(o); }, ErrorCode::kInvalidArgument, {"--lossy", "--fpzip", "'ta'"});
  o.fpzip = {"all"};
  expect_error([&] { build::convert(o); }, ErrorCode::kInvalidArgument, {"--lossy", "--fpzip"});
  for (const char* bad : {"ta=abs:-1", "ta=abs:nan", "ta=abs:0", "ta=abs:inf", "ta=rel:x", "ta=1",
                          "ta=sq:1", "=abs:1", "ta=abs:1,"}) {
    expect_error([&] { build::parse_lossy(bad); }, ErrorCode::kInvalidArgument, {"--lossy"});
  }
  // The plain store was planned without --lossy: resuming it with --lossy is another plan.
  o = options(inputs_, dir_ / "plain", 12);
  o.lossy = build::parse_lossy("ta=abs:0.05");
  expect_error([&] { build::convert(o); }, ErrorCode::kAlreadyExists, {"plain"});
}

TEST_F(LossySampleStoreTest, ADamagedZfpChunkIsNamedAndOtherNodesStayReadable) {
  NodeId damaged = 0;
  std::uint64_t offset = 0;
  std::uint32_t ta = 0;
  {
    const auto store = Store::open(dir_ / "lossy");
    ta = static_cast<std::uint32_t>(store->manifest().variable_index("ta"));
    const auto entries = store->index(0, ta);
    while (damaged < entries.size() && entries[damaged].coding != format::ChunkCoding::kZfp) ++damaged;
    ASSERT_LT(damaged, entries.size());
    offset = entries[damaged].chunk_offset + entries[damaged].chunk_size / 2;
  }
  {
    std::fstream f(dir_ / "lossy" / format::step_file_name(0), std::ios::in | std::ios::out | std::ios::binary);
    f.seekg(static_cast<std::streamoff>(offset));
    char c = 0;
    f.read(&c, 1);
    c = static_cast<char>(c ^ 0x5a);
    f.seekp(static_cast<std::streamoff>(offset));
    f.write(&c, 1);
  }
  const auto store = Store::open(dir_ / "lossy");
  expect_error([&] { store->read_brick(0, ta, damaged); }, ErrorCode::kCorrupt,
               {"'ta'", fmt::format("node {}", damaged)});
  for (NodeId n = 0; n < store->index(0, ta).size(); ++n) {
    if (n != damaged) {
      EXPECT_NO_THROW(store->read_brick(0, ta, n)) << n;
    }
  }
  EXPECT_FALSE(verify_store(dir_ / "lossy").ok());
}

// A float field with fill, subnormals and 1e30 values in some bricks.
std::filesystem::path write_extreme_file(const std::filesystem::path& dir) {
  testing::SimpleGrid g;
  g.lev = testing::ramp(8, 1000.0, -100.0);
  g.lat = testing::ramp(12, -30.0, 5.0);
  g.lon = testing::ramp(16, 0.0, 5.0);
  std::vector<double> data(g.samples());
  for (std::size_t i = 0; i < data.size(); ++i) {
    const std::size_t x = i % 16, y = (i / 16) % 12, z = i / (16 * 12);
    data[i] = 250.0 + 0.5 * double(z) + std::sin(0.4 * double(x)) * std::cos(0.3 * double(y));
    if (x < 4 && y < 4) data[i] = -999.0;                           // fill: terrain
    if (x >= 8 && y >= 8 && (x + y + z) % 5 == 0) data[i] = 1e30;  // huge values
    if (x >= 8 && y < 4 && (x + z) % 3 == 0) data[i] = 1e-40;      // float subnormals
  }
  const auto path = dir / "extreme.nc";
  testing::NetcdfFixture(NC_NETCDF4)
      .grid(g)
      .variable("T", NC_FLOAT, g.dims(), data, {testing::NcAttr::number("_FillValue", NC_FLOAT, {-999})})
      .write(path);
  return path;
}

TEST(LossyExtremes, BricksZfpCannotKeepAreCountedAndStoredExactly) {
  TempDir dir;
  const auto input = write_extreme_file(dir.path());
  build::convert(options({input}, dir / "plain", 4));
  auto o = options({input}, dir / "lossy", 4);
  o.lossy = build::parse_lossy("T=abs:0.001");
  const build::ConvertResult r = build::convert(o);
  EXPECT_GT(r.lossy_fallback, 0u);  // the bricks with 1e30 next to 250
  EXPECT_GT(r.lossy, 0u);
  const auto plain = Store::open(dir / "plain");
  const auto lossy = Store::open(dir / "lossy");
  BoundCheck check;
  expect_bound_on_every_brick(*plain, *lossy, {0.001}, check);
  EXPECT_EQ(check.zfp_chunks, r.lossy);
  const VerifyReport report = verify_store(dir / "lossy");
  EXPECT_TRUE(report.ok()) << (report.problems.empty() ? "" : report.problems.front());
}

struct RealFile {
  const char* path;
  const char* variable;
};

class LossyNcargFilesTest : public ::testing::TestWithParam<RealFile> {};

TEST_P(LossyNcargFilesTest, BoundHoldsOnEveryBrick) {
  const RealFile f = GetParam();
  const auto input = testing::ncarg_file(f.path);
  if (!std::filesystem::exists(input)) GTEST_SKIP() << "libncarg-data not installed";
  TempDir dir;
  auto o = options({input}, dir / "plain", 8);
  o.scan.variables = {f.variable};
  build::convert(o);
  o.store = dir / "lossy";
  o.lossy = build::parse_lossy(std::string(f.variable) + "=rel:0.01");
  const build::ConvertResult r = build::convert(o);
  const auto plain = Store::open(dir / "plain");
  const auto lossy = Store::open(dir / "lossy");
  const double tolerance = lossy->manifest().codec_of(0).zfp->tolerance;
  BoundCheck check;
  expect_bound_on_every_brick(*plain, *lossy, {tolerance}, check);
  EXPECT_GT(check.zfp_chunks + r.lossy_fallback, 0u) << f.path;
  const VerifyReport report = verify_store(dir / "lossy");
  EXPECT_TRUE(report.ok()) << (report.problems.empty() ? "" : report.problems.front());
}

INSTANTIATE_TEST_SUITE_P(RealFiles, LossyNcargFilesTest,
                         ::testing::Values(RealFile{"cdf/contour.cdf", "Z"},
                                           RealFile{"cdf/contour.cdf", "T"},
                                           RealFile{"nug/rectilinear_grid_3D.nc", "t"}),
                         [](const auto& info) {
                           std::string name = std::string(info.param.path) + "_" + info.param.variable;
                           for (char& c : name) {
                             if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           }
                           return name;
                         });

}  // namespace
}  // namespace strielad
