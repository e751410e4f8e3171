// A tissue touched by the proxy, on whichever thread runs the proxy: the force the proxy's spring presses a deforming
// object with goes to the corners of the triangles it touches, the elastic solid steps under it
// at its own rate, and the proxy solver is given the surface where the step left it (issue 35,
// item 3). The surface is the solid's boundary over the solid's own points (boundarySoup), so
// the solid's positions are the object's points as they are.
#pragma once

#include "Core/Vec3.h"
#include "Proxy/CollisionScene.h"
#include "Proxy/ProxySolver.h"
#include "Tissue/ElasticSolid.h"

#include <cstdint>
#include <memory>
#include <vector>

namespace proxima
{
/// Couples an ElasticSolid to scene object `object` of a ProxySolver, which this makes deforming
/// (ProxySolver::setDeformingObjects). Per proxy tick, addTick(); per simulation step, step().
/// Neither allocates after construction. Made in two halves where a runner needs them apart:
/// the construction from the scene allocates every buffer (any thread), and bind() couples it to
/// the solver on the solver's own thread without allocating (ThreadedRuntime, at a scene's
/// install).
class TissueContact
{
public:
  /// In one go, for a runner that owns `solver`: `object`'s mesh must have the solid's points, in
  /// order (a scene object built from boundarySoup(solid.rest())); it is made deforming unless it
  /// already is (setDeformingObjects with every tissue of the scene first, for a scene of
  /// several); `stiffness` is the spring's kp (N/m), the one the servo renders the proxy's force
  /// with. Throws std::invalid_argument when the counts differ.
  TissueContact(ElasticSolid& solid, ProxySolver& solver, std::uint32_t object, double stiffness);
  /// The first half, unbound: allocates every buffer and checks `object` of `scene` as above
  /// (also that it is in the scene). bind() before the first addTick, addPress or step.
  TissueContact(ElasticSolid& solid, const CollisionScene& scene, std::uint32_t object,
                double stiffness);
  /// The second half: couples to `solver`, which has the scene this was made for and `object`
  /// among its deforming objects (useDeformingObjects); false, and still unbound, when it has
  /// not. Allocates nothing.
  bool bind(ProxySolver& solver);
  /// True once bound to a solver.
  bool bound() const { return m_solver != nullptr; }

  /// After a proxy tick: the force the spring presses the object with, the sum of kp mu_i along
  /// -n_i over its contact planes (eq. 19, with each plane's stiffness scale), is spread over the
  /// proxy's footprint and added to the sum for the next step. The footprint is every triangle of
  /// the object within kFootprintGap radii of the proxy's surface, each weighted by how close it
  /// comes (1 at the surface, 0 at the gap), its share applied at its point nearest the proxy by
  /// that point's weights. A soft surface wraps around a pressing sphere; loaded at the one or
  /// two points the proxy's planes touch, a block's surface was dented into a pit whose sides the
  /// proxy then pressed in turn, flipping from one to the other every step.
  void addTick(const ProxyTickResult& result);
  /// The same for a tick seen from outside the solver: the proxy at `proxy` presses the object
  /// with `force` (N) through a spring of `stiffness` (N/m, kp times the contacts' stiffness
  /// scale); a stiffness of 0 is a tick without contact on the object.
  void addPress(const Vec3& proxy, const Vec3& force, double stiffness);
  /// How far beyond the proxy's radius, as a fraction of it, the footprint reaches by default.
  static constexpr double kFootprintGap = 0.25;
  /// Sets how far the footprint reaches beyond the proxy's radius, as a fraction of it (above 0).
  void setFootprintGap(double fraction) { m_footprintGap = fraction; }
  /// How far the footprint reaches beyond the proxy's radius, as a fraction of it.
  double footprintGap() const { return m_footprintGap; }
  /// Sets how much of each step's load is this step's footprint: 1 (the default) loads the
  /// solid as the ticks since the last step pressed it; below 1, the rest keeps the shape of the
  /// last step's load, scaled to this step's total, so that the total is the press's and only
  /// how it is spread lags. A narrow footprint on a fine mesh then settles where it chattered:
  /// the triangles a step moves out of the footprint lose their load over a few steps, not at
  /// once (Documentation/Tissue.md, "Hertz's law"). A fraction outside (0, 1] is ignored.
  void setLoadRelaxation(double fraction)
  {
    if (fraction > 0.0 && fraction <= 1.0)
    {
      m_relaxation = fraction;
    }
  }
  /// How much of each step's load is this step's footprint (setLoadRelaxation).
  double loadRelaxation() const { return m_relaxation; }
  /// The most triangles a footprint spreads the force over (the nearest first).
  static constexpr std::uint32_t kMaxFootprint = 512;
  static_assert(3 * kMaxFootprint <= kMaxContactSprings,
                "a spring per axis per footprint triangle");
  /// One step of the solid under the mean of the forces added since the last step, then the
  /// solver is given the new positions (ProxySolver::setObjectPoints). The force is the proxy's
  /// sampled at the servo rate and held over the slower step, and the last tick's contacts press
  /// on as springs of stiffness kp along their normals, taken implicitly by the step
  /// (ElasticSolid::setContactSprings): as the surface gives way under the proxy the spring's
  /// force falls within the step, as the hand's would. Held explicitly alone, a 1000 N/m spring
  /// on a 5 kPa block threw its surface centimetres a step and the block gained energy. Without
  /// contact at the last tick, the footprint's triangles moving toward the proxy are held along
  /// the direction to it the same way, from where they are, so that a surface springing back
  /// does not rise into the proxy unheld.
  void step();
  /// The first half of step(), for a solid that steps on another thread (TissueDynamics): gives
  /// the solid the press summed since the last step and the springs, as step() does. Then the
  /// solid steps, on any thread. Allocates nothing; the solid must not be stepping.
  void loadStep();
  /// Before the solver is given the points of a step that finished on another thread, while it
  /// still has the surface before them: the ticks since the last loadStep() pressed that older
  /// surface, which the solid has since moved on from. Each of the last tick's springs is
  /// anchored where they pressed it, so the press those ticks summed is corrected by the
  /// spring's change over the solid's move, as the proxy would have pressed had it seen the new
  /// surface: a surface that already gave way is not pushed again for it. Nothing when no tick
  /// pressed since loadStep() (lockstep hands over at once). Allocates nothing; the solid must
  /// not be stepping.
  void beforeSurfaceHandOver();
  /// The last half of step(): gives the solver the solid's points. Allocates nothing; the solid
  /// must not be stepping.
  void handOverSurface();

  /// The force the last step applied to the solid, summed over its vertices (N).
  const Vec3& lastForce() const { return m_lastForce; }
  /// The largest distance of any vertex from where it rests (m).
  double maxDisplacement() const;

private:
  ElasticSolid& m_solid;
  ProxySolver* m_solver = nullptr;
  std::uint32_t m_object;
  double m_stiffness;
  double m_footprintGap = kFootprintGap;
  double m_relaxation = 1.0;
  /// Per vertex, the force the last step applied, and the vertices it applied one to.
  std::vector<Vec3> m_applied;
  std::vector<std::uint32_t> m_appliedTo;
  /// Per vertex, the force summed over the ticks since the last step.
  std::vector<Vec3> m_forceSum;
  /// The vertices with a force in m_forceSum (each once), to clear them after a step.
  std::vector<std::uint32_t> m_loaded;
  std::vector<char> m_isLoaded;
  int m_ticks = 0;
  Vec3 m_lastForce;
  /// The last tick's footprint, as springs for the next step.
  std::vector<ContactSpring> m_springs = std::vector<ContactSpring>(kMaxContactSprings);
  int m_numSprings = 0;
  /// Without contact, the triangles near the proxy, each along the direction to it: those moving
  /// toward it become springs of the next step.
  std::vector<ContactSpring> m_approaching = std::vector<ContactSpring>(kMaxContactSprings);
  int m_numApproaching = 0;
  /// Loads the solid with the mean press of the ticks since the last step (`share` is one over
  /// their number) blended with the last step's load (setLoadRelaxation), and clears the sums.
  void applyRelaxedLoad(double share);
  /// Fills m_approaching from the first `count` entries of m_footprint (sorted), whose weights
  /// sum to `total`.
  void noteApproach(const Vec3& proxy, std::uint32_t count, double total);
  /// A footprint triangle's weight, from its nearest point's distance to the proxy's centre: 1 at
  /// the proxy's surface, 0 at kFootprintGap radii beyond it.
  double footprintWeight(double distanceToCentre) const;
  /// Sorts the first `count` entries of m_footprint nearest first and returns their weights' sum.
  double sortFootprint(std::uint32_t count);
  /// The footprint's triangles, and the scratch of the query that finds them.
  std::vector<NearbyTriangle> m_footprint;
  std::unique_ptr<SphereTreeScratch> m_scratch;
};
} // namespace proxima
