#include "IO/Mesh/Private/VtkMessageCapture.h"

#include <vtkLogger.h>
#include <vtkObjectFactory.h>
#include <vtkOutputWindow.h>
#include <vtkSmartPointer.h>

#include <mutex>
#include <regex>

namespace proxima::detail
{
namespace
{
// The capture active on this thread: VTK's output window is one global object, but readers may
// run on several threads at once (a scene loader), so each thread collects only its own messages.
thread_local std::vector<VtkMessage>* t_sink = nullptr;

VtkMessage parseMessage(const char* raw, bool isError)
{
  // VTK formats "ERROR: In <file>, line <n>\n<Class> (0x...): <text>\n\n"; generic warnings lack
  // the class. Keep only the class name and the text.
  std::string text = raw ? raw : "";
  if (const auto newline = text.find('\n');
      newline != std::string::npos &&
      (text.rfind("ERROR: In ", 0) == 0 || text.rfind("Warning: In ", 0) == 0 ||
       text.rfind("Generic Warning: In ", 0) == 0))
  {
    text.erase(0, newline + 1);
  }
  VtkMessage message;
  message.isError = isError;
  static const std::regex prefix(R"(^(\w+) \(0x[0-9a-fA-F]+\): )");
  std::smatch match;
  if (std::regex_search(text, match, prefix))
  {
    message.source = match[1].str();
    text.erase(0, static_cast<std::size_t>(match.length(0)));
  }
  while (!text.empty() && (text.back() == '\n' || text.back() == ' '))
  {
    text.pop_back();
  }
  message.text = text;
  return message;
}

/// Routes errors and warnings to the thread's capture when there is one, and everything else
/// (and everything on threads that capture nothing) to the window that was installed before.
class CapturingOutputWindow : public vtkOutputWindow
{
public:
  static CapturingOutputWindow* New();
  vtkTypeMacro(CapturingOutputWindow, vtkOutputWindow)

    void setPrevious(vtkOutputWindow* previous)
  {
    m_previous = previous;
  }

  void DisplayText(const char* text) override { forward(text, &vtkOutputWindow::DisplayText); }
  void DisplayErrorText(const char* text) override
  {
    if (t_sink)
    {
      t_sink->push_back(parseMessage(text, true));
      return;
    }
    forward(text, &vtkOutputWindow::DisplayErrorText);
  }
  void DisplayWarningText(const char* text) override
  {
    if (t_sink)
    {
      t_sink->push_back(parseMessage(text, false));
      return;
    }
    forward(text, &vtkOutputWindow::DisplayWarningText);
  }
  void DisplayGenericWarningText(const char* text) override
  {
    if (t_sink)
    {
      t_sink->push_back(parseMessage(text, false));
      return;
    }
    forward(text, &vtkOutputWindow::DisplayGenericWarningText);
  }
  void DisplayDebugText(const char* text) override
  {
    forward(text, &vtkOutputWindow::DisplayDebugText);
  }

protected:
  CapturingOutputWindow() = default;
  ~CapturingOutputWindow() override = default;

private:
  void forward(const char* text, void (vtkOutputWindow::*display)(const char*))
  {
    if (m_previous)
    {
      (m_previous.Get()->*display)(text);
    }
  }

  vtkSmartPointer<vtkOutputWindow> m_previous;
};

vtkStandardNewMacro(CapturingOutputWindow);

// VTK logs every error and warning through vtkLogger (to stderr) before it reaches the output
// window, so while any thread captures, vtkLogger's stderr channel is closed; messages of other
// threads still reach stderr through the previous output window, which CapturingOutputWindow
// forwards to (it prints them itself when not inside VTK's macros).
std::mutex g_loggerMutex;
int g_numActiveCaptures = 0;
vtkLogger::Verbosity g_savedStderrVerbosity = vtkLogger::VERBOSITY_INFO;

void silenceLogger()
{
  std::lock_guard<std::mutex> lock(g_loggerMutex);
  if (g_numActiveCaptures++ == 0)
  {
    g_savedStderrVerbosity = vtkLogger::GetCurrentVerbosityCutoff();
    vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
  }
}

void restoreLogger()
{
  std::lock_guard<std::mutex> lock(g_loggerMutex);
  if (--g_numActiveCaptures == 0)
  {
    vtkLogger::SetStderrVerbosity(g_savedStderrVerbosity);
  }
}

void installOnce()
{
  // Installed once for the process and never removed: swapping the global window back and forth
  // would race with other threads, while forwarding keeps everyone else's output unchanged.
  static std::once_flag once;
  std::call_once(once, [] {
    vtkSmartPointer<vtkOutputWindow> previous = vtkOutputWindow::GetInstance();
    auto window = vtkSmartPointer<CapturingOutputWindow>::New();
    window->setPrevious(previous);
    vtkOutputWindow::SetInstance(window);
  });
}
} // namespace

VtkMessageCapture::VtkMessageCapture()
{
  installOnce();
  silenceLogger();
  m_outer = t_sink;
  t_sink = &m_messages;
}

VtkMessageCapture::~VtkMessageCapture()
{
  t_sink = m_outer;
  restoreLogger();
}

bool VtkMessageCapture::hasErrors() const
{
  for (const VtkMessage& message : m_messages)
  {
    if (message.isError)
    {
      return true;
    }
  }
  return false;
}

std::string VtkMessageCapture::bestMessage() const
{
  auto isPipeline = [](const VtkMessage& m) {
    return m.source == "vtkCompositeDataPipeline" ||
           m.source == "vtkStreamingDemandDrivenPipeline" ||
           m.source == "vtkDemandDrivenPipeline" || m.source == "vtkExecutive";
  };
  for (const VtkMessage& message : m_messages)
  {
    if (message.isError && !isPipeline(message))
    {
      return message.text;
    }
  }
  for (const VtkMessage& message : m_messages)
  {
    if (message.isError)
    {
      // The pipeline's report runs on with a dump of the request; its first line says it all.
      return message.text.substr(0, message.text.find('\n'));
    }
  }
  return m_messages.empty() ? std::string() : m_messages.front().text;
}

} // namespace proxima::detail
