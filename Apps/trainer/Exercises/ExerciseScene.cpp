#include "Exercises/ExerciseScene.h"

namespace proxima::trainer
{

ScriptedRunSettings exerciseRunSettings(const Exercise& exercise, const std::string& pathName)
{
  ScriptedRunSettings settings;
  settings.scene = exercise.scene;
  settings.radius = exercise.radius;
  settings.stiffness = exercise.stiffness;
  settings.rate = exercise.rate;
  settings.maxForce = exercise.maxForce;
  settings.path = pathName;
  return settings;
}

LoadedScene loadExerciseScene(const ScriptedRunSettings& settings)
{
  LoadedScene loaded = loadScene(settings);
  refuseSceneBodies(loaded, "the trainer");
  checkRadiusAgainstScene(settings, loaded);
  return loaded;
}

} // namespace proxima::trainer
