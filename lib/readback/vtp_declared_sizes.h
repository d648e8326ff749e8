// SPDX-License-Identifier: Apache-2.0
// Checks, before VTK reads a .vtp, that the sizes the file declares could be backed by its
// bytes, on the element tree VTK's own XML parser (vtkXMLDataParser) makes of them. VTK's XML
// reader allocates what a file declares (a piece's point and cell counts, an array's tuples and
// components, a compressed block count) before it reads the data, so a few damaged digits would
// have it allocate terabytes: std::bad_alloc thrown through VTK (which leaks what it had built),
// or, with overcommit, memory it then fills. Internal to lib/readback/vtp_reader.cpp.
#pragma once

#include <span>
#include <string>

namespace strielad::vtp {

// Every array of a VTK XML data type (VTK 9.1 dereferences a null array for others);
// every array's values (tuples x components) at most kMaxExpansion times the file's
// bytes (zlib expands at most 1032-fold) plus 1 MiB; a compressed header's block count
// within the bytes that follow it, and not 0 for an array with values (VTK 9.1 then
// dereferences a null block table).
// \error kInvalidInput naming `what`, the element and the size or type, or the XML
// parser's message when the bytes are not XML.
void check_declared_sizes(std::span<const char> file, const std::string& what);

inline constexpr double kMaxExpansion = 1100;

}  // namespace strielad::vtp
