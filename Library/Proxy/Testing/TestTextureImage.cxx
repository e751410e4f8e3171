// TextureImage against an independent oracle: the bilinear interpolant with repeat wrapping
// written as a sum of tent functions, value(u, v) = sum_ij T_ij L(x - i) L(y - j) over every
// periodic copy of every texel, with x = frac(u) w - 1/2 (texel centres on the integers) and
// L(z) = max(0, 1 - |z|), evaluated in long double. It shares no code or cell logic with the
// kernel, which locates one cell and blends four texels.
//
// Tolerances, relative to the largest |texel| (the image's only scale):
// - value: 1e-12, far above the rounding of frac(u) * w and of three blends (~1e-15 for the
//   sizes here) and far below any real error (a wrong cell is off by O(1));
// - gradient against the oracle: 1e-12 per texel (so times the size, derivatives are per unit u);
// - gradient against central differences of sample(): 1e-8 per texel, with steps of 1e-4 texel
//   and points kept 2e-4 texel from cell boundaries, where the interpolant is linear along each
//   axis and the difference quotient is exact but for rounding (~1e-12 here).
// The worst error of each kind is printed.
#include "Proxy/TextureImage.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <iostream>
#include <limits>
#include <new>
#include <random>
#include <stdexcept>
#include <vector>

// Counts allocations on this thread while armed, to check that a lookup never allocates.
namespace
{
thread_local bool g_countAllocations = false;
std::atomic<long> g_allocations{0};
} // namespace

void* operator new(std::size_t size)
{
  if (g_countAllocations)
  {
    ++g_allocations;
  }
  if (void* p = std::malloc(size == 0 ? 1 : size))
  {
    return p;
  }
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept
{
  std::free(p);
}
void operator delete(void* p, std::size_t) noexcept
{
  std::free(p);
}

namespace proxima
{
namespace
{

struct Image
{
  std::uint32_t width;
  std::uint32_t height;
  std::vector<float> values;
  double scale; // the largest |value|
};

Image randomImage(std::uint32_t width, std::uint32_t height, std::mt19937_64& rng)
{
  std::uniform_real_distribution<float> value(-2.0f, 3.0f);
  Image image{width, height, std::vector<float>(std::size_t(width) * height), 0.0};
  for (float& x : image.values)
  {
    x = value(rng);
    image.scale = std::max(image.scale, double(std::fabs(x)));
  }
  return image;
}

// Sizes: single texels and single rows (every lookup wraps onto itself), powers of two (whose
// texel centres are exact doubles) and odd sizes.
const std::vector<std::pair<std::uint32_t, std::uint32_t>> kSizes = {
  {1, 1}, {1, 5}, {6, 1}, {2, 2}, {3, 7}, {8, 8}, {16, 4}, {13, 11}};

long double wrapped(double coordinate)
{
  long double r = std::fmod(static_cast<long double>(coordinate), 1.0L);
  return r < 0 ? r + 1.0L : r;
}

long double tent(long double z)
{
  return std::max(0.0L, 1.0L - std::fabs(z));
}
long double tentSlope(long double z)
{
  return std::fabs(z) >= 1.0L ? 0.0L : (z > 0 ? -1.0L : 1.0L);
}

struct OracleAnswer
{
  long double value = 0;
  long double du = 0;
  long double dv = 0;
};

// The tent-sum interpolant; copies k in -2..2 of the texel grid cover x in [-0.5, w - 0.5).
OracleAnswer oracle(const Image& image, double u, double v)
{
  const long double w = image.width;
  const long double h = image.height;
  const long double x = wrapped(u) * w - 0.5L;
  const long double y = wrapped(v) * h - 0.5L;
  OracleAnswer answer;
  for (std::uint32_t j = 0; j < image.height; ++j)
  {
    for (std::uint32_t i = 0; i < image.width; ++i)
    {
      const long double texel = image.values[std::size_t(j) * image.width + i];
      for (int k = -2; k <= 2; ++k)
      {
        const long double zx = x - i - k * w;
        if (std::fabs(zx) >= 1.0L)
        {
          continue;
        }
        for (int l = -2; l <= 2; ++l)
        {
          const long double zy = y - j - l * h;
          if (std::fabs(zy) >= 1.0L)
          {
            continue;
          }
          answer.value += texel * tent(zx) * tent(zy);
          answer.du += texel * tentSlope(zx) * tent(zy) * w;
          answer.dv += texel * tent(zx) * tentSlope(zy) * h;
        }
      }
    }
  }
  return answer;
}

// Distance in texel units from the coordinate to the nearest cell boundary (a texel centre).
double distanceToKink(double coordinate, std::uint32_t size)
{
  const long double x = wrapped(coordinate) * size - 0.5L;
  return double(std::fabs(x - std::round(x)));
}

TEST(TextureImage, RefusesBadConstruction)
{
  EXPECT_THROW(TextureImage(0, 3, {}), std::invalid_argument);
  EXPECT_THROW(TextureImage(3, 0, {}), std::invalid_argument);
  EXPECT_THROW(TextureImage(2, 2, {1, 2, 3}), std::invalid_argument);
  EXPECT_THROW(TextureImage(2, 2, {1, 2, 3, 4, 5}), std::invalid_argument);
  // 70000^2 overflows 32 bits: the size check must not wrap around.
  EXPECT_THROW(TextureImage(70000, 70000, std::vector<float>(4)), std::invalid_argument);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  EXPECT_THROW(TextureImage(2, 2, {1, nan, 3, 4}), std::invalid_argument);
  EXPECT_THROW(TextureImage(2, 2, {1, 2, -inf, 4}), std::invalid_argument);
  EXPECT_NO_THROW(TextureImage(2, 1, {std::numeric_limits<float>::max(), -1.0f}));
}

TEST(TextureImage, EmptyImageSamplesAsZero)
{
  const TextureImage image;
  EXPECT_TRUE(image.empty());
  EXPECT_EQ(image.sample(0.3, 0.7), 0.0);
  double du = 1.0, dv = 1.0;
  image.gradient(0.3, 0.7, du, dv);
  EXPECT_EQ(du, 0.0);
  EXPECT_EQ(dv, 0.0);
}

TEST(TextureImage, RowZeroIsAtVZero)
{
  // Column 0 at small u, row 0 at small v: texel (1, 0) is the centre (0.75, 0.25).
  const TextureImage image(2, 2, {10, 20, 30, 40});
  EXPECT_EQ(image.texel(1, 0), 20.0f);
  EXPECT_EQ(image.sample(0.75, 0.25), 20.0);
  EXPECT_EQ(image.sample(0.25, 0.75), 30.0);
  // Halfway between the centres of row 0, and across the wrap from column 1 back to column 0.
  EXPECT_EQ(image.sample(0.5, 0.25), 15.0);
  EXPECT_EQ(image.sample(0.0, 0.25), 15.0);
}

TEST(TextureImage, TexelCentresGiveTexels)
{
  std::mt19937_64 rng(11);
  for (const auto& [width, height] : kSizes)
  {
    const Image image = randomImage(width, height, rng);
    const TextureImage texture(width, height, image.values);
    // Powers of two: (i + 0.5) / w is a double, and so is the centre shifted by whole tiles.
    const bool exact = (width & (width - 1)) == 0 && (height & (height - 1)) == 0;
    for (std::uint32_t j = 0; j < height; ++j)
    {
      for (std::uint32_t i = 0; i < width; ++i)
      {
        const double texel = texture.texel(i, j);
        EXPECT_EQ(texel, image.values[std::size_t(j) * width + i]);
        for (int tile = -3; tile <= 3; ++tile)
        {
          const double u = (i + 0.5) / width + tile;
          const double v = (j + 0.5) / height - tile;
          const double value = texture.sample(u, v);
          if (exact)
          {
            EXPECT_EQ(value, texel) << width << "x" << height << " texel " << i << "," << j;
          }
          else
          {
            // The double nearest the centre is off by an ulp of u: so is the value, times w.
            EXPECT_NEAR(value, texel, 1e-14 * image.scale * std::max(width, height))
              << width << "x" << height << " texel " << i << "," << j;
          }
        }
      }
    }
  }
}

TEST(TextureImage, SampleMatchesOracle)
{
  std::mt19937_64 rng(12345);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::uniform_real_distribution<double> few(-3.0, 3.0);
  std::uniform_real_distribution<double> far(-1e6, 1e6);
  double worst = 0.0;
  int trials = 0;
  for (const auto& [width, height] : kSizes)
  {
    const Image image = randomImage(width, height, rng);
    const TextureImage texture(width, height, image.values);
    for (int n = 0; n < 3000; ++n, ++trials)
    {
      double u, v;
      switch (n % 4)
      {
        case 0:
          u = unit(rng);
          v = unit(rng);
          break;
        case 1:
          u = few(rng);
          v = few(rng);
          break;
        case 2:
          u = far(rng);
          v = far(rng);
          break;
        default:
          // On and next to cell boundaries and tile edges, where the wrap and the cell change.
          u = (std::floor(unit(rng) * width) + 0.5) / width + few(rng) * 1e-12;
          v = std::floor(few(rng)) + few(rng) * 1e-15;
          break;
      }
      const double expected = double(oracle(image, u, v).value);
      const double value = texture.sample(u, v);
      const double error = std::fabs(value - expected) / image.scale;
      worst = std::max(worst, error);
      ASSERT_LE(error, 1e-12) << width << "x" << height << " at (" << u << ", " << v
                              << "): " << value << " vs oracle " << expected;
    }
  }
  std::cout << "sample: " << trials << " trials, worst error " << worst << " of the texel scale\n";
}

TEST(TextureImage, WholeTilesChangeNothing)
{
  // Dyadic coordinates plus whole tiles are exact doubles, so the wrap must be exact too.
  std::mt19937_64 rng(99);
  std::uniform_int_distribution<int> fraction(0, 4095);
  std::uniform_int_distribution<long> tile(-(1l << 30), 1l << 30);
  for (const auto& [width, height] : kSizes)
  {
    const Image image = randomImage(width, height, rng);
    const TextureImage texture(width, height, image.values);
    for (int n = 0; n < 1500; ++n)
    {
      const double u = fraction(rng) / 4096.0;
      const double v = fraction(rng) / 4096.0;
      const double shiftedU = u + double(tile(rng));
      const double shiftedV = v + double(tile(rng));
      ASSERT_EQ(texture.sample(shiftedU, shiftedV), texture.sample(u, v))
        << width << "x" << height << " at (" << u << ", " << v << ")";
      double du0, dv0, du1, dv1;
      texture.gradient(u, v, du0, dv0);
      texture.gradient(shiftedU, shiftedV, du1, dv1);
      ASSERT_EQ(du0, du1);
      ASSERT_EQ(dv0, dv1);
    }
  }
}

TEST(TextureImage, GradientMatchesOracleAndDifferences)
{
  std::mt19937_64 rng(2024);
  std::uniform_real_distribution<double> few(-3.0, 3.0);
  constexpr double kStep = 1e-4;   // texel widths
  constexpr double kMargin = 2e-4; // texel widths from a kink
  double worstOracle = 0.0;
  double worstDifference = 0.0;
  int trials = 0;
  for (const auto& [width, height] : kSizes)
  {
    const Image image = randomImage(width, height, rng);
    const TextureImage texture(width, height, image.values);
    for (int n = 0; n < 1500; ++trials)
    {
      const double u = few(rng);
      const double v = few(rng);
      if (distanceToKink(u, width) < kMargin || distanceToKink(v, height) < kMargin)
      {
        continue;
      }
      ++n;
      double du, dv;
      texture.gradient(u, v, du, dv);
      const OracleAnswer expected = oracle(image, u, v);
      const double perU = image.scale * width;
      const double perV = image.scale * height;
      const double oracleError = std::max(std::fabs(du - double(expected.du)) / perU,
                                          std::fabs(dv - double(expected.dv)) / perV);
      const double hu = kStep / width;
      const double hv = kStep / height;
      const double differenceU = (texture.sample(u + hu, v) - texture.sample(u - hu, v)) / (2 * hu);
      const double differenceV = (texture.sample(u, v + hv) - texture.sample(u, v - hv)) / (2 * hv);
      const double differenceError =
        std::max(std::fabs(du - differenceU) / perU, std::fabs(dv - differenceV) / perV);
      worstOracle = std::max(worstOracle, oracleError);
      worstDifference = std::max(worstDifference, differenceError);
      ASSERT_LE(oracleError, 1e-12)
        << width << "x" << height << " at (" << u << ", " << v << "): (" << du << ", " << dv
        << ") vs oracle (" << double(expected.du) << ", " << double(expected.dv) << ")";
      ASSERT_LE(differenceError, 1e-8)
        << width << "x" << height << " at (" << u << ", " << v << "): (" << du << ", " << dv
        << ") vs differences (" << differenceU << ", " << differenceV << ")";
    }
  }
  std::cout << "gradient: " << trials << " points drawn, worst error " << worstOracle
            << " against the oracle and " << worstDifference
            << " against central differences, per texel scale and texel\n";
}

TEST(TextureImage, GradientOnABoundaryIsThePositiveSide)
{
  // Column values 0, 1, 3 repeating: slopes per texel 1, 2, -3; texel 1's centre is u = 0.5.
  const TextureImage image(3, 1, {0, 1, 3});
  double du, dv;
  image.gradient(0.5, 0.5, du, dv);
  EXPECT_DOUBLE_EQ(du, 2.0 * 3);
  EXPECT_EQ(dv, 0.0);
  image.gradient(0.5 - 1e-9, 0.5, du, dv);
  EXPECT_DOUBLE_EQ(du, 1.0 * 3);
}

TEST(TextureImage, ExtremeCoordinatesGiveFiniteAnswers)
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  const double big = std::numeric_limits<double>::max();
  const double tiny = std::numeric_limits<double>::denorm_min();
  const double eps = std::numeric_limits<double>::epsilon();
  const std::vector<double> coordinates = {
    0.0,           -0.0,           tiny, -tiny, 1e-300,       -1e-300, eps / 4,    -eps / 4,
    1.0 - eps / 2, -1.0 + eps / 2, 1.0,  -1.0,  0x1p52 + 0.5, 0x1p53,  0x1p53 + 2, -0x1p60,
    1e300,         -1e300,         big,  -big,  inf,          -inf,    nan,        -nan};
  std::mt19937_64 rng(5);
  for (const auto& [width, height] : kSizes)
  {
    const Image image = randomImage(width, height, rng);
    const TextureImage texture(width, height, image.values);
    const auto [lowest, highest] = std::minmax_element(image.values.begin(), image.values.end());
    const double slack = 1e-15 * image.scale;
    for (double u : coordinates)
    {
      for (double v : coordinates)
      {
        const double value = texture.sample(u, v);
        ASSERT_TRUE(std::isfinite(value)) << "at (" << u << ", " << v << ")";
        // A bilinear blend stays within the texels it blends.
        EXPECT_GE(value, *lowest - slack) << "at (" << u << ", " << v << ")";
        EXPECT_LE(value, *highest + slack) << "at (" << u << ", " << v << ")";
        double du, dv;
        texture.gradient(u, v, du, dv);
        ASSERT_TRUE(std::isfinite(du) && std::isfinite(dv)) << "at (" << u << ", " << v << ")";
        // Where the double is finite, the answer is the oracle's; otherwise that at coordinate 0.
        const double uu = std::isfinite(u) ? u : 0.0;
        const double vv = std::isfinite(v) ? v : 0.0;
        EXPECT_NEAR(value, double(oracle(image, uu, vv).value), 1e-12 * image.scale)
          << "at (" << u << ", " << v << ")";
        if (!std::isfinite(u) || !std::isfinite(v))
        {
          EXPECT_EQ(value, texture.sample(uu, vv));
        }
      }
    }
  }
  // The largest texels and the largest size stay finite through the differences and gradients.
  const float huge = std::numeric_limits<float>::max();
  const TextureImage extreme(2, 2, {huge, -huge, -huge, huge});
  for (double u : coordinates)
  {
    double du, dv;
    extreme.gradient(u, 0.3, du, dv);
    ASSERT_TRUE(std::isfinite(extreme.sample(u, 0.3)) && std::isfinite(du) && std::isfinite(dv));
  }
}

TEST(TextureImage, LookupsDoNotAllocate)
{
  std::mt19937_64 rng(8);
  const Image image = randomImage(13, 11, rng);
  const TextureImage texture(13, 11, image.values);
  std::uniform_real_distribution<double> few(-3.0, 3.0);
  std::vector<double> coordinates(2000);
  for (double& c : coordinates)
  {
    c = few(rng);
  }
  double sum = 0.0;
  g_allocations = 0;
  g_countAllocations = true;
  for (std::size_t k = 0; k + 1 < coordinates.size(); ++k)
  {
    double du, dv;
    texture.gradient(coordinates[k], coordinates[k + 1], du, dv);
    sum += texture.sample(coordinates[k], coordinates[k + 1]) + du + dv;
  }
  g_countAllocations = false;
  EXPECT_EQ(g_allocations.load(), 0);
  EXPECT_TRUE(std::isfinite(sum));
}

} // namespace
} // namespace proxima
