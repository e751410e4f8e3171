#include "Probing/ProbeSession.h"

#include "IO/ScriptedRun/ScriptedRun.h"
#include "Runtime/SimulatedDevice.h"

namespace proxima::inspector
{

ProbeMeasurements playProbeSession(const ScriptedRunSettings& settings, const FingerPath& path,
                                   const std::vector<double>& markTimes,
                                   const ProbeMeterSettings& meterSettings)
{
  checkScriptedRunSettings(settings);
  const LoadedScene loaded = loadScene(settings);
  refuseSceneBodies(loaded, "the inspector");
  refuseSceneTissue(loaded, "the inspector");
  checkRadiusAgainstScene(settings, loaded);
  checkPathStart(settings, loaded, path);
  ProbeMeter meter(*loaded.scene, meterSettings);
  std::size_t nextMark = 0;
  SimulatedDevice device(path);
  playScriptedPath(settings, *loaded.scene, path, device, [&](const HapticState& state) {
    // A marker at t belongs to the last tick at or before t: drop those due before this tick.
    while (nextMark < markTimes.size() && markTimes[nextMark] < state.time)
    {
      meter.mark();
      ++nextMark;
    }
    meter.addTick(state);
  });
  for (; nextMark < markTimes.size(); ++nextMark)
  {
    meter.mark();
  }
  return meter.measurements();
}

} // namespace proxima::inspector
