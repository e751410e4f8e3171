// A training exercise (Documentation/SurgicalTrainer.md): the scene a trainee touches, the proxy
// and servo settings, the tissues with the force that damages them, and the tasks scored. Read
// from JSON by ExerciseFile, scored tick by tick by ExerciseScorer. Positions are metres in the
// scene's frame.
#pragma once

#include "Core/Vec3.h"

#include <string>
#include <vector>

namespace proxima::trainer
{

/// A touched object's name and the force above which touching it counts as damage.
struct ExerciseTissue
{
  std::uint32_t object = 0;
  std::string name;
  /// Newtons; a force above it while touching the object is a damage event.
  double forceLimit = 0.0;
};

/// Find the hidden inclusion and mark it: the inclusion is stiffness region `region` of object
/// `object`'s material in the scene (a nodule felt through a stiffness map), or, with
/// `tissueInclusion`, inclusion `region` of the object's tissue (a stiffer sphere of its elastic
/// solid, Documentation/Tissue.md); the spot to mark is the point of that object's surface at
/// rest nearest the inclusion's centre, and a mark passes within `passDistance`.
struct PalpationTask
{
  std::uint32_t object = 0;
  /// The stiffness region's index, or the tissue inclusion's with `tissueInclusion`.
  std::uint32_t region = 0;
  double passDistance = 0.0;
  /// True when `region` numbers the object's tissue inclusions (the file's "inclusion").
  bool tissueInclusion = false;
};

/// A spot on the surface: touched when the contact point is within `radius` of `center`.
struct ExerciseTarget
{
  std::string name;
  Vec3 center;
  double radius = 0.0;
};

/// Touch the targets in order, each with a force in [minForce, maxForce] held for holdSeconds.
struct TargetTask
{
  std::vector<ExerciseTarget> targets;
  double minForce = 0.0;
  double maxForce = 0.0;
  double holdSeconds = 0.0;
};

/// Follow a line drawn on the surface (a polyline through surface points) in contact: passes when
/// the contact came within `tolerance` of at least minCoverage of the line's length, and at most
/// maxOffLine of the contact ticks between its first and last covered stretch strayed further.
struct TraceTask
{
  std::vector<Vec3> line;
  double tolerance = 0.0;
  double minCoverage = 0.9;
  double maxOffLine = 0.1;
};

enum class TaskKind
{
  Palpation,
  Targets,
  Trace
};

struct ExerciseTask
{
  TaskKind kind = TaskKind::Palpation;
  PalpationTask palpation;
  TargetTask targets;
  TraceTask trace;
};

struct Exercise
{
  /// The exercise file as the caller named it.
  std::string path;
  int version = 1;
  std::string name;
  /// What the trainee is asked to do, shown before the exercise starts.
  std::string instructions;
  /// The scene file, resolved against the exercise file's folder.
  std::string scene;
  double radius = 0.002;
  double stiffness = 500.0;
  double rate = 1000.0;
  double maxForce = 10.0;
  std::vector<ExerciseTissue> tissues;
  std::vector<ExerciseTask> tasks;
};

} // namespace proxima::trainer
