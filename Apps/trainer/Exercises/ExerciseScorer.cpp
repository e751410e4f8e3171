#include "Exercises/ExerciseScorer.h"

#include "Geometry/ClosestPoint.h"
#include "Geometry/SphereTree.h"
#include "IO/InputChecks/InputError.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>

namespace proxima::trainer
{
namespace
{
// A trace line is sampled at most this many times: a line longer than 20,000 half-tolerances is
// sampled coarser (its coverage then counts in longer stretches).
constexpr std::size_t kMaxTraceSamples = 20000;

std::string taskWhere(std::size_t task)
{
  return "tasks[" + std::to_string(task) + "]";
}

double distanceToPolyline(const Vec3& point, const std::vector<Vec3>& line)
{
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i + 1 < line.size(); ++i)
  {
    const double t = closestParameterOnSegment(point, line[i], line[i + 1]);
    best = std::min(best, norm(point - (line[i] + (line[i + 1] - line[i]) * t)));
  }
  return best;
}

std::vector<Vec3> sampleLine(const std::vector<Vec3>& line, double tolerance)
{
  double length = 0.0;
  for (std::size_t i = 0; i + 1 < line.size(); ++i)
  {
    length += norm(line[i + 1] - line[i]);
  }
  const double spacing = std::max(tolerance / 2.0, length / static_cast<double>(kMaxTraceSamples));
  std::vector<Vec3> samples;
  for (std::size_t i = 0; i + 1 < line.size(); ++i)
  {
    const double segment = norm(line[i + 1] - line[i]);
    // A hair under whole: a 4 cm segment sampled every 1 mm is 40 pieces, not 41.
    const auto pieces = static_cast<std::size_t>(std::ceil(segment / spacing - 1e-9));
    for (std::size_t k = 0; k < std::max<std::size_t>(pieces, 1); ++k)
    {
      samples.push_back(line[i] + (line[i + 1] - line[i]) *
                                    (static_cast<double>(k) / static_cast<double>(pieces)));
    }
  }
  samples.push_back(line.back());
  return samples;
}

// The point of `object`'s surface nearest `point` (the spot above a region under the surface).
Vec3 nearestSurfacePoint(const CollisionObject& object, const Vec3& point)
{
  auto scratch = std::make_unique<SphereTreeScratch>();
  const NearestTriangle nearest =
    object.tree.nearest(object.mesh, point, std::numeric_limits<double>::infinity(), *scratch);
  return nearest.closest.point;
}

// The centre of palpation task `t`'s inclusion: a stiffness region of the object's material, or
// an inclusion of its tissue (from the scene's description).
Vec3 inclusionCenter(const Exercise& exercise, std::size_t t, const CollisionScene& scene,
                     const SceneDescription* description)
{
  const PalpationTask& palpation = exercise.tasks[t].palpation;
  if (palpation.tissueInclusion)
  {
    std::size_t numInclusions = 0;
    if (description != nullptr && palpation.object < description->objects.size() &&
        description->objects[palpation.object].hasTissue)
    {
      numInclusions = description->objects[palpation.object].tissue.inclusions.size();
    }
    if (palpation.region >= numInclusions)
    {
      throw InputError(exercise.path, taskWhere(t) + ".inclusion: the scene's object " +
                                        std::to_string(palpation.object) + " has " +
                                        std::to_string(numInclusions) +
                                        " tissue inclusion(s) (its tissue's inclusions), "
                                        "numbered from 0: the inclusion to find is one of them");
    }
    return description->objects[palpation.object].tissue.inclusions[palpation.region].center;
  }
  const CollisionObject& object = scene.objects[palpation.object];
  const std::size_t numRegions = object.material.stiffnessRegions.size();
  if (palpation.region >= numRegions)
  {
    throw InputError(exercise.path, taskWhere(t) + ".region: the scene's object " +
                                      std::to_string(palpation.object) + " has " +
                                      std::to_string(numRegions) +
                                      " stiffness region(s) (its material's stiffness_regions), "
                                      "numbered from 0: the inclusion to find is one of them");
  }
  return object.material.stiffnessRegions[palpation.region].center;
}
} // namespace

ExerciseScorer::ExerciseScorer(const Exercise& exercise, const CollisionScene& scene,
                               const SceneDescription* description)
  : m_exercise(exercise)
  , m_holdStarts(exercise.tasks.size(), -1.0)
  , m_traces(exercise.tasks.size())
{
  const std::size_t numObjects = scene.objects.size();
  for (std::size_t i = 0; i < exercise.tissues.size(); ++i)
  {
    if (exercise.tissues[i].object >= numObjects)
    {
      throw InputError(exercise.path, "tissues[" + std::to_string(i) + "].object: the scene has " +
                                        std::to_string(numObjects) + " object(s), numbered from 0");
    }
  }
  for (std::size_t t = 0; t < exercise.tasks.size(); ++t)
  {
    const ExerciseTask& task = exercise.tasks[t];
    TaskScore score;
    score.kind = task.kind;
    if (task.kind == TaskKind::Palpation)
    {
      const PalpationTask& palpation = task.palpation;
      if (palpation.object >= numObjects)
      {
        throw InputError(exercise.path, taskWhere(t) + ".object: the scene has " +
                                          std::to_string(numObjects) +
                                          " object(s), numbered from 0");
      }
      const CollisionObject& object = scene.objects[palpation.object];
      score.palpation.spot =
        nearestSurfacePoint(object, inclusionCenter(exercise, t, scene, description));
    }
    if (task.kind == TaskKind::Trace)
    {
      m_traces[t].samples = sampleLine(task.trace.line, task.trace.tolerance);
      m_traces[t].covered.assign(m_traces[t].samples.size(), false);
    }
    m_score.tasks.push_back(score);
  }
}

void ExerciseScorer::addTick(const HapticState& state)
{
  const double forceMagnitude = norm(state.force);
  if (m_last)
  {
    m_score.fingerPathLength += norm(state.finger - m_last->finger);
  }
  else
  {
    m_score.startTime = state.time;
  }
  m_score.endTime = state.time;
  ++m_score.ticks;
  m_score.contactTicks += state.numContacts > 0 ? 1 : 0;
  m_score.peakForce = std::max(m_score.peakForce, forceMagnitude);
  for (std::size_t t = 0; t < m_exercise.tasks.size(); ++t)
  {
    const ExerciseTask& task = m_exercise.tasks[t];
    if (task.kind == TaskKind::Targets)
    {
      scoreTargets(task, m_score.tasks[t], state, forceMagnitude, m_holdStarts[t]);
    }
    else if (task.kind == TaskKind::Trace)
    {
      scoreTrace(task, m_score.tasks[t], m_traces[t], state);
    }
  }
  scoreDamage(state, forceMagnitude);
  m_last = state;
}

void ExerciseScorer::mark()
{
  for (std::size_t t = 0; t < m_exercise.tasks.size(); ++t)
  {
    if (m_exercise.tasks[t].kind != TaskKind::Palpation)
    {
      continue;
    }
    PalpationScore& palpation = m_score.tasks[t].palpation;
    ++palpation.marks;
    if (m_last && m_last->numContacts > 0)
    {
      palpation.mark = m_last->contacts[0].point;
      palpation.distance = norm(*palpation.mark - palpation.spot);
    }
    else
    {
      // A mark in the air marks nothing: the last mark is what counts.
      palpation.mark.reset();
    }
  }
}

void ExerciseScorer::scoreTargets(const ExerciseTask& task, TaskScore& score,
                                  const HapticState& state, double forceMagnitude,
                                  double& holdStart)
{
  const TargetTask& targets = task.targets;
  TargetScore& progress = score.targets;
  const auto next = static_cast<std::size_t>(progress.touched);
  if (next >= targets.targets.size())
  {
    return;
  }
  if (m_last)
  {
    progress.fingerPathLength += norm(state.finger - m_last->finger);
  }
  progress.peakForce = std::max(progress.peakForce, forceMagnitude);
  progress.seconds = state.time - m_score.startTime;
  const ExerciseTarget& target = targets.targets[next];
  const bool onTarget = state.numContacts > 0 &&
                        norm(state.contacts[0].point - target.center) <= target.radius &&
                        forceMagnitude >= targets.minForce && forceMagnitude <= targets.maxForce;
  if (!onTarget)
  {
    holdStart = -1.0;
    return;
  }
  if (holdStart < 0.0)
  {
    holdStart = state.time;
  }
  // Held for the hold time, counted in whole ticks: a hold of 0 is met by the first tick on it.
  if (state.time - holdStart >= targets.holdSeconds - 1e-9)
  {
    ++progress.touched;
    progress.touchedTimes.push_back(state.time);
    holdStart = -1.0;
  }
}

void ExerciseScorer::scoreTrace(const ExerciseTask& task, TaskScore& score, TraceProgress& progress,
                                const HapticState& state)
{
  if (state.numContacts == 0)
  {
    return;
  }
  const Vec3& contact = state.contacts[0].point;
  const double tolerance = task.trace.tolerance;
  for (std::size_t i = 0; i < progress.samples.size(); ++i)
  {
    if (!progress.covered[i] && norm(contact - progress.samples[i]) <= tolerance)
    {
      progress.covered[i] = true;
    }
  }
  const double deviation = distanceToPolyline(contact, task.trace.line);
  const bool onLine = deviation <= tolerance;
  progress.maxDeviationAnyContact = std::max(progress.maxDeviationAnyContact, deviation);
  // Before the trainee reached the line, a tick counts for none of the figures since the first.
  if (progress.onLineSeen || onLine)
  {
    progress.onLineSeen = true;
    ++progress.contactSinceFirst;
    progress.strayedSinceFirst += onLine ? 0 : 1;
    progress.maxDeviationSinceFirst = std::max(progress.maxDeviationSinceFirst, deviation);
    if (onLine)
    {
      progress.contactAtLast = progress.contactSinceFirst;
      progress.strayedAtLast = progress.strayedSinceFirst;
      progress.maxDeviationAtLast = progress.maxDeviationSinceFirst;
    }
  }
  TraceScore& trace = score.trace;
  trace.touched = true;
  const auto covered =
    static_cast<double>(std::count(progress.covered.begin(), progress.covered.end(), true));
  trace.coverage = covered / static_cast<double>(progress.samples.size());
  trace.contactTicks = progress.contactAtLast;
  trace.offLine = progress.contactAtLast > 0 ? static_cast<double>(progress.strayedAtLast) /
                                                 static_cast<double>(progress.contactAtLast)
                                             : 0.0;
  // A trace that never came within the tolerance has no ticks from the first on the line: its
  // deviation is the largest of every contact tick's, not the 0 of an empty count.
  trace.maxDeviation =
    progress.onLineSeen ? progress.maxDeviationAtLast : progress.maxDeviationAnyContact;
}

void ExerciseScorer::scoreDamage(const HapticState& state, double forceMagnitude)
{
  const ExerciseTissue* tissue = nullptr;
  if (state.numContacts > 0)
  {
    for (const ExerciseTissue& candidate : m_exercise.tissues)
    {
      if (static_cast<int>(candidate.object) == state.contactObject)
      {
        tissue = &candidate;
      }
    }
  }
  if (tissue == nullptr)
  {
    m_openDamage = -1;
    return;
  }
  const bool open = m_openDamage >= 0 &&
                    m_score.damage[static_cast<std::size_t>(m_openDamage)].object == tissue->object;
  // An open event lasts down to the release level, a new one starts only above the limit: a
  // press held at the limit crossed it at every ripple of the force, and each crossing was an
  // event of its own (the soft kidney counted 29 for one press before the servo's local model).
  const bool damaging = open ? forceMagnitude >= kDamageReleaseFraction * tissue->forceLimit
                             : forceMagnitude > tissue->forceLimit;
  if (!damaging)
  {
    m_openDamage = -1;
    return;
  }
  if (!open)
  {
    DamageEvent event;
    event.object = tissue->object;
    event.tissue = tissue->name;
    event.startTime = state.time;
    event.position = state.contacts[0].point;
    m_score.damage.push_back(event);
    m_openDamage = static_cast<long>(m_score.damage.size()) - 1;
  }
  DamageEvent& event = m_score.damage[static_cast<std::size_t>(m_openDamage)];
  event.duration = state.time - event.startTime;
  event.peakForce = std::max(event.peakForce, forceMagnitude);
}

ExerciseScore ExerciseScorer::score() const
{
  ExerciseScore score = m_score;
  bool allPassed = true;
  for (std::size_t t = 0; t < m_exercise.tasks.size(); ++t)
  {
    const ExerciseTask& task = m_exercise.tasks[t];
    TaskScore& result = score.tasks[t];
    switch (task.kind)
    {
      case TaskKind::Palpation:
        result.passed = result.palpation.mark.has_value() &&
                        result.palpation.distance <= task.palpation.passDistance;
        break;
      case TaskKind::Targets:
        result.passed =
          static_cast<std::size_t>(result.targets.touched) == task.targets.targets.size();
        break;
      case TaskKind::Trace:
        result.passed = result.trace.coverage >= task.trace.minCoverage &&
                        result.trace.offLine <= task.trace.maxOffLine;
        break;
    }
    allPassed = allPassed && result.passed;
  }
  score.passed = allPassed && score.damage.empty();
  return score;
}

} // namespace proxima::trainer
