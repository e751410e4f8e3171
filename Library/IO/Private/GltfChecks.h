// Checks a glTF file (JSON .gltf or binary .glb) before VTK's loader sees it. VTK trusts the
// file's lengths, offsets and indices: fuzzing found a SEGV (an accessor reaching past its
// buffer) and an allocation sized by a byteLength the file does not hold
// (Testing/Fuzz/Findings/FuzzMeshReader-glb, -gltf). Here every length is compared with the bytes
// that are really there, and every index with the array it points into.
#pragma once

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
/// node hierarchy a forest (no cycles, no node with two parents).
void checkGltf(const std::string& path, std::uintmax_t fileSize);

} // namespace proxima::detail
