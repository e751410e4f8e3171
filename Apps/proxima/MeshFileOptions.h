// --mesh and --scale as the commands that read one mesh file take them (tree, inspect): the file
// in any of the readers' formats, and the factor from its units to metres.
#pragma once

#include "Validators.h"

#include <CLI/CLI.hpp>

#include <string>

namespace proxima::cli
{

inline void addMeshFileOptions(CLI::App& app, std::string& mesh, double& scale)
{
  app
    .add_option("--mesh", mesh,
                "Mesh file: .stl .obj .ply .vtp .gltf .glb .off (extension in any case)")
    ->required();
  app.add_option("--scale", scale, "Factor from file units to metres, applied to every coordinate")
    ->check(numberIn(kMeshScaleRange))
    ->capture_default_str();
}

} // namespace proxima::cli
