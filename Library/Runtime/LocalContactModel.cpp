#include "Runtime/LocalContactModel.h"

#include <algorithm>

namespace proxima
{

Vec3 LocalContactModel::force(const HapticState& state, const Vec3& finger, double stiffness,
                              const Vec3& spring)
{
  // Only a press on tissue alone: a rigid object pressed beside it (a bone under the organ)
  // must hold at kp between the tissue's steps as at them.
  bool onTissue = false;
  for (int k = 0; k < state.numContacts; ++k)
  {
    if (state.contacts[k].depth > 0.0)
    {
      if (!state.contacts[k].deforms)
      {
        onTissue = false;
        break;
      }
      onTissue = true;
    }
  }
  const Vec3 stretch = state.proxy - finger;
  const double length = norm(stretch);
  if (!onTissue || !(stiffness > 0.0) || !(length > 0.0))
  {
    m_active = false;
    return spring;
  }
  m_springStiffness = stiffness;
  if (!m_active || state.surfaceChanges != m_surfaceChanges)
  {
    newReference(state, finger, stretch / length, stretch, spring);
    return spring;
  }
  if (!m_measured)
  {
    return spring;
  }
  // The spring's force at the reference tick, and the stretch's change since at the measured
  // stiffness: the contact, proxy pinned or sliding, one spring of the tissue's stiffness there.
  Vec3 shaped = m_referenceForce + (stretch - m_referenceStretch) * m_stiffness;
  const double along = dot(shaped, m_direction);
  if (along < 0.0)
  {
    shaped -= m_direction * along; // a contact pushes, never pulls
  }
  return shaped;
}

void LocalContactModel::newReference(const HapticState& state, const Vec3& finger,
                                     const Vec3& direction, const Vec3& stretch, const Vec3& spring)
{
  if (m_active)
  {
    // The contact went on through the step: how far the finger went in along the last
    // reference's force since it, and how much the spring's force along it changed over that.
    const double press = dot(m_referenceFinger - finger, m_direction);
    const double change = dot(spring - m_referenceForce, m_direction);
    m_forcePress = kForgetting * m_forcePress + change * press;
    m_pressPress = kForgetting * m_pressPress + press * press;
    if (m_pressPress > 0.0)
    {
      // Between 0 (the surface gives way as fast as the finger comes) and the spring's own
      // (a surface that did not move): the tissue in series with kp is never stiffer than kp.
      m_stiffness = std::clamp(m_forcePress / m_pressPress, 0.0, m_springStiffness);
      m_measured = true;
    }
  }
  m_active = true;
  m_surfaceChanges = state.surfaceChanges;
  m_direction = direction;
  m_referenceStretch = stretch;
  m_referenceFinger = finger;
  m_referenceForce = spring;
}

} // namespace proxima
