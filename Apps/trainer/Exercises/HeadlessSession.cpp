#include "Exercises/HeadlessSession.h"

#include "Exercises/ExerciseScene.h"

#include "IO/ScriptedRun/ScriptedRun.h"
#include "IO/ScriptedRun/ScriptedRunSettings.h"
#include "Runtime/SimulatedDevice.h"

namespace proxima::trainer
{

ExerciseScore playHeadlessSession(const Exercise& exercise, const FingerPath& path,
                                  const std::string& pathName, const std::vector<double>& markTimes,
                                  const SessionObserver& observer)
{
  const ScriptedRunSettings settings = exerciseRunSettings(exercise, pathName);
  const LoadedScene loaded = loadExerciseScene(settings);
  checkPathStart(settings, loaded, path);
  ExerciseScorer scorer(exercise, *loaded.scene);
  std::size_t nextMark = 0;
  SimulatedDevice device(path);
  playScriptedPath(settings, *loaded.scene, path, device, [&](const HapticState& state) {
    // A mark at t belongs to the last tick at or before t: apply those due before this tick.
    while (nextMark < markTimes.size() && markTimes[nextMark] < state.time)
    {
      scorer.mark();
      ++nextMark;
    }
    scorer.addTick(state);
    if (observer)
    {
      observer(state, scorer, *loaded.scene);
    }
  });
  // Marks at or after the last tick mark its contact.
  for (; nextMark < markTimes.size(); ++nextMark)
  {
    scorer.mark();
  }
  return scorer.score();
}

} // namespace proxima::trainer
