// SPDX-License-Identifier: Apache-2.0
// WGS84 in GLSL, for the shaders that draw on the globe (lod/world_frame.h FrameShape):
// the ellipsoid's constants, the geodetic latitude and height of an ECEF position and
// back, and globe_redrawn(), which moves geometry placed with its heights at one vertical
// exaggeration to where it lies at another.
#pragma once

namespace strielad::render {

inline constexpr const char* kWgs84Glsl = R"(
const float WGS84_A = 6378.137;          // km
const float WGS84_B = 6356.752314245;    // km
const float WGS84_E2 = 6.69437999014e-3;
const float WGS84_EP2 = 6.73949674228e-3;  // second eccentricity squared
// The geodetic latitude (radians) of an ECEF position: Bowring's closed form.
float globe_latitude(vec3 p) {
  float r = length(p.xy);
  float t = atan(p.z * WGS84_A, r * WGS84_B);
  float st = sin(t), ct = cos(t);
  return atan(p.z + WGS84_EP2 * WGS84_B * st * st * st, r - WGS84_E2 * WGS84_A * ct * ct * ct);
}
// The height above the WGS84 ellipsoid (km, as placed: exaggerated) of an ECEF position
// whose geodetic latitude is `lat`: h = r cos(lat) + z sin(lat) - a w, which holds at
// every latitude (poles included) without dividing by a small number.
float globe_height_at(vec3 p, float lat) {
  float s = sin(lat);
  return length(p.xy) * cos(lat) + p.z * s - WGS84_A * sqrt(1.0 - WGS84_E2 * s * s);
}
float globe_height_km(vec3 p) { return globe_height_at(p, globe_latitude(p)); }
// ECEF km of geodetic longitude and latitude (radians) and height (km).
vec3 globe_place(float lon, float lat, float h) {
  float s = sin(lat), c = cos(lat);
  float n = WGS84_A / sqrt(1.0 - WGS84_E2 * s * s);
  return vec3((n + h) * c * cos(lon), (n + h) * c * sin(lon), (n * (1.0 - WGS84_E2) + h) * s);
}
// A position placed with its height at one exaggeration, drawn at `ratio` times it (the
// exaggeration drawn over the one placed): moved along the ellipsoid normal so that its
// height scales by `ratio`, its longitude and latitude kept; exact, since a geodetic
// position is its ellipsoid point plus the height along that normal. `normal`'s part
// along the ellipsoid normal is divided by `ratio`, as z's is by the exaggeration on the
// plane, so that a surface's normal stays perpendicular to the surface drawn. At ratio 1
// both stay as they are.
vec3 globe_redrawn(vec3 p, inout vec3 normal, float ratio) {
  if (ratio == 1.0) return p;
  float lat = globe_latitude(p), lon = atan(p.y, p.x);
  vec3 up = vec3(cos(lat) * cos(lon), cos(lat) * sin(lon), sin(lat));
  float n_up = dot(normal, up);
  normal += (n_up / ratio - n_up) * up;
  return p + (ratio - 1.0) * globe_height_at(p, lat) * up;
}
)";

}  // namespace strielad::render
