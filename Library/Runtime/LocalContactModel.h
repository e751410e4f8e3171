// The servo's local model of a contact on deforming tissue (issue 35, item 3; Cavusoglu and
// Tendick 2000, Mark et al. 1996). A tissue's solid steps every few servo ticks; between steps its
// surface stands still, so the spring kp (proxy - finger) alone rises at kp per metre of press
// and falls back when the next step lets the surface give way: a sawtooth at the step's rate
// (200 Hz, a quarter of the force on the kidney pressed at 3 cm/s), which the hand feels as a
// buzz. Between steps the servo instead renders the spring's force at the step's first tick plus
// the local stiffness times the stretch's change since: the stiffness the contact has shown over
// the last steps, the secant of the spring's force at each step's first tick against how far the
// finger went in since the step before, both along the force (kp in series with the tissue's own
// stiffness there), fitted by least squares that forget half their weight a step.
//
// At each step's first tick the force is the spring's, exactly; between steps it is a spring
// about a fixed point, so no interval gives the hand energy of its own. The solid is loaded as
// before (TissueDynamics: the spring's press), so the surface and the proxy are unchanged. A
// press that also touches a rigid object is the spring's alone: the rigid side must not soften.
#pragma once

#include "Core/Vec3.h"
#include "Runtime/HapticState.h"

#include <cstdint>

namespace proxima
{

/// One servo loop's local contact model. Plain values; for one thread; allocation-free.
class LocalContactModel
{
public:
  /// The force on the finger at `finger` for a tick whose proxy half is `state`, given the
  /// spring's stiffness `stiffness` (kp times the contacts' scale) and its force `spring`
  /// (stiffness (proxy - finger)). Without a press on deforming objects alone, or at the first
  /// tick on a surface the tissue's step has just moved (state.surfaceChanges new), it is
  /// `spring`. Otherwise it is the spring's force at that first tick plus the measured stiffness
  /// times the stretch (proxy - finger) gained since, never pulling against that tick's force.
  Vec3 force(const HapticState& state, const Vec3& finger, double stiffness, const Vec3& spring);
  /// The stiffness rendered between steps (N/m): kp until two steps of one contact measured it.
  double stiffness() const { return m_measured ? m_stiffness : m_springStiffness; }
  /// True while a contact on a deforming object is modelled.
  bool active() const { return m_active; }
  /// Forgets the contact and the measured stiffness (a new scene).
  void reset() { *this = LocalContactModel{}; }

  /// The share of its weight the stiffness fit keeps from one step to the next.
  static constexpr double kForgetting = 0.5;

private:
  /// Takes this tick as the reference of a new surface, and measures the stiffness against the
  /// last reference when the contact went on through it.
  void newReference(const HapticState& state, const Vec3& finger, const Vec3& direction,
                    const Vec3& stretch, const Vec3& spring);

  bool m_active = false;
  std::uint64_t m_surfaceChanges = 0;
  /// The reference tick's spring force's direction, its stretch (proxy - finger, m), its finger
  /// and its force (N).
  Vec3 m_direction;
  Vec3 m_referenceStretch;
  Vec3 m_referenceFinger;
  Vec3 m_referenceForce;
  /// The stiffness fit's sums: force change times press, press squared, each forgetting.
  double m_forcePress = 0.0;
  double m_pressPress = 0.0;
  double m_stiffness = 0.0;
  double m_springStiffness = 0.0;
  bool m_measured = false;
};

} // namespace proxima
