// SPDX-License-Identifier: Apache-2.0
#include "support/cs2cs.h"

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "support/temp_dir.h"

namespace strielad::testing {

bool have_cs2cs() { return std::system("cs2cs </dev/null >/dev/null 2>&1") == 0; }

namespace {

// cs2cs on N-coordinate points (N = 2: lon lat or x y; N = 3 with a height), the first N
// coordinates of each output line.
template <std::size_t N>
std::optional<std::vector<std::array<double, N>>> run_cs2cs(
    const std::string& from, const std::string& to, const std::vector<std::array<double, N>>& points) {
  TempDir dir;
  const auto input = dir / "points.txt";
  {
    std::ofstream out(input);
    out.precision(17);
    for (const auto& p : points) {
      for (std::size_t c = 0; c < N; ++c) out << p[c] << (c + 1 < N ? ' ' : '\n');
    }
  }
  const std::string command =
      "cs2cs -f %.12f " + from + " +to " + to + " < '" + input.string() + "'";
  FILE* pipe = popen(command.c_str(), "r");
  if (pipe == nullptr) return std::nullopt;
  std::string text;
  char buffer[4096];
  while (const std::size_t n = std::fread(buffer, 1, sizeof buffer, pipe)) text.append(buffer, n);
  if (pclose(pipe) != 0) return std::nullopt;
  std::vector<std::array<double, N>> out;
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);) {
    std::istringstream fields(line);
    std::array<double, N> p{};
    for (auto& c : p) {
      if (!(fields >> c)) return std::nullopt;
    }
    out.push_back(p);
  }
  if (out.size() != points.size()) return std::nullopt;
  return out;
}

}  // namespace

std::optional<std::vector<std::array<double, 2>>> cs2cs(
    const std::string& from, const std::string& to, const std::vector<std::array<double, 2>>& points) {
  return run_cs2cs<2>(from, to, points);
}

std::optional<std::vector<std::array<double, 3>>> cs2cs_3d(
    const std::string& from, const std::string& to, const std::vector<std::array<double, 3>>& points) {
  return run_cs2cs<3>(from, to, points);
}

}  // namespace strielad::testing
