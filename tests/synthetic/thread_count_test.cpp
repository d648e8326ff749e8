// SPDX-License-Identifier: Apache-2.0
// The output does not depend on how many threads compute it.
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cstring>

#include "sample_test_util.h"

namespace strielad::testing {
namespace {

std::vector<std::vector<float>> generate_with_threads(std::size_t threads) {
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
  auto spec = small_spec(Dims3{61, 53, 20}, 2);
  spec.file_per_step = false;
  const GeneratedSample s(spec);
  const NcFile f(s.file());
  std::vector<std::vector<float>> all;
  for (const auto& name : synthetic::all_sample_variable_names()) all.push_back(f.floats(name));
  return all;
}

TEST(SampleThreadCountTest, OneThreadAndFourThreadsWriteTheSameValues) {
  const auto one = generate_with_threads(1);
  const auto four = generate_with_threads(4);
  ASSERT_EQ(one.size(), four.size());
  const auto names = synthetic::all_sample_variable_names();
  for (std::size_t v = 0; v < one.size(); ++v) {
    ASSERT_EQ(one[v].size(), four[v].size());
    EXPECT_EQ(std::memcmp(one[v].data(), four[v].data(), one[v].size() * sizeof(float)), 0)
        << names[v];
  }
}

}  // namespace
}  // namespace strielad::testing
