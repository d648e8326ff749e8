// SPDX-License-Identifier: Apache-2.0
// An edge crossing has the same bits whatever the build's target: with FMA available
// (compiled here for AVX2 + FMA, as -march=native would on a current x86) the library's
// -ffp-contract=off keeps every product rounded on its own, as in a default x86-64
// build. Fused multiply-adds would move crossings by an ulp, and nodes extracted by
// differently built binaries would no longer meet at bit-identical vertices.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>
#include <vector>

#include "extract/tet_clipper.h"

namespace strielad {
namespace {

struct Input {
  Vec3 p, q;
  double sp, sq;
};

// The same inline code, compiled without FMA (the default x86-64 target) ...
EdgeCrossing crossing_default_target(const Input& in) {
  std::uint64_t corner_crossings = 0;
  return edge_crossing(in.p, in.q, in.sp, in.sq, corner_crossings);
}

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define STRIELAD_HAVE_FMA_TARGET 1
// ... and with FMA available to the compiler (flatten: edge_crossing inlined here, so
// compiled for this target).
__attribute__((target("avx2,fma"), flatten)) EdgeCrossing crossing_fma_target(const Input& in) {
  std::uint64_t corner_crossings = 0;
  return edge_crossing(in.p, in.q, in.sp, in.sq, corner_crossings);
}
#endif

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// Lattice edges (unit steps along one, two or three axes) far from the origin, with
// sample values of opposite sign and very different magnitudes.
std::vector<Input> random_edges(std::size_t n) {
  std::mt19937_64 rng(20261123);
  std::uniform_int_distribution<int> corner(0, 4000), axes(1, 7);
  std::uniform_real_distribution<double> value(1e-3, 1e3);
  std::vector<Input> out;
  for (std::size_t i = 0; i < n; ++i) {
    Input in;
    const int step = axes(rng);
    for (int a = 0; a < 3; ++a) {
      in.p[a] = corner(rng);
      in.q[a] = in.p[a] + ((step >> a) & 1);
    }
    in.sp = value(rng);
    in.sq = -value(rng);
    out.push_back(in);
  }
  return out;
}

TEST(EdgeCrossings, RoundEveryProductWhereTheTargetHasFma) {
#ifndef STRIELAD_HAVE_FMA_TARGET
  GTEST_SKIP() << "not an x86-64 GCC or Clang build";
#else
  if (!__builtin_cpu_supports("avx2") || !__builtin_cpu_supports("fma")) {
    GTEST_SKIP() << "this CPU has no AVX2 and FMA";
  }
  const std::vector<Input> edges = random_edges(20000);
  std::size_t fusing_would_differ = 0, differ = 0;
  for (const Input& in : edges) {
    const EdgeCrossing plain = crossing_default_target(in);
    const EdgeCrossing fma = crossing_fma_target(in);
    bool same = same_bits(plain.t, fma.t);
    for (int a = 0; a < 3; ++a) same = same && same_bits(plain.p[a], fma.p[a]);
    differ += same ? 0 : 1;
    // The inputs are ones where fusing shows: wp p + wq q rounded once differs.
    const double t = in.sp / (in.sp - in.sq);
    for (int a = 0; a < 3; ++a) {
      if (in.p[a] == in.q[a]) continue;
      const volatile double wp_p = (1.0 - t) * in.p[a];
      const double separate = wp_p + t * in.q[a];
      fusing_would_differ += same_bits(separate, std::fma(t, in.q[a], wp_p)) ? 0 : 1;
    }
  }
  EXPECT_GT(fusing_would_differ, 1000u);
  EXPECT_EQ(differ, 0u) << "of " << edges.size() << " crossings";
#endif
}

}  // namespace
}  // namespace strielad
