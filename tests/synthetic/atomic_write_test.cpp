// SPDX-License-Identifier: Apache-2.0
// Files appear only when complete: a failure part way leaves the finished files intact,
// no partial file under a final name, and no temporary files.
#include <gtest/gtest.h>

#include <fstream>

#include "core/error.h"
#include "sample_test_util.h"

namespace strielad::testing {
namespace {

bool has_temporary(const std::filesystem::path& dir) {
  for (const auto& e : std::filesystem::directory_iterator(dir)) {
    if (e.path().filename().string().find(".tmp.") != std::string::npos) return true;
  }
  return false;
}

TEST(SampleAtomicWriteTest, FailureOnTheSecondFileKeepsTheFirstAndLeavesNoTemporary) {
  TempDir dir;
  // A non-empty directory where the second file must go: it cannot be replaced.
  std::filesystem::create_directories(dir.path() / "sample_t001.nc" / "blocker");
  auto spec = small_spec(Dims3{6, 5, 4}, 3);
  spec.variables = {"ta"};
  try {
    synthetic::write_sample_dataset(spec, dir.path());
    ADD_FAILURE() << "expected an I/O error";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::kIo) << e.what();
    EXPECT_NE(std::string(e.what()).find("sample_t001.nc"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(has_temporary(dir.path()));
  EXPECT_TRUE(std::filesystem::is_directory(dir.path() / "sample_t001.nc"));
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "sample_t002.nc"));
  const NcFile first(dir.path() / "sample_t000.nc");  // complete and readable
  EXPECT_EQ(first.floats("ta").size(), 6u * 5u * 4u);
}

TEST(SampleAtomicWriteTest, SuccessLeavesOnlyFinalFiles) {
  auto spec = small_spec(Dims3{6, 5, 4}, 2);
  spec.variables = {"qr"};
  const GeneratedSample s(spec);
  EXPECT_FALSE(has_temporary(s.dir.path()));
  for (const auto& f : s.result.files) EXPECT_TRUE(std::filesystem::is_regular_file(f.path));
}

}  // namespace
}  // namespace strielad::testing
