#include "Exercises/ExerciseFile.h"

#include "IO/InputChecks/ParameterRanges.h"
#include "IO/JsonInput/JsonChecker.h"

namespace proxima::trainer
{
namespace
{
// Lengths in an exercise: a target, a tolerance, a pass distance (a millimetre to a metre's
// fraction of an organ; anything up to 1 m is taken).
constexpr ParameterRange kExerciseLengthRange{0.0, true, 1.0, " m"};
constexpr ParameterRange kForceLimitRange{0.0, true, 1000.0, " N"};
constexpr ParameterRange kHoldRange{0.0, false, 60.0, " s"};
constexpr ParameterRange kFractionRange{0.0, false, 1.0, ""};
constexpr ParameterRange kIndexRange{0.0, false, 1e6, ""};

class ExerciseReader : public JsonChecker
{
public:
  explicit ExerciseReader(const std::string& path)
    : JsonChecker(path)
  {}

  Exercise read(const Json& root) const
  {
    Exercise exercise;
    exercise.path = m_path;
    requireObject(root, "top level");
    const Json& format = require(root, "format", "");
    if (!format.is_string() || format.get<std::string>() != "proxima-exercise")
    {
      fail("format",
           "must be \"proxima-exercise\" (this is not an exercise file), got " + quoted(format));
    }
    // The version before the other keys: a newer file's keys are a newer version's, not typos.
    const Json& version = require(root, "version", "");
    if (!version.is_number() || version.get<double>() != kExerciseFileVersion)
    {
      fail("version", "must be " + std::to_string(kExerciseFileVersion) +
                        " (the exercise file version this program reads), got " + quoted(version));
    }
    checkKeys(root, "",
              {"format", "version", "name", "instructions", "scene", "proxy", "tissues", "tasks"});
    exercise.name = text(require(root, "name", ""), "name");
    if (const Json* instructions = find(root, "instructions"))
    {
      exercise.instructions = text(*instructions, "instructions");
    }
    exercise.scene = filePath(require(root, "scene", ""), "scene");
    if (const Json* proxy = find(root, "proxy"))
    {
      readProxy(*proxy, "proxy", exercise);
    }
    if (const Json* tissues = find(root, "tissues"))
    {
      const Json& list = array(*tissues, "tissues", "tissues [{\"object\": 0, ...}]");
      for (std::size_t i = 0; i < list.size(); ++i)
      {
        exercise.tissues.push_back(readTissue(list[i], element("tissues", i)));
      }
    }
    const Json& tasks = require(root, "tasks", "");
    if (!tasks.is_array() || tasks.empty())
    {
      fail("tasks", "must be an array of at least one task, got " + quoted(tasks));
    }
    for (std::size_t i = 0; i < tasks.size(); ++i)
    {
      exercise.tasks.push_back(readTask(tasks[i], element("tasks", i)));
    }
    return exercise;
  }

private:
  const Json& array(const Json& value, const std::string& where, const std::string& of) const
  {
    if (!value.is_array())
    {
      fail(where, "must be an array of " + of + ", got " + quoted(value));
    }
    return value;
  }

  std::uint32_t index(const Json& value, const std::string& where) const
  {
    const double v = number(value, where, "an index (a whole number from 0)", [](double x) {
      return kIndexRange.contains(x) && x == static_cast<double>(static_cast<std::uint32_t>(x));
    });
    return static_cast<std::uint32_t>(v);
  }

  Vec3 point(const Json& value, const std::string& where) const
  {
    const std::vector<double> p = numbers(value, where, 3, "[x, y, z] in metres");
    return {p[0], p[1], p[2]};
  }

  void readProxy(const Json& value, const std::string& where, Exercise& exercise) const
  {
    requireObject(value, where);
    checkKeys(value, where, {"radius", "stiffness", "rate", "max_force"});
    if (const Json* radius = find(value, "radius"))
    {
      exercise.radius = ranged(*radius, child(where, "radius"), kProxyRadiusRange);
    }
    if (const Json* stiffness = find(value, "stiffness"))
    {
      exercise.stiffness = ranged(*stiffness, child(where, "stiffness"), kStiffnessRange);
    }
    if (const Json* rate = find(value, "rate"))
    {
      exercise.rate = ranged(*rate, child(where, "rate"), kScriptedRateRange);
    }
    if (const Json* maxForce = find(value, "max_force"))
    {
      exercise.maxForce = ranged(*maxForce, child(where, "max_force"), kMaxForceRange);
    }
  }

  ExerciseTissue readTissue(const Json& value, const std::string& where) const
  {
    requireObject(value, where);
    checkKeys(value, where, {"object", "name", "force_limit"});
    ExerciseTissue tissue;
    tissue.object = index(require(value, "object", where), child(where, "object"));
    tissue.name = text(require(value, "name", where), child(where, "name"));
    tissue.forceLimit =
      ranged(require(value, "force_limit", where), child(where, "force_limit"), kForceLimitRange);
    return tissue;
  }

  ExerciseTask readTask(const Json& value, const std::string& where) const
  {
    requireObject(value, where);
    ExerciseTask task;
    constexpr TaskKind kKinds[] = {TaskKind::Palpation, TaskKind::Targets, TaskKind::Trace};
    task.kind = kKinds[choice(require(value, "type", where), child(where, "type"),
                              {"palpation", "targets", "trace"})];
    switch (task.kind)
    {
      case TaskKind::Palpation:
      {
        checkKeys(value, where, {"type", "object", "region", "inclusion", "pass_distance"});
        task.palpation.object = index(require(value, "object", where), child(where, "object"));
        const Json* region = find(value, "region");
        const Json* inclusion = find(value, "inclusion");
        if ((region == nullptr) == (inclusion == nullptr))
        {
          fail(where, std::string(region == nullptr ? "needs" : "takes only") +
                        " one of \"region\" (a stiffness region of the object's material) and "
                        "\"inclusion\" (an inclusion of the object's tissue)");
        }
        task.palpation.tissueInclusion = inclusion != nullptr;
        task.palpation.region = region != nullptr ? index(*region, child(where, "region"))
                                                  : index(*inclusion, child(where, "inclusion"));
        task.palpation.passDistance = ranged(require(value, "pass_distance", where),
                                             child(where, "pass_distance"), kExerciseLengthRange);
        break;
      }
      case TaskKind::Targets: readTargets(value, where, task.targets); break;
      case TaskKind::Trace: readTrace(value, where, task.trace); break;
    }
    return task;
  }

  void readTargets(const Json& value, const std::string& where, TargetTask& task) const
  {
    checkKeys(value, where, {"type", "targets", "force", "hold"});
    const std::string at = child(where, "targets");
    const Json& targets = require(value, "targets", where);
    if (!targets.is_array() || targets.empty())
    {
      fail(at, "must be an array of at least one target, got " + quoted(targets));
    }
    for (std::size_t i = 0; i < targets.size(); ++i)
    {
      const std::string here = element(at, i);
      requireObject(targets[i], here);
      checkKeys(targets[i], here, {"name", "center", "radius"});
      ExerciseTarget target;
      target.name = text(require(targets[i], "name", here), child(here, "name"));
      target.center = point(require(targets[i], "center", here), child(here, "center"));
      target.radius =
        ranged(require(targets[i], "radius", here), child(here, "radius"), kExerciseLengthRange);
      task.targets.push_back(target);
    }
    const std::vector<double> band =
      numbers(require(value, "force", where), child(where, "force"), 2, "[least, most] in newtons");
    if (!(band[0] >= 0.0 && band[1] > band[0] && band[1] <= kForceLimitRange.high))
    {
      fail(child(where, "force"), "must be [least, most] newtons with 0 <= least < most <= 1000, "
                                  "got " +
                                    quoted(require(value, "force", where)));
    }
    task.minForce = band[0];
    task.maxForce = band[1];
    if (const Json* hold = find(value, "hold"))
    {
      task.holdSeconds = ranged(*hold, child(where, "hold"), kHoldRange);
    }
  }

  void readTrace(const Json& value, const std::string& where, TraceTask& task) const
  {
    checkKeys(value, where, {"type", "line", "tolerance", "min_coverage", "max_off_line"});
    const std::string at = child(where, "line");
    const Json& line = require(value, "line", where);
    if (!line.is_array() || line.size() < 2)
    {
      fail(at, "must be an array of at least two points [x, y, z], got " + quoted(line));
    }
    double length = 0.0;
    for (std::size_t i = 0; i < line.size(); ++i)
    {
      task.line.push_back(point(line[i], element(at, i)));
      length += i == 0 ? 0.0 : overflowSafeNorm(task.line[i] - task.line[i - 1]);
    }
    // A line of no length has nothing to trace: its one point would be covered by a touch.
    if (!(length > 0.0))
    {
      fail(at, "has no length (all its points are one point): give a line to trace, got " +
                 quoted(line));
    }
    task.tolerance =
      ranged(require(value, "tolerance", where), child(where, "tolerance"), kExerciseLengthRange);
    if (const Json* coverage = find(value, "min_coverage"))
    {
      task.minCoverage = ranged(*coverage, child(where, "min_coverage"), kFractionRange);
    }
    if (const Json* offLine = find(value, "max_off_line"))
    {
      task.maxOffLine = ranged(*offLine, child(where, "max_off_line"), kFractionRange);
    }
  }
};
} // namespace

Exercise readExerciseFile(const std::string& path)
{
  return ExerciseReader(path).read(readCheckedJsonFile(path, "exercise file"));
}

} // namespace proxima::trainer
