#include "Exercises/ExerciseReport.h"

#include <nlohmann/json.hpp>

namespace proxima::trainer
{
namespace
{
using Json = nlohmann::ordered_json;

Json point(const Vec3& p)
{
  return Json::array({p.x, p.y, p.z});
}

Json taskJson(const ExerciseTask& task, const TaskScore& score)
{
  Json json;
  switch (task.kind)
  {
    case TaskKind::Palpation:
      json["type"] = "palpation";
      json["passed"] = score.passed;
      json["marks"] = score.palpation.marks;
      json["spot"] = point(score.palpation.spot);
      if (score.palpation.mark)
      {
        json["mark"] = point(*score.palpation.mark);
        json["distance_m"] = score.palpation.distance;
      }
      else
      {
        json["mark"] = nullptr;
        json["distance_m"] = nullptr;
      }
      json["pass_distance_m"] = task.palpation.passDistance;
      break;
    case TaskKind::Targets:
    {
      json["type"] = "targets";
      json["passed"] = score.passed;
      json["touched"] = score.targets.touched;
      json["of"] = task.targets.targets.size();
      Json targets = Json::array();
      for (std::size_t i = 0; i < task.targets.targets.size(); ++i)
      {
        Json target;
        target["name"] = task.targets.targets[i].name;
        target["touched_s"] = i < score.targets.touchedTimes.size()
                                ? Json(score.targets.touchedTimes[i])
                                : Json(nullptr);
        targets.push_back(target);
      }
      json["targets"] = targets;
      json["seconds"] = score.targets.seconds;
      json["path_length_m"] = score.targets.fingerPathLength;
      json["peak_force_n"] = score.targets.peakForce;
      json["force_band_n"] = {task.targets.minForce, task.targets.maxForce};
      break;
    }
    case TaskKind::Trace:
      json["type"] = "trace";
      json["passed"] = score.passed;
      json["coverage"] = score.trace.coverage;
      json["min_coverage"] = task.trace.minCoverage;
      json["off_line"] = score.trace.offLine;
      json["max_off_line"] = task.trace.maxOffLine;
      json["max_deviation_m"] = score.trace.touched ? Json(score.trace.maxDeviation) : Json();
      json["tolerance_m"] = task.trace.tolerance;
      json["contact_ticks"] = score.trace.contactTicks;
      break;
  }
  return json;
}
} // namespace

std::string exerciseReportJson(const Exercise& exercise, const ExerciseScore& score,
                               const ReportContext& context)
{
  Json json;
  json["format"] = "proxima-exercise-report";
  json["version"] = 1;
  json["exercise"] = exercise.path;
  json["name"] = exercise.name;
  json["path"] = context.path.empty() ? Json(nullptr) : Json(context.path);
  json["marks"] = context.marks.empty() ? Json(nullptr) : Json(context.marks);
  json["passed"] = score.passed;
  json["seconds"] = score.endTime - score.startTime;
  json["ticks"] = score.ticks;
  json["contact_ticks"] = score.contactTicks;
  json["path_length_m"] = score.fingerPathLength;
  json["peak_force_n"] = score.peakForce;
  Json events = Json::array();
  for (const DamageEvent& event : score.damage)
  {
    events.push_back({{"object", event.object},
                      {"tissue", event.tissue},
                      {"start_s", event.startTime},
                      {"duration_s", event.duration},
                      {"peak_force_n", event.peakForce},
                      {"position", point(event.position)}});
  }
  json["damage_events"] = events;
  Json tasks = Json::array();
  for (std::size_t t = 0; t < exercise.tasks.size(); ++t)
  {
    tasks.push_back(taskJson(exercise.tasks[t], score.tasks[t]));
  }
  json["tasks"] = tasks;
  return json.dump(2) + "\n";
}

} // namespace proxima::trainer
