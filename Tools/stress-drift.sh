#!/usr/bin/env bash
# The nightly drift run of the stress suite: StressDrift with ten million ticks (about two minutes
# in Release on one core), not part of CI or of the `stress` label's default 200,000 ticks.
# Usage: bash Tools/stress-drift.sh [build-dir] [ticks]      (defaults: build, 10000000)
set -euo pipefail
cd "$(dirname "$0")/.."
build="${1:-build}"
PROXIMA_DRIFT_TICKS="${2:-10000000}" "$build/Testing/Stress/StressSuite" \
  --gtest_filter='StressDrift.*'
