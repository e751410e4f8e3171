#include "Exercises/HeadlessSession.h"

#include "Exercises/ExerciseScene.h"

#include "IO/ScriptedRun/ScriptedRun.h"
#include "IO/ScriptedRun/ScriptedRunSettings.h"
#include "Runtime/SimulatedDevice.h"

#include <memory>

namespace proxima::trainer
{

ExerciseScore playHeadlessSession(const Exercise& exercise, const FingerPath& path,
                                  const std::string& pathName, const std::vector<double>& markTimes,
                                  const SessionObserver& observer)
{
  const ScriptedRunSettings settings = exerciseRunSettings(exercise, pathName);
  const LoadedScene loaded = loadExerciseScene(settings);
  checkPathStart(settings, loaded, path);
  ExerciseScorer scorer(exercise, *loaded.scene, &loaded.description);
  // A soft organ deforms under the finger in lockstep, as `proxima run` plays it.
  const std::unique_ptr<TissueDynamics> tissue =
    buildSceneTissue(loaded, settings.stiffness, settings.rate);
  std::size_t nextMark = 0;
  SimulatedDevice device(path);
  const auto onTick = [&](const HapticState& state) {
    // A mark at t belongs to the last tick at or before t: apply those due before this tick.
    while (nextMark < markTimes.size() && markTimes[nextMark] < state.time)
    {
      scorer.mark();
      ++nextMark;
    }
    scorer.addTick(state);
    if (observer)
    {
      observer(state, scorer, *loaded.scene, tissue.get());
    }
  };
  playScriptedPath(settings, *loaded.scene, path, device, onTick, {}, nullptr, tissue.get());
  // Marks at or after the last tick mark its contact.
  for (; nextMark < markTimes.size(); ++nextMark)
  {
    scorer.mark();
  }
  return scorer.score();
}

} // namespace proxima::trainer
