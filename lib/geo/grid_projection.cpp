// SPDX-License-Identifier: Apache-2.0
#include "geo/grid_projection.h"

#include <proj.h>

#include <cmath>
#include <limits>
#include <map>
#include <string>

#include "core/error.h"

namespace strielad::geo {

struct GridProjection::Impl {
  PJ_CONTEXT* ctx = nullptr;
  PJ* pj = nullptr;
  ~Impl() {
    if (pj != nullptr) proj_destroy(pj);
    if (ctx != nullptr) proj_context_destroy(ctx);
  }
};

GridProjection::GridProjection(std::string_view pipeline) {
  if (pipeline.empty()) return;
  auto impl = std::make_unique<Impl>();
  impl->ctx = proj_context_create();
  if (impl->ctx == nullptr) {
    throw make_error(ErrorCode::kUnsupported, "PROJ: cannot create a context for '{}'", pipeline);
  }
  proj_log_level(impl->ctx, PJ_LOG_NONE);
  // No network and no grid files: every pipeline here is a plain projection.
  proj_context_set_enable_network(impl->ctx, 0);
  const std::string definition(pipeline);
  impl->pj = proj_create(impl->ctx, definition.c_str());
  if (impl->pj == nullptr) {
    const int err = proj_context_errno(impl->ctx);
    throw make_error(ErrorCode::kUnsupported, "PROJ rejects '{}': {}", pipeline,
                     proj_context_errno_string(impl->ctx, err));
  }
  impl_ = std::move(impl);
}

const GridProjection& GridProjection::for_this_thread(const std::string& pipeline) {
  thread_local std::map<std::string, GridProjection, std::less<>> projections;
  auto it = projections.find(pipeline);
  if (it == projections.end()) it = projections.emplace(pipeline, GridProjection(pipeline)).first;
  return it->second;
}

GridProjection::~GridProjection() = default;
GridProjection::GridProjection(GridProjection&&) noexcept = default;
GridProjection& GridProjection::operator=(GridProjection&&) noexcept = default;

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

std::array<double, 2> run(PJ* pj, PJ_DIRECTION direction, double a, double b) {
  PJ_COORD c = proj_coord(a, b, 0, 0);
  const PJ_COORD r = proj_trans(pj, direction, c);
  const double u = r.xy.x, v = r.xy.y;
  if (!std::isfinite(u) || !std::isfinite(v) || u == HUGE_VAL || v == HUGE_VAL) return {kNaN, kNaN};
  return {u, v};
}

}  // namespace

std::array<double, 2> GridProjection::to_geographic(double x, double y) const {
  if (impl_ == nullptr) return {x, y};
  proj_errno_reset(impl_->pj);
  return run(impl_->pj, PJ_FWD, x, y);
}

std::array<double, 2> GridProjection::to_axis(double lon, double lat) const {
  if (impl_ == nullptr) return {lon, lat};
  proj_errno_reset(impl_->pj);
  return run(impl_->pj, PJ_INV, lon, lat);
}

std::array<double, 4> GridProjection::jacobian(double x, double y, double h) const {
  const auto xp = to_geographic(x + h, y), xm = to_geographic(x - h, y);
  const auto yp = to_geographic(x, y + h), ym = to_geographic(x, y - h);
  auto dlon = [](double a, double b) { return std::remainder(a - b, 360.0); };
  const double two_h = 2 * h;
  return {dlon(xp[0], xm[0]) / two_h, dlon(yp[0], ym[0]) / two_h, (xp[1] - xm[1]) / two_h,
          (yp[1] - ym[1]) / two_h};
}

}  // namespace strielad::geo
