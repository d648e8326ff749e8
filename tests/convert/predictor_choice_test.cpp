// SPDX-License-Identifier: Apache-2.0
// Predictors in conversion: `auto` picks lorenzo3 for the sample generator's dense
// fields and none for its cloud fields, the same way every time; explicit and
// per-variable choices land in the manifest and its store_id; stores written with either
// predictor hold bit-identical bricks; version-1 stores keep their version when
// finalized.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "convert/converter.h"
#include "convert/predictor_choice.h"
#include "core/file_io.h"
#include "format/manifest.h"
#include "ingest/input_catalog.h"
#include "synthetic/sample_dataset.h"
#include "store/store.h"
#include "store/store_verifier.h"
#include "support/expect_error.h"
#include "support/small_dataset.h"
#include "support/temp_dir.h"

namespace strielad {
namespace {

using testing::expect_error;
using testing::TempDir;

TEST(PredictorChoiceTest, SampledBricksAreSpreadEvenlyAndDependOnTheGridOnly) {
  const OctreeLayout layout(Dims3{512, 512, 150}, 24);  // 22 x 22 x 7 leaves
  const auto nodes = build::predictor_sample_nodes(layout, {3, 3, 3});
  ASSERT_EQ(nodes.size(), 27u);
  EXPECT_EQ(nodes.front(), (NodeKey{0, {3, 3, 1}}));
  EXPECT_EQ(nodes[1], (NodeKey{0, {11, 3, 1}}));
  EXPECT_EQ(nodes[2], (NodeKey{0, {18, 3, 1}}));
  EXPECT_EQ(nodes.back(), (NodeKey{0, {18, 18, 5}}));
  // The converter's lattice: x and y at nodes 2, 6, 11, 15, 19, z-major order.
  const auto used = build::predictor_sample_nodes(layout, build::kPredictorSamples);
  ASSERT_EQ(used.size(), 75u);
  EXPECT_EQ(used[4], (NodeKey{0, {19, 2, 1}}));
  EXPECT_EQ(used[5], (NodeKey{0, {2, 6, 1}}));
  EXPECT_EQ(used[25], (NodeKey{0, {2, 2, 3}}));
  EXPECT_EQ(build::predictor_sample_nodes(layout, {5, 5, 1}).size(), 25u);
  // A grid with fewer nodes than samples per axis takes every node.
  const OctreeLayout tiny(Dims3{9, 7, 5}, 4);  // 2 x 2 x 1 leaves
  const auto all = build::predictor_sample_nodes(tiny, {3, 3, 3});
  ASSERT_EQ(all.size(), 4u);
  EXPECT_EQ(all[3], (NodeKey{0, {1, 1, 0}}));
}

TEST(PredictorChoiceTest, Lorenzo3MustSaveMoreThanTenPercent) {
  EXPECT_EQ(build::decide_predictor(1000, 899), "lorenzo3");
  EXPECT_EQ(build::decide_predictor(1000, 900), "none");
  EXPECT_EQ(build::decide_predictor(1000, 950), "none");
  EXPECT_EQ(build::decide_predictor(1000, 1300), "none");
  EXPECT_EQ(build::decide_predictor(0, 0), "none");  // no sampled brick held data
}

// The sample generator's output (the README's sample job), at a size a unit test affords.
struct SampleInput {
  TempDir dir;
  ingest::InputCatalog catalog;
  build::ConvertOptions options;
  explicit SampleInput(int deflate = 0) {
    synthetic::SampleSpec spec;
    spec.dims = Dims3{160, 144, 72};  // 7 x 6 x 3 leaves of 24 cells
    spec.steps = 2;
    spec.deflate = deflate;
    spec.variables = {"clw", "qr", "ta", "ua"};
    const auto written = synthetic::write_sample_dataset(spec, dir / "nc");
    for (const auto& f : written.files) options.inputs.push_back(f.path);
    options.store = dir / "store";
    catalog = ingest::scan_inputs(options.inputs, options.scan);
  }
  const format::CodecSpec& codec(const format::Manifest& m, const std::string& name) const {
    return m.codec_of(m.variable_index(name));
  }
};

TEST(PredictorChoiceTest, AutoPicksNoneForCloudsAndLorenzo3ForDenseFields) {
  // Uncompressed input samples 5 x 5 x 3 bricks; deflated input one layer, 5 x 5 x 1.
  for (const int deflate : {0, 1}) {
    const SampleInput in(deflate);
    std::vector<build::PredictorTrial> trials;
    const format::Manifest m = build::plan_store(in.catalog, in.options, &trials);
    EXPECT_EQ(in.codec(m, "clw").predictor, "none") << "deflate " << deflate;
    EXPECT_EQ(in.codec(m, "qr").predictor, "none") << "deflate " << deflate;
    EXPECT_EQ(in.codec(m, "ta").predictor, "lorenzo3") << "deflate " << deflate;
    EXPECT_EQ(in.codec(m, "ua").predictor, "lorenzo3") << "deflate " << deflate;
    ASSERT_EQ(trials.size(), 4u);
    for (const auto& t : trials) {
      // Layers of 5 x 5 bricks; dense fields make their case after the first one.
      EXPECT_EQ(t.bricks_sampled % 25, 0u) << t.variable;
      EXPECT_LE(t.bricks_sampled, deflate ? 25u : 75u) << t.variable;
      if (t.variable == "ta" || t.variable == "ua") {
        EXPECT_EQ(t.bricks_sampled, 25u) << t.variable;
        EXPECT_EQ(t.data_bricks, 25u) << t.variable;
        EXPECT_GT(t.saving(), 0.2) << t.variable;
      } else {
        EXPECT_GT(t.data_bricks, 0u) << t.variable;
        EXPECT_LT(t.saving(), 0.0) << t.variable;
      }
      EXPECT_EQ(t.chosen, in.codec(m, t.variable).predictor);
    }
  }
  const SampleInput in;
  const format::Manifest m = build::plan_store(in.catalog, in.options);
  // Two of four variables each way: the store-wide codec takes "none" (ties), the dense
  // fields carry their own codec.
  EXPECT_EQ(m.format_version, 2u);
  EXPECT_EQ(m.codec.predictor, "none");
  EXPECT_FALSE(m.variables[m.variable_index("clw")].codec.has_value());
  EXPECT_TRUE(m.variables[m.variable_index("ta")].codec.has_value());
}

TEST(PredictorChoiceTest, AutoIsDecidedTheSameWayEveryTime) {
  SampleInput in;
  const auto a = build::plan_store(in.catalog, in.options);
  in.options.threads = 1;
  in.options.only_first = in.options.only_last = 1;  // another Slurm task's share
  const auto b = build::plan_store(in.catalog, in.options);
  EXPECT_EQ(a.store_id, b.store_id);
  EXPECT_EQ(format::manifest_plan_json(a), format::manifest_plan_json(b));
}

TEST(PredictorChoiceTest, ExplicitAndPerVariableChoicesLandInThePlan) {
  SampleInput in;
  in.options.codec.predictor = "lorenzo3";
  std::vector<build::PredictorTrial> trials;
  const auto all = build::plan_store(in.catalog, in.options, &trials);
  EXPECT_TRUE(trials.empty());  // nothing sampled when nothing is "auto"
  EXPECT_EQ(all.codec.predictor, "lorenzo3");
  for (const auto& v : all.variables) EXPECT_FALSE(v.codec.has_value()) << v.name;

  in.options.codec.predictor = "none";
  const auto none = build::plan_store(in.catalog, in.options);
  EXPECT_NE(none.store_id, all.store_id);

  in.options.codec_for.insert(build::parse_codec_for("clw=zstd:5:byte", "auto"));
  const auto own = build::plan_store(in.catalog, in.options, &trials);
  EXPECT_EQ(in.codec(own, "clw"), (format::CodecSpec{"zstd", 5, "byte", "none"}));
  EXPECT_EQ(in.codec(own, "ta"), (format::CodecSpec{"zstd", 1, "byte", "none"}));
  ASSERT_EQ(trials.size(), 1u);
  EXPECT_EQ(trials[0].variable, "clw");

  in.options.codec_for = {{"nope", format::CodecSpec{}}};
  expect_error([&] { build::plan_store(in.catalog, in.options); }, ErrorCode::kInvalidArgument,
               {"'nope'", "not converted", "clw, qr, ta, ua"});
  in.options.codec_for.clear();
  in.options.codec.predictor = "delta";
  expect_error([&] { build::plan_store(in.catalog, in.options); }, ErrorCode::kInvalidArgument,
               {"predictor 'delta' is not one of auto, none, lorenzo3"});
}

TEST(PredictorChoiceTest, CodecForIsParsedStrictly) {
  const auto [name, codec] = build::parse_codec_for("grp/qr=lz4:9:bit:lorenzo3", "auto");
  EXPECT_EQ(name, "grp/qr");
  EXPECT_EQ(codec, (format::CodecSpec{"lz4", 9, "bit", "lorenzo3"}));
  EXPECT_EQ(build::parse_codec_for("ta=zstd:1:none", "none").second.predictor, "none");
  for (const char* bad : {"clw", "=zstd:1:byte", "clw=zstd:1", "clw=zstd:10:byte",
                          "clw=zstd:x:byte", "clw=zstd:1:byte:none:more"}) {
    expect_error([&] { build::parse_codec_for(bad, "auto"); }, ErrorCode::kInvalidArgument,
                 {"--codec-for", bad});
  }
  expect_error([&] { build::parse_codec_for("clw=gzip:1:byte", "auto"); },
               ErrorCode::kInvalidArgument, {"codec 'gzip'"});
  expect_error([&] { build::parse_codec_for("clw=zstd:1:byte:delta", "auto"); },
               ErrorCode::kInvalidArgument, {"predictor 'delta'"});
}

bool same_brick(const Brick& a, const Brick& b) {
  if (a.kind != b.kind || a.dims != b.dims) return false;
  if (a.kind == format::BrickKind::kConstant) {
    return std::memcmp(&a.constant, &b.constant, sizeof a.constant) == 0;
  }
  return a.bytes == b.bytes;
}

// Every brick of every level equals, bit for bit, between the two stores.
void expect_same_bricks(const Store& a, const Store& b) {
  ASSERT_EQ(a.octree().node_count(), b.octree().node_count());
  std::size_t data = 0;
  for (std::uint32_t s = 0; s < a.step_count(); ++s)
    for (std::uint32_t v = 0; v < a.variable_count(); ++v)
      for (NodeId n = 0; n < a.octree().node_count(); ++n) {
        const Brick x = a.read_brick(s, v, n), y = b.read_brick(s, v, n);
        data += x.kind == format::BrickKind::kData;
        ASSERT_TRUE(same_brick(x, y)) << "step " << s << " " << a.describe_node(v, n);
      }
  EXPECT_GT(data, 0u);
}

// The small dataset holds float32 clouds with _FillValue holes, dense float64 and packed
// data; its bricks at the far edges are thinner than the others.
TEST(PredictorChoiceTest, StoresWithEitherPredictorHoldIdenticalBricks) {
  for (const std::size_t nz : {std::size_t{11}, std::size_t{1}}) {
    TempDir dir;
    const auto data = testing::write_small_dataset(dir.path(), 23, 17, nz, 2);
    auto none = testing::small_convert_options(data, dir / "none");
    none.codec.predictor = "none";
    auto lorenzo = testing::small_convert_options(data, dir / "lorenzo3");
    lorenzo.codec.predictor = "lorenzo3";
    build::convert(none);
    const auto r = build::convert(lorenzo);
    EXPECT_EQ(r.codecs["temp"]["predictor"], "lorenzo3");
    const auto a = Store::open(dir / "none"), b = Store::open(dir / "lorenzo3");
    EXPECT_EQ(b->manifest().codec.predictor, "lorenzo3");
    expect_same_bricks(*a, *b);
    const VerifyReport report = verify_store(dir / "lorenzo3");
    EXPECT_TRUE(report.ok()) << (report.problems.empty() ? "" : report.problems.front());
    // A different predictor is a different plan: no steps are added to the other store.
    auto other = lorenzo;
    other.store = dir / "none";
    expect_error([&] { build::convert(other); },
                 ErrorCode::kAlreadyExists, {"codec"});
  }
}

TEST(PredictorChoiceTest, FinalizingAVersion1StoreKeepsVersion1) {
  TempDir dir;
  const auto golden = std::filesystem::path(STRIELAD_SOURCE_DIR) / "tests/data/golden-store-v1";
  std::filesystem::copy(golden, dir / "store", std::filesystem::copy_options::recursive);
  const auto manifest_path = dir / "store/MANIFEST";
  std::filesystem::permissions(manifest_path, std::filesystem::perms::owner_write,
                               std::filesystem::perm_options::add);
  format::Manifest m = format::decode_manifest(read_file_bytes(manifest_path), "MANIFEST");
  ASSERT_EQ(m.format_version, 1u);
  const std::uint64_t id = m.store_id;
  m.complete = false;  // as an interrupted version-1 conversion left it
  m.steps.clear();
  m.summary = nlohmann::json::object();
  write_file_atomically(manifest_path, format::encode_manifest(m));
  build::finalize_store(dir / "store");
  const auto store = Store::open(dir / "store");
  EXPECT_EQ(store->manifest().format_version, 1u);
  EXPECT_EQ(store->manifest().store_id, id);
  EXPECT_TRUE(verify_store(dir / "store").ok());
}

}  // namespace
}  // namespace strielad
