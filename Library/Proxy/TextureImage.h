// A single-channel texture image for the kernel (paper section 4.3): plain floats, sampled
// bilinearly at texture coordinates, never allocating after construction. Images come from files
// through the IO layer (IO/TextureImageFile.h, OpenImageIO inside).
#pragma once

#include <cstdint>
#include <vector>

namespace proxima
{

class TextureImage
{
public:
  TextureImage() = default;
  /// `values` holds width * height samples, row-major; row 0 lies at v = 0 and column 0 at
  /// u = 0 (texture coordinates of OBJ and VTK: v = 0 is the bottom of the picture). Texel (i, j)
  /// is centred at u = (i + 0.5) / width, v = (j + 0.5) / height. Throws std::invalid_argument
  /// if the size does not match, a size is zero, or a value is not finite.
  TextureImage(std::uint32_t width, std::uint32_t height, std::vector<float> values);

  std::uint32_t width() const { return m_width; }
  std::uint32_t height() const { return m_height; }
  bool empty() const { return m_values.empty(); }
  /// Texel (i, j), no wrapping: i < width, j < height.
  float texel(std::uint32_t i, std::uint32_t j) const { return m_values[j * m_width + i]; }

  /// The bilinear interpolant at (u, v), repeating outside [0, 1) (the texture tiles).
  double sample(double u, double v) const;
  /// The derivatives of that interpolant with respect to u and v at (u, v) (per unit of u and v,
  /// not per texel), for bump mapping. Piecewise constant across texel cells.
  void gradient(double u, double v, double& dSampleDu, double& dSampleDv) const;

private:
  std::uint32_t m_width = 0;
  std::uint32_t m_height = 0;
  std::vector<float> m_values;
};

} // namespace proxima
