#include "Proxy/TextureImage.h"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <stdexcept>
#include <utility>

namespace proxima
{
namespace
{

// Where a lookup lands: the cell between the texel centres i0 and i1 (wrapped), at fraction t.
struct CellCoordinate
{
  std::uint32_t i0;
  std::uint32_t i1;
  double t;
};

// Reduces one texture coordinate to [0, 1) first, so that huge coordinates never overflow the
// texel arithmetic (above 2^53 a double is an integer and lands on 0), then finds its cell
// among `size` texel centres at (i + 0.5) / size. A non-finite coordinate is taken as 0: a NaN
// must not reach a force, and there is no better guess for where it meant to be.
CellCoordinate locate(double coordinate, std::uint32_t size)
{
  // A tiny negative coordinate wraps to 1 - tiny, which may round to 1.0: that lands on
  // x = size - 0.5 below, in the last cell at t = 0.5, the same point as 0, so it needs no care.
  const double wrapped = std::isfinite(coordinate) ? coordinate - std::floor(coordinate) : 0.0;
  // In texel units with centres on the integers: x in [-0.5, size - 0.5].
  const double x = wrapped * static_cast<double>(size) - 0.5;
  const double cell = std::floor(x);
  CellCoordinate result{};
  result.t = x - cell;
  result.i0 = cell < 0.0 ? size - 1 : static_cast<std::uint32_t>(cell);
  result.i1 = result.i0 + 1 == size ? 0 : result.i0 + 1;
  return result;
}

} // namespace

TextureImage::TextureImage(std::uint32_t width, std::uint32_t height, std::vector<float> values)
{
  if (width == 0 || height == 0)
  {
    std::ostringstream out;
    out << "texture image of " << width << " x " << height << " texels: a size is zero";
    throw std::invalid_argument(out.str());
  }
  const std::uint64_t expected = static_cast<std::uint64_t>(width) * height;
  if (values.size() != expected)
  {
    std::ostringstream out;
    out << "texture image of " << width << " x " << height << " texels needs " << expected
        << " values, not " << values.size();
    throw std::invalid_argument(out.str());
  }
  for (std::size_t k = 0; k < values.size(); ++k)
  {
    if (!std::isfinite(values[k]))
    {
      std::ostringstream out;
      out << "texture image value at texel (" << k % width << ", " << k / width
          << ") is not finite (" << values[k] << ")";
      throw std::invalid_argument(out.str());
    }
  }
  m_width = width;
  m_height = height;
  m_values = std::move(values);
}

double TextureImage::sample(double u, double v) const
{
  // A default-constructed image has no texels: it reads as a flat 0, never as garbage.
  if (m_values.empty())
  {
    return 0.0;
  }
  const CellCoordinate x = locate(u, m_width);
  const CellCoordinate y = locate(v, m_height);
  const double a = texel(x.i0, y.i0);
  const double b = texel(x.i1, y.i0);
  const double c = texel(x.i0, y.i1);
  const double d = texel(x.i1, y.i1);
  // a + t (b - a) rather than (1 - t) a + t b: exact at t = 0, so a texel centre gives its texel.
  const double bottom = a + x.t * (b - a);
  const double top = c + x.t * (d - c);
  return bottom + y.t * (top - bottom);
}

void TextureImage::gradient(double u, double v, double& dSampleDu, double& dSampleDv) const
{
  if (m_values.empty())
  {
    dSampleDu = 0.0;
    dSampleDv = 0.0;
    return;
  }
  // The same cell as sample(); on a cell boundary that is the cell on the positive side.
  const CellCoordinate x = locate(u, m_width);
  const CellCoordinate y = locate(v, m_height);
  const double a = texel(x.i0, y.i0);
  const double b = texel(x.i1, y.i0);
  const double c = texel(x.i0, y.i1);
  const double d = texel(x.i1, y.i1);
  // Derivatives in texel units, times texels per unit of u (or v).
  dSampleDu = ((b - a) + y.t * ((d - c) - (b - a))) * static_cast<double>(m_width);
  dSampleDv = ((c - a) + x.t * ((d - b) - (c - a))) * static_cast<double>(m_height);
}

} // namespace proxima
