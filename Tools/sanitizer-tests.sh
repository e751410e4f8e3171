#!/usr/bin/env bash
# The whole test suite again in an AddressSanitizer + UndefinedBehaviorSanitizer build
# (RelWithDebInfo, in build-asan/; any report fails the test that made it). CI runs it after the
# README's two commands; about 5 minutes to build on two cores without ccache, 2 to test.
set -euo pipefail
cd "$(dirname "$0")/.."

cmake -G Ninja -S . -B build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DPROXIMA_ENABLE_SANITIZERS=ON -DPROXIMA_BUILD_BENCHMARKS=OFF
cmake --build build-asan --parallel 2
# The stress label runs a quarter of its random cases here (the same seeds, the first ones).
PROXIMA_STRESS_SCALE=0.25 ctest --test-dir build-asan --output-on-failure -j2
