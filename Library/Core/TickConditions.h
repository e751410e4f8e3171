// The conditions of one haptic tick, defined once: the proxy solver sets the ones its update met
// (Proxy/ProxySolver.h: ProxyTickResult), the runtime passes them on and adds the force stage's
// (Runtime/HapticState.h), and the trace, the network messages and Python carry the same bits.
// A plain 32-bit value: copying it is copying an integer, so a state holding it stays trivially
// copyable between threads.
#pragma once

#include <cstdint>

namespace proxima
{

/// One condition of a tick. The values are the bits of trace v2's `flags` column
/// (Documentation/CommandLine.md) and of the network messages' `flags`: they are part of the file
/// and wire formats, so new conditions take new bits and no value ever changes.
enum class TickCondition : std::uint32_t
{
  /// The tick's work budget stopped the proxy before it settled: feasible, but not yet at the
  /// constrained minimum; the next tick goes on from there.
  budgetLimited = 1u << 0,
  /// The iteration cap ended the tick before the proxy stopped moving.
  hitIterationCap = 1u << 1,
  /// The force was clamped to the maximum force.
  forceClamped = 1u << 2,
  /// The force was fading: out after the device was lost or the proxy loop stalled, or back in
  /// after either.
  forceFading = 1u << 3,
  /// The device reported itself disconnected.
  deviceLost = 1u << 4,
  /// The sample held no usable finger (invalid, device lost, or not finite): the proxy held.
  fingerRefused = 1u << 5,
  /// Static friction held the proxy where the tick began: the finger was inside a contact's
  /// friction cone.
  stuck = 1u << 6,
  /// Dynamic or viscous friction shortened the proxy's slide.
  frictionLimited = 1u << 7,
  /// More primitives were within reach than the solver's fixed buffers hold (planes dropped).
  contactOverflow = 1u << 8,
  /// The force's rate of change was limited (after a scene change or a start outside).
  forceRateLimited = 1u << 9,
  /// The proxy began the tick at a start moved out of the closed object that held the finger.
  startedOutside = 1u << 10,
  /// A moving object came into the proxy at the tick's start and pushed it along.
  pushedByObject = 1u << 11,
  /// The proxy met a deforming object's surface a step older than lockstep gives it: the solid's
  /// step launched at the last step tick, on its own thread, had not finished (real-time runners
  /// only; Documentation/Tissue.md, "On the real clock").
  surfaceLagging = 1u << 12,
};

/// The set of conditions a tick met, as the bitmask of their TickCondition values.
class TickConditions
{
public:
  constexpr TickConditions() = default;
  /// The conditions whose bits are set in `bits` (a trace row's or a message's flags).
  constexpr explicit TickConditions(std::uint32_t bits)
    : m_bits(bits)
  {}
  /// The set holding `condition` alone (implicit, so a single condition passes as a set).
  constexpr TickConditions(TickCondition condition)
    : m_bits(static_cast<std::uint32_t>(condition))
  {}

  /// The bitmask: trace v2's `flags` value.
  constexpr std::uint32_t bits() const { return m_bits; }
  /// True when `condition` is set.
  constexpr bool has(TickCondition condition) const
  {
    return (m_bits & static_cast<std::uint32_t>(condition)) != 0;
  }
  /// True when any condition of `conditions` is set.
  constexpr bool hasAny(TickConditions conditions) const
  {
    return (m_bits & conditions.m_bits) != 0;
  }
  /// True when no condition is set.
  constexpr bool none() const { return m_bits == 0; }
  /// Sets `condition` when `met`, clears it otherwise.
  constexpr void set(TickCondition condition, bool met = true)
  {
    const auto bit = static_cast<std::uint32_t>(condition);
    m_bits = met ? (m_bits | bit) : (m_bits & ~bit);
  }
  /// Clears `condition`.
  constexpr void clear(TickCondition condition) { set(condition, false); }
  /// These conditions without any of `conditions`.
  constexpr TickConditions without(TickConditions conditions) const
  {
    return TickConditions(m_bits & ~conditions.m_bits);
  }

  /// Adds the conditions of `other`.
  constexpr TickConditions& operator|=(TickConditions other)
  {
    m_bits |= other.m_bits;
    return *this;
  }
  /// The conditions of `a` and of `b`.
  friend constexpr TickConditions operator|(TickConditions a, TickConditions b)
  {
    return TickConditions(a.m_bits | b.m_bits);
  }
  /// True when `a` and `b` hold the same conditions.
  friend constexpr bool operator==(TickConditions a, TickConditions b)
  {
    return a.m_bits == b.m_bits;
  }
  /// True when `a` and `b` differ in any condition.
  friend constexpr bool operator!=(TickConditions a, TickConditions b) { return !(a == b); }

private:
  std::uint32_t m_bits = 0;
};

/// The set of conditions `a` and `b`, so that `TickCondition::stuck | TickCondition::forceClamped`
/// is a TickConditions.
constexpr TickConditions operator|(TickCondition a, TickCondition b)
{
  return TickConditions(a) | TickConditions(b);
}

/// A condition and its name: snake_case, as Python and the messages spell it.
struct TickConditionName
{
  TickCondition condition; ///< The condition (a single bit).
  const char* name;        ///< Its snake_case name, a static string.
};

/// Every condition once, in the order of its bit: the one table of their names.
inline constexpr TickConditionName kTickConditionNames[] = {
  {TickCondition::budgetLimited, "budget_limited"},
  {TickCondition::hitIterationCap, "hit_iteration_cap"},
  {TickCondition::forceClamped, "force_clamped"},
  {TickCondition::forceFading, "force_fading"},
  {TickCondition::deviceLost, "device_lost"},
  {TickCondition::fingerRefused, "finger_refused"},
  {TickCondition::stuck, "stuck"},
  {TickCondition::frictionLimited, "friction_limited"},
  {TickCondition::contactOverflow, "contact_overflow"},
  {TickCondition::forceRateLimited, "force_rate_limited"},
  {TickCondition::startedOutside, "started_outside"},
  {TickCondition::pushedByObject, "pushed_by_object"},
  {TickCondition::surfaceLagging, "surface_lagging"},
};

/// The name of `condition` in kTickConditionNames ("" for a value that is no single condition).
constexpr const char* tickConditionName(TickCondition condition)
{
  for (const TickConditionName& entry : kTickConditionNames)
  {
    if (entry.condition == condition)
    {
      return entry.name;
    }
  }
  return "";
}

} // namespace proxima
