// SPDX-License-Identifier: Apache-2.0
// Reports name a machine's files relative to the repository or by a folder's placeholder,
// never by their absolute paths, and a command saved that way resolves back to runnable
// paths.
#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

#include "bench/report_paths.h"

namespace strielad {
namespace {

// $TMPDIR (an existing folder) and $HOME come from the environment when the paths are made.
bench::ReportPaths make_paths() {
  ::setenv("TMPDIR", "/tmp", 1);
  ::setenv("HOME", "/home/someone", 1);
  return bench::ReportPaths("/work/repo", {{"$WORK", "/data/work"}, {"$OUT", "/work/repo/out"}});
}

class ReportPathsTest : public ::testing::Test {
 protected:
  const bench::ReportPaths paths = make_paths();
};

TEST_F(ReportPathsTest, RewritesPathsInRunningText) {
  EXPECT_EQ(paths.text("/work/repo/build/cmd/strielad-bench/strielad-bench io --work "
                       "/data/work/io --json /tmp/r/io.json --plot=/home/someone/a.png"),
            "build/cmd/strielad-bench/strielad-bench io --work $WORK/io --json "
            "$TMPDIR/r/io.json --plot=$HOME/a.png");
  EXPECT_EQ(paths.text("converting into /data/work/store (brick 24)"),
            "converting into $WORK/store (brick 24)");
  EXPECT_EQ(paths.text("`/work/repo`: /data/work: x"), "`.`: $WORK: x");
  // A folder inside the repository keeps its path relative to the repository.
  EXPECT_EQ(paths.text("/work/repo/out/io.json"), "out/io.json");
}

TEST_F(ReportPathsTest, LeavesOtherTextAlone) {
  EXPECT_EQ(paths.text("12.5 MB/s, /proc/self/io, /work/repository/x, a/work/repo/b"),
            "12.5 MB/s, /proc/self/io, /work/repository/x, a/work/repo/b");
  EXPECT_EQ(paths.text("/data/workshop"), "/data/workshop");
}

TEST_F(ReportPathsTest, RewritesEveryStringOfJsonAndTables) {
  nlohmann::json j = {{"command", "/work/repo/bench x"},
                      {"machine", {{"storage", {{"path", "/data/work"}}}}},
                      {"list", {"/tmp/a", 3}}};
  paths.rewrite(j);
  EXPECT_EQ(j["command"], "bench x");
  EXPECT_EQ(j["machine"]["storage"]["path"], "$WORK");
  EXPECT_EQ(j["list"][0], "$TMPDIR/a");
  EXPECT_EQ(j["list"][1], 3);

  std::vector<bench::Table> tables(1);
  tables[0].title = "in /data/work";
  tables[0].columns = {"case", "detail"};
  tables[0].add({"a", "/data/work/a/input.nc: NaN"});
  tables[0].notes = {"see /work/repo/docs"};
  paths.rewrite(tables);
  EXPECT_EQ(tables[0].title, "in $WORK");
  EXPECT_EQ(std::get<std::string>(tables[0].rows[0][1].value), "$WORK/a/input.nc: NaN");
  EXPECT_EQ(tables[0].notes[0], "see docs");
}

TEST_F(ReportPathsTest, ResolvesWhatItWrote) {
  EXPECT_EQ(paths.resolve("$WORK/io"), "/data/work/io");
  EXPECT_EQ(paths.resolve("$TMPDIR"), "/tmp");
  EXPECT_EQ(paths.resolve("build/cmd/x"), "/work/repo/build/cmd/x");
  EXPECT_EQ(paths.resolve("/elsewhere/x"), "/elsewhere/x");
  const std::string written = paths.text("/work/repo/bench/report/io.json");
  EXPECT_EQ(paths.resolve(written), "/work/repo/bench/report/io.json");
}

}  // namespace
}  // namespace strielad
