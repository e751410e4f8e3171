#include "Net/Private/SceneBundlePacking.h"

#include "IO/InputChecks/FileChecks.h"
#include "IO/InputChecks/InputError.h"
#include "IO/JsonInput/JsonChecker.h"
#include "IO/Scene/SceneFile.h"

#include <cctype>
#include <filesystem>
#include <map>

namespace proxima::detail
{
namespace
{
// The bundle's files, one per path however often the scene names it.
class BundleFiles
{
public:
  explicit BundleFiles(net::SceneBundle& bundle)
    : m_bundle(bundle)
  {}

  // The local name of `path` (resolved as the scene reader resolves it), added when new.
  std::string add(const std::string& path, const char* kind)
  {
    const auto known = m_names.find(path);
    if (known != m_names.end())
    {
      return known->second;
    }
    // "file<K>" and the extension the readers go by, if it is letters and digits only.
    std::string extension = std::filesystem::path(path).extension().string();
    for (std::size_t i = 1; i < extension.size(); ++i)
    {
      if (!std::isalnum(static_cast<unsigned char>(extension[i])))
      {
        extension.clear();
        break;
      }
    }
    const std::string local = "file" + std::to_string(m_names.size()) + extension;
    net::BundledFile* file = m_bundle.add_files();
    file->set_local_name(local);
    file->set_client_name(path);
    file->set_data(readWholeFile(path, kind));
    m_names.emplace(path, local);
    return local;
  }

private:
  net::SceneBundle& m_bundle;
  std::map<std::string, std::string> m_names;
};
} // namespace

net::SceneBundle packSceneFile(const std::string& scenePath)
{
  // The reader checks everything a local run checks, and resolves each path as that run would
  // open it; the JSON is then rewritten key by key in the same places.
  const SceneDescription description = readSceneFile(scenePath);
  CheckedJson json = readCheckedJsonFile(scenePath, "scene file");
  net::SceneBundle bundle;
  BundleFiles files(bundle);
  if (!description.mjcf.empty())
  {
    json["mjcf"] = files.add(description.mjcf, "MJCF file");
  }
  auto& objects = json["objects"];
  for (std::size_t i = 0; i < description.objects.size(); ++i)
  {
    const SceneObject& object = description.objects[i];
    objects[i]["mesh"] = files.add(object.mesh, "mesh file");
    for (std::size_t t = 0; t < object.material.textures.size(); ++t)
    {
      objects[i]["material"]["textures"][t]["image"] =
        files.add(object.material.textures[t].image, "texture image");
    }
  }
  bundle.set_scene_name(scenePath);
  bundle.set_scene_json(json.dump());
  return bundle;
}

} // namespace proxima::detail
