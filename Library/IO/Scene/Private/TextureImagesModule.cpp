// The module proxima-texture-images: TextureImageFile.cpp's reader behind a C name for dlsym
// (TextureImagesModule.h). Exceptions (InputError) pass through to the caller as they are.
#include "IO/Scene/Private/TextureImagesModule.h"

extern "C" proxima::TextureImage proximaReadTextureImage(const std::string& path,
                                                         proxima::TextureChannel channel)
{
  return proxima::readTextureImage(path, channel);
}
