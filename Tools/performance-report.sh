#!/usr/bin/env bash
# Regenerates Documentation/Performance.md's measured parts: the run-time-against-error sweep
# (Testing/Benchmarks/BenchTimeVersusError: every knob one at a time on the 1.3M-triangle
# icosphere, each setting timed and then checked by the oracle) into
# Documentation/PerformanceTable.md and Documentation/Figures/time_versus_error.png; the default
# setting on icospheres of 20k to 1.3M triangles and the shared meshes (time, error, build time,
# memory) into PerformanceScalingTable.md and Figures/time_versus_triangles.png; and, unless
# SWEEP_ONLY=1, the query, build and surface-effect benchmarks of
# Testing/Benchmarks/run_benchmarks.sh (their tables and figures). About 15 minutes on 2 cores.
# Run it on an idle machine: the figures name the machine and its load.
# Usage: bash Tools/performance-report.sh [build-dir]      (default: build; SUBDIVISIONS=8, PASSES=5)
set -euo pipefail
# shellcheck source=report-helpers.sh
source "$(dirname "$0")/report-helpers.sh"
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${1:-$root/build}"
figures="$root/Documentation/Figures"
mkdir -p "$figures"

build_benchmark "$root" "$build" BenchTimeVersusError

machine="$(machine_description)"
json="$figures/time_versus_error.json"
"$build/Testing/Benchmarks/BenchTimeVersusError" "$json" "${SUBDIVISIONS:-8}" "${PASSES:-5}"

python="$(matplotlib_python performance-report.sh)" || exit 1
"$python" "$root/Testing/Benchmarks/plot_time_versus_error.py" "$json" \
  --figure "$figures/time_versus_error.png" --table "$root/Documentation/PerformanceTable.md" \
  --machine "$machine"

# The default setting against triangle count: icospheres and the shared meshes.
scaling="$figures/time_versus_triangles.json"
"$build/Testing/Benchmarks/BenchTimeVersusError" --scaling "$scaling" "${PASSES:-5}"
"$python" "$root/Testing/Benchmarks/plot_scaling.py" "$scaling" \
  --figure "$figures/time_versus_triangles.png" \
  --table "$root/Documentation/PerformanceScalingTable.md" --machine "$machine"

if [ "${SWEEP_ONLY:-0}" != 1 ]; then
  bash "$root/Testing/Benchmarks/run_benchmarks.sh"
fi
