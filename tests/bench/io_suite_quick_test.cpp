// SPDX-License-Identifier: Apache-2.0
// The io benchmark suite runs end to end in quick mode on a tiny grid and reports sane
// numbers, so the harness cannot rot between full benchmark runs.
#include <gtest/gtest.h>

#include <sstream>

#include "bench/io_suite.h"
#include "bench/process_runner.h"
#include "support/temp_dir.h"

namespace strielad {
namespace {

using testing::TempDir;

TEST(IoSuiteQuick, ReportsSaneNumbers) {
  TempDir tmp;
  bench::IoSuiteOptions options = bench::quick_io_options({});
  options.work = tmp / "work";
  // Stores of format version 3: each brick keeps the smaller of its Blosc and fpzip chunks,
  // so both codings are read, and the reads add a set of fpzip chunks.
  options.fpzip = {"all"};
  const bool have_nccopy = bench::find_program("nccopy").has_value();

  const bench::IoSuiteReport r = bench::run_io_suite(options);

  // Conversion: every contender ran and has a positive throughput.
  const auto* convert = r.conversion.find("strielad-convert");
  const auto* copy = r.conversion.find("read+copy");
  const auto* read = r.conversion.find("read");
  const auto* buffered = r.conversion.find("strielad-convert (buffered input)");
  ASSERT_NE(convert, nullptr);
  ASSERT_NE(copy, nullptr);
  ASSERT_NE(read, nullptr);
  ASSERT_NE(buffered, nullptr);
  for (const auto* c : {convert, buffered, copy, read}) {
    EXPECT_EQ(c->seconds.size(), 1u) << c->name;
    EXPECT_GT(c->median_mb_per_s(), 0) << c->name;
    EXPECT_GT(c->input_bytes, 0u) << c->name;
  }
  // Reading with O_DIRECT runs where the work directory's file system allows it.
  if (const auto* direct = r.conversion.find("read (O_DIRECT)")) {
    EXPECT_EQ(direct->seconds.size(), 1u);
    EXPECT_GT(direct->median_mb_per_s(), 0);
  }
  EXPECT_EQ(r.conversion.find("nccopy") != nullptr, have_nccopy);
  if (have_nccopy) {
    EXPECT_GT(r.conversion.find("nccopy")->median_mb_per_s(), 0);
  }

  // Sizes: every variable has raw and stored bytes; deflate sizes when nccopy exists.
  ASSERT_EQ(r.sizes.variables.size(), options.variables.size());
  for (const auto& v : r.sizes.variables) {
    EXPECT_EQ(v.raw_bytes, std::uint64_t{40} * 36 * 24 * 4) << v.name;
    EXPECT_GT(v.store_bytes(), 0) << v.name;
    EXPECT_GT(v.index_bytes, 0u) << v.name;
    EXPECT_EQ(v.chunk_bytes, v.level0_chunk_bytes + v.coarse_chunk_bytes) << v.name;
    if (have_nccopy) {
      const auto* d = r.deflate.find(v.name);
      ASSERT_NE(d, nullptr) << v.name;
      EXPECT_GT(d->bytes, 0u) << v.name;
    }
  }
  EXPECT_GT(r.sizes.overhead_fraction, 0);
  EXPECT_GT(r.sizes.levels, 1u);

  // Reads: the sets exist, latencies are ordered, cold reads fetched bytes from disk.
  const auto* cold = r.reads.find("store cold, level 0");
  const auto* warm = r.reads.find("store warm, level 0");
  ASSERT_NE(cold, nullptr);
  ASSERT_NE(warm, nullptr);
  for (const auto* s : {cold, warm}) {
    const bench::Summary l = s->latency();
    EXPECT_EQ(l.count, options.reads) << s->name;
    EXPECT_GT(l.p50, 0) << s->name;
    EXPECT_LE(l.min, l.p50) << s->name;
    EXPECT_LE(l.p50, l.p99) << s->name;
    EXPECT_LE(l.p99, l.max) << s->name;
    EXPECT_GT(s->mean_payload_bytes(), 0) << s->name;
  }
  EXPECT_GT(cold->mean_disk_bytes(), 0);
  EXPECT_GT(cold->amplification(), 0);
  EXPECT_GE(cold->page_amplification(), 1.0);
  if (have_nccopy) {
    EXPECT_NE(r.reads.find("netcdf cold, B^3 box"), nullptr);
  }
  const auto* fpzip = r.reads.find("store cold, fpzip chunks");
  ASSERT_NE(fpzip, nullptr);
  EXPECT_EQ(fpzip->latency().count, options.reads);
  EXPECT_GT(fpzip->mean_payload_bytes(), 0);
  // The same bricks through OpenVDB delayed loading, every read measured.
  const auto* vdb = r.reads.find("openvdb delayed, (B+1)^3 box");
  ASSERT_NE(vdb, nullptr);
  EXPECT_EQ(vdb->latency().count, options.reads);
  EXPECT_GT(vdb->latency().p50, 0);

  // Sweeps: one row per configuration, each measured.
  ASSERT_EQ(r.brick_sweep.size(), options.sweep_bricks.size());
  ASSERT_EQ(r.codec_sweep.size(), options.sweep_codecs.size());
  for (const auto* rows : {&r.brick_sweep, &r.codec_sweep}) {
    for (const auto& row : *rows) {
      EXPECT_GT(row.convert.median_mb_per_s(), 0) << row.config.label;
      EXPECT_GT(row.sizes.node_count, 0u) << row.config.label;
      EXPECT_GT(row.data_bricks, 0u) << row.config.label;
      EXPECT_LE(row.cold_us.p50, row.cold_us.p99) << row.config.label;
      EXPECT_GT(row.warm_us.p50, 0) << row.config.label;
    }
  }
  EXPECT_EQ(r.brick_sweep[0].sizes.brick, options.sweep_bricks[0]);

  // Targets and output formats.
  EXPECT_GE(r.targets.size(), 3u);
  const auto tables = bench::io_report_tables(r);
  ASSERT_FALSE(tables.empty());
  for (const auto& t : tables) EXPECT_FALSE(t.rows.empty()) << t.name;
  std::ostringstream csv, text;
  bench::write_csv(csv, tables);
  EXPECT_EQ(csv.str().rfind("table,row,column,value\n", 0), 0u);
  for (const auto& t : tables) bench::print_table(text, t);
  EXPECT_NE(text.str().find("strielad-convert"), std::string::npos);
  const auto json = bench::io_report_json(r, tables);
  EXPECT_EQ(json.at("tables").size(), tables.size());
  EXPECT_TRUE(json.at("machine").contains("cores"));

  // Without keep the scratch data is gone.
  EXPECT_FALSE(std::filesystem::exists(options.work / "main"));
}

}  // namespace
}  // namespace strielad
