#include "OutputChecks.h"

#include "DeviceChoice.h"
#include "SceneOptions.h"

#include <string>

namespace proxima::cli
{

std::vector<NamedFile> sceneMeshInputs(const LoadedScene& loaded)
{
  std::vector<NamedFile> meshes;
  for (std::size_t i = 0; i < loaded.objects.size(); ++i)
  {
    meshes.push_back(
      {loaded.objects[i].mesh, "the mesh of the scene's objects[" + std::to_string(i) + "]"});
    const SceneObject& object = loaded.description.objects[i];
    if (object.hasTissue && !object.tissue.tets.empty())
    {
      meshes.push_back({object.tissue.tets,
                        "the tetrahedra of the scene's objects[" + std::to_string(i) + "].tissue"});
    }
  }
  return meshes;
}

std::vector<NamedFile> runInputs(const SceneOptions& scene, const LoadedScene& loaded,
                                 const DeviceChoiceOptions& device)
{
  std::vector<NamedFile> inputs = {{scene.mesh, "--mesh"},
                                   {scene.scene, "--scene"},
                                   {scene.path, "--path"},
                                   {scene.texture, "--texture"},
                                   {device.falconFirmware, "--falcon-firmware"}};
  const std::string replay = "replay:";
  if (device.device.rfind(replay, 0) == 0)
  {
    inputs.push_back({device.device.substr(replay.size()), "--device " + device.device});
  }
  if (!scene.scene.empty())
  {
    const std::vector<NamedFile> meshes = sceneMeshInputs(loaded);
    inputs.insert(inputs.end(), meshes.begin(), meshes.end());
  }
  return inputs;
}

} // namespace proxima::cli
