// The module proxima-texture-images: TextureImageFile.cpp's reader in the table of
// TextureImagesModule.h. Exceptions (InputError) pass through to the caller as they are.
#include "IO/Scene/Private/TextureImagesModule.h"

extern "C" const proxima::detail::TextureImageReaders* proximaTextureImageReaders()
{
  static const proxima::detail::TextureImageReaders readers{&proxima::readTextureImage};
  return &readers;
}
