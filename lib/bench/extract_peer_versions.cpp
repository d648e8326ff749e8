// SPDX-License-Identifier: Apache-2.0
// peer_versions (extract_suite.h): the versions of the libraries the extraction peers
// come from, for the report's machine facts.
#include <openvdb/version.h>
#include <vtkVersion.h>

#include "bench/extract_suite.h"

namespace strielad::bench {

nlohmann::json peer_versions() {
  return {{"vtk", vtkVersion::GetVTKVersion()}, {"openvdb", OPENVDB_LIBRARY_VERSION_STRING}};
}

}  // namespace strielad::bench
