// The options `proxima run` and `proxima view` share: what to touch (--mesh with its surface
// flags, or --scene), the finger path, and the proxy and servo knobs. One registration, one
// scene loader, one start check, so that the viewer plays exactly what a run plays.
#pragma once

#include "IO/ScriptedRun/ScriptedRunSettings.h"

#include <CLI/CLI.hpp>

#include "IO/InputChecks/ParameterRanges.h"

#include <string>

namespace proxima::cli
{

/// The settings of a scripted run (IO/ScriptedRun), filled from the options.
using SceneOptions = ScriptedRunSettings;

/// Registers --mesh, --scene, --radius, --stiffness and --path on `app`. Separate from
/// addSceneOptionsAfterPath so that a command can put its own options (run's --out, --summary)
/// where `--help` has always listed them.
void addSceneOptionsThroughPath(CLI::App& app, SceneOptions& options, bool pathRequired = true);
/// Registers --rate, --max-force, --max-iterations, --skin and the --mesh-only surface options
/// (--scale, --shading, --feature-angle, friction, viscosity, --texture*), which --scene
/// excludes. `rateRange` is the --rate the command takes (the view's servo loop has its own).
void addSceneOptionsAfterPath(CLI::App& app, SceneOptions& options,
                              const ParameterRange& rateRange = kScriptedRateRange);
/// Registers --tick-budget; `defaults` says in the help what the command uses without it.
void addTickBudgetOption(CLI::App& app, SceneOptions& options, const std::string& defaults);
/// The checks between these options that CLI11 cannot say by itself, as usage errors (status 2);
/// call from the subcommand's callback.
void checkSceneOptions(const SceneOptions& options, const CLI::App& app);

} // namespace proxima::cli
