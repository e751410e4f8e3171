#!/usr/bin/env bash
# The whole test suite again in an AddressSanitizer + UndefinedBehaviorSanitizer build
# (RelWithDebInfo, in build-asan/; any report fails the test that made it). CI runs it after the
# README's two commands; see Documentation/Testing.md for how long it takes.
set -euo pipefail
cd "$(dirname "$0")/.."
# -O1 -g1: what the sanitizers' authors advise, line tables enough for their stack traces, and
# half the compile time of -O2 -g (RunCommand.cpp under ASan: 44 s against 24 s on 2 cores).
sanitizerOptimisation="-O1 -g1 -DNDEBUG"

# A unity build (CMAKE_UNITY_BUILD: each target's sources compiled as a few files that include
# them): the headers (gtest, VTK, CGAL, gRPC) are parsed, and their inline functions instrumented
# and optimised, once per batch instead of once per file. A quarter less compiler time for this
# tree, cold (Documentation/Testing.md, "How long it takes"). The Release build stays one object
# per file, for incremental rebuilds; this build also shows a helper whose name two files of one
# target share in an anonymous namespace (rename it).
cmake -G Ninja -S . -B build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="$sanitizerOptimisation" -DCMAKE_C_FLAGS_RELWITHDEBINFO="$sanitizerOptimisation" \
  -DCMAKE_UNITY_BUILD=ON -DPROXIMA_ENABLE_SANITIZERS=ON -DPROXIMA_BUILD_BENCHMARKS=OFF \
  -DPROXIMA_BUILD_QT=OFF -DPROXIMA_BUILD_DOCS=OFF
cmake --build build-asan --parallel 2
# The stress label runs a quarter of its random cases here (the same seeds, the first ones).
# Left to the Release suite, to keep a cold CI within its time (Documentation/Testing.md, "How
# long it takes"): the Qt windows (PROXIMA_BUILD_QT=OFF above: the heaviest compile of the tree,
# and tests that mostly wait for a window to draw), the install test (it installs the tree and
# builds the examples against it: packaging, not memory) and proxima.help-ranges (some 300 runs of
# the programs' option checks, each refused before anything is read: 116 s under ASan) and the
# trainer's soft-liver cases (9,874 ticks and 1,974 steps of a 5,845-tetrahedron solid: 105 s each
# under ASan; the solid and its coupling run here in ElasticSolid, TissueContact,
# ScriptedTissueScenes and proxima.run.tissue-kidney).
PROXIMA_STRESS_SCALE=0.25 ctest --test-dir build-asan --output-on-failure -j2 -LE '^install$' \
  -E '^(proxima\.help-ranges|Trainer\.soft-palpation-.*)$'
