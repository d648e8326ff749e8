// SPDX-License-Identifier: Apache-2.0
// The `strielad-bench view-fade` measure: the default fly-in over a generated sample
// store, rendered frame by frame at a fixed frame rate (each frame complete, simulated
// time 1 / fps per frame, render/complete_frame.h) once with the level-of-detail
// cross-fade off and once on (render/lod_fade.h). The per-pixel change of two images is
// the largest difference of any channel (0-255); its maximum and 99.9th percentile over
// the pixels are taken for two pairs per frame:
// - the level-of-detail change: frame i against what was on screen at frame i - 1 (its
//   meshes and fade weight) drawn from frame i's camera, so that only the change of
//   meshes (and the fade's progress) counts, not the camera's motion;
// - the frame-to-frame change, camera motion included (edges that move saturate it).
// The largest of each along the path is how hard the worst pop is.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "grid/axis.h"

namespace strielad::bench {

struct FadeBenchOptions {
  Dims3 dims{286, 312, 60};  // the sample of scripts/sample.sh
  std::vector<std::string> variables{"clw", "cli", "qr", "ta"};
  std::uint64_t seed = 1;
  std::uint32_t brick = 24;  // the converter's default
  std::filesystem::path work = "/tmp/strielad-bench-view-fade";
  int width = 480, height = 270;
  double fly_seconds = 20;  // the default fly-in's duration
  double from_s = 0, to_s = 20;  // the stretch of it rendered
  double fps = 30;
  double fade_ms = 300;
  unsigned threads = 0;
  std::string command_line;
};

// The per-pixel change between two RGBA8 images of one size: max over pixels of the
// largest channel difference, and its 99.9th percentile.
struct FrameChange {
  int max = 0;
  int p999 = 0;
};
FrameChange frame_change(const std::vector<std::uint8_t>& a, const std::vector<std::uint8_t>& b);

struct FadeRun {
  double fade_ms = 0;
  std::size_t frames = 0;
  std::size_t cut_changes = 0;    // frames whose cut differs from the previous frame's
  std::size_t faded_frames = 0;   // frames drawn as a blend (two renders)
  // Level-of-detail change (same camera): the largest max and p99.9 along the path, the
  // frame of the largest max, the median of the per-frame max over frames whose cut changed.
  FrameChange lod;
  std::size_t lod_at = 0;
  double lod_median_max = 0;
  FrameChange motion;             // frame to frame, camera motion included
  double render_ms_mean = 0;      // wall time per frame's render, read-back included
  std::vector<FrameChange> lod_changes, motion_changes;  // per frame from the second on
};

struct FadeBenchReport {
  FadeBenchOptions options;
  std::string gl;
  FadeRun off, on;
};

FadeBenchReport run_fade_bench(const FadeBenchOptions& options);
std::string fade_report_text(const FadeBenchReport& report);
nlohmann::json fade_report_json(const FadeBenchReport& report);

}  // namespace strielad::bench
