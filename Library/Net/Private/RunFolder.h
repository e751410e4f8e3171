// A folder of the server's own for the files a client sent (a remote run's mesh, path and
// texture, or a scene bundle), removed with everything in it however the call ends. Only names the
// server chooses or checks reach its file system, and it remembers which client path each local
// file stands for, so that messages name the client's files.
#pragma once

#include "IO/Scene/SceneDescription.h"

#include "proxima_haptic.pb.h"

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace proxima::detail
{

class RunFolder
{
public:
  /// Throws std::runtime_error when no folder can be made.
  RunFolder();
  ~RunFolder();
  RunFolder(const RunFolder&) = delete;
  RunFolder& operator=(const RunFolder&) = delete;

  /// Writes `data` as `stem` with `clientName`'s extension (the readers go by it; dropped unless
  /// letters and digits) and returns its local path.
  std::string write(const std::string& clientName, const std::string& data,
                    const std::string& stem);

  /// Writes a scene bundle's files under their local names and its scene file, and returns the
  /// scene file's local path. Throws InputError naming the scene for a bundled file whose name is
  /// not one a client makes ("file<K>.<ext>"), and std::runtime_error when it cannot write.
  std::string writeScene(const net::SceneBundle& bundle);

  /// Throws InputError naming the scene when `description` (read from writeScene's file) names a
  /// file that is not one of the bundle's (a path elsewhere on the server), or its MJCF file
  /// names files of its own (includes, mesh assets: not sent, and they would be the server's).
  void requireBundledFiles(const SceneDescription& description) const;

  /// `text` with the local paths replaced by the client's names.
  std::string clientWords(std::string text) const;

private:
  std::string writeAs(const std::string& localName, const std::string& data,
                      const std::string& clientName);

  std::filesystem::path m_path;
  std::vector<std::pair<std::string, std::string>> m_names;
  /// The scene file's client name, once writeScene has written it.
  std::string m_sceneName;
};

} // namespace proxima::detail
