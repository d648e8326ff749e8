// SPDX-License-Identifier: Apache-2.0
// Smooth level-of-detail transitions: when what the viewer draws changes (a node of the
// cut splits or merges, a node's result arrives or is replaced), the frame cross-fades
// from the set shown before the change to the new set over a fixed time instead of
// popping. The blend is in image space: while a fade runs, the renderer draws the
// frame twice, once with the outgoing set and once with the incoming set, each through
// the whole A-buffer (a sub-volume's parent and children meshes are never in one
// fragment list, so the entry-exit pairing stays exact), and the two images are mixed
// as (1 - w) * outgoing + w * incoming, w going linearly from 0 to 1 (docs/view.md).
// Outside a fade a frame costs one render, as without fading; the outgoing set shares
// the GPU meshes of the nodes that did not change (GpuMeshes retaining).
// A change during a fade: while the frame on screen weighs the incoming set below 1/2
// the outgoing set stays and the incoming one is the newest; from 1/2 on the incoming
// set becomes the outgoing one and the fade starts over. Either way a frame changes by
// at most about half of a pop. A change from nothing drawn at all (the first picture)
// does not fade.
#pragma once

#include <cstdint>
#include <memory>

#include "render/gl_handles.h"
#include "render/offscreen_target.h"
#include "render/volume_renderer.h"

namespace strielad::render {

inline constexpr double kDefaultLodFadeMs = 300;

// The weight over time of one fade (no GL): idle, or running for `seconds` of `fade_s`.
class LodFadeSchedule {
 public:
  explicit LodFadeSchedule(double fade_ms = kDefaultLodFadeMs) { set_fade_ms(fade_ms); }
  // <= 0 (or not finite): fading off.
  void set_fade_ms(double fade_ms);
  double fade_ms() const { return fade_ms_; }
  bool enabled() const { return fade_s_ > 0; }

  void start() { running_ = enabled(); elapsed_s_ = 0; }
  void stop() { running_ = false; elapsed_s_ = 0; }
  // Time passes; the fade ends once its time is over.
  void advance(double seconds);
  bool running() const { return running_; }
  // The incoming set's weight: 0 at the start, elapsed / fade time, 1 when idle.
  double weight() const;

 private:
  double fade_ms_ = 0;
  double fade_s_ = 0;
  double elapsed_s_ = 0;
  bool running_ = false;
};

// (1 - weight) * outgoing + weight * incoming per channel, rounded to the nearest of 256
// levels: the GPU blend's arithmetic, on the CPU (tests, reference).
std::uint8_t blend_channel(std::uint8_t outgoing, std::uint8_t incoming, double weight);

// The cross-fade around a VolumeRenderer: sync() in place of GpuMeshes::sync, render()
// in place of VolumeRenderer::render. Needs the renderer's GL context.
class LodCrossFade {
 public:
  explicit LodCrossFade(double fade_ms = kDefaultLodFadeMs);
  ~LodCrossFade();
  LodCrossFade(const LodCrossFade&) = delete;
  LodCrossFade& operator=(const LodCrossFade&) = delete;

  // Changing the time ends a running fade (the new set is shown).
  void set_fade_ms(double fade_ms, GpuMeshes& meshes);
  const LodFadeSchedule& schedule() const { return schedule_; }

  // `seconds` since the last frame pass, then the renderer's meshes are synced with
  // `shown` (GpuMeshes::sync); a change of what is drawn starts a fade.
  std::size_t sync(GpuMeshes& meshes, const view::ProgressiveMeshes& shown,
                   std::size_t max_upload_bytes, double seconds);
  // Ends a running fade: the incoming set is shown alone from now on.
  void finish(GpuMeshes& meshes);
  // Renders the frame into `framebuffer`: one render when no fade runs, else both sets
  // and their blend. Returns the incoming set's statistics.
  FrameStats render(VolumeRenderer& renderer, const FrameInputs& inputs, GLuint framebuffer,
                    int width, int height);
  // The weight the last render() used (1 outside a fade).
  double last_weight() const { return last_weight_; }

 private:
  void ensure_targets(int width, int height);
  void blend(GLuint framebuffer, int width, int height, double weight);

  LodFadeSchedule schedule_;
  GlProgram blend_program_;
  GlVertexArray empty_vertex_array_;
  std::unique_ptr<OffscreenTarget> outgoing_, incoming_;
  double last_weight_ = 1;
  std::uint64_t synced_shown_version_ = ~0ull;
};

}  // namespace strielad::render
