// SPDX-License-Identifier: Apache-2.0
// Mesh output frames beyond the dataset's axis coordinates (formats/scene.md,
// "Output frames"):
// - kLocalMetric: metres on the plane tangent at the grid's centre (equirectangular:
//   x = R cos(lat0) (lon - lon0), y = R (lat - lat0), z = height; R = 6371008.8 m, the
//   IUGG mean Earth radius). Distances are exact along meridians and the centre
//   parallel; elsewhere east-west distances are off by cos(lat)/cos(lat0) - 1.
// - kEcef: geocentric WGS84 metres (a = 6378137 m, f = 1/298.257223563), heights taken
//   as ellipsoidal heights.
// Normals are transformed as gradients (by the inverse transpose of the map's Jacobian)
// and renormalized; triangle orientation is kept outward.
#pragma once

#include <string_view>

#include "extract/mesh.h"
#include "format/manifest.h"

namespace strielad {

enum class OutputFrame { kAxis, kLocalMetric, kEcef };

// "axis", "metric" or "ecef"; throws kInvalidArgument listing them.
OutputFrame parse_output_frame(std::string_view name);

// Throws kUnsupported naming the axis unless x is longitude, y latitude and z height
// in metres (a pressure or model-level vertical axis has no metric frame).
void check_frame_supported(const format::Manifest& manifest, OutputFrame frame);

// Moves positions and normals of `mesh` from axis coordinates into `frame`.
void transform_mesh(Mesh& mesh, const format::Manifest& manifest, OutputFrame frame);

}  // namespace strielad
