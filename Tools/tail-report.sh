#!/usr/bin/env bash
# Regenerates the worst-tick report (DESIGN.md section 5, "the tail is the headline"): builds
# Testing/Benchmarks/BenchProbeTail, runs the probe path on every shared mesh at radii 0.5-3 mm
# (and the shared person-like paths), each without a budget and with each iteration budget of the
# sweep, every tick replayed for its work, and plots the tail into
# Documentation/Figures/probe_tail.png, run time against error over the budgets into
# Documentation/Figures/budget_sweep.png (its table into the generated block at the top of
# Documentation/Performance.md), the cost of one iteration into
# Documentation/Figures/probe_iteration_cost.png, and the cases into
# Documentation/ProbeTailTable.md. About ten minutes on one core; QUICK=1 for one seed and two
# radii. Run it on an idle machine: the figure and table name the machine and its load.
# Usage: bash Tools/tail-report.sh [build-dir]      (default: build; SEEDS=3, QUICK=0)
set -euo pipefail
# shellcheck source=report-helpers.sh
source "$(dirname "$0")/report-helpers.sh"
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${1:-$root/build}"
figures="$root/Documentation/Figures"
mkdir -p "$figures"

build_benchmark "$root" "$build" BenchProbeTail

machine="$(machine_description)"
json="$figures/probe_tail.json"
arguments=(--seeds "${SEEDS:-3}")
if [ "${QUICK:-0}" = 1 ]; then
  arguments=(--quick)
fi
"$build/Testing/Benchmarks/BenchProbeTail" "$json" "${arguments[@]}"

python="$(matplotlib_python tail-report.sh)" || exit 1
"$python" "$root/Testing/Benchmarks/plot_probe_tail.py" "$json" \
  --figure "$figures/probe_tail.png" --budget-figure "$figures/budget_sweep.png" \
  --iteration-figure "$figures/probe_iteration_cost.png" \
  --table "$root/Documentation/ProbeTailTable.md" \
  --performance-page "$root/Documentation/Performance.md" \
  --machine "$machine"
