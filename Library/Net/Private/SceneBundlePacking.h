// A scene file packed for the server (proxima_haptic.proto's SceneBundle): the client checks the
// file as a local run would, then sends it with every file it names, its paths replaced by names
// the server can write into a folder of its own. Both clients use it: remote runs with --scene
// and the live client's scene uploads.
#pragma once

#include "proxima_haptic.pb.h"

#include <string>

namespace proxima::detail
{

/// Reads `scenePath` (readSceneFile's checks and errors) and the files it names: meshes, texture
/// images and an MJCF file, each once however often it is named. Throws InputError naming the
/// file that cannot be read.
net::SceneBundle packSceneFile(const std::string& scenePath);

} // namespace proxima::detail
