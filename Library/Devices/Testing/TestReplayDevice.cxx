// Recording and replay: a session recorded from a run plays back to the same trace (every field
// but the measured solve time), the file round-trips every double, and bad files are refused
// with the file, the line and the defect.
#include "Devices/ReplayDevice.h"

#include "DeviceTestScene.h"
#include "Runtime/SimulatedDevice.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

namespace proxima
{
namespace
{
using namespace proxima::testing;

std::string scratchFile(const std::string& name)
{
  return (std::filesystem::temp_directory_path() /
          ("proxima-" + std::to_string(::getpid()) + "-" + name))
    .string();
}

void expectSameTrace(const std::vector<HapticState>& a, const std::vector<HapticState>& b)
{
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i)
  {
    EXPECT_EQ(a[i].time, b[i].time) << i;
    EXPECT_EQ(a[i].finger, b[i].finger) << i;
    EXPECT_EQ(a[i].proxy, b[i].proxy) << i;
    EXPECT_EQ(a[i].force, b[i].force) << i;
    EXPECT_EQ(a[i].numContacts, b[i].numContacts) << i;
    EXPECT_EQ(a[i].iterations, b[i].iterations) << i;
    EXPECT_EQ(a[i].conditions.has(TickCondition::fingerRefused),
              b[i].conditions.has(TickCondition::fingerRefused))
      << i;
  }
}

TEST(ReplayDevice, ReplayedRunHasTheRecordedTrace)
{
  GridScene scene;
  const FingerPath path = pressStrokePath();
  SimulatedDevice simulated(path);
  RecordingDevice recording(simulated, 400);
  const std::vector<HapticState> recorded = scene.run(recording, path);
  ASSERT_GT(contactTicks(recorded), 50u);

  const std::string file = scratchFile("replay.csv");
  std::string error;
  ASSERT_TRUE(writeDeviceRecording(file, recording.samples(), error)) << error;
  auto samples = readDeviceRecording(file, error);
  ASSERT_TRUE(samples) << error;
  ASSERT_EQ(samples->size(), recording.samples().size());
  for (std::size_t i = 0; i < samples->size(); ++i)
  {
    EXPECT_EQ((*samples)[i].time, recording.samples()[i].time);
    EXPECT_EQ((*samples)[i].sample.position, recording.samples()[i].sample.position);
  }
  ReplayDevice replay(std::move(*samples));
  expectSameTrace(recorded, scene.run(replay, path));
  std::remove(file.c_str());
}

TEST(RecordingDevice, KeepsWhatItReservedRoomForAndCountsTheRest)
{
  SimulatedDevice simulated(pressStrokePath());
  RecordingDevice recording(simulated, 10);
  const RecordedSample* storage = nullptr;
  for (int tick = 0; tick < 25; ++tick)
  {
    const double time = tick / kTestRate;
    // Every read is passed on, recorded or not.
    EXPECT_EQ(recording.read(time).position, simulated.read(time).position);
    if (tick == 0)
    {
      storage = recording.samples().data();
    }
  }
  ASSERT_EQ(recording.samples().size(), 10u);
  EXPECT_EQ(recording.samplesLeftOut(), 15u);
  // The first ten, in the room reserved at construction: no reallocation on the servo thread.
  EXPECT_EQ(recording.samples().data(), storage);
  EXPECT_EQ(recording.samples().back().time, 9 / kTestRate);
}

TEST(ReplayDevice, KeepsButtonsOrientationAndNaNAndEndsInADisconnect)
{
  std::vector<RecordedSample> rows(2);
  rows[0].time = 0.0;
  rows[0].sample.position = {0.1, std::nan(""), 0.3};
  rows[0].sample.buttons = 0x80000001u;
  rows[0].sample.hasOrientation = true;
  rows[0].sample.orientation = {0.5, 0.5, 0.5, 0.5};
  rows[1].time = 0.001;
  rows[1].sample.valid = false;
  const std::string file = scratchFile("rows.csv");
  std::string error;
  ASSERT_TRUE(writeDeviceRecording(file, rows, error)) << error;
  auto samples = readDeviceRecording(file, error);
  ASSERT_TRUE(samples) << error;
  ReplayDevice replay(std::move(*samples));
  DeviceSample sample = replay.read(0.0);
  EXPECT_TRUE(std::isnan(sample.position.y));
  EXPECT_EQ(sample.buttons, 0x80000001u);
  EXPECT_EQ(sample.orientation, (std::array<double, 4>{0.5, 0.5, 0.5, 0.5}));
  EXPECT_FALSE(replay.read(0.001).valid);
  EXPECT_TRUE(replay.read(0.001).connected);
  sample = replay.read(0.002);
  EXPECT_FALSE(sample.connected);
  std::remove(file.c_str());
}

std::string readError(const std::string& name, const std::string& text)
{
  const std::string file = scratchFile(name);
  {
    std::ofstream out(file);
    out << text;
  }
  std::string error;
  EXPECT_FALSE(readDeviceRecording(file, error));
  std::remove(file.c_str());
  // Without the scratch folder, so that the messages can be compared.
  return error.substr(error.find(name));
}

TEST(DeviceRecording, BadFilesAreRefusedWithLineAndDefect)
{
  const std::string header = std::string(kDeviceRecordingHeader) + "\n";
  const std::string row = "0,0,0,0,1,1,0,0,1,0,0,0\n";
  EXPECT_EQ(readError("a.csv", "t,x,y,z\n"),
            "a.csv: line 1: the header must be '" + header.substr(0, header.size() - 1) + "'");
  EXPECT_EQ(readError("b.csv", header + row + "0.001,1,2\n"),
            "b.csv: line 3: has 3 values, not 12");
  EXPECT_EQ(readError("c.csv", header + "0,0,zero,0,1,1,0,0,1,0,0,0\n"),
            "c.csv: line 2: y is not a number ('zero')");
  EXPECT_EQ(readError("d.csv", header + "0.002,0,0,0,1,1,0,0,1,0,0,0\n" + row),
            "d.csv: line 3: t goes backwards (0 after 0.002000)");
  EXPECT_EQ(readError("e.csv", header + "0,0,0,0,2,1,0,0,1,0,0,0\n"),
            "e.csv: line 2: valid must be 0 or 1, not '2'");
  EXPECT_EQ(readError("f.csv", header), "f.csv: has no samples");
  std::string error;
  EXPECT_FALSE(readDeviceRecording("/no/such/recording.csv", error));
  EXPECT_EQ(error, "/no/such/recording.csv: cannot open the file");
}

} // namespace
} // namespace proxima
