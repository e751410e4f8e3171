// The update stage's goal (paper 2.2, eqs. 8-19): the point nearest the finger in the
// intersection of the half-spaces above the constraint planes, all of which pass through the
// proxy. Solved as the paper does, with Gilbert's algorithm in the dual space; the answer is
// then checked against every plane, and the rare case the dual misses (a plane the finger lies
// above that the slide would still cross, as in a groove narrower than 90 degrees) is solved
// exactly by enumerating active sets of at most three planes.
#pragma once

#include "Core/Vec3.h"

namespace proxima
{

/// The most constraint planes the update stage passes to the goal solver; the dual solver reads
/// no more than this many.
constexpr int kMaxConstraintPlanes = 32;

/// The goal of one update iteration: the step from the proxy to the point nearest the finger
/// above every constraint plane, and the planes that hold it there.
struct GoalSolution
{
  /// Goal minus proxy: the step the proxy should take (x of eq. 18).
  Vec3 displacement;
  /// Number of active planes, 0 to 3: the planes the goal lies on that push back on the finger.
  int numActive = 0;
  /// The active planes, as indices into the normals given; the first numActive are set.
  int active[3] = {0, 0, 0};
  /// For each active plane, the depth mu_i >= 0 (m) with finger - goal = -sum mu_i n_i; the force
  /// the user applies to plane i is -k mu_i n_i (eq. 19).
  double depth[3] = {0.0, 0.0, 0.0};
  /// True when the dual solution violated a plane and the exact enumeration answered instead.
  bool usedExactFallback = false;
};

/// `toFinger` is finger minus proxy; `normals` are unit normals pointing into free space.
GoalSolution solveGoal(const Vec3& toFinger, const Vec3* normals, int numPlanes);

/// The exact solver on its own (enumeration of active sets of up to three planes, checked for
/// feasibility and sign): the fallback of solveGoal.
GoalSolution solveGoalByEnumeration(const Vec3& toFinger, const Vec3* normals, int numPlanes);

} // namespace proxima
