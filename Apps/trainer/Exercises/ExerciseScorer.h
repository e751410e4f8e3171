// Scores an exercise tick by tick (Documentation/SurgicalTrainer.md, "Scores"): fed every haptic
// state of a session, headless (a scripted path in lockstep) or live (the window's latest
// states), and the trainee's marks. The same rules either way:
//   - palpation: the last mark's contact point against the spot above the hidden inclusion (the
//     point of the object's surface nearest the stiffness region's centre);
//   - targets: each in order, touched when the contact point is within its radius with a force in
//     the band, held for the hold time;
//   - trace: the share of the line's length the contact passed within the tolerance, and the
//     share of contact ticks strayed further, between the first and the last covered stretch;
//   - damage: a run of ticks touching a tissue with a force above its limit is one event.
// The session's time, the finger's path length and the peak force go with them.
#pragma once

#include "Exercises/Exercise.h"
#include "IO/Scene/SceneDescription.h"
#include "Proxy/CollisionScene.h"
#include "Runtime/HapticState.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace proxima::trainer
{

struct DamageEvent
{
  std::uint32_t object = 0;
  std::string tissue;
  double startTime = 0.0;
  double duration = 0.0;
  double peakForce = 0.0;
  /// The contact point where the event began.
  Vec3 position;
};

struct PalpationScore
{
  Vec3 spot;
  int marks = 0;
  /// The last mark's contact point and its distance from the spot; none without a mark in contact.
  std::optional<Vec3> mark;
  double distance = 0.0;
};

struct TargetScore
{
  int touched = 0;
  /// When each touched target's hold was complete, in order.
  std::vector<double> touchedTimes;
  /// From the session's start to the last target's completion (or the end when incomplete).
  double seconds = 0.0;
  double fingerPathLength = 0.0;
  double peakForce = 0.0;
};

struct TraceScore
{
  double coverage = 0.0;
  double offLine = 0.0;
  /// The largest distance of the contact point from the line, over the ticks from the first on
  /// the line to the last (those offLine counts), or over every contact tick when none came
  /// within the tolerance.
  double maxDeviation = 0.0;
  /// A contact tick was scored (else the report's deviation is null: nothing was touched).
  bool touched = false;
  std::uint64_t contactTicks = 0;
};

struct TaskScore
{
  TaskKind kind = TaskKind::Palpation;
  bool passed = false;
  PalpationScore palpation;
  TargetScore targets;
  TraceScore trace;
};

struct ExerciseScore
{
  bool passed = false;
  double startTime = 0.0;
  double endTime = 0.0;
  std::uint64_t ticks = 0;
  std::uint64_t contactTicks = 0;
  double fingerPathLength = 0.0;
  double peakForce = 0.0;
  std::vector<DamageEvent> damage;
  std::vector<TaskScore> tasks;
};

class ExerciseScorer
{
public:
  /// Checks the exercise's references into `scene` (objects, stiffness regions, and tissue
  /// inclusions in `description`, what the scene was built from) and finds each palpation's spot;
  /// throws InputError naming the exercise file and the task when one does not exist.
  ExerciseScorer(const Exercise& exercise, const CollisionScene& scene,
                 const SceneDescription* description = nullptr);

  /// The next tick's state (in time order).
  void addTick(const HapticState& state);
  /// The trainee marks the spot touched at the last tick added (a key in the window, a time in
  /// --marks headless).
  void mark();

  /// The scores so far.
  ExerciseScore score() const;

private:
  struct TraceProgress
  {
    /// The line sampled at most half a tolerance apart, and which samples a contact came near.
    std::vector<Vec3> samples;
    std::vector<bool> covered;
    bool onLineSeen = false;
    /// Contact ticks, strayed ticks and the largest deviation since the first tick on the line,
    /// and their values at the last tick on the line (ticks after it do not count).
    std::uint64_t contactSinceFirst = 0;
    std::uint64_t strayedSinceFirst = 0;
    double maxDeviationSinceFirst = 0.0;
    std::uint64_t contactAtLast = 0;
    std::uint64_t strayedAtLast = 0;
    double maxDeviationAtLast = 0.0;
    /// The largest deviation of any contact tick, on the line or not.
    double maxDeviationAnyContact = 0.0;
  };

  void scoreTargets(const ExerciseTask& task, TaskScore& score, const HapticState& state,
                    double forceMagnitude, double& holdStart);
  void scoreTrace(const ExerciseTask& task, TaskScore& score, TraceProgress& progress,
                  const HapticState& state);
  /// A damage event opens when the force on a tissue rises above its limit and closes when it
  /// falls below kDamageReleaseFraction of the limit or the proxy leaves the tissue: a force that
  /// hovers at the limit (a press held there, a texture's ripple, a deforming tissue's steps)
  /// is one event, not one per crossing.
  void scoreDamage(const HapticState& state, double forceMagnitude);

  const Exercise m_exercise;
  ExerciseScore m_score;
  std::vector<double> m_holdStarts;
  std::vector<TraceProgress> m_traces;
  std::optional<HapticState> m_last;
  /// The open damage event's index in m_score.damage, or -1.
  long m_openDamage = -1;
  /// The fraction of a tissue's force limit below which an open damage event ends.
  static constexpr double kDamageReleaseFraction = 0.9;
};

} // namespace proxima::trainer
