// The virtual proxy of Ruspini and Khatib (paper section 2): each tick, move the proxy sphere
// toward its goal until the first contact, collect the constraint planes of every primitive
// within radius + epsilon, solve for the new goal in the dual space, and repeat until the proxy
// stops moving. No allocation, locks, exceptions, I/O or virtual calls inside update().
#pragma once

#include "Core/RigidTransform.h"
#include "Core/TickConditions.h"
#include "Geometry/ClosestPoint.h"
#include "Geometry/SphereTree.h"
#include "Proxy/CandidateCache.h"
#include "Proxy/CollisionScene.h"
#include "Proxy/DeformingObjects.h"
#include "Proxy/GoalSolver.h"
#include "Proxy/MoveRecord.h"
#include "Proxy/MovingObjects.h"
#include "Proxy/ProxyParameters.h"

#include <cstdint>
#include <vector>

namespace proxima
{

struct ProxyTickState;

/// One constraint plane at the proxy: its normal (into free space), the primitive that made it
/// and the contact weights of the nearest point on that primitive.
struct ContactPlane
{
  /// Unit normal from the primitive's nearest point toward the proxy's centre, in the scene's
  /// frame.
  Vec3 normal;
  /// Index of the object, in the scene's objects.
  std::uint32_t object = 0;
  /// Index of the triangle, in that object's mesh.
  std::uint32_t triangle = 0;
  /// The triangle's point nearest the proxy's centre (in the scene's frame) and its weights.
  ClosestPointResult closest;
  /// Penetration depth the spring has on this plane (mu of GoalSolution); force = k * depth.
  double depth = 0.0;
  /// The configuration-space surface here is a cylinder or sphere (the proxy touches an edge or
  /// corner off the normal of every triangle that gave this plane), not a flat face.
  bool curved = false;
  /// Force shading (paper 3.1): the point normals interpolated with the contact weights, turned
  /// to the proxy's side; used by the first pass of the update stage. Set when `shaded`.
  bool shaded = false;
  /// The shaded normal (unit, in the scene's frame); meaningful only when `shaded`.
  Vec3 shadedNormal;
  /// Texture (paper 4.3): true on a textured surface, where `texCoord` is set.
  bool textured = false;
  /// The texture coordinate at the contact, interpolated with the contact weights; meaningful
  /// only when `textured`.
  TexCoord texCoord;
  /// The factor stiffness maps put on the servo's kp at this contact (1 without them).
  double stiffnessScale = 1.0;
  /// The surface's static friction coefficient mu_s here (paper 4.1), texture maps applied; all
  /// three friction values are 0 on a surface without friction.
  double staticFriction = 0.0;
  /// The dynamic friction coefficient mu_d here (paper 4.2), texture maps applied.
  double dynamicFriction = 0.0;
  /// The viscosity b here (N s/m, paper 4.2), texture maps applied.
  double viscosity = 0.0;
};

/// What one ProxySolver::update() reports: where the proxy ended, the contacts the finger pushes
/// on, and what the tick met on the way.
struct ProxyTickResult
{
  /// The proxy's centre at the end of the tick (m), in the scene's frame.
  Vec3 proxy;
  /// Active constraint planes at the end of the tick (those the finger pushes on), at most 3.
  int numContacts = 0;
  /// The active constraint planes; the first numContacts are set.
  ContactPlane contacts[3];
  /// Move stages run this tick.
  int iterations = 0;
  /// The conditions the update met: of TickConditions, the solver sets budgetLimited,
  /// hitIterationCap, pushedByObject (a moving object, setObjectPose, pushed the proxy at the
  /// tick's start), fingerRefused (the finger was not finite: the tick was refused and the proxy
  /// held), startedOutside (the first update after resetProxyOutside), contactOverflow, stuck and
  /// frictionLimited.
  TickConditions conditions;
  /// Diagnostic, not a condition of the tick (the trace does not record it): the exact fallback
  /// answered the goal problem at least once.
  bool usedExactFallback = false;
  /// Diagnostic, as usedExactFallback: a shaded plane took part in an update stage (two passes,
  /// paper section 3).
  bool usedShading = false;
  /// The factor on the servo's stiffness from stiffness maps at the contacts, weighted by their
  /// depths (1 without contact or maps).
  double stiffnessScale = 1.0;
  /// Work counters of the tick's sphere-tree and candidate-cache queries, summed.
  QueryStats queries;
};

/// The virtual proxy of one haptic device over one collision scene: update() once per haptic
/// tick moves the proxy toward the finger. update() allocates nothing and takes no lock; the
/// setup calls that say so allocate. One thread at a time uses a solver.
class ProxySolver
{
public:
  /// The most triangles within reach of the proxy one gather of constraint planes keeps; more
  /// are reported as contactOverflow.
  static constexpr int kMaxNearbyTriangles = 256;
  /// The number of cached triangles the candidate cache's margin aims at (adaptCacheMargin).
  static constexpr int kCacheTriangles = 96;

  ProxySolver() = default;
  /// A copy is a replica of this solver's whole state (proxy, caches, planes): its next update
  /// runs exactly the update this one would run next, which is how a tick's work is replayed
  /// (Runtime/TickReplay.h). It shares the scene and the moving objects: on a scene with moving
  /// objects the two solvers move the same meshes, so replay only static scenes. Copying costs
  /// the solver's size (over a hundred kilobytes of fixed buffers) and allocates nothing.
  ProxySolver(const ProxySolver&) = default;
  /// Makes this solver a replica of another, as the copy constructor does.
  ProxySolver& operator=(const ProxySolver&) = default;

  /// Uses `scene` (not owned; must outlive its use here) with `parameters`. The proxy stays where
  /// it was (at the origin for a new solver): place it with resetProxy, or with placeProxyStart
  /// (ProxyStart.h), which moves a start inside a closed object out of it; HapticSession
  /// (Runtime/HapticSession.h) does that at the first finger it is given.
  void setScene(const CollisionScene* scene, const ProxyParameters& parameters);
  /// Changes only the work budget (ProxyParameters::tickBudget*), keeping the proxy and its
  /// caches: a replica given no budget ends a budget-limited tick where it would have settled.
  void setTickBudget(int iterations, double seconds)
  {
    m_parameters.tickBudgetIterations = iterations > 0 ? iterations : 0;
    m_parameters.tickBudgetSeconds = seconds > 0.0 ? seconds : 0.0;
  }
  /// The parameters setScene() was given, with the budget of any later setTickBudget().
  const ProxyParameters& parameters() const { return m_parameters; }
  /// The scene setScene gave (null before any).
  const CollisionScene* scene() const { return m_scene; }
  /// Places the proxy without moving through the scene (start of a run, or a teleport).
  void resetProxy(const Vec3& position)
  {
    m_proxy = position;
    m_lastTravel = 0.0;
    m_cache.invalidate();
    m_planesValid = false;
    m_startedOutsidePending = false;
  }
  /// Places the proxy like resetProxy, at a start moved out of the closed object that holds the
  /// finger (ProxyStart.h); the next update reports startedOutside.
  void resetProxyOutside(const Vec3& position)
  {
    resetProxy(position);
    m_startedOutsidePending = true;
  }

  /// Lets the listed objects of the scene move (paper section 6: bodies and mechanisms). Each gets
  /// a copy of its mesh that setObjectPose moves; its sphere tree stays in the frame the object
  /// was placed in, and queries reach it through the pose, so nothing is rebuilt when it moves.
  /// A scene with moving objects answers every query from the trees (no candidate cache, whose
  /// triangles would move under it). Allocates: call after setScene, off the haptic thread. Every
  /// pose starts as the identity (the object where it was placed). An empty list: a static scene.
  void setMovingObjects(const std::vector<std::uint32_t>& objects);
  /// The same with a set made elsewhere (makeMovingObjects on this solver's scene; not owned,
  /// must outlive its use here, null for none): allocates and frees nothing, so a threaded
  /// runner may hand over a set built off the haptic thread with the scene it belongs to.
  void useMovingObjects(MovingObjectSet* objects);
  /// Where moving object `object` now is, relative to where it was placed. The next update first
  /// lets it push the proxy: the proxy is swept, in the object's frame, along its motion relative
  /// to the object since the last pose, and carried with the object from its first contact; then
  /// the tick runs as usual against the object where it now is. Costs O(the object's points) per
  /// pose that changed. Allocates nothing.
  void setObjectPose(std::uint32_t object, const RigidTransform& pose);
  /// The pose setObjectPose gave (the identity for any other object).
  const RigidTransform& objectPose(std::uint32_t object) const;
  /// True when the solver uses a non-empty set of moving objects.
  bool hasMovingObjects() const { return m_moving != nullptr && !m_moving->entries.empty(); }
  /// Object `object`'s mesh where it is now: the moved copy of a moving object, the current copy
  /// of a deforming one, or the scene's.
  const TriangleMesh& placedMesh(std::uint32_t object) const
  {
    const int moving = m_moving != nullptr ? m_moving->indexOf(object) : -1;
    if (moving >= 0)
    {
      return m_moving->entries[static_cast<std::size_t>(moving)].mesh;
    }
    return queryObject(object).mesh;
  }

  /// Lets the listed objects deform (issue 35: tissue). Each gets its own copy (mesh, a sphere
  /// tree of one sphere per triangle, filter records) that setObjectPoints moves and refits; the
  /// scene's object is never changed. A scene with deforming objects answers every query from
  /// the trees (no candidate cache). An object should not also be moving. Allocates: call after
  /// setScene, off the haptic thread. An empty list: nothing deforms.
  void setDeformingObjects(const std::vector<std::uint32_t>& objects);
  /// The same with a set made elsewhere (makeDeformingObjects on this solver's scene; null or
  /// empty for none). Allocates nothing, and frees nothing while its maker keeps a reference
  /// (the solver lets go of its own at the next setScene), so a threaded runner may hand over a
  /// set built off the haptic thread with the scene it belongs to.
  void useDeformingObjects(std::shared_ptr<DeformingObjectSet> objects);
  /// Gives deforming object `object` its `count` points (as many as its mesh has, all finite,
  /// in the scene's frame) where a simulation step left them. The next update first moves the
  /// object there: the surface point the proxy rests on carries the proxy along its contact
  /// normal as far as that point comes toward it, the tree is refit, and a proxy the new surface
  /// still overlaps is pushed out along its nearest point's normal (at most
  /// kMaxDeformationPushes times); then the tick runs as usual against the new surface. Returns
  /// false and changes nothing for an object that does not deform or another count. Copies the
  /// points; allocates nothing.
  bool setObjectPoints(std::uint32_t object, const Vec3* points, std::size_t count);
  /// How many times, at most, a tick's start pushes the proxy out of a deformed surface it
  /// overlaps, each time to its nearest point's normal at the radius plus half the skin.
  static constexpr int kMaxDeformationPushes = 8;
  /// True when the solver has a non-empty set of deforming objects.
  bool hasDeformingObjects() const
  {
    return m_deforming != nullptr && !m_deforming->entries.empty();
  }
  /// How many updates have moved deforming objects to new points (setObjectPoints): a counter
  /// that tells the servo a tissue's surface has just changed.
  std::uint64_t surfaceChanges() const { return m_surfaceChanges; }
  /// True when scene object `object` is one of the deforming objects.
  bool isDeforming(std::uint32_t object) const
  {
    return m_deforming != nullptr && m_deforming->indexOf(object) >= 0;
  }
  /// The collision object the queries use for scene object `object`: a deforming object's current
  /// copy, or the scene's.
  const CollisionObject& queryObject(std::uint32_t object) const
  {
    const int deforming = m_deforming != nullptr ? m_deforming->indexOf(object) : -1;
    return deforming < 0 ? m_scene->objects[object]
                         : m_deforming->entries[static_cast<std::size_t>(deforming)].current;
  }

  /// One tick: moves the proxy as far toward `finger` as the constraints allow. A finger farther
  /// than reachRadius() from the scene's centre is sought at that distance, in its direction.
  ProxyTickResult update(const Vec3& finger);

  /// How far from the centre of the scene's bounding box the proxy may go: kReachFactor times
  /// (largest absolute coordinate + max(diagonal, radius)). Out there the rounding of a position
  /// is a sixteenth of the skin (resolveSkin: at least 256 units in the last place of that sum);
  /// beyond it a move back to the scene cannot place the proxy within its skin, and a finger
  /// 1e200 m away made the swept-sphere quadratic overflow and the proxy pass through a sphere
  /// (stress suite, StressFingerInput.AbsurdlyFarFiniteFingers). 0 without a scene.
  static constexpr double kReachFactor = 16.0;
  /// How far the proxy may go from reachCenter() (m), as kReachFactor sets it; 0 without a scene
  /// or objects.
  double reachRadius() const { return m_reachRadius; }
  /// The centre of the scene's bounding box, where reachRadius() is measured from; meaningful
  /// only while reachRadius() is above 0.
  const Vec3& reachCenter() const { return m_reachCenter; }

  /// Records the chain of segments each update moves the proxy along into `record` (not owned;
  /// null to stop): a debug mode for oracles, which check every segment and the approach at its
  /// accepted points. A copy of the solver records into the same record.
  void recordMoves(MoveRecord* record) { m_moveRecord = record; }

  /// The proxy's centre (m), in the scene's frame.
  const Vec3& proxy() const { return m_proxy; }
  /// The proxy sphere's radius (m), from the parameters.
  double radius() const { return m_parameters.radius; }
  /// The contact skin in use (m): the parameters' skin, or the one resolveSkin() chose.
  double skin() const { return m_skin; }
  /// Primitives within radius + contactEpsilon() of the proxy give constraint planes.
  double contactEpsilon() const { return 2.0 * m_skin; }
  /// Primitives within radius + nearBand() of the proxy, beyond contactEpsilon(), are held in
  /// reserve: one whose plane the goal would cross becomes a constraint plane before the move
  /// (promoteNearPlanes). 0.8 of the contact gap DESIGN.md allows (max(1e-9 m, 1e-9 x the scene
  /// diagonal)), and at least contactEpsilon(); a scene with deforming objects keeps no reserve.
  double nearBand() const { return m_nearBand; }

private:
  // The steps of one tick (update()), in the order the loop takes them; the state they share
  // is in ProxyTickState.h.
  /// Update stage (2.2): the planes at the proxy, the (shaded) target, the goal, friction's cut.
  void updateStage(ProxyTickState& tick, ProxyTickResult& result);
  /// Static friction holds the goal at the proxy; dynamic and viscous friction shorten it.
  void applyFriction(ProxyTickState& tick, ProxyTickResult& result) const;
  /// Stop rule: the goal is within the step tolerance of the proxy.
  bool atLocalMinimum(const ProxyTickState& tick) const;
  /// The goal's displacement, stretched by the curvature correction while its trust region
  /// allows.
  Vec3 nextStep(const ProxyTickState& tick) const;
  /// Stop rules on work: the iteration cap, then the tick's budget (flagged in `result`).
  bool outOfWork(const ProxyTickState& tick, ProxyTickResult& result) const;
  /// Move stage (2.1): sweeps toward `goal` and stops at the first contact. Returns how far the
  /// proxy was from the target before the move.
  double moveStage(ProxyTickState& tick, const Vec3& goal, ProxyTickResult& result);
  /// After a move: accepts the proxy's position if it is no farther from the target than the last
  /// accepted point, or else adds it to the trial chain (TrialChain, ProxyTickState.h); a full
  /// chain is walked back at once. Returns true when it walked back.
  bool judgeMove(ProxyTickState& tick);
  /// At a stop with trials pending (the proxy farther from the target than the last accepted
  /// point): walks back along the trials' segments to that point, forbids stretching for the rest
  /// of the tick and returns true; with none pending, false.
  bool retracedTrials(ProxyTickState& tick);
  /// The planes at the proxy and the goal there, for a tick that ends where it is.
  void solveAtProxy(ProxyTickState& tick, ProxyTickResult& result);
  /// Stop rule: the proxy reached a target that no longer moves.
  bool reachedTarget(ProxyTickState& tick, const ProxyTickResult& result) const;
  /// Stop rule: NoProgress, counted for a move that ended `toTarget` from the target after
  /// starting `distanceBefore` from it; on stopping, solves the goal at the proxy once more.
  bool stopsWithoutProgress(ProxyTickState& tick, double toTarget, double distanceBefore,
                            ProxyTickResult& result);
  /// Reports the proxy and the contacts the finger pushes on.
  void finishTick(ProxyTickState& tick, ProxyTickResult& result);
  /// gatherPlanes at `position`, an overflow flagged in `result`.
  void gatherPlanesInto(const Vec3& position, ProxyTickResult& result);

  struct SweepOutcome
  {
    bool hit = false;
    double t = 1.0;
  };
  SweepOutcome sweep(const Vec3& from, const Vec3& to, QueryStats& stats);
  /// Fills m_planes with the deduplicated constraint planes at `position`; false on overflow.
  /// Reuses the last planes when `position` is where they were gathered.
  bool gatherPlanes(const Vec3& position, QueryStats& stats);
  /// gatherPlanes without the reuse.
  bool collectPlanes(const Vec3& position, QueryStats& stats);
  /// Makes a constraint plane of m_nearby[i] at `position` unless one with the same normal is
  /// there; false when the planes are full.
  bool addPlane(const Vec3& position, std::uint32_t i);
  /// The triangles held in reserve (nearBand()) whose planes the goal crosses, nearest crossing
  /// first, become constraint planes and the goal is solved again, until the goal crosses none.
  void promoteNearPlanes(ProxyTickState& tick, ProxyTickResult& result);
  /// True if the object's planes get no surface effects (shading, texture, friction).
  bool plainSurface(std::uint32_t objectIndex) const;
  /// Gives a gathered plane its surface effects (shading, friction, texture) and its first-pass
  /// normals; `alone`: no other triangle gave the same plane. False if the buffers overflowed.
  bool dressPlane(ContactPlane& plane, bool alone);
  /// True if another triangle within reach (of the first `numNearby` gathered) has the plane's
  /// touched edge or corner: then it is no rim of an open sheet.
  bool sharesTouchedFeature(const ContactPlane& plane, std::uint32_t numNearby) const;
  /// The shaded normal at the rim of an open sheet (paper Fig. 7).
  Vec3 tiltedRimNormal(const TriangleMesh& mesh, const ContactPlane& plane) const;
  /// The first pass of section 3 on the gathered planes: the subgoal (minus the proxy) of the
  /// shaded and bumped planes, projected onto the nearest true plane when above them all.
  Vec3 shadedSubgoal(const Vec3& toFinger) const;
  /// True if the finger lies inside the static friction cone of a plane at the proxy (4.1).
  bool insideStaticCone(const Vec3& toFinger) const;
  /// The slide `solution` may make under dynamic and viscous friction (4.2, eq. 21): its length
  /// cut to leave the finger on the dynamic cone, and to the viscous travel left in the tick
  /// (`viscousBudget`, negative until the tick's first viscous contact sets it).
  double frictionLimitedTravel(const GoalSolution& solution, double travel,
                               double& viscousBudget) const;
  /// The update stage's step, with the slide over an edge or corner stretched by the curvature of
  /// its configuration-space surface (a Newton step; CurvatureStretch.cpp).
  /// The stretched step is kept only if it stays above every plane, as the planar one does.
  Vec3 curvatureCorrectedStep(const GoalSolution& solution, const Vec3& toFinger,
                              double creaseStretchLimit) const;
  /// The stretched slide of curvatureCorrectedStep before that check.
  Vec3 stretchedSlide(const GoalSolution& solution, const Vec3& toFinger,
                      double creaseStretchLimit) const;
  /// stretchedSlide for two active planes: the Newton step along their crease, at most
  /// `stretchLimit` times the planar slide.
  Vec3 stretchedCreaseSlide(const GoalSolution& solution, double stretchLimit) const;
  /// The curvature of a plane's configuration-space surface along a unit tangent `direction`:
  /// 0 on a face, 1 / rho on a corner's sphere, across an edge's cylinder (1 - cos^2) / rho.
  double curvatureAlong(const ContactPlane& plane, const Vec3& direction) const;
  /// `finger`, or the point at reachRadius() from reachCenter() in its direction if farther.
  Vec3 withinReach(const Vec3& finger) const;
  /// Re-centres the candidate cache on the proxy when it has wandered off, at a tick's start.
  void refreshCache(QueryStats& stats);
  /// Within a tick: re-centres the candidate cache on a proxy that a move took into contact far
  /// from the cached centre.
  void followInCache(QueryStats& stats);
  /// Rebuilds the candidate cache around the proxy, with a smaller margin if the ball is too
  /// crowded for it.
  void rebuildCache(QueryStats& stats);
  /// Puts the first `count` triangles of m_nearby (and their objects) in the order of object,
  /// then triangle.
  void sortNearby(std::uint32_t count);
  /// After a rebuild with `margin` that cached `numCached` triangles: the next rebuild's margin.
  void adaptCacheMargin(double margin, int numCached);
  /// Whether temporal coherence is on and the candidate cache is invalid or the proxy beyond
  /// half its margin of its centre.
  bool cacheNeedsRebuild() const;

  /// At a tick's start: moves each moving object whose pose changed, letting it push the proxy.
  void followMovingObjects(ProxyTickResult& result);
  /// At a tick's start: moves each deforming object that was given new points, letting its
  /// surface carry and push the proxy (setObjectPoints). Returns whether anything moved.
  bool followDeformingObjects(ProxyTickResult& result);
  /// The pose a query in the world reaches object `object`'s tree through, or null for a static
  /// object.
  const RigidTransform* treePose(std::uint32_t object) const
  {
    const int moving = m_moving != nullptr ? m_moving->indexOf(object) : -1;
    return moving < 0 ? nullptr : &m_moving->entries[static_cast<std::size_t>(moving)].applied;
  }

  const CollisionScene* m_scene = nullptr;
  ProxyParameters m_parameters;
  /// The moving objects in use (null: a static scene), and the set setMovingObjects made (shared
  /// with copies, so that a copy's m_moving never dangles).
  MovingObjectSet* m_moving = nullptr;
  std::shared_ptr<MovingObjectSet> m_ownedMoving;
  /// The deforming objects (null: none), shared with copies like the moving objects.
  std::shared_ptr<DeformingObjectSet> m_deforming;
  std::uint64_t m_surfaceChanges = 0;
  double m_skin = 0.0;
  Vec3 m_proxy;
  SphereTreeScratch m_scratch;
  CandidateCache m_cache;
  double m_coherenceMargin = 0.0;
  /// The margin of the next cache rebuild (adaptCacheMargin), at most m_coherenceMargin.
  double m_cacheMargin = 0.0;
  /// A shaded target that moves less than this between update stages is settled.
  double m_shadingTolerance = 1e-9;
  double m_lastTravel = 0.0;
  Vec3 m_reachCenter;
  double m_reachRadius = 0.0;
  NearbyTriangle m_nearby[kMaxNearbyTriangles];
  std::uint32_t m_nearbyObject[kMaxNearbyTriangles];
  /// Scratch of sortNearby.
  NearbyTriangle m_sortedNearby[kMaxNearbyTriangles];
  ContactPlane m_planes[kMaxConstraintPlanes];
  Vec3 m_normals[kMaxConstraintPlanes];
  /// The first pass's planes: shaded (and bumped, one per bump map) where the surface is, true
  /// elsewhere.
  Vec3 m_firstPassNormals[kMaxConstraintPlanes];
  int m_numFirstPass = 0;
  int m_numPlanes = 0;
  /// Gathered triangles (indices into m_nearby) beyond contactEpsilon() but within nearBand(),
  /// not yet promoted.
  std::uint16_t m_reserve[kMaxNearbyTriangles];
  int m_numReserve = 0;
  /// How many of m_nearby the last gather filled.
  std::uint32_t m_numNearby = 0;
  double m_nearBand = 0.0;
  bool m_anyShaded = false;
  bool m_anyFriction = false;
  bool m_planesValid = false;
  bool m_startedOutsidePending = false;
  bool m_planesComplete = true;
  Vec3 m_planesPosition;
  MoveRecord* m_moveRecord = nullptr;
};

} // namespace proxima
