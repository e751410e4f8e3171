#!/usr/bin/env bash
# Hunts flaky tests: runs the Release suite (build/) several times in a row under `ctest -j2`
# while a busy loop of its own holds one core, so that the tests' threads are starved now and
# then as on a loaded CI machine. A test that passes alone and fails here waits on a guessed time
# or races; it is fixed at its cause (Documentation/Testing.md). Prints a table of the runs and
# of the tests that failed, writes it to build/flake-hunt/table.md with each run's ctest log
# beside it, and exits 1 if any run failed a test (2 on a usage error).
# Usage: bash Tools/flake-hunt.sh [--runs N] [--build DIR] [-- CTEST_ARGUMENTS...]
#   --runs N     how many whole runs (default 10)
#   --build DIR  the build to test (default build)
#   after --     passed to every ctest run, e.g. -L 'threads|net' or -R 'realtime' for a subset
# Example: bash Tools/flake-hunt.sh --runs 1 -- -L 'threads|net|realtime'
set -euo pipefail
cd "$(dirname "$0")/.."

runs=10
build=build
ctestArguments=()
usage()
{
  sed -n 's/^# \{0,1\}//;/^Usage:/,/^Example:/p' "$0" >&2
  exit 2
}
while [ "$#" -gt 0 ]; do
  case "$1" in
    --runs)
      [ "$#" -ge 2 ] || usage
      runs="$2"
      shift 2
      ;;
    --build)
      [ "$#" -ge 2 ] || usage
      build="$2"
      shift 2
      ;;
    --)
      shift
      ctestArguments=("$@")
      break
      ;;
    *) usage ;;
  esac
done
if ! [[ "$runs" =~ ^[1-9][0-9]*$ ]]; then
  echo "flake-hunt: --runs must be a whole number from 1, not '$runs'" >&2
  exit 2
fi
if [ ! -f "$build/CTestTestfile.cmake" ]; then
  echo "flake-hunt: $build is not a configured build (run Tools/quickstart.sh first)" >&2
  exit 2
fi

# The hog: one shell spinning on the last core, pinned there when taskset can. It is this
# script's own child, stopped by its process id however the script ends.
hogCore=$(($(nproc) - 1))
hog=""
ctestProcess=""
stopHog()
{
  if [ -n "$hog" ]; then
    kill "$hog" 2>/dev/null || true
    wait "$hog" 2>/dev/null || true
    hog=""
  fi
}
# Interrupted: the ctest run in progress ends too, with the tests it started (it runs in the
# background, in a process group of its own, so that the signal is handled at once and reaches
# them all).
interrupted()
{
  if [ -n "$ctestProcess" ]; then
    kill -- "-$ctestProcess" 2>/dev/null || true
    wait "$ctestProcess" 2>/dev/null || true
  fi
  stopHog
  exit "$1"
}
trap stopHog EXIT
trap 'interrupted 130' INT
trap 'interrupted 143' TERM
if command -v taskset >/dev/null; then
  taskset -c "$hogCore" bash -c 'while :; do :; done' &
else
  echo "flake-hunt: no taskset; the busy loop is not pinned to one core" >&2
  bash -c 'while :; do :; done' &
fi
hog=$!
echo "flake-hunt: a busy loop (process $hog) holds core $hogCore; $runs run(s) of" \
  "ctest -j2 ${ctestArguments[*]:-(the whole suite)} in $build"

out="$build/flake-hunt"
rm -rf "$out"
mkdir -p "$out"
declare -A failuresOf=()
rows=()
failedRuns=0
for ((run = 1; run <= runs; ++run)); do
  log="$out/run-$run.log"
  started=$SECONDS
  status=0
  setsid ctest --test-dir "$build" -j2 --output-on-failure "${ctestArguments[@]}" >"$log" 2>&1 &
  ctestProcess=$!
  wait "$ctestProcess" || status=$?
  ctestProcess=""
  took=$((SECONDS - started))
  if ! kill -0 "$hog" 2>/dev/null; then
    echo "flake-hunt: the busy loop ended during run $run: that run was not under load" >&2
    exit 1
  fi
  # ctest's last lines: "N% tests passed, F tests failed out of T", then under "The following
  # tests FAILED:" one "<number> - <name> (<why>)" line per failure.
  total="$(sed -n 's/.*tests failed out of \([0-9]*\).*/\1/p' "$log" | tail -n 1)"
  if [ -z "$total" ] || [ "$total" -eq 0 ]; then
    echo "flake-hunt: run $run ran no test (status $status); the end of its log:" >&2
    tail -n 20 "$log" >&2
    exit 1
  fi
  mapfile -t failed < <(sed -n '/^The following tests FAILED:/,$s/^[[:space:]]*[0-9]\{1,\} - \(.*\) (\(.*\))$/\1 (\2)/p' "$log")
  if [ "$status" -ne 0 ] && [ "${#failed[@]}" -eq 0 ]; then
    failed=("ctest exited $status without naming a failed test: see run-$run.log")
  fi
  if [ "${#failed[@]}" -gt 0 ]; then
    failedRuns=$((failedRuns + 1))
  fi
  for test in "${failed[@]}"; do
    name="${test% (*}"
    failuresOf["$name"]=$((${failuresOf["$name"]:-0} + 1))
  done
  list="$(printf '%s, ' "${failed[@]}")"
  rows+=("| $run | $total | ${#failed[@]} | $took | ${list%, } |")
  echo "flake-hunt: run $run of $runs: $total tests, ${#failed[@]} failed, $took s"
done
stopHog

{
  echo "Flake hunt: $runs run(s) of \`ctest -j2 ${ctestArguments[*]}\` in $build, a busy loop on" \
    "core $hogCore of $(nproc), commit $(git rev-parse --short HEAD 2>/dev/null || echo unknown)."
  echo
  echo "| run | tests | failed | seconds | failed tests |"
  echo "|---:|---:|---:|---:|---|"
  printf '%s\n' "${rows[@]}"
  echo
  if [ "${#failuresOf[@]}" -eq 0 ]; then
    echo "No test failed in $runs run(s)."
  else
    echo "| test | runs it failed in (of $runs) |"
    echo "|---|---:|"
    for name in "${!failuresOf[@]}"; do
      echo "| $name | ${failuresOf[$name]} |"
    done | sort
  fi
} >"$out/table.md"
cat "$out/table.md"
if [ "$failedRuns" -gt 0 ]; then
  echo "flake-hunt: $failedRuns of $runs run(s) failed a test; logs in $out/" >&2
  exit 1
fi
