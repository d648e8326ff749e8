// SPDX-License-Identifier: Apache-2.0
// Bad specs and unusable output directories give a strielad::Error naming the problem,
// before anything is written.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "core/error.h"
#include "sample_test_util.h"

namespace strielad::testing {
namespace {

void expect_error(const synthetic::SampleSpec& spec, const std::filesystem::path& out,
                  ErrorCode code, const std::string& needle) {
  try {
    synthetic::write_sample_dataset(spec, out);
    ADD_FAILURE() << "expected an error mentioning '" << needle << "'";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), code) << e.what();
    EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
  }
}

class SampleBadArgumentsTest : public ::testing::Test {
 protected:
  synthetic::SampleSpec spec_ = small_spec(Dims3{4, 4, 4});
  TempDir dir_;
  std::filesystem::path out() const { return dir_.path() / "out"; }
};

TEST_F(SampleBadArgumentsTest, ZeroDimension) {
  spec_.dims = Dims3{4, 0, 4};
  expect_error(spec_, out(), ErrorCode::kInvalidArgument, "4x0x4");
  EXPECT_FALSE(std::filesystem::exists(out()));
}

TEST_F(SampleBadArgumentsTest, ZeroSteps) {
  spec_.steps = 0;
  expect_error(spec_, out(), ErrorCode::kInvalidArgument, "steps");
  EXPECT_FALSE(std::filesystem::exists(out()));
}

TEST_F(SampleBadArgumentsTest, AbsurdNumberOfSteps) {
  spec_.steps = static_cast<std::size_t>(-1);  // e.g. "-1" wrapped by a careless parser
  expect_error(spec_, out(), ErrorCode::kInvalidArgument, "steps");
  EXPECT_FALSE(std::filesystem::exists(out()));
}

TEST_F(SampleBadArgumentsTest, UnknownVariable) {
  spec_.variables = {"ta", "hus"};
  expect_error(spec_, out(), ErrorCode::kInvalidArgument, "'hus'");
  EXPECT_FALSE(std::filesystem::exists(out()));
}

TEST_F(SampleBadArgumentsTest, DuplicateVariable) {
  spec_.variables = {"ta", "clw", "ta"};
  expect_error(spec_, out(), ErrorCode::kInvalidArgument, "'ta'");
}

TEST_F(SampleBadArgumentsTest, NoVariables) {
  spec_.variables.clear();
  expect_error(spec_, out(), ErrorCode::kInvalidArgument, "variables");
}

TEST_F(SampleBadArgumentsTest, DeflateOutOfRange) {
  spec_.deflate = 10;
  expect_error(spec_, out(), ErrorCode::kInvalidArgument, "deflate");
  spec_.deflate = -1;
  expect_error(spec_, out(), ErrorCode::kInvalidArgument, "deflate");
}

TEST_F(SampleBadArgumentsTest, NonPositiveOrNanStepSeconds) {
  spec_.step_seconds = 0;
  expect_error(spec_, out(), ErrorCode::kInvalidArgument, "step_seconds");
  spec_.step_seconds = std::nan("");
  expect_error(spec_, out(), ErrorCode::kInvalidArgument, "step_seconds");
}

TEST_F(SampleBadArgumentsTest, LevelTooLargeForOneChunk) {
  spec_.dims = Dims3{1u << 16, 1u << 15, 1};
  expect_error(spec_, out(), ErrorCode::kInvalidArgument, "chunk");
}

TEST_F(SampleBadArgumentsTest, OutputDirectoryUnderAFile) {
  const auto file = dir_.path() / "plain";
  std::ofstream(file) << "x";
  expect_error(spec_, file / "sub", ErrorCode::kIo, (file / "sub").string());
}

TEST_F(SampleBadArgumentsTest, OutputPathIsAFile) {
  const auto file = dir_.path() / "plain";
  std::ofstream(file) << "x";
  expect_error(spec_, file, ErrorCode::kIo, file.string());
}

TEST_F(SampleBadArgumentsTest, EmptyOutputPath) {
  expect_error(spec_, std::filesystem::path{}, ErrorCode::kInvalidArgument, "output");
}

}  // namespace
}  // namespace strielad::testing
