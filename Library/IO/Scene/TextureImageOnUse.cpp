// readTextureImage for SceneIO's users: forwarded to the module that holds it
// (TextureImageFile.cpp with OpenImageIO), loaded the first time an image is read
// (IO/LoadOnUse/ModuleEntry.h).
#include "IO/LoadOnUse/ModuleEntry.h"
#include "IO/Scene/Private/TextureImagesModule.h"
#include "IO/Scene/TextureImageFile.h"

namespace proxima
{

TextureImage readTextureImage(const std::string& path, TextureChannel channel)
{
  static const auto read = reinterpret_cast<detail::ReadTextureImageEntry>(
    detail::moduleEntry(PROXIMA_MODULE_PROXIMA_TEXTURE_IMAGES, detail::kReadTextureImageEntry));
  return read(path, channel);
}

} // namespace proxima
