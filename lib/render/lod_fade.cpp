// SPDX-License-Identifier: Apache-2.0
#include "render/lod_fade.h"

#include <algorithm>
#include <cmath>

#include "render/shader_program.h"

namespace strielad::render {
namespace {

constexpr const char* kBlendVertex = R"(#version 450 core
void main() {
  // One triangle over the whole viewport.
  const vec2 corner = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2);
  gl_Position = vec4(corner * 2.0 - 1.0, 0.0, 1.0);
}
)";

constexpr const char* kBlendFragment = R"(#version 450 core
layout(binding = 0) uniform sampler2D u_outgoing;
layout(binding = 1) uniform sampler2D u_incoming;
uniform float u_weight;
out vec4 o_color;
void main() {
  const ivec2 p = ivec2(gl_FragCoord.xy);
  o_color = mix(texelFetch(u_outgoing, p, 0), texelFetch(u_incoming, p, 0), u_weight);
}
)";

// Swaps the renderer's meshes to the retained set for its lifetime.
class RetainedShown {
 public:
  explicit RetainedShown(GpuMeshes& meshes) : meshes_(meshes) { meshes_.exchange_retained(); }
  ~RetainedShown() { meshes_.exchange_retained(); }
  RetainedShown(const RetainedShown&) = delete;
  RetainedShown& operator=(const RetainedShown&) = delete;

 private:
  GpuMeshes& meshes_;
};

}  // namespace

void LodFadeSchedule::set_fade_ms(double fade_ms) {
  fade_ms_ = std::isfinite(fade_ms) && fade_ms > 0 ? fade_ms : 0;
  fade_s_ = fade_ms_ / 1e3;
  if (!enabled()) stop();
}

void LodFadeSchedule::advance(double seconds) {
  if (!running_) return;
  elapsed_s_ += std::max(seconds, 0.0);
  if (!(elapsed_s_ < fade_s_)) stop();
}

double LodFadeSchedule::weight() const {
  return running_ ? std::clamp(elapsed_s_ / fade_s_, 0.0, 1.0) : 1.0;
}

std::uint8_t blend_channel(std::uint8_t outgoing, std::uint8_t incoming, double weight) {
  const double v = (1 - weight) * outgoing + weight * incoming;
  return static_cast<std::uint8_t>(std::clamp(std::lround(v), 0l, 255l));
}

LodCrossFade::LodCrossFade(double fade_ms) : schedule_(fade_ms) {
  blend_program_ = compile_builtin_program(kBlendVertex, kBlendFragment, "level-of-detail blend");
  empty_vertex_array_ = make_vertex_array();
}

LodCrossFade::~LodCrossFade() = default;

void LodCrossFade::set_fade_ms(double fade_ms, GpuMeshes& meshes) {
  if (fade_ms == schedule_.fade_ms() || (!(fade_ms > 0) && !schedule_.enabled())) return;
  schedule_.set_fade_ms(fade_ms);
  schedule_.stop();
  meshes.end_retaining();
}

std::size_t LodCrossFade::sync(GpuMeshes& meshes, const view::ProgressiveMeshes& shown,
                               std::size_t max_upload_bytes, double seconds) {
  if (!schedule_.enabled()) {
    if (meshes.retaining()) meshes.end_retaining();
    return meshes.sync(shown, max_upload_bytes);
  }
  const double shown_weight = schedule_.weight();  // of the frame on screen
  if (schedule_.running()) {
    schedule_.advance(seconds);
    if (!schedule_.running()) meshes.end_retaining();  // over: the outgoing set is freed
  }
  if (!meshes.retaining()) meshes.begin_retaining();
  const bool change_coming =
      shown.version() != synced_shown_version_ || meshes.deferred() > 0;
  if (schedule_.running() && change_coming && shown_weight >= 0.5) {
    // The incoming set, already the larger part of the picture, becomes the outgoing one.
    schedule_.stop();
    meshes.begin_retaining();
  }
  const bool was_empty = meshes.meshes().empty() && !meshes.retained_differs();
  const auto before = meshes.shown_version();
  const std::size_t bytes = meshes.sync(shown, max_upload_bytes);
  synced_shown_version_ = shown.version();
  if (meshes.shown_version() != before && !schedule_.running()) {
    if (was_empty) {
      meshes.begin_retaining();  // the first picture appears at once
    } else {
      schedule_.start();
    }
  }
  if (schedule_.running() && !meshes.retained_differs()) {
    schedule_.stop();
    meshes.begin_retaining();
  }
  return bytes;
}

void LodCrossFade::finish(GpuMeshes& meshes) {
  schedule_.stop();
  if (meshes.retaining()) meshes.begin_retaining();
}

FrameStats LodCrossFade::render(VolumeRenderer& renderer, const FrameInputs& inputs,
                                GLuint framebuffer, int width, int height) {
  if (!schedule_.running() || !renderer.meshes().retained_differs() || width <= 0 ||
      height <= 0) {
    last_weight_ = 1;
    return renderer.render(inputs, framebuffer, width, height);
  }
  ensure_targets(width, height);
  {
    const RetainedShown outgoing(renderer.meshes());
    renderer.render(inputs, outgoing_->framebuffer(), width, height);
  }
  const FrameStats stats = renderer.render(inputs, incoming_->framebuffer(), width, height);
  last_weight_ = schedule_.weight();
  blend(framebuffer, width, height, last_weight_);
  return stats;
}

void LodCrossFade::ensure_targets(int width, int height) {
  if (outgoing_ && outgoing_->width() == width && outgoing_->height() == height) return;
  outgoing_ = std::make_unique<OffscreenTarget>(width, height);
  incoming_ = std::make_unique<OffscreenTarget>(width, height);
  for (const auto* target : {outgoing_.get(), incoming_.get()}) {
    glTextureParameteri(target->color_texture(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTextureParameteri(target->color_texture(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  }
}

void LodCrossFade::blend(GLuint framebuffer, int width, int height, double weight) {
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  glViewport(0, 0, width, height);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_BLEND);
  glDepthMask(GL_FALSE);
  glUseProgram(blend_program_.get());
  glProgramUniform1f(blend_program_.get(),
                     glGetUniformLocation(blend_program_.get(), "u_weight"),
                     static_cast<float>(weight));
  glBindTextureUnit(0, outgoing_->color_texture());
  glBindTextureUnit(1, incoming_->color_texture());
  glBindVertexArray(empty_vertex_array_.get());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindTextureUnit(0, 0);
  glBindTextureUnit(1, 0);
}

}  // namespace strielad::render
