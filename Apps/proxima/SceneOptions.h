// The options `proxima run` and `proxima view` share: what to touch (--mesh with its surface
// flags, or --scene), the finger path, and the proxy and servo knobs. One registration, one
// scene loader, one start check, so that the viewer plays exactly what a run plays.
#pragma once

#include "IO/Scene/SceneBuilder.h"
#include "Proxy/ProxyParameters.h"
#include "Runtime/FingerPath.h"
#include "Runtime/ServoParameters.h"
#include "Runtime/TickBudget.h"

#include <CLI/CLI.hpp>

#include <string>

namespace proxima::cli
{

struct SceneOptions
{
  std::string mesh;
  std::string scene;
  double scale = 1.0;
  double radius = 0.001;
  double stiffness = 1000.0;
  std::string path;
  double rate = 1000.0;
  double maxForce = 10.0;
  int maxIterations = 256;
  double skin = 0.0;
  std::string shading = "off";
  double featureAngle = 30.0;
  double staticFriction = 0.0;
  double dynamicFriction = 0.0;
  double viscosity = 0.0;
  std::string texture;
  std::string textureRole;
  double textureAmplitude = 0.0;
  std::string textureChannel = "luminance";
  /// --tick-budget as given (checked by tickBudgetValue); empty: the command's default.
  std::string tickBudget;
};

/// Registers --mesh, --scene, --radius, --stiffness and --path on `app`. Separate from
/// addSceneOptionsAfterPath so that a command can put its own options (run's --out, --summary)
/// where `--help` has always listed them.
void addSceneOptionsThroughPath(CLI::App& app, SceneOptions& options);
/// Registers --rate, --max-force, --max-iterations, --skin and the --mesh-only surface options
/// (--scale, --shading, --feature-angle, friction, viscosity, --texture*), which --scene
/// excludes.
void addSceneOptionsAfterPath(CLI::App& app, SceneOptions& options);
/// Registers --tick-budget; `defaults` says in the help what the command uses without it.
void addTickBudgetOption(CLI::App& app, SceneOptions& options, const std::string& defaults);
/// The budget of --tick-budget, or `byDefault` when it was not given.
TickWorkBudget tickBudget(const SceneOptions& options, const TickWorkBudget& byDefault);
/// The checks between these options that CLI11 cannot say by itself, as usage errors (status 2);
/// call from the subcommand's callback.
void checkSceneOptions(const SceneOptions& options, const CLI::App& app);

/// The scene of --scene, or of --mesh and its surface flags (one object at rest).
LoadedScene loadScene(const SceneOptions& options);
ProxyParameters proxyParameters(const SceneOptions& options);
ServoParameters servoParameters(const SceneOptions& options);

/// Throws InputError naming --radius when the proxy is larger than the whole scene (the
/// diagonal of its bounding box).
void checkRadiusAgainstScene(const SceneOptions& options, const LoadedScene& loaded);
/// Throws InputError naming --path when the path's first sample leaves no room for the proxy
/// sphere against some object: a proxy that starts overlapping a surface has no free side to be
/// pushed back to.
void checkPathStart(const SceneOptions& options, const LoadedScene& loaded,
                    const FingerPath& fingerPath);

} // namespace proxima::cli
