#!/usr/bin/env bash
# The whole test suite again in an AddressSanitizer + UndefinedBehaviorSanitizer build
# (RelWithDebInfo, in build-asan/; any report fails the test that made it). CI runs it after the
# README's two commands; about 5 minutes to build on two cores without ccache, 2 to test.
set -euo pipefail
cd "$(dirname "$0")/.."
# -O1 -g1: what the sanitizers' authors advise, line tables enough for their stack traces, and
# half the compile time of -O2 -g (RunCommand.cpp under ASan: 44 s against 24 s on 2 cores).
sanitizerOptimisation="-O1 -g1 -DNDEBUG"

cmake -G Ninja -S . -B build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="$sanitizerOptimisation" -DCMAKE_C_FLAGS_RELWITHDEBINFO="$sanitizerOptimisation" \
  -DPROXIMA_ENABLE_SANITIZERS=ON -DPROXIMA_BUILD_BENCHMARKS=OFF
cmake --build build-asan --parallel 2
# The stress label runs a quarter of its random cases here (the same seeds, the first ones).
PROXIMA_STRESS_SCALE=0.25 ctest --test-dir build-asan --output-on-failure -j2
