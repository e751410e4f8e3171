// Texture images from files into the kernel's TextureImage (paper section 4.3): PNG, JPEG, TIFF
// and OpenEXR, read through OpenImageIO (private to this layer). Conventions in
// Documentation/Texture.md.
#pragma once

#include "IO/InputChecks/InputError.h"
#include "Proxy/TextureImage.h"

#include <string>

namespace proxima
{

/// Which one value per pixel a texture takes from an image.
enum class TextureChannel
{
  /// Rec. 709 luminance 0.2126 R + 0.7152 G + 0.0722 B of the stored values (no colour-space
  /// conversion); a grey image (one channel, or grey and alpha) is its own luminance.
  Luminance,
  Red,
  Green,
  Blue,
  Alpha
};

/// The channel's name for messages and command lines: "luminance", "red", ...
const char* textureChannelName(TextureChannel channel);

/// Reads the first image of a PNG, JPEG, TIFF or OpenEXR file (told apart by their first bytes,
/// not by the extension). Unsigned integer samples are normalised to [0, 1] (8-bit 255 is 1),
/// floating-point samples are kept as stored. Rows are flipped so that row 0 of the result is
/// the bottom row of the picture, v = 0 in the texture coordinates of OBJ and VTK.
/// Throws InputError naming the file and the defect for a missing, unreadable, empty, garbled or
/// truncated file, an image of another format, one of more than 2^26 pixels (a guard against
/// garbled sizes), a channel the image lacks (Red on a grey image, Alpha without alpha), or a
/// value that is not finite.
TextureImage readTextureImage(const std::string& path,
                              TextureChannel channel = TextureChannel::Luminance);

} // namespace proxima
