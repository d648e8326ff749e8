// SPDX-License-Identifier: Apache-2.0
// A curvilinear grid's position at a fractional index: the stored longitude and latitude
// at every column, bilinear between them (linear along each lattice edge), the bilinear
// map's derivatives, and the orientation of (i, j) against (east, north).
#include <gtest/gtest.h>

#include <cmath>

#include "core/error.h"
#include "format/curvilinear_lonlat.h"
#include "support/expect_error.h"

namespace strielad {
namespace {

// A sheared, bent 4 x 3 grid crossing the antimeridian, its longitudes unwrapped.
std::shared_ptr<format::HorizontalCoordinates> bent_grid() {
  auto c = std::make_shared<format::HorizontalCoordinates>();
  c->nx = 4;
  c->ny = 3;
  for (std::uint32_t j = 0; j < c->ny; ++j) {
    for (std::uint32_t i = 0; i < c->nx; ++i) {
      c->lon.push_back(178.0 + 1.5 * i + 0.3 * j + 0.05 * i * j);
      c->lat.push_back(60.0 + 0.2 * i + 1.0 * j - 0.04 * i * i);
    }
  }
  return c;
}

TEST(CurvilinearLonLatTest, ColumnsKeepTheirStoredPositions) {
  const auto c = bent_grid();
  const CurvilinearLonLat map(c);
  for (std::uint32_t j = 0; j < c->ny; ++j) {
    for (std::uint32_t i = 0; i < c->nx; ++i) {
      const auto p = map.at(i, j);
      EXPECT_EQ(p[0], c->lon[j * c->nx + i]) << i << " " << j;
      EXPECT_EQ(p[1], c->lat[j * c->nx + i]) << i << " " << j;
    }
  }
}

TEST(CurvilinearLonLatTest, BilinearInsideACellAndLinearAlongItsEdges) {
  const auto c = bent_grid();
  const CurvilinearLonLat map(c);
  const auto corner = [&](std::uint32_t i, std::uint32_t j) {
    return std::array<double, 2>{c->lon[j * c->nx + i], c->lat[j * c->nx + i]};
  };
  // Along the edge (1, 1) - (2, 1): linear, so a vertex a kernel puts there gets the
  // position of the two samples it lies between, whichever node computes it.
  const auto a = corner(1, 1), b = corner(2, 1);
  const auto e = map.at(1.25, 1);
  EXPECT_NEAR(e[0], 0.75 * a[0] + 0.25 * b[0], 1e-12);
  EXPECT_NEAR(e[1], 0.75 * a[1] + 0.25 * b[1], 1e-12);
  // The cell centre is the mean of its corners.
  const auto m = map.at(2.5, 0.5);
  const auto p00 = corner(2, 0), p10 = corner(3, 0), p01 = corner(2, 1), p11 = corner(3, 1);
  EXPECT_NEAR(m[0], 0.25 * (p00[0] + p10[0] + p01[0] + p11[0]), 1e-12);
  EXPECT_NEAR(m[1], 0.25 * (p00[1] + p10[1] + p01[1] + p11[1]), 1e-12);
  // Longitudes stay unwrapped across the antimeridian (no jump of a turn).
  EXPECT_GT(map.at(2.9, 1.5)[0], 180.0);
}

TEST(CurvilinearLonLatTest, JacobianIsTheBilinearMapsDerivative) {
  const CurvilinearLonLat map(bent_grid());
  for (const auto& [i, j] : {std::pair{0.3, 0.4}, std::pair{1.7, 1.2}, std::pair{2.9, 1.9}}) {
    const auto d = map.jacobian(i, j);
    const double h = 1e-6;
    const auto pi = map.at(i + h, j), mi = map.at(i - h, j);
    const auto pj = map.at(i, j + h), mj = map.at(i, j - h);
    EXPECT_NEAR(d[0], (pi[0] - mi[0]) / (2 * h), 1e-6);
    EXPECT_NEAR(d[1], (pj[0] - mj[0]) / (2 * h), 1e-6);
    EXPECT_NEAR(d[2], (pi[1] - mi[1]) / (2 * h), 1e-6);
    EXPECT_NEAR(d[3], (pj[1] - mj[1]) / (2 * h), 1e-6);
  }
}

TEST(CurvilinearLonLatTest, OrientationFollowsTheIndexDirections) {
  EXPECT_EQ(CurvilinearLonLat(bent_grid()).orientation(), 1);  // i east, j north
  // Rows stored north to south: (i, j) against (east, north) reverses.
  auto flipped = std::make_shared<format::HorizontalCoordinates>(*bent_grid());
  for (std::uint32_t j = 0; j < flipped->ny; ++j) {
    for (std::uint32_t i = 0; i < flipped->nx; ++i) {
      flipped->lat[j * flipped->nx + i] = -flipped->lat[j * flipped->nx + i];
    }
  }
  EXPECT_EQ(CurvilinearLonLat(flipped).orientation(), -1);
}

TEST(CurvilinearLonLatTest, TooFewColumnsAreRefused) {
  auto c = std::make_shared<format::HorizontalCoordinates>();
  c->nx = 1;
  c->ny = 3;
  c->lon = {0, 0, 0};
  c->lat = {0, 1, 2};
  testing::expect_error([&] { CurvilinearLonLat map(c); }, ErrorCode::kInvalidArgument,
                        {"at least 2 x 2"});
}

}  // namespace
}  // namespace strielad
