// FuzzModelUpload: the live server's checks of an uploaded model (issue 16). Random bytes decoded
// as a sequence of upload messages, as the server receives them, each checked by ModelAssembly
// in order until one is refused, and built (meshes and sphere trees) when a commit comes, within
// limits small enough for every input to end quickly. A scene bundle is written into a folder of
// its own, with the server's checks of the bundled names, and its scene file read and checked,
// down to naming only bundled files (its meshes are the mesh readers' fuzz targets'). Every input must end with a model or a
// refusal: no crash, hang or leak.
#include "IO/Scene/SceneFile.h"
#include "Net/Private/ModelAssembly.h"
#include "Net/Private/RunFolder.h"

#include <cstddef>
#include <cstdint>
#include <exception>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  proxima::net::ModelUploadSequence sequence;
  if (!sequence.ParseFromArray(data, static_cast<int>(size)))
  {
    return 0;
  }
  proxima::detail::ModelLimits limits;
  limits.maxTriangles = 20000;
  limits.maxPoints = 20000;
  proxima::detail::ModelAssembly model(limits);
  std::string error;
  for (const proxima::net::ModelUpload& part : sequence.parts())
  {
    if (part.has_shape())
    {
      if (!model.add(part.shape(), error))
      {
        return 0;
      }
    }
    else if (part.has_scene())
    {
      try
      {
        proxima::detail::RunFolder folder;
        folder.requireBundledFiles(proxima::readSceneFile(folder.writeScene(part.scene())));
      }
      catch (const std::exception&)
      {
        return 0; // refused in words
      }
    }
    else if (part.commit())
    {
      proxima::CollisionScene scene;
      model.build(scene, error);
      return 0;
    }
  }
  return 0;
}
