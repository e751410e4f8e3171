// What a scripted run plays and with which knobs: the options `proxima run` and `proxima view`
// share (what to touch: a mesh with its surface flags, or a scene file; the finger path; the
// proxy and servo knobs), as plain values. The command line fills them from its options, the
// Python module from its keywords; both then load, check and play them through the same
// functions, so that a run gives the same trace whoever asked for it.
#pragma once

#include "IO/ScriptedRun/RunSettingList.h"
#include "IO/Scene/SceneBuilder.h"
#include "Proxy/ProxyParameters.h"
#include "Runtime/FingerPath.h"
#include "Runtime/ServoParameters.h"
#include "Runtime/TickBudget.h"

#include <string>

namespace proxima
{

/// What a scripted run plays (a mesh or a scene, and a finger path) and its knobs, as plain
/// values that the command line and the Python module fill in alike.
struct ScriptedRunSettings
{
  /// A mesh file, or (exclusive) a scene file.
  std::string mesh;
  /// The scene file; empty when `mesh` is given instead.
  std::string scene;
  /// The finger path file (what messages about the path's start name).
  std::string path;
  // The knobs, one member per row of RunSettingList.h with the row's default: --scale, --radius,
  // ..., --tick-budget. An empty --tick-budget is the caller's default; a skin of 0 the scene's.
#define PROXIMA_RUN_SETTING_MEMBER(member, option, type, kind, byDefault, range, choices, scope,   \
                                   field, help)                                                    \
  type member = byDefault;
  PROXIMA_RUN_SETTINGS(PROXIMA_RUN_SETTING_MEMBER)
#undef PROXIMA_RUN_SETTING_MEMBER
};

/// Throws InputError naming the option (its command-line spelling, "--radius") when a value is
/// out of its documented range (IO/InputChecks/ParameterRanges.h) or two values contradict each
/// other. The command line checks the same through its option validators before this could run;
/// this is for callers that fill the settings themselves (the Python module).
void checkScriptedRunSettings(const ScriptedRunSettings& settings);

/// The budget of `tickBudget`, or `byDefault` when it is empty.
TickWorkBudget tickBudget(const ScriptedRunSettings& settings, const TickWorkBudget& byDefault);
/// The scene of `scene`, or of `mesh` and its surface settings (one object at rest).
LoadedScene loadScene(const ScriptedRunSettings& settings);
/// The proxy solver's parameters the settings give (radius, skin, iterations, friction, ...).
ProxyParameters proxyParameters(const ScriptedRunSettings& settings);
/// The force stage's parameters the settings give (stiffness, force limit, rate, fades).
ServoParameters servoParameters(const ScriptedRunSettings& settings);

/// Throws InputError naming --radius when the proxy is larger than the whole scene (the
/// diagonal of its bounding box).
void checkRadiusAgainstScene(const ScriptedRunSettings& settings, const LoadedScene& loaded);

/// Throws InputError naming the scene file when its scene has bodies, which `who` (a program or
/// mode that runs scenes without their dynamics so far) would show standing still.
void refuseSceneBodies(const LoadedScene& loaded, const std::string& who);
/// Throws InputError naming the scene file when its scene has tissue, which `who` (a program or
/// mode other than a lockstep run) would show rigid.
void refuseSceneTissue(const LoadedScene& loaded, const std::string& who);
/// Throws InputError naming the path when its first sample leaves no room for the proxy sphere
/// against some object: a proxy that starts overlapping a surface has no free side to be pushed
/// back to.
void checkPathStart(const ScriptedRunSettings& settings, const LoadedScene& loaded,
                    const FingerPath& fingerPath);

} // namespace proxima
