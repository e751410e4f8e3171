// Image tests: render offscreen, compare with a baseline PNG, and on a difference leave the
// actual image and a difference image in the build folder for a person to look at.
//
// The metric (Documentation/VtkPipeline.md): a pixel differs when any channel differs by more
// than kChannelTolerance (of 255); the image matches when at most kDifferingFraction of its
// pixels differ. That absorbs antialiasing and rasterizer rounding between Mesa builds, while a
// missing, moved or recoloured part of a representation (hundreds of pixels at 400x300) fails.
#pragma once

#include <string>

class vtkRenderWindow;

namespace proxima::vtk::testing
{

inline constexpr int kChannelTolerance = 40;
inline constexpr double kDifferingFraction = 0.002;

struct ImageComparison
{
  bool matches = false;
  /// Why not, for the test's message (missing baseline, size, how many pixels differ).
  std::string message;
  double differingFraction = 0.0;
};

/// Renders `window` and compares its pixels with Library/VTK/Testing/Baselines/<name>.png.
/// With the environment variable PROXIMA_UPDATE_BASELINES=1 the baseline is (re)written
/// instead and the comparison passes. On a mismatch writes <outputFolder>/<name>-actual.png and
/// <name>-diff.png (differing pixels in red over a darkened copy of the actual image).
ImageComparison compareWithBaseline(vtkRenderWindow* window, const std::string& name,
                                    const std::string& baselineFolder,
                                    const std::string& outputFolder);

} // namespace proxima::vtk::testing
