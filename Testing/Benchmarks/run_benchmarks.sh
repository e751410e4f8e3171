#!/usr/bin/env bash
# Builds the benchmarks in Release, runs them (a few minutes on 2 cores), and turns their JSON into
# the plots under Documentation/Figures and the tables Documentation/SphereTreeBenchmarksTable.md
# (BenchSphereTree) and Documentation/ProxyBenchmarksTable.md (BenchProxyTick).
# Usage: Testing/Benchmarks/run_benchmarks.sh [build-dir]      (default: build-bench)
# BENCHMARKS=tree or BENCHMARKS=proxy runs one of the two (default: both). Extra Google Benchmark
# flags for BenchSphereTree go in BENCHMARK_ARGS, e.g. BENCHMARK_ARGS=--benchmark_filter=icosphere5
set -euo pipefail
# shellcheck source=report-helpers.sh
source "$(dirname "$0")/../../Tools/report-helpers.sh"
root="$(cd "$(dirname "$0")/../.." && pwd)"
build="${1:-$root/build-bench}"
figures="$root/Documentation/Figures"
mkdir -p "$figures"
which="${BENCHMARKS:-both}"
# The apps are on because BenchProxyTick reads the shared skull through the IO layer.
cmake -G Ninja -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DPROXIMA_BUILD_APPS=ON \
  -DPROXIMA_BUILD_TESTING=OFF -DPROXIMA_BUILD_BENCHMARKS=ON >/dev/null
cmake --build "$build" --target BenchSphereTree BenchProxyTick -j 2
json="$figures/sphere_tree_benchmarks.json"
proxyJson="$figures/proxy_tick_benchmarks.json"
if [ "$which" != proxy ]; then
  # shellcheck disable=SC2086 # BENCHMARK_ARGS is a list of flags on purpose
  "$build/Testing/Benchmarks/BenchSphereTree" --benchmark_out="$json" --benchmark_out_format=json \
    --benchmark_min_time=0.5 ${BENCHMARK_ARGS:-}
fi
if [ "$which" != tree ]; then
  "$build/Testing/Benchmarks/BenchProxyTick" --benchmark_out="$proxyJson" \
    --benchmark_out_format=json
fi
# A python3 with matplotlib, Debian's first (a pyenv shim may shadow python3-matplotlib).
python="$(matplotlib_python run_benchmarks.sh)" || exit 1
if [ "$which" != proxy ]; then
  "$python" "$root/Testing/Benchmarks/plot_benchmarks.py" "$json" --figures "$figures" \
    --table "$root/Documentation/SphereTreeBenchmarksTable.md"
fi
if [ "$which" != tree ]; then
  "$python" "$root/Testing/Benchmarks/plot_proxy_benchmarks.py" "$proxyJson" \
    --figure "$figures/proxy_tick.png" --table "$root/Documentation/ProxyBenchmarksTable.md"
fi
