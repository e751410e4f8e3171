// Collects VTK's error and warning messages raised on this thread while it is alive, instead of
// letting VTK print them to stderr: readers often report a bad file only this way (and then hand
// back empty output), and a command line must answer with one line of its own, not VTK's spam.
// Private to the IO layer: VTK types may appear here.
#pragma once

#include <string>
#include <vector>

namespace proxima::detail
{

struct VtkMessage
{
  bool isError = false;
  /// The class that raised it ("vtkOBJReader"), or empty for a generic warning.
  std::string source;
  /// The message itself, without VTK's "ERROR: In file, line n" and "vtkClass (0x...):" prefixes.
  std::string text;
};

class VtkMessageCapture
{
public:
  VtkMessageCapture();
  ~VtkMessageCapture();
  VtkMessageCapture(const VtkMessageCapture&) = delete;
  VtkMessageCapture& operator=(const VtkMessageCapture&) = delete;

  const std::vector<VtkMessage>& messages() const { return m_messages; }
  bool hasErrors() const;
  /// The most telling message: the first error raised by a reader or parser (the pipeline's own
  /// "returned failure" only when nothing else was said), else the first warning; empty if none.
  std::string bestMessage() const;

private:
  std::vector<VtkMessage> m_messages;
  std::vector<VtkMessage>* m_outer = nullptr;
};

} // namespace proxima::detail
