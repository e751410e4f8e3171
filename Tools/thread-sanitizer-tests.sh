#!/usr/bin/env bash
# The runtime's tests again under ThreadSanitizer (RelWithDebInfo, in build-tsan/): every
# hand-off between the servo thread, the proxy thread and the reader is checked for data races;
# any report fails the test. Only the kernel, the runtime, the Dynamics layer (the bodies on the
# proxy thread), the Tissue layer (a solid stepped on the proxy thread, its surface handed to a
# reader) and the mesh readers (for the model swap's skull) are built, not the VTK pipeline
# or the applications. CI runs it after the AddressSanitizer suite.
set -euo pipefail
cd "$(dirname "$0")/.."

# -O1 -g1, as in Tools/sanitizer-tests.sh: what ThreadSanitizer's authors advise, line tables
# enough for both stacks of a race, and a third less compile time than -O2 -g; and a unity build,
# as there: these targets' sources share the runtime's and gtest's headers, and the compile takes
# a third of the time of -O2 -g one file at a time (Documentation/Testing.md, "How long it takes").
sanitizerOptimisation="-O1 -g1 -DNDEBUG"

cmake -G Ninja -S . -B build-tsan -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="$sanitizerOptimisation" -DCMAKE_C_FLAGS_RELWITHDEBINFO="$sanitizerOptimisation" \
  -DCMAKE_UNITY_BUILD=ON -DPROXIMA_ENABLE_THREAD_SANITIZER=ON -DPROXIMA_BUILD_APPS=OFF -DPROXIMA_BUILD_VTK=OFF \
  -DPROXIMA_BUILD_BENCHMARKS=OFF -DPROXIMA_BUILD_DOCS=OFF
cmake --build build-tsan --parallel 2 --target RuntimeTests ThreadedRuntimeTests ThreadedBodyTests ThreadedTissueTests
# halt_on_error: the first race fails the test that found it, with both stacks printed.
TSAN_OPTIONS="halt_on_error=1 second_deadlock_stack=1" \
  ctest --test-dir build-tsan --output-on-failure -j2 -R '^(ThreadedRuntime|ThreadedBodies|ThreadedTissue|SnapshotChannel|TripleBuffer|LoopStatistics|ServoForce|Lockstep|PointerDevice)'
