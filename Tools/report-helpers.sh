# Shared by the report scripts (performance-report.sh, tail-report.sh, run_benchmarks.sh): source
# it, then call these. Debian's /usr/bin/python3 first (a pyenv python3 may come first on PATH and
# lack matplotlib).

# Prints a python3 that imports matplotlib, or says what to install and returns 1.
# Usage: python="$(matplotlib_python SCRIPT-NAME)" || exit 1
matplotlib_python() {
  local candidate
  for candidate in /usr/bin/python3 python3; do
    if "$candidate" -c "import matplotlib" 2>/dev/null; then
      echo "$candidate"
      return 0
    fi
  done
  echo "$1: no python3 with matplotlib (Debian: apt-get install python3-matplotlib)" >&2
  return 1
}

# The machine and its load, as the figures and tables name them.
machine_description() {
  local cpu
  cpu="$(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ *//')"
  echo "$cpu, $(nproc) cores, load $(cut -d' ' -f1 /proc/loadavg) at start, $(date -u +%Y-%m-%d)"
}

# Configures the Release test-and-benchmark build in BUILD-DIR from ROOT and builds TARGET.
# Usage: build_benchmark ROOT BUILD-DIR TARGET
build_benchmark() {
  cmake -G Ninja -S "$1" -B "$2" -DCMAKE_BUILD_TYPE=Release -DPROXIMA_BUILD_TESTING=ON \
    -DPROXIMA_BUILD_BENCHMARKS=ON >/dev/null
  cmake --build "$2" --target "$3" -j 2
}
