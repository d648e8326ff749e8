// SPDX-License-Identifier: Apache-2.0
// strielad-convert --fpzip (store format version 3): every brick of every level reads back
// bit for bit what the default store holds, fpzip makes temperature smaller (which
// bricks try it: fpzip_trials_follow_zero_share_test.cpp), the store verifies, and a
// damaged fpzip chunk is an error for that node only.
#include <gtest/gtest.h>

#include <cstring>
#include <fstream>

#include "convert/converter.h"
#include "store/store.h"
#include "store/store_verifier.h"
#include "support/expect_error.h"
#include "synthetic/sample_dataset.h"
#include "support/temp_dir.h"

namespace strielad {
namespace {

using testing::expect_error;
using testing::TempDir;

// The sample generator's cloud water and temperature (fpzip), rain (Blosc only).
class FpzipStoreTest : public ::testing::Test {
 protected:
  void SetUp() override {
    synthetic::SampleSpec spec;
    spec.dims = {48, 40, 20};
    spec.steps = 2;
    spec.variables = {"clw", "ta", "qr"};
    for (const auto& f : synthetic::write_sample_dataset(spec, dir_ / "input").files) {
      inputs_.push_back(f.path);
    }
    build::convert(options(dir_ / "plain"));
    auto o = options(dir_ / "fpzip");
    o.fpzip = {"clw", "ta"};
    build::convert(o);
  }
  build::ConvertOptions options(const std::filesystem::path& store) const {
    build::ConvertOptions o;
    o.inputs = inputs_;
    o.store = store;
    o.brick = 12;
    o.threads = 2;
    return o;
  }
  TempDir dir_;
  std::vector<std::filesystem::path> inputs_;
};

TEST_F(FpzipStoreTest, EveryBrickReadsBackLikeTheDefaultStoreAndFpzipMakesTemperatureSmaller) {
  const auto plain = Store::open(dir_ / "plain");
  const auto fpzip = Store::open(dir_ / "fpzip");
  EXPECT_EQ(plain->manifest().format_version, 2u);
  EXPECT_EQ(fpzip->manifest().format_version, 3u);
  std::size_t fpzip_chunks = 0;
  for (std::uint32_t v = 0; v < fpzip->variable_count(); ++v) {
    const auto& name = fpzip->manifest().variables[v].name;
    EXPECT_EQ(fpzip->manifest().codec_of(v).fpzip, name != "qr") << name;
    std::uint64_t plain_bytes = 0, fpzip_bytes = 0;
    for (std::uint32_t t = 0; t < 2; ++t) {
      const auto pe = plain->index(t, v);
      const auto fe = fpzip->index(t, v);
      ASSERT_EQ(pe.size(), fe.size());
      for (NodeId n = 0; n < fe.size(); ++n) {
        EXPECT_EQ(pe[n].kind, fe[n].kind);
        if (fe[n].coding == format::ChunkCoding::kCodec) {  // the same chain, the same chunk
          EXPECT_EQ(fe[n].chunk_size, pe[n].chunk_size) << name << " node " << n;
        }
        plain_bytes += pe[n].chunk_size;
        fpzip_bytes += fe[n].chunk_size;
        if (fe[n].coding == format::ChunkCoding::kFpzip) {
          ++fpzip_chunks;
          EXPECT_NE(name, "qr");
        }
        const Brick a = plain->read_brick(t, v, n), b = fpzip->read_brick(t, v, n);
        ASSERT_EQ(a.bytes.size(), b.bytes.size());
        EXPECT_EQ(std::memcmp(a.bytes.data(), b.bytes.data(), a.bytes.size()), 0)
            << name << " step " << t << " node " << n;
      }
    }
    // This small sample's cloud water bricks are all mostly zeros: fpzip is not tried there.
    if (name == "ta") {
      EXPECT_LT(fpzip_bytes, plain_bytes) << name;
    }
    if (name == "clw") {
      EXPECT_LE(fpzip_bytes, plain_bytes) << name;
    }
  }
  EXPECT_GT(fpzip_chunks, 0u);
  const VerifyReport report = verify_store(dir_ / "fpzip");
  EXPECT_TRUE(report.ok()) << (report.problems.empty() ? "" : report.problems.front());
  EXPECT_GT(report.bricks_checked, 0u);
}

TEST_F(FpzipStoreTest, ResumingWithOrWithoutFpzipIsRefusedAndUnknownVariablesAreNamed) {
  auto o = options(dir_ / "plain");
  o.fpzip = {"ta"};
  expect_error([&] { build::convert(o); }, ErrorCode::kAlreadyExists, {"plain"});
  o = options(dir_ / "other");
  o.fpzip = {"nosuch"};
  expect_error([&] { build::convert(o); }, ErrorCode::kInvalidArgument,
               {"--fpzip", "'nosuch'"});
  o.fpzip = {"all"};
  const build::ConvertResult r = build::convert(o);
  for (const auto& [name, codec] : r.codecs.items()) EXPECT_TRUE(codec["fpzip"].get<bool>()) << name;
}

// The node that holds a variable's first fpzip chunk in step 0.
NodeId first_fpzip_node(const Store& store, std::uint32_t v) {
  const auto entries = store.index(0, v);
  for (NodeId n = 0; n < entries.size(); ++n) {
    if (entries[n].coding == format::ChunkCoding::kFpzip) return n;
  }
  ADD_FAILURE() << "no fpzip chunk";
  return 0;
}

TEST_F(FpzipStoreTest, ADamagedFpzipChunkIsNamedAndOtherNodesStayReadable) {
  const auto path = dir_ / "fpzip";
  std::uint32_t ta = 0;
  NodeId victim = 0;
  format::IndexEntry e;
  {
    const auto store = Store::open(path);
    ta = static_cast<std::uint32_t>(store->manifest().variable_index("ta"));
    victim = first_fpzip_node(*store, ta);
    e = store->index(0, ta)[victim];
  }
  {
    std::fstream f(path / format::step_file_name(0), std::ios::in | std::ios::out | std::ios::binary);
    const auto at = static_cast<std::streamoff>(e.chunk_offset + e.chunk_size - 3);
    f.seekg(at);
    char c = 0;
    f.get(c);
    f.seekp(at);
    f.put(static_cast<char>(c ^ 0x21));
  }
  const auto store = Store::open(path);
  expect_error([&] { store->read_brick(0, ta, victim); }, ErrorCode::kCorrupt,
               {fmt::format("node {} ", victim), "variable 'ta'", "chunk checksum mismatch"});
  const auto entries = store->index(0, ta);
  for (NodeId n = 0; n < entries.size(); ++n) {
    if (n != victim) {
      EXPECT_NO_THROW(store->read_brick(0, ta, n));
    }
  }
  const VerifyReport report = verify_store(path);
  ASSERT_EQ(report.problems.size(), 1u);
  EXPECT_NE(report.problems[0].find(fmt::format("node {} ", victim)), std::string::npos);
}

}  // namespace
}  // namespace strielad
