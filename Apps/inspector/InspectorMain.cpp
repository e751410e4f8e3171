// proxima-inspector: the CAD inspector (Documentation/CadInspector.md). Without --path it opens
// the inspector's window on a part, to probe it by touch with the mouse or a device, drop
// markers, measure, and see its defects and where the tool cannot reach:
//   proxima-inspector --mesh PART [--scale S] [--tool-radius R] [--device mouse|spacemouse|...]
// Headless, it plays a scripted finger path over the part in lockstep with the proxy at the
// tool's radius and writes what the probe measured (markers, distances, the narrowest gap passed
// through, where the probe stopped):
//   proxima-inspector --mesh PART --path P.csv [--marks M.csv] --report R.json
// The defect report alone is `proxima inspect`. Exit statuses as the proxima command line's
// (DESIGN.md section 3): 0 when the session ran, 2 for bad input or an output that cannot be
// written (one line naming the file and the defect), 1 for an internal error.
#include "NumberOptions.h"
#include "Probing/ProbeReport.h"
#include "Probing/ProbeSession.h"
#include "ProgramMain.h"
#if PROXIMA_INSPECTOR_WINDOW
#include "Window/InspectorWindowMain.h"
#endif

#include "IO/InputChecks/InputError.h"
#include "IO/InputChecks/ParameterRanges.h"
#include "IO/Output/AtomicOutputFile.h"
#include "IO/Output/OutputIdentity.h"
#include "IO/Output/StandardOutput.h"
#include "IO/PathAndTrace/FingerPathFile.h"
#include "IO/PathAndTrace/MarkTimesFile.h"
#include "Runtime/ServoRate.h"

#include <CLI/CLI.hpp>

#include <cstdio>

namespace
{
using namespace proxima;
using namespace proxima::inspector;

struct InspectorOptions
{
  std::string mesh;
  double scale = 1.0;
  double toolRadius = 0.001;
  double stiffness = 1000.0;
  double rate = 1000.0;
  std::string path;
  std::string marks;
  std::string report;
  double stopDepth = -1.0;
  double widestGap = 0.02;
  std::string device;
  std::string falconFirmware;
  int width = 1024;
  int height = 720;
};

// The options of one mode given in the other: a window takes no report, a scripted session no
// device.
void checkMode(const InspectorOptions& options)
{
  if (options.path.empty())
  {
    for (const auto& [value, name] :
         {std::pair{options.report, "--report"}, std::pair{options.marks, "--marks"}})
    {
      if (!value.empty())
      {
        throw InputError(name, "belongs to a scripted session: give --path too (the window's "
                               "File menu exports the report)");
      }
    }
    return;
  }
  if (!options.device.empty())
  {
    throw InputError("--device", "moves the finger in the window: leave out --path for it");
  }
  if (options.report.empty())
  {
    throw InputError("--report", "is required with --path");
  }
}

int runHeadless(const InspectorOptions& options)
{
  const FingerPath path = readFingerPathFile(options.path);
  const std::vector<double> marks =
    options.marks.empty() ? std::vector<double>{} : readMarkTimesFile(options.marks);
  refuseOverlappingFiles(
    {{options.report, "--report"}},
    {{options.mesh, "--mesh"}, {options.path, "--path"}, {options.marks, "--marks"}});
  // The report's temporary before the session: an unwritable report fails before the run.
  AtomicOutputFile report(options.report);
  ScriptedRunSettings settings;
  settings.mesh = options.mesh;
  settings.scale = options.scale;
  settings.radius = options.toolRadius;
  settings.stiffness = options.stiffness;
  settings.rate = options.rate;
  settings.path = options.path;
  ProbeMeterSettings meter;
  meter.stopDepth = options.stopDepth >= 0.0 ? options.stopDepth : 0.5 * options.toolRadius;
  meter.widestGap = options.widestGap;
  ProbeMeasurements measured;
  try
  {
    measured = playProbeSession(settings, path, marks, meter);
  }
  catch (const InputError& error)
  {
    // The scripted run's checks name the proxy's radius as proxima run spells it; here the proxy
    // is the tool.
    if (error.path() == "--radius")
    {
      throw InputError("--tool-radius", error.defect());
    }
    throw;
  }

  nlohmann::ordered_json json;
  json["format"] = "proxima-probe-session";
  json["version"] = 1;
  json["mesh"] = options.mesh;
  json["scale"] = options.scale;
  json["tool_radius"] = options.toolRadius;
  json["path"] = options.path;
  json["marks"] = options.marks;
  json["stop_depth"] = meter.stopDepth;
  json["widest_gap"] = meter.widestGap;
  json["probe"] = probeMeasurementsJson(measured);
  report.write(json.dump(2) + "\n");
  report.commit();

  std::string line = options.report + ": " + std::to_string(measured.markers.size()) + " markers";
  char text[256];
  for (const MarkerDistance& distance : measured.distances)
  {
    std::snprintf(text, sizeof text, ", %zu to %zu: %.3f mm (across %.3f mm)", distance.from,
                  distance.to, distance.distance * 1000.0, distance.across * 1000.0);
    line += text;
  }
  if (measured.narrowestGap)
  {
    std::snprintf(text, sizeof text, ", narrowest gap %.3f mm",
                  measured.narrowestGap->width * 1000.0);
    line += text;
  }
  std::snprintf(text, sizeof text, ", %zu stops\n", measured.stopCount);
  writeStandardOutput(line + text);
  return 0;
}
} // namespace

int main(int argc, char** argv)
{
  CLI::App app{"proxima-inspector: probe a CAD part by touch, measure clearances, see its defects "
               "(Documentation/CadInspector.md)",
               "proxima-inspector"};
  InspectorOptions options;
  app
    .add_option("--mesh", options.mesh,
                "The part: .stl .obj .ply .vtp .gltf .glb .off (extension in any case)")
    ->required();
  // The ranges are the table's (ParameterRanges.h) that `proxima run` checks too, so --help shows
  // what the checks take: the tool is the proxy, and the session a scripted run.
  app.add_option("--scale", options.scale, "Factor from file units to metres")
    ->check(cli::numberIn(kMeshScaleRange))
    ->capture_default_str();
  app
    .add_option("--tool-radius", options.toolRadius,
                "The probe's radius in metres: the proxy's, and the tool whose reach is shown")
    ->check(cli::numberIn(kProxyRadiusRange))
    ->capture_default_str();
  app.add_option("--stiffness", options.stiffness, "The proxy's spring kp in N/m")
    ->check(cli::numberIn(kStiffnessRange))
    ->capture_default_str();
  app
    .add_option("--rate", options.rate,
                "Servo rate in Hz; in the window (without --path) " + servoRateRange() +
                  ", the servo loop's range")
    ->check(cli::numberIn(kScriptedRateRange))
    ->capture_default_str();
  app.add_option("--path", options.path,
                 "Finger path CSV (t,x,y,z) played in lockstep, headless; without it the "
                 "inspector's window opens");
  app.add_option("--marks", options.marks,
                 "Markers: CSV with the header t, one time in seconds per row (with --path)");
  app.add_option("--report", options.report, "The probing report to write (JSON; with --path)");
  app
    .add_option("--stop-depth", options.stopDepth,
                "The finger this far beyond the proxy is a stop (metres; default half the tool "
                "radius)")
    ->check(cli::numberIn(kStopDepthRange));
  app.add_option("--widest-gap", options.widestGap, "Gaps wider than this are not measured (m)")
    ->check(cli::numberIn(kWidestGapRange))
    ->capture_default_str();
  shell::addWindowDeviceOptions(app, options.device, options.falconFirmware);
  app.add_option("--width", options.width, "Window width in pixels")
    ->check(cli::wholeNumberIn(kWindowSizeRange));
  app.add_option("--height", options.height, "Window height in pixels")
    ->check(cli::wholeNumberIn(kWindowSizeRange));
  return shell::runProgram(app, "proxima-inspector", argc, argv, [&] {
    checkMode(options);
    if (options.path.empty())
    {
      // The window runs the real-time loops: their rate rule, before anything is loaded.
      if (!isServoRate(options.rate))
      {
        throw InputError("--rate", "must be " + servoRateRange() +
                                     " in the window (the servo loop's range); a scripted "
                                     "session (--path) takes " +
                                     describeRange(kScriptedRateRange));
      }
#if PROXIMA_INSPECTOR_WINDOW
      InspectorWindowOptions window;
      window.mesh = options.mesh;
      window.scale = options.scale;
      window.toolRadius = options.toolRadius;
      window.stiffness = options.stiffness;
      window.rate = options.rate;
      window.device = options.device.empty() ? "mouse" : options.device;
      window.falconFirmware = options.falconFirmware;
      window.width = options.width;
      window.height = options.height;
      return runInspectorWindow(window, argc, argv);
#else
      throw InputError("--path", "is required: this build has no window (PROXIMA_BUILD_QT=OFF)");
#endif
    }
    const int status = runHeadless(options);
    finishStandardOutput();
    return status;
  });
}
