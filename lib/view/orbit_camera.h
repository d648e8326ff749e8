// SPDX-License-Identifier: Apache-2.0
// The viewer's interactive camera in the world frame (lod/world_frame.h, km): orbit
// about a target, pan, zoom and fly, as mouse and keys drive it. Pitch stays within
// +-89 degrees so the view never flips over the pole of the orbit.
//
// On the globe (lod/world_frame.h, ECEF km; set_globe) the orbit is about the Earth's
// centre with the polar axis up, so dragging turns the Earth under the view; home looks
// down on a chosen longitude and latitude from where the whole Earth shows; zoom keeps the
// eye above the ground and towards the point under the cursor (zoom_at); panning and
// flying turn the Earth by the ground they cross; and below two Earth radii from the centre the view tilts from
// straight down towards the horizon, all the way (70 degrees) at the ground.
#pragma once

#include "lod/camera.h"
#include "lod/geometry.h"

namespace strielad::view {

class OrbitCamera {
 public:
  // Starts at home() for the domain.
  explicit OrbitCamera(const lod::WorldBox& domain);

  // The home view: the whole domain from the south at 50 degrees elevation, at a
  // distance where a 45 degree view holds its bounding sphere.
  void home();
  // Globe mode, home above (lon_deg, lat_deg); the domain must be the globe's.
  void set_globe(double lon_deg, double lat_deg);
  bool globe() const { return globe_; }
  // Rotates about the target: yaw about world z, pitch up/down (degrees).
  void orbit(double yaw_deg, double pitch_deg);
  // Moves eye and target across the view: fractions of the visible height at the target.
  void pan(double right_fraction, double up_fraction);
  // Moves the eye towards (factor < 1) or away from the target; the distance stays
  // between 10 m and 100 times the domain's size.
  void zoom(double factor);
  // zoom, and on the globe also towards the ground under the cursor, `right_fraction` and
  // `up_fraction` of the view's height from its centre (the plane zooms at the centre).
  void zoom_at(double factor, double right_fraction, double up_fraction);
  // What a mouse drag's degrees are multiplied by: 1 on the plane; on the globe the
  // altitude over the home view's, so the ground follows the mouse near the surface.
  double drag_scale() const;
  // Moves eye and target along the view direction projected on the ground (forward),
  // sideways and vertically, in km.
  void fly(double forward_km, double right_km, double up_km);
  void look_from(const Vec3& eye, const Vec3& target);
  // The vertical exaggeration changed by `ratio` (new / old): on the plane world z
  // scales with it; on the globe (ECEF, the Earth unchanged) the camera stays.
  void rescale_vertical(double ratio, const lod::WorldBox& new_domain);

  lod::Camera camera(double aspect, double fov_y_deg = 45.0) const;
  Vec3 eye() const;
  const Vec3& target() const { return target_; }
  double distance() const { return distance_; }

 private:
  lod::WorldBox domain_;
  Vec3 target_{};
  double distance_ = 1.0;
  double yaw_deg_ = 0;    // 0: looking north (eye south of the target)
  double pitch_deg_ = 50; // elevation of the eye above the target's horizon
  bool globe_ = false;
  double home_lon_deg_ = 0, home_lat_deg_ = 0;
};

}  // namespace strielad::view
