// A single-channel texture image for the kernel (paper section 4.3): plain floats, sampled
// bilinearly at texture coordinates, never allocating after construction. Images come from files
// through the IO layer (IO/TextureImageFile.h, OpenImageIO inside).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace proxima
{

/// A single-channel image of floats sampled bilinearly at texture coordinates (u, v), which tile
/// outside [0, 1). Its reads are const and allocate nothing, so threads may sample one image at
/// once.
class TextureImage
{
public:
  TextureImage() = default;
  /// `values` holds width * height samples, row-major; row 0 lies at v = 0 and column 0 at
  /// u = 0 (texture coordinates of OBJ and VTK: v = 0 is the bottom of the picture). Texel (i, j)
  /// is centred at u = (i + 0.5) / width, v = (j + 0.5) / height. Throws std::invalid_argument
  /// if the size does not match, a size is zero, or a value is not finite.
  TextureImage(std::uint32_t width, std::uint32_t height, std::vector<float> values);

  /// Texels per row (along u); 0 for an empty image.
  std::uint32_t width() const { return m_width; }
  /// Rows (along v); 0 for an empty image.
  std::uint32_t height() const { return m_height; }
  /// True for a default-constructed image, which samples as 0.
  bool empty() const { return m_values.empty(); }
  /// Texel (i, j), no wrapping: i < width, j < height.
  float texel(std::uint32_t i, std::uint32_t j) const
  {
    // In size_t: j * width overflows 32 bits on an image of more than 4 Gi texels.
    return m_values[static_cast<std::size_t>(j) * m_width + i];
  }

  /// The bilinear interpolant at (u, v), repeating outside [0, 1) (the texture tiles). Never
  /// allocates and never returns NaN: any finite u and v work, however large or negative, and a
  /// coordinate that is not finite is taken as 0. An empty image samples as 0.
  double sample(double u, double v) const;
  /// The derivatives of that interpolant with respect to u and v at (u, v) (per unit of u and v,
  /// not per texel), for bump mapping. Each is linear in the other coordinate within a texel
  /// cell (the cell between four texel centres); on a cell boundary, where the interpolant has a
  /// kink, it is the derivative in the cell on the positive side. Same coordinate handling as
  /// sample(); an empty image has gradient 0.
  void gradient(double u, double v, double& dSampleDu, double& dSampleDv) const;

private:
  std::uint32_t m_width = 0;
  std::uint32_t m_height = 0;
  std::vector<float> m_values;
};

} // namespace proxima
