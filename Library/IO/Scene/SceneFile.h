// Scene files: JSON that lists the objects of a scene with their meshes, scales, poses and
// materials (Documentation/SceneFiles.md). Reading one only checks it and fills in a
// SceneDescription; IO/SceneBuilder.h turns that into a CollisionScene. No JSON type appears in
// this header.
#pragma once

#include "IO/InputChecks/InputError.h"
#include "IO/Scene/SceneDescription.h"

#include <string>

namespace proxima
{

/// The scene file format version this build reads ("version" in the file).
inline constexpr int kSceneFileVersion = 3;

/// Reads and checks a scene file; mesh and image paths come back resolved against the file's
/// folder (absolute paths stay as written). Reads no mesh or image.
///
/// Throws InputError, its message one line "<path>: <where>: <defect>", for a file that cannot
/// be read, is not JSON (with line and column), or breaks the format: an unknown or repeated
/// key, a missing required key, a value of the wrong type or out of range, where being the JSON
/// location (`objects[1].material.static_friction`).
SceneDescription readSceneFile(const std::string& path);

} // namespace proxima
