#include "Runtime/HapticState.h"

namespace proxima
{

std::uint32_t tickFlags(const HapticState& state)
{
  std::uint32_t flags = 0;
  const auto set = [&flags](bool condition, TickFlag flag) { flags |= condition ? flag : 0u; };
  set(state.budgetLimited, kTickBudgetLimited);
  set(state.hitIterationCap, kTickIterationCap);
  set(state.forceClamped, kTickForceClamped);
  set(state.fading, kTickForceFading);
  set(state.deviceLost, kTickDeviceLost);
  set(state.fingerRefused, kTickFingerRefused);
  set(state.stuck, kTickStuck);
  set(state.frictionLimited, kTickFrictionLimited);
  set(state.contactOverflow, kTickContactOverflow);
  set(state.rateLimited, kTickForceRateLimited);
  set(state.startedOutside, kTickStartedOutside);
  set(state.pushedByObject, kTickPushedByObject);
  return flags;
}

void setTickFlags(HapticState& state, std::uint32_t flags)
{
  const auto has = [flags](TickFlag flag) { return (flags & flag) != 0; };
  state.budgetLimited = has(kTickBudgetLimited);
  state.hitIterationCap = has(kTickIterationCap);
  state.forceClamped = has(kTickForceClamped);
  state.fading = has(kTickForceFading);
  state.deviceLost = has(kTickDeviceLost);
  state.fingerRefused = has(kTickFingerRefused);
  state.stuck = has(kTickStuck);
  state.frictionLimited = has(kTickFrictionLimited);
  state.contactOverflow = has(kTickContactOverflow);
  state.rateLimited = has(kTickForceRateLimited);
  state.startedOutside = has(kTickStartedOutside);
  state.pushedByObject = has(kTickPushedByObject);
}

} // namespace proxima
