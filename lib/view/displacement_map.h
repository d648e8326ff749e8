// SPDX-License-Identifier: Apache-2.0
// How far the air moves between two output steps, as a map the renderer can apply to
// every mesh vertex for free, so that the viewer advects the current meshes smoothly.
//
// A regular lattice spans the domain's world box (km, exaggeration 1). From each lattice
// point a trajectory runs through the wind of a WindStep (lib/advect, RK4 60 s by
// default) and its world displacement is recorded at `keyframes` evenly spaced times
// from 0 to the step's length. A vertex at world position p shown `s` seconds after its
// step moves by the displacement interpolated trilinearly in space at p and linearly
// between the two keyframes around s (the geometry vertex shader does exactly this with
// 3D textures; displacement_at is the same on the CPU).
//
// Why a map and not every vertex: a mesh vertex costs ~20 field evaluations per 5 min
// of RK4, i.e. seconds of CPU for the millions of vertices of one view, again for every
// new mesh; the map costs the same once per time step whatever the meshes, and moving
// vertices is one texture lookup each on the GPU. Its error against advecting each
// vertex itself is the interpolation error of a smooth displacement field on the
// lattice (measured in tests/view/displacement_map_test.cpp and BENCHMARKS.md).
//
// Trajectories that leave the domain or reach missing wind stop there (lib/advect flags
// them): their displacement stays at where they stopped, so meshes never move outside
// the domain and never get NaN positions.
//
// On the globe (a frame whose world is WGS84 ECEF km) a straight world offset would lift
// a cloud that drifts east at constant height off the curved Earth, so the lattice spans
// geodetic (longitude, latitude, height) instead: the domain's geographic bounds (a
// whole turn of longitudes, the last column the first again, where the store's x is
// periodic) by its height range, and each point records (dlon cos(lat0) degrees, dlat
// degrees, dh km) of its trajectory, lat0 its own latitude. The east part is stored
// times cos(lat0) so that it stays smooth up to the poles (a constant zonal wind gives
// the same value at every latitude); a vertex at latitude lat moves by that over
// cos(lat) (at least 1e-6) degrees of longitude. The geometry vertex shader recovers
// each vertex's geodetic position from its ECEF one (the exaggeration taken out), adds
// the interpolated displacement in longitude, latitude and height and places the point
// back at its exaggerated height; moved_on_globe is the same on the CPU.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "advect/integrators.h"
#include "lod/world_frame.h"
#include "view/wind_source.h"

namespace strielad::view {

struct DisplacementOptions {
  // Lattice points per axis; 0 picks: x, y the wind level's samples clamped to [8, 128],
  // z twice the wind level's samples clamped to [8, 64] (the vertical axis is often
  // stretched: a uniform lattice needs more points than the level to resolve the
  // bottom layers).
  std::array<std::size_t, 3> lattice{0, 0, 0};
  std::size_t keyframes = 5;  // >= 2, including time 0
  advect::AdvectOptions integrator{};
};

struct DisplacementMap {
  std::uint32_t step = 0;    // the step whose meshes it moves
  double seconds = 0;        // length of the step (the last keyframe's time)
  // The lattice's corners: world km at exaggeration 1 on the plane; on the globe
  // {longitude deg, latitude deg, height km} (longitudes continuous about the domain's
  // centre; hi = lo + 360 when periodic).
  lod::WorldBox box;
  bool globe = false;
  bool periodic = false;  // globe only: x wraps round (the last column is the first)
  std::array<std::size_t, 3> lattice{};
  std::size_t keyframes = 0;
  // [keyframe][z][y][x] x 3 floats (keyframe 0 is all zero): world km displacement on
  // the plane; (dlon cos(lat0) deg, dlat deg, dh km) on the globe.
  std::vector<float> displacement;
  std::uint64_t stopped = 0;       // trajectories that stopped early (left, missing wind)
  std::uint64_t evaluations = 0;   // wind field evaluations
  double compute_seconds = 0;

  std::size_t points() const { return lattice[0] * lattice[1] * lattice[2]; }
  double keyframe_seconds(std::size_t k) const {
    return seconds * static_cast<double>(k) / static_cast<double>(keyframes - 1);
  }
  // The recorded displacement at lattice-space position p (world km on the plane, {lon,
  // lat, height km} on the globe), `s` seconds after the step (clamped to [0, seconds]):
  // trilinear in space, linear in time; p outside the box is clamped to it (a periodic
  // longitude is first turned into [lo, lo + 360)).
  Vec3 displacement_at(const Vec3& p, double s) const;
  // The globe: where the vertex at ECEF `ecef_km` (heights times `exaggeration`, as the
  // meshes are placed) is `s` seconds after the step, as the geometry vertex shader
  // moves it: geodetic position, + displacement (the east part over cos(lat)), back to
  // ECEF at the exaggerated height.
  Vec3 moved_on_globe(const Vec3& ecef_km, double s, double exaggeration) const;
  const float* keyframe(std::size_t k) const { return displacement.data() + k * points() * 3; }
};

// Meshes of time step map->step drawn `seconds` after their step (what the renderer's
// FrameInputs::motions hold).
struct MeshMotion {
  std::shared_ptr<const DisplacementMap> map;
  double seconds = 0;
};

// Runs one trajectory per lattice point through `wind` in parallel (oneTBB).
// `frame` must be the store's frame at exaggeration 1 (GeometryPlacer::frame()), of the
// shape the meshes are drawn on (a globe frame gives a globe map).
// \error kInvalidArgument for a lattice axis < 2 points or > 1024, keyframes < 2 or
// > 64, or integrator options advect() refuses.
DisplacementMap compute_displacement_map(const WindStep& wind, const lod::WorldFrame& frame,
                                         const DisplacementOptions& options = {});

}  // namespace strielad::view
