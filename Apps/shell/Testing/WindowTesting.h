// What the applications' window tests (QTest under Xvfb) share: waiting for a state while the
// window's timer runs, saving the window as a documentation figure, and a finger path as a device
// recording that a replay device plays through the threaded runtime.
#pragma once

#include "Devices/DeviceRecording.h"
#include "Runtime/FingerPath.h"
#include "Runtime/SimulatedDevice.h"

#include <QByteArray>
#include <QString>
#include <QTest>
#include <QWidget>

#include <chrono>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

namespace proxima::shell::testing
{

/// Lets the window's timer run until `done` or `seconds` pass; whether `done` came.
inline bool waitUntil(const std::function<bool()>& done, double seconds)
{
  const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  while (std::chrono::steady_clock::now() < end)
  {
    if (done())
    {
      return true;
    }
    QTest::qWait(20);
  }
  return done();
}

/// With the environment variable `folderVariable` set to a folder, saves the window, menus and
/// all, as FOLDER/NAME: the documentation's pictures come from these runs.
inline void saveFigure(QWidget* window, const char* folderVariable, const char* name)
{
  const QByteArray folder = qgetenv(folderVariable);
  if (!folder.isEmpty())
  {
    window->grab().save(QString::fromLocal8Bit(folder) + "/" + name, "PNG");
  }
}

/// `path` sampled at `rate` as a device recording written to `file`; false with `error`.
inline bool writePathAsRecording(const FingerPath& path, double rate, const std::string& file,
                                 std::string& error)
{
  SimulatedDevice device(path);
  std::vector<RecordedSample> samples;
  const auto ticks = static_cast<std::uint64_t>(std::floor(path.endTime() * rate)) + 1;
  for (std::uint64_t k = 0; k < ticks; ++k)
  {
    const double time = static_cast<double>(k) / rate;
    samples.push_back({time, device.read(time)});
  }
  return writeDeviceRecording(file, samples, error);
}

} // namespace proxima::shell::testing
