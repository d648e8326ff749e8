// SPDX-License-Identifier: Apache-2.0
#include "bench/report_plots.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <sstream>

#include "bench/gnuplot_run.h"
#include "bench/table_writer.h"

namespace strielad::bench {
namespace {

// Gnuplot single-quoted strings: a quote is doubled.
std::string quoted(const std::string& text) {
  std::string out = "'";
  for (char c : text) out += c == '\'' ? std::string("''") : std::string(1, c);
  return out + "'";
}

// Gnuplot double-quoted strings: backslash escapes, so '\n' breaks the line.
std::string double_quoted(const std::string& text) {
  std::string out = "\"";
  for (char c : text) {
    if (c == '\n') out += "\\n";
    else if (c == '"' || c == '\\') out += std::string("\\") + c;
    else out += c;
  }
  return out + "\"";
}

std::string header(const std::filesystem::path& png, const ChartAxes& axes, int width) {
  std::ostringstream gp;
  // About 7 px per character at 10 pt; the title wraps rather than being cut off.
  const std::size_t title_chars = static_cast<std::size_t>(std::max(40, width / 7 - 4));
  gp << "set terminal pngcairo noenhanced size " << width << ",480 font 'sans,10'\n"
     << "set output " << quoted(png.filename().string()) << "\n"
     << "set title " << double_quoted(wrap_title(axes.title, title_chars)) << "\n"
     << "set xlabel " << quoted(axes.x_label) << "\n"
     << "set ylabel " << quoted(axes.y_label) << "\n"
     << "set grid ytics\n";
  if (axes.log_x) gp << "set logscale x\n";
  if (axes.log_y) gp << "set logscale y\n";
  return gp.str();
}

std::filesystem::path with_extension(const std::filesystem::path& png, const char* ext) {
  auto p = png;
  return p.replace_extension(ext);
}

}  // namespace

std::string bar_chart(const std::filesystem::path& png, const ChartAxes& axes,
                      const std::vector<std::string>& labels, const std::vector<double>& values) {
  if (labels.empty() || labels.size() != values.size()) return "no data";
  std::ostringstream dat;
  for (std::size_t i = 0; i < labels.size(); ++i) {
    std::string label = labels[i];
    std::replace(label.begin(), label.end(), '"', '\'');
    dat << i << " \"" << label << "\" " << fmt::format("{:.9g}", values[i]) << "\n";
  }
  const auto dat_path = with_extension(png, ".dat");
  write_text_file(dat_path, dat.str());
  std::ostringstream gp;
  gp << header(png, axes, std::max<int>(640, 90 * static_cast<int>(labels.size())))
     << "set style fill solid 0.8 border -1\n"
     << "set boxwidth 0.7\n"
     << "set xtics rotate by -30\n"
     // The last label runs down to the right of its bar: room for it, in characters.
     << "set rmargin " << 2 + static_cast<int>(0.87 * double(labels.back().size())) << "\n"
     << "set yrange [" << (axes.log_y ? "*" : "0") << ":*]\n"
     << "unset key\n"
     << "plot " << quoted(dat_path.filename().string())
     << " using 1:3:xtic(2) with boxes lc rgb '#4477aa', '' using 1:3:(sprintf('%.3g', $3)) "
        "with labels offset 0,0.7 notitle\n";
  const auto gp_path = with_extension(png, ".gp");
  write_text_file(gp_path, gp.str());
  return run_gnuplot(gp_path, png);
}

std::string line_chart(const std::filesystem::path& png, const ChartAxes& axes,
                       const std::vector<ChartSeries>& series, bool points) {
  std::ostringstream dat;
  std::vector<std::string> plots;
  int block = 0;
  const auto dat_path = with_extension(png, ".dat");
  for (const auto& s : series) {
    bool any = false;
    for (std::size_t i = 0; i < s.x.size() && i < s.y.size(); ++i) {
      if (!std::isfinite(s.x[i]) || !std::isfinite(s.y[i])) continue;
      if ((axes.log_x && s.x[i] <= 0) || (axes.log_y && s.y[i] <= 0)) continue;
      dat << fmt::format("{:.9g} {:.9g}\n", s.x[i], s.y[i]);
      any = true;
    }
    if (!any) continue;
    dat << "\n\n";
    plots.push_back(fmt::format("{} index {} using 1:2 with {} lw 2 title {}",
                                quoted(dat_path.filename().string()), block++,
                                points ? "linespoints" : "lines", quoted(s.name)));
  }
  if (plots.empty()) return "no data";
  write_text_file(dat_path, dat.str());
  std::ostringstream gp;
  gp << header(png, axes, 800) << "set key outside right top\n"
     << "plot " << fmt::format("{}", fmt::join(plots, ", \\\n     ")) << "\n";
  const auto gp_path = with_extension(png, ".gp");
  write_text_file(gp_path, gp.str());
  return run_gnuplot(gp_path, png);
}

std::string wrap_title(const std::string& title, std::size_t width) {
  std::string out, line;
  std::istringstream words(title);
  std::string word;
  while (words >> word) {
    if (!line.empty() && line.size() + 1 + word.size() > width) {
      out += (out.empty() ? "" : "\n") + line;
      line.clear();
    }
    line += (line.empty() ? "" : " ") + word;
  }
  if (!line.empty()) out += (out.empty() ? "" : "\n") + line;
  return out;
}

}  // namespace strielad::bench
