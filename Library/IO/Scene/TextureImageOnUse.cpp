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
  // Loaded once, by the first caller (a function-local static is initialised thread-safely).
  static const detail::TextureImageReaders* const table =
    reinterpret_cast<const detail::TextureImageReaders* (*)()>(detail::moduleEntry(
      PROXIMA_MODULE_PROXIMA_TEXTURE_IMAGES, detail::kTextureImageReadersEntry))();
  return table->readTextureImage(path, channel);
}

} // namespace proxima
