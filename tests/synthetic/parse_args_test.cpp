// SPDX-License-Identifier: Apache-2.0
// The command-line spellings of the sample subcommand.
#include <gtest/gtest.h>

#include "core/error.h"
#include "synthetic/sample_args.h"
#include "synthetic/sample_spec.h"

namespace strielad::synthetic {
namespace {

TEST(SampleParseArgsTest, ParsesDims) {
  EXPECT_EQ(parse_dims("1429x1556x150"), (Dims3{1429, 1556, 150}));
  EXPECT_EQ(parse_dims("2X3x4"), (Dims3{2, 3, 4}));
  EXPECT_EQ(parse_dims(" 7x5x3 "), (Dims3{7, 5, 3}));
  EXPECT_EQ(parse_dims("1429x1556x150"), kFullSampleDims);
}

TEST(SampleParseArgsTest, RejectsBadDims) {
  for (const char* bad : {"", "12", "12x3", "1x2x3x4", "0x2x3", "ax2x3", "-1x2x3", "1x2x", "x2x3",
                          "1.5x2x3", "1x2x99999999999999999999999"}) {
    try {
      parse_dims(bad);
      ADD_FAILURE() << "accepted '" << bad << "'";
    } catch (const Error& e) {
      EXPECT_EQ(e.code(), ErrorCode::kInvalidArgument) << bad;
      EXPECT_NE(std::string(e.what()).find(std::string("'") + bad), std::string::npos)
          << e.what();
    }
  }
}

TEST(SampleParseArgsTest, ParsesVariableLists) {
  EXPECT_EQ(parse_variable_list("clw"), std::vector<std::string>{"clw"});
  EXPECT_EQ(parse_variable_list("clw,ta, ua"), (std::vector<std::string>{"clw", "ta", "ua"}));
}

TEST(SampleParseArgsTest, RejectsBadVariableLists) {
  for (const char* bad : {"", " ", "clw,,ta", "clw,", "clw,foo", "CLW"}) {
    EXPECT_THROW(parse_variable_list(bad), Error) << "'" << bad << "'";
  }
  try {
    parse_variable_list("ta,foo");
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("'foo'"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("clw"), std::string::npos) << "lists known names";
  }
}

TEST(SampleParseArgsTest, ParsesUnsignedWithoutWrapping) {
  EXPECT_EQ(parse_unsigned("4", "--steps"), 4u);
  EXPECT_EQ(parse_unsigned("18446744073709551615", "--seed"), 18446744073709551615ULL);
  for (const char* bad : {"-1", "", "1e3", "12abc", "18446744073709551616", "+"}) {
    try {
      parse_unsigned(bad, "--steps");
      ADD_FAILURE() << "accepted '" << bad << "'";
    } catch (const Error& e) {
      EXPECT_EQ(e.code(), ErrorCode::kInvalidArgument);
      EXPECT_NE(std::string(e.what()).find("--steps"), std::string::npos) << e.what();
    }
  }
}

TEST(SampleParseArgsTest, DefaultSpecHasAllVariablesAtFullSize) {
  const SampleSpec spec;
  EXPECT_EQ(spec.dims, kFullSampleDims);
  EXPECT_EQ(spec.steps, 4u);
  EXPECT_EQ(spec.variables,
            (std::vector<std::string>{"clw", "cli", "qr", "ta", "pres", "ua", "va", "wa"}));
  EXPECT_EQ(validate_sample_spec(spec).size(), 8u);
}

}  // namespace
}  // namespace strielad::synthetic
