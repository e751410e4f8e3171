// The entry of the module proxima-texture-images (TextureImagesModule.cpp), which SceneIO loads
// on first use (TextureImageOnUse.cpp): a table holding readTextureImage, returned by a function
// with a C name that dlsym finds.
#pragma once

#include "IO/Scene/TextureImageFile.h"

#include <string>

namespace proxima::detail
{

struct TextureImageReaders
{
  TextureImage (*readTextureImage)(const std::string& path, TextureChannel channel);
};

/// The name of `const TextureImageReaders* entry()` in the module.
inline constexpr const char* kTextureImageReadersEntry = "proximaTextureImageReaders";

} // namespace proxima::detail
