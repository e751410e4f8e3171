#!/usr/bin/env bash
# Quick start, first command (README.md): installs the Debian packages, configures a Release
# build in build/ with Ninja (ccache is used when installed), builds everything on two cores and
# runs the main job: `proxima run` on the bundled scene (a sphere and a press-and-stroke finger
# path), which writes the trace to build/quickstart-trace.csv and prints the run's summary as
# JSON. The second command, `ctest --test-dir build --output-on-failure -j2`, runs the tests.
set -euo pipefail
cd "$(dirname "$0")/.."

bash Tools/install-dependencies.sh
cmake -G Ninja -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build --parallel 2
./build/bin/proxima run --mesh Data/Meshes/icosphere-4.obj \
  --path Data/Paths/icosphere-4-press-stroke.csv --out build/quickstart-trace.csv
