// The entry of the module proxima-texture-images (TextureImagesModule.cpp), which SceneIO loads
// on first use (TextureImageOnUse.cpp): readTextureImage under a C name that dlsym finds.
#pragma once

#include "IO/Scene/TextureImageFile.h"

#include <string>

namespace proxima::detail
{

using ReadTextureImageEntry = TextureImage (*)(const std::string&, TextureChannel);
inline constexpr const char* kReadTextureImageEntry = "proximaReadTextureImage";

} // namespace proxima::detail
