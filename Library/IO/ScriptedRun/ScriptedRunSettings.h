// What a scripted run plays and with which knobs: the options `proxima run` and `proxima view`
// share (what to touch: a mesh with its surface flags, or a scene file; the finger path; the
// proxy and servo knobs), as plain values. The command line fills them from its options, the
// Python module from its keywords; both then load, check and play them through the same
// functions, so that a run gives the same trace whoever asked for it.
#pragma once

#include "IO/Scene/SceneBuilder.h"
#include "Proxy/ProxyParameters.h"
#include "Runtime/FingerPath.h"
#include "Runtime/ServoParameters.h"
#include "Runtime/TickBudget.h"

#include <string>

namespace proxima
{

struct ScriptedRunSettings
{
  /// A mesh file, or (exclusive) a scene file.
  std::string mesh;
  std::string scene;
  /// --mesh only: file units to metres.
  double scale = 1.0;
  /// Proxy radius in metres.
  double radius = 0.001;
  /// Spring kp in N/m.
  double stiffness = 1000.0;
  /// The finger path file (what messages about the path's start name).
  std::string path;
  /// Servo rate in Hz.
  double rate = 1000.0;
  /// Force clamp in newtons.
  double maxForce = 10.0;
  int maxIterations = 256;
  /// Contact skin in metres; 0: the scene's (Documentation/Epsilons.md).
  double skin = 0.0;
  // --mesh only: the surface.
  std::string shading = "off";
  double featureAngle = 30.0;
  double staticFriction = 0.0;
  double dynamicFriction = 0.0;
  double viscosity = 0.0;
  std::string texture;
  std::string textureRole;
  double textureAmplitude = 0.0;
  std::string textureChannel = "luminance";
  /// --tick-budget as given (parseTickBudget); empty: the caller's default.
  std::string tickBudget;
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
ProxyParameters proxyParameters(const ScriptedRunSettings& settings);
ServoParameters servoParameters(const ScriptedRunSettings& settings);

/// Throws InputError naming --radius when the proxy is larger than the whole scene (the
/// diagonal of its bounding box).
void checkRadiusAgainstScene(const ScriptedRunSettings& settings, const LoadedScene& loaded);

/// Throws InputError naming the scene file when its scene has bodies, which `who` (a program or
/// mode that runs scenes without their dynamics so far) would show standing still.
void refuseSceneBodies(const LoadedScene& loaded, const std::string& who);
/// Throws InputError naming the path when its first sample leaves no room for the proxy sphere
/// against some object: a proxy that starts overlapping a surface has no free side to be pushed
/// back to.
void checkPathStart(const ScriptedRunSettings& settings, const LoadedScene& loaded,
                    const FingerPath& fingerPath);

} // namespace proxima
