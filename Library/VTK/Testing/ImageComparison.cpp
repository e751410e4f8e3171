#include "ImageComparison.h"

#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPNGReader.h>
#include <vtkPNGWriter.h>
#include <vtkRenderWindow.h>
#include <vtkWindowToImageFilter.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <sstream>

namespace proxima::vtk::testing
{
namespace
{
void writePng(vtkImageData* image, const std::string& path)
{
  vtkNew<vtkPNGWriter> writer;
  writer->SetFileName(path.c_str());
  writer->SetInputData(image);
  writer->Write();
}
} // namespace

ImageComparison compareWithBaseline(vtkRenderWindow* window, const std::string& name,
                                    const std::string& baselineFolder,
                                    const std::string& outputFolder)
{
  window->Render();
  vtkNew<vtkWindowToImageFilter> capture;
  capture->SetInput(window);
  capture->SetInputBufferTypeToRGB();
  capture->ReadFrontBufferOff();
  capture->Update();
  vtkImageData* actual = capture->GetOutput();

  ImageComparison comparison;
  const std::string baselinePath = baselineFolder + "/" + name + ".png";
  const char* update = std::getenv("PROXIMA_UPDATE_BASELINES");
  if (update && std::string(update) == "1")
  {
    writePng(actual, baselinePath);
    comparison.matches = true;
    comparison.message = "wrote " + baselinePath;
    return comparison;
  }
  std::filesystem::create_directories(outputFolder);
  const std::string actualPath = outputFolder + "/" + name + "-actual.png";
  if (!std::filesystem::exists(baselinePath))
  {
    writePng(actual, actualPath);
    comparison.message = "no baseline " + baselinePath + " (the actual image is " + actualPath +
                         "; PROXIMA_UPDATE_BASELINES=1 writes baselines)";
    return comparison;
  }
  vtkNew<vtkPNGReader> reader;
  reader->SetFileName(baselinePath.c_str());
  reader->Update();
  vtkImageData* baseline = reader->GetOutput();

  int actualSize[3];
  int baselineSize[3];
  actual->GetDimensions(actualSize);
  baseline->GetDimensions(baselineSize);
  if (actualSize[0] != baselineSize[0] || actualSize[1] != baselineSize[1] ||
      baseline->GetNumberOfScalarComponents() < 3 || baseline->GetScalarType() != VTK_UNSIGNED_CHAR)
  {
    writePng(actual, actualPath);
    std::ostringstream message;
    message << name << ": the image is " << actualSize[0] << "x" << actualSize[1]
            << ", the baseline " << baselineSize[0] << "x" << baselineSize[1]
            << " (or not 8-bit RGB); actual image: " << actualPath;
    comparison.message = message.str();
    return comparison;
  }

  vtkNew<vtkImageData> diff;
  diff->SetDimensions(actualSize[0], actualSize[1], 1);
  diff->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  long differing = 0;
  for (int y = 0; y < actualSize[1]; ++y)
  {
    for (int x = 0; x < actualSize[0]; ++x)
    {
      const auto* a = static_cast<const unsigned char*>(actual->GetScalarPointer(x, y, 0));
      const auto* b = static_cast<const unsigned char*>(baseline->GetScalarPointer(x, y, 0));
      auto* d = static_cast<unsigned char*>(diff->GetScalarPointer(x, y, 0));
      int largest = 0;
      for (int c = 0; c < 3; ++c)
      {
        largest = std::max(largest, std::abs(int(a[c]) - int(b[c])));
      }
      const bool differs = largest > kChannelTolerance;
      differing += differs ? 1 : 0;
      for (int c = 0; c < 3; ++c)
      {
        d[c] = differs ? (c == 0 ? 255 : 0) : static_cast<unsigned char>(a[c] / 3);
      }
    }
  }
  const double pixels = static_cast<double>(actualSize[0]) * actualSize[1];
  comparison.differingFraction = static_cast<double>(differing) / pixels;
  comparison.matches = comparison.differingFraction <= kDifferingFraction;
  if (!comparison.matches)
  {
    const std::string diffPath = outputFolder + "/" + name + "-diff.png";
    writePng(actual, actualPath);
    writePng(diff, diffPath);
    std::ostringstream message;
    message << name << ": " << differing << " pixels (" << 100.0 * comparison.differingFraction
            << "%) differ from " << baselinePath << " by more than " << kChannelTolerance
            << "/255, over the " << 100.0 * kDifferingFraction << "% allowed; see " << actualPath
            << " and " << diffPath;
    comparison.message = message.str();
  }
  return comparison;
}

} // namespace proxima::vtk::testing
