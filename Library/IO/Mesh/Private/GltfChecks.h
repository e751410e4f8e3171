// Checks a glTF file (JSON .gltf or binary .glb) before VTK's loader sees it. VTK trusts the
// file's lengths, offsets and indices: fuzzing found a SEGV (an accessor reaching past its
// buffer) and an allocation sized by a byteLength the file does not hold
// (Testing/Fuzz/Findings/FuzzMeshReader-glb, -gltf). Here every length is compared with the bytes
// that are really there, and every index with the array it points into.
#pragma once

#include "IO/Mesh/Private/GltfGeometryFile.h"

#include <cstdint>
#include <string>

namespace proxima::detail
{

/// Throws InputError naming `path` and the first defect found unless: a GLB's header and chunk
/// lengths fit the file's `fileSize` bytes; every buffer holds its byteLength (the GLB's BIN
/// chunk, a base64 data: URI, or an external file next to `path`); every bufferView lies within
/// its buffer and every accessor within its bufferView (known componentType and type, count >= 1,
/// no sparse storage); every mesh primitive draws triangles (mode 4) from a float VEC3 POSITION
/// accessor, with SCALAR unsigned indices, a multiple of three of them; and every index between
/// scenes, nodes, meshes, skins, materials, textures, images and accessors is in range, with the
/// node hierarchy a forest (no cycles, no node with two parents). VTK's loader drops an array
/// element it cannot load and so shifts every later index into that array, so whatever it would
/// drop is refused too: accessor bounds that do not fit the type, a bufferView target other than
/// 34962 or 34963, a skin without joints, a node with both a skin and a matrix, an empty scene.
/// Returns the geometry-only copy of the checked document that VTK's loader is to read.
GltfGeometryFile checkGltfAndCopyGeometry(const std::string& path, std::uintmax_t fileSize);

} // namespace proxima::detail
