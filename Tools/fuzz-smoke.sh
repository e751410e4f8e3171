#!/usr/bin/env bash
# Builds the libFuzzer targets of Testing/Fuzz with clang (build-fuzz/: only the targets and the
# libraries they need, with AddressSanitizer and UndefinedBehaviorSanitizer) and runs each one
# briefly from its seed corpus in Testing/Fuzz/Corpus/<target>/. New inputs go to a scratch
# corpus, not into the repository; a crash leaves its input in build-fuzz/findings/ and fails.
# Usage: bash Tools/fuzz-smoke.sh                 (CI: a fixed number of inputs per target)
#        bash Tools/fuzz-smoke.sh 600             (hunting: 600 s per target instead)
#        FUZZ_TARGETS="FuzzMeshReader-glb FuzzMeshReader-gltf" FUZZ_SEED=0 bash Tools/fuzz-smoke.sh 600
#        (FUZZ_TARGETS replaces the list below: one reader at a time while fixing it)
# CI's run is deterministic: a fixed mutation seed (FUZZ_SEED, default 1) and a fixed number of
# inputs per target, so that every machine, fast or slow, tries the same inputs and CI passes or
# fails on the code alone. A run for a fixed time instead tried more inputs on a faster machine,
# and CI failed there on a crash no local run had reached. Hunting for new findings is a timed
# run with FUZZ_SEED=0 (libFuzzer: a seed from the clock); its findings go into
# Testing/Fuzz/Findings/<target>/ with the fix, and CI replays them all.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-}"
clangxx="$(command -v clang++-14 || command -v clang++)"
clangc="$(command -v clang-14 || command -v clang)"

# The targets that CI runs: our own parsers (OBJ, PLY, scene files, path files), the solver, the
# server's requests (decoded and played: each input runs a path, hence fewer inputs), and
# VTK's and OpenMesh's readers behind our checks (STL, OFF, glTF, GLB; see
# Documentation/Fuzzing.md), each with the number of inputs CI tries: 25-75 s of runs each on
# one core of our 2-core machine (measured in a cold CI run on 2026-12-05), about 6 minutes in
# all, run two at a time.
declare -A inputs=(
  [FuzzMeshReader-obj]=250000 [FuzzMeshReader-ply]=250000 [FuzzSceneFile]=200000
  [FuzzFingerPathFile]=400000 [FuzzProxySolver]=10000 [FuzzMeshReader-stl]=70000
  [FuzzMeshReader-off]=250000 [FuzzMeshReader-gltf]=300000 [FuzzMeshReader-glb]=400000
  [FuzzMeshReader-vtp]=20000 [FuzzRunRequest]=5000 [FuzzModelUpload]=500000)
# VTP is back since IO/Mesh/Private/VtpChecks.cpp bounds the declared sizes and compression
# headers by the file's bytes (its out-of-memory finding is replayed below).
targets=(FuzzMeshReader-obj FuzzMeshReader-ply FuzzSceneFile FuzzFingerPathFile FuzzProxySolver
         FuzzMeshReader-stl FuzzMeshReader-off FuzzMeshReader-gltf FuzzMeshReader-glb
         FuzzMeshReader-vtp FuzzRunRequest FuzzModelUpload)
if [ -n "${FUZZ_TARGETS:-}" ]; then
  read -r -a targets <<<"$FUZZ_TARGETS"
fi

cmake -G Ninja -S . -B build-fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_COMPILER="$clangxx" -DCMAKE_C_COMPILER="$clangc" \
  -DPROXIMA_BUILD_FUZZERS=ON -DPROXIMA_BUILD_TESTING=OFF -DPROXIMA_BUILD_BENCHMARKS=OFF \
  -DPROXIMA_BUILD_APPS=ON -DPROXIMA_BUILD_DOCS=OFF >/dev/null
cmake --build build-fuzz --parallel 2 --target "${targets[@]}"
# The findings kept from earlier runs must not crash any more (each is replayed once).
for target in "${targets[@]}"; do
  if [ -d "Testing/Fuzz/Findings/$target" ]; then
    "build-fuzz/Testing/Fuzz/$target" -runs=0 "Testing/Fuzz/Findings/$target"/* \
      >"build-fuzz/$target-findings.log" 2>&1 || {
      echo "fuzz-smoke: a kept finding of $target still fails" >&2
      tail -20 "build-fuzz/$target-findings.log" >&2
      exit 1
    }
  fi
done

# What makes a run with a fixed seed and input count differ between two runs on one machine
# (measured: the coverage after 50,000 inputs of the OBJ target differed run to run): libFuzzer
# learns the operands of comparisons, which include addresses that move with address-space
# randomisation, and reloads its corpus folder on a timer. CI's run turns all three off; hunting
# keeps them (they find magic values and lengths).
reproducible=()
if [ -z "$seconds" ]; then
  if setarch "$(uname -m)" -R true 2>/dev/null; then
    reproducible=(setarch "$(uname -m)" -R)
  else
    echo "fuzz-smoke: setarch -R refused here; address randomisation stays on" >&2
  fi
fi

mkdir -p build-fuzz/findings
# One target's run; its lines are printed when it ends. Two run at once, one per core: each is
# one process whose inputs and seed are fixed, so running beside another changes its wall time,
# not what it tries.
runTarget()
{
  local target="$1" seeds scratch budget
  seeds="Testing/Fuzz/Corpus/$target"
  scratch="build-fuzz/corpus/$target"
  mkdir -p "$scratch"
  if [ -n "$seconds" ]; then
    echo "fuzz-smoke: $target for ${seconds}s"
    budget=(-max_total_time="$seconds")
  else
    # A fresh scratch corpus each time: what earlier runs found must not change what CI tries.
    rm -rf "$scratch" && mkdir -p "$scratch"
    echo "fuzz-smoke: $target, ${inputs[$target]} inputs"
    budget=(-runs="${inputs[$target]}" -reload=0 -use_cmp=0 -use_memmem=0)
  fi
  # VTK's readers report through its output window; only libFuzzer's own lines matter here.
  if ! "${reproducible[@]}" "build-fuzz/Testing/Fuzz/$target" "$scratch" "$seeds" "${budget[@]}" \
       -rss_limit_mb=2048 -timeout=10 -print_final_stats=0 -seed="${FUZZ_SEED:-1}" \
       -artifact_prefix="build-fuzz/findings/$target-" >"build-fuzz/$target.log" 2>&1; then
    echo "fuzz-smoke: $target FAILED; the end of its log:" >&2
    tail -40 "build-fuzz/$target.log" >&2
    return 1
  fi
  echo "fuzz-smoke: $target: $(grep -E "^#[0-9]+.*DONE|Done [0-9]+ runs" "build-fuzz/$target.log" |
    tail -1)"
}

status=0
running=0
for target in "${targets[@]}"; do
  if [ "$running" -eq 2 ]; then
    wait -n || status=1
    running=$((running - 1))
  fi
  runTarget "$target" &
  running=$((running + 1))
done
while [ "$running" -gt 0 ]; do
  wait -n || status=1
  running=$((running - 1))
done
exit "$status"
