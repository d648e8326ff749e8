// SPDX-License-Identifier: Apache-2.0
#include "ingest/curvilinear_grid.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/error.h"

namespace strielad::ingest {
namespace {

// The longitude difference b - a brought into [-180, 180].
double wrapped_difference(double a, double b) {
  const double d = b - a;
  return d - 360.0 * std::round(d / 360.0);
}

class GridChecker {
 public:
  GridChecker(CurvilinearGrid& g, std::string_view what) : g_(g), what_(what) {}

  void check_values(const std::vector<double>& lon_missing,
                    const std::vector<double>& lat_missing) {
    for (std::size_t j = 0; j < g_.ny; ++j) {
      for (std::size_t i = 0; i < g_.nx; ++i) {
        check_value(g_.lon_variable, lon(i, j), lon_missing, i, j);
        check_value(g_.lat_variable, lat(i, j), lat_missing, i, j);
        if (lat(i, j) < -90 || lat(i, j) > 90) {
          throw make_error(ErrorCode::kInvalidInput,
                           "{}: 2-D latitude '{}' at (i {}, j {}) is {}, outside [-90, 90]", what_,
                           g_.lat_variable, i, j, lat(i, j));
        }
        if (std::fabs(lat(i, j)) == 90) {
          throw make_error(ErrorCode::kInvalidInput,
                           "{}: the sample at (i {}, j {}) lies on the {} pole ('{}' = {}): a "
                           "curvilinear grid must not touch a pole, where longitude is undefined",
                           what_, i, j, lat(i, j) > 0 ? "north" : "south", g_.lat_variable,
                           lat(i, j));
        }
      }
    }
  }

  // A cell whose corners' longitudes turn once round (winding number not 0) holds a pole.
  void check_no_pole_in_cells() {
    for (std::size_t j = 0; j + 1 < g_.ny; ++j) {
      for (std::size_t i = 0; i + 1 < g_.nx; ++i) {
        const double turn = wrapped_difference(lon(i, j), lon(i + 1, j)) +
                            wrapped_difference(lon(i + 1, j), lon(i + 1, j + 1)) +
                            wrapped_difference(lon(i + 1, j + 1), lon(i, j + 1)) +
                            wrapped_difference(lon(i, j + 1), lon(i, j));
        if (std::fabs(turn) > 180) {
          const double mean_lat = lat(i, j) + lat(i + 1, j) + lat(i, j + 1) + lat(i + 1, j + 1);
          throw make_error(ErrorCode::kInvalidInput,
                           "{}: the grid cell from (i {}, j {}) to (i {}, j {}) contains the {} "
                           "pole (its corners' longitudes '{}' go once round it): a curvilinear "
                           "grid must not cover a pole",
                           what_, i, j, i + 1, j + 1, mean_lat > 0 ? "north" : "south",
                           g_.lon_variable);
        }
      }
    }
  }

  // Down column 0, then along every row, each longitude moved by whole turns to within
  // 180 degrees of its neighbour; then every neighbour along j must be within 180 too.
  void unwrap() {
    for (std::size_t j = 1; j < g_.ny; ++j) move_near(lon(0, j - 1), lon(0, j));
    for (std::size_t j = 0; j < g_.ny; ++j) {
      for (std::size_t i = 1; i < g_.nx; ++i) move_near(lon(i - 1, j), lon(i, j));
    }
    for (std::size_t j = 0; j < g_.ny; ++j) {
      for (std::size_t i = 0; i < g_.nx; ++i) {
        const bool along_i = i + 1 < g_.nx && !(std::fabs(lon(i + 1, j) - lon(i, j)) < 180);
        const bool along_j = j + 1 < g_.ny && !(std::fabs(lon(i, j + 1) - lon(i, j)) < 180);
        if (!along_i && !along_j) continue;
        const std::size_t i2 = along_i ? i + 1 : i, j2 = along_i ? j : j + 1;
        throw make_error(ErrorCode::kInvalidInput,
                         "{}: 2-D longitude '{}' cannot be unwrapped: (i {}, j {}) and (i {}, j "
                         "{}) lie {} degrees apart once rows and columns are made continuous "
                         "(neighbours must be less than 180 apart)",
                         what_, g_.lon_variable, i, j, i2, j2,
                         std::fabs(lon(i2, j2) - lon(i, j)));
      }
    }
  }

  // The sign of the cross product of the (i+1) and (j+1) steps in a local (east, north)
  // frame at two opposite corners of every cell.
  int orientation() {
    int sign = 0;
    std::size_t first_i = 0, first_j = 0;
    for (std::size_t j = 0; j + 1 < g_.ny; ++j) {
      for (std::size_t i = 0; i + 1 < g_.nx; ++i) {
        for (const double c : {cross({i, j}, {i + 1, j}, {i, j}, {i, j + 1}),
                               cross({i, j + 1}, {i + 1, j + 1}, {i + 1, j}, {i + 1, j + 1})}) {
          const int s = c > 0 ? 1 : c < 0 ? -1 : 0;
          if (s == 0) {
            throw make_error(ErrorCode::kInvalidInput,
                             "{}: the grid cell from (i {}, j {}) to (i {}, j {}) is degenerate: "
                             "its steps along i and j are parallel ('{}', '{}')",
                             what_, i, j, i + 1, j + 1, g_.lon_variable, g_.lat_variable);
          }
          if (sign == 0) {
            sign = s;
            first_i = i;
            first_j = j;
          } else if (s != sign) {
            throw make_error(ErrorCode::kInvalidInput,
                             "{}: the grid folds: the cell from (i {}, j {}) to (i {}, j {}) "
                             "turns the other way than the cell at (i {}, j {}) (the sign of the "
                             "cross product of its i and j steps east and north changes; '{}', "
                             "'{}')",
                             what_, i, j, i + 1, j + 1, first_i, first_j, g_.lon_variable,
                             g_.lat_variable);
          }
        }
      }
    }
    return sign;
  }

 private:
  double& lon(std::size_t i, std::size_t j) { return g_.lon[j * g_.nx + i]; }
  double& lat(std::size_t i, std::size_t j) { return g_.lat[j * g_.nx + i]; }

  struct Sample {
    std::size_t i, j;
  };
  // Cross product of the step a -> b (along i) and the step c -> d (along j) that meet at
  // a corner, east scaled by the cosine of the latitude at d.
  double cross(Sample a, Sample b, Sample c, Sample d) {
    const double k = std::cos(lat(d.i, d.j) * std::numbers::pi / 180.0);
    const double ue = (lon(b.i, b.j) - lon(a.i, a.j)) * k, un = lat(b.i, b.j) - lat(a.i, a.j);
    const double ve = (lon(d.i, d.j) - lon(c.i, c.j)) * k, vn = lat(d.i, d.j) - lat(c.i, c.j);
    return ue * vn - un * ve;
  }

  static void move_near(double reference, double& value) {
    const double turns = std::round((reference - value) / 360.0);
    if (turns != 0) value += 360.0 * turns;
  }

  void check_value(const std::string& name, double v, const std::vector<double>& missing,
                   std::size_t i, std::size_t j) const {
    if (!std::isfinite(v)) {
      throw make_error(ErrorCode::kInvalidInput,
                       "{}: 2-D coordinate '{}' at (i {}, j {}) is {}: every column of a "
                       "curvilinear grid needs a finite position",
                       what_, name, i, j, v);
    }
    if (std::find(missing.begin(), missing.end(), v) != missing.end()) {
      throw make_error(ErrorCode::kInvalidInput,
                       "{}: 2-D coordinate '{}' at (i {}, j {}) is missing ({}, its _FillValue "
                       "or missing_value): every column of a curvilinear grid needs a position",
                       what_, name, i, j, v);
    }
  }

  CurvilinearGrid& g_;
  std::string_view what_;
};

}  // namespace

CurvilinearGrid make_curvilinear_grid(std::string lon_variable, std::string lat_variable,
                                      std::size_t nx, std::size_t ny, std::vector<double> lon,
                                      std::vector<double> lat,
                                      const std::vector<double>& lon_missing,
                                      const std::vector<double>& lat_missing,
                                      std::string_view what) {
  CurvilinearGrid g{std::move(lon_variable), std::move(lat_variable), nx, ny, std::move(lon),
                    std::move(lat), 1};
  if (g.lon.size() != nx * ny || g.lat.size() != nx * ny) {
    throw make_error(ErrorCode::kInvalidInput,
                     "{}: 2-D coordinates '{}' and '{}' hold {} and {} values, {} x {} expected",
                     what, g.lon_variable, g.lat_variable, g.lon.size(), g.lat.size(), nx, ny);
  }
  if (nx < 2 || ny < 2) {
    throw make_error(ErrorCode::kInvalidInput,
                     "{}: a curvilinear grid needs at least 2 x 2 samples ('{}' is {} x {})", what,
                     g.lon_variable, nx, ny);
  }
  GridChecker checker(g, what);
  checker.check_values(lon_missing, lat_missing);
  checker.check_no_pole_in_cells();
  checker.unwrap();
  g.orientation = checker.orientation();
  return g;
}

std::optional<std::string> curvilinear_difference(const CurvilinearGrid& got,
                                                  const CurvilinearGrid& want,
                                                  std::string_view want_where) {
  if (got.lon_variable != want.lon_variable || got.lat_variable != want.lat_variable) {
    return fmt::format("2-D coordinates are '{}' and '{}' but {} has '{}' and '{}'",
                       got.lon_variable, got.lat_variable, want_where, want.lon_variable,
                       want.lat_variable);
  }
  if (got.nx != want.nx || got.ny != want.ny) {
    return fmt::format("2-D coordinates are {} x {} but {} has {} x {}", got.nx, got.ny,
                       want_where, want.nx, want.ny);
  }
  for (const auto which : {&CurvilinearGrid::lon, &CurvilinearGrid::lat}) {
    const std::vector<double>& a = got.*which;
    const std::vector<double>& b = want.*which;
    const std::string& name =
        which == &CurvilinearGrid::lon ? got.lon_variable : got.lat_variable;
    for (std::size_t k = 0; k < a.size(); ++k) {
      if (a[k] == b[k]) continue;
      return fmt::format("2-D coordinate '{}' at (i {}, j {}) is {} but {} has {}; the 2-D "
                         "coordinates must be the same in every file and time step",
                         name, k % got.nx, k / got.nx, a[k], want_where, b[k]);
    }
  }
  return std::nullopt;
}

}  // namespace strielad::ingest
