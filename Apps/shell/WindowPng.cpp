#include "WindowPng.h"

#include "IO/Output/OutputError.h"

#include <vtkNew.h>
#include <vtkPNGWriter.h>
#include <vtkRenderWindow.h>
#include <vtkUnsignedCharArray.h>
#include <vtkWindowToImageFilter.h>

namespace proxima::shell
{

std::string windowPng(vtkRenderWindow* window, const std::string& path)
{
  window->Render();
  vtkNew<vtkWindowToImageFilter> capture;
  capture->SetInput(window);
  capture->SetInputBufferTypeToRGB();
  capture->ReadFrontBufferOff();
  vtkNew<vtkPNGWriter> writer;
  writer->WriteToMemoryOn();
  writer->SetInputConnection(capture->GetOutputPort());
  writer->Write();
  vtkUnsignedCharArray* png = writer->GetResult();
  if (writer->GetErrorCode() != 0 || png == nullptr || png->GetNumberOfValues() == 0)
  {
    throw OutputError::cannotWrite(path, "VTK's PNG writer produced no image");
  }
  return std::string(reinterpret_cast<const char*>(png->GetPointer(0)),
                     static_cast<std::size_t>(png->GetNumberOfValues()));
}

} // namespace proxima::shell
