// SPDX-License-Identifier: Apache-2.0
// The compact, quantized mesh encoding carried by NodeResult for outcome kMesh
// (formats/protocol.md, "Mesh encoding"): positions as 3 x u16 in the mesh's bounding
// box, normals octahedral 2 x snorm16, indices 16 or 32 bits, one face-kind byte per
// triangle, attributes as u16 in their own range with 0xFFFF for a missing value.
// Attribute names and the mesh's sub-volume id are not part of the encoding.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "core/byte_io.h"
#include "extract/mesh.h"

namespace strielad::protocol {

// Bytes before the first position: vertex_count, triangle_count, attribute_count,
// index_bytes, box lo[3] and hi[3].
inline constexpr std::size_t kMeshHeaderBytes = 58;
// Meshes with at most this many vertices use 16-bit indices, larger ones 32-bit.
inline constexpr std::uint32_t kMaxVerticesFor16BitIndices = 65536;
inline constexpr std::uint16_t kPositionSteps = 65535;   // q = 0 .. 65535
inline constexpr std::uint16_t kAttributeSteps = 65534;  // q = 0 .. 65534
inline constexpr std::uint16_t kMissingAttribute = 0xFFFF;
inline constexpr std::int16_t kNormalSteps = 32767;      // snorm16: q / 32767

// What a mesh is the result of: a sub-volume's mesh has face kinds 0..3 and the scene's
// attributes; a slice's mesh (protocol version 2) has face kind 4 (FaceKind::kSlice) on
// every triangle and exactly one attribute, its colouring variable.
enum class MeshRole : std::uint8_t { kSubVolume, kSlice };

// Appends the encoding of `mesh` to `out`. Throws kInvalidArgument, with a message
// starting with `what` and naming the field, when the mesh breaks Mesh's contract: no
// triangle, more than 2^32 - 1 vertices or triangles, more than kMaxSceneAttributes
// attributes, normals / face_kinds / an attribute whose size differs from the vertex or
// triangle count, a non-finite position or a box whose extent overflows a double, a
// normal of zero length or not finite, an index >= the vertex count, a face kind > 3,
// an infinite attribute value (NaN is fine: it is "missing"); for MeshRole::kSlice a
// face kind other than 4 or an attribute count other than 1. Nothing is appended then.
void encode_mesh(const Mesh& mesh, ByteWriter& out, std::string_view what = "mesh",
                 MeshRole role = MeshRole::kSubVolume);

// Exactly the bytes encode_mesh appends (no validation).
std::size_t encoded_mesh_bytes(const Mesh& mesh);

// Reads one encoded mesh at the reader's position. The returned mesh has subvolume_id 0
// and no attribute names (the caller knows both); its positions are within the
// documented quantization error of the encoder's, its normals have unit length.
// Throws kTruncated when the counts need more bytes than remain (checked before any
// allocation), kInvalidInput for any other violation of formats/protocol.md; messages
// start with `what` and name the field ("NodeResult: subvolumes[0].mesh: triangles[7][2]:
// index 90 >= vertex_count 12").
// A face kind or attribute count that `role` does not allow is kInvalidInput too.
Mesh decode_mesh(ByteReader& in, std::string_view what, MeshRole role = MeshRole::kSubVolume);

// The octahedral snorm16 pair of a non-zero, finite direction (not necessarily unit),
// and back. Decoding accepts every pair (-32768 reads as -1) and returns a unit vector.
std::array<std::int16_t, 2> encode_normal(const std::array<float, 3>& normal);
std::array<float, 3> decode_normal(std::int16_t u, std::int16_t v);

}  // namespace strielad::protocol
