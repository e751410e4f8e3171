// The files a command reads, named as its command line names them, so that none of its outputs
// overwrites one of them (DESIGN.md section 6; OutputIdentity.h does the comparing).
#pragma once

#include "IO/Output/OutputIdentity.h"
#include "IO/Scene/SceneBuilder.h"
#include "IO/ScriptedRun/ScriptedRunSettings.h"

#include <vector>

namespace proxima::cli
{

using SceneOptions = ScriptedRunSettings;
struct DeviceChoiceOptions;

/// The mesh files a scene file named, as "the mesh of the scene's objects[i]".
std::vector<NamedFile> sceneMeshInputs(const LoadedScene& loaded);

/// What run and view read: --mesh or --scene and the scene's meshes, --path, --texture, and the
/// files of --device replay:FILE and --falcon-firmware.
std::vector<NamedFile> runInputs(const SceneOptions& scene, const LoadedScene& loaded,
                                 const DeviceChoiceOptions& device);

} // namespace proxima::cli
