#!/usr/bin/env bash
# Times CI as a new machine runs it: clones the current commit into a fresh temporary folder with
# the shared data beside it as `shared` (CI has a copy of ../shared beside its clone; here a
# symbolic link to this checkout's ../shared), runs .ci/run there with CI=true and
# CCACHE_DISABLE=1 (a cold compiler cache: every object is compiled), and prints the table of its
# steps from the log's "ci: '<step>' took N s" lines and the total from its last line
# ("ci: total N s"). The goal is a cold CI under 45 minutes on two cores (Documentation/Testing.md).
# Like CI, .ci/run installs the Debian packages first (as root; quick when they are there). The
# log is kept in build/ci-time/, the clone is removed at the end unless --keep is given. Commit
# first: uncommitted changes are not in the clone. Exits with .ci/run's status.
# Usage: bash Tools/ci-time.sh [--keep] [--shared DIR]
#        bash Tools/ci-time.sh --table LOG     (only the table, from a saved log; exits 1 unless
#                                              the log is of a whole run that passed)
set -euo pipefail
cd "$(dirname "$0")/.."

goalSeconds=2700

# The step table of a .ci/run log, as Markdown.
printTable()
{
  local log="$1" total last
  echo "| step | seconds | minutes |"
  echo "|---|---:|---:|"
  sed -n "s/^ci: '\(.*\)' took \([0-9]\{1,\}\) s (.*in all)$/\1\t\2/p" "$log" |
    while IFS=$'\t' read -r step seconds; do
      printf '| `%s` | %d | %d:%02d |\n' "$step" "$seconds" $((seconds / 60)) $((seconds % 60))
    done
  total="$(sed -n 's/^ci: total \([0-9]\{1,\}\) s.*/\1/p' "$log" | tail -n 1)"
  if [ -z "$total" ]; then
    # A log cut off before .ci/run's end (killed, or an older .ci/run): the last step's count.
    last="$(sed -n "s/^ci: '.*' took [0-9]\{1,\} s (\([0-9]\{1,\}\) s in all)$/\1/p" "$log" | tail -n 1)"
    echo "| total (no \"ci: total\" line: the run did not end normally) | ${last:-0} | $((${last:-0} / 60)):$(printf '%02d' $((${last:-0} % 60))) |"
    return 1
  fi
  printf '| **total** | **%d** | **%d:%02d** |\n' "$total" $((total / 60)) $((total % 60))
  if grep -q '^ci: total .*failed' "$log"; then
    echo
    echo "The run failed: $(grep '^ci: total' "$log" | tail -n 1)"
    return 1
  elif [ "$total" -le "$goalSeconds" ]; then
    echo
    echo "Under the goal of $((goalSeconds / 60)) minutes."
  else
    echo
    echo "Over the goal of $((goalSeconds / 60)) minutes."
  fi
}

keep=false
shared="$(cd .. && pwd)/shared"
while [ "$#" -gt 0 ]; do
  case "$1" in
    --table)
      [ "$#" -eq 2 ] || { echo "usage: ci-time.sh --table LOG" >&2; exit 2; }
      printTable "$2"
      exit
      ;;
    --keep)
      keep=true
      shift
      ;;
    --shared)
      [ "$#" -ge 2 ] || { echo "usage: ci-time.sh [--keep] [--shared DIR]" >&2; exit 2; }
      shared="$(cd "$2" && pwd)"
      shift 2
      ;;
    *)
      echo "usage: ci-time.sh [--keep] [--shared DIR] | ci-time.sh --table LOG" >&2
      exit 2
      ;;
  esac
done

commit="$(git rev-parse HEAD)"
if [ -n "$(git status --porcelain --untracked-files=no)" ]; then
  echo "ci-time: the working tree has uncommitted changes; timing the commit $commit without them" >&2
fi
work="$(mktemp -d "${TMPDIR:-/tmp}/proxima-ci-time.XXXXXX")"
removeClone()
{
  if [ "$keep" = true ]; then
    echo "ci-time: the clone stays in $work" >&2
  else
    rm -rf "$work"
  fi
}
trap removeClone EXIT
git clone --quiet --no-local "$(pwd)" "$work/proxima"
git -C "$work/proxima" checkout --quiet --detach "$commit"
if [ -d "$shared" ]; then
  ln -s "$shared" "$work/shared"
else
  echo "ci-time: no shared data at $shared: the shared-data tests will skip, unlike CI" >&2
fi

mkdir -p build/ci-time
log="$(pwd)/build/ci-time/$(git rev-parse --short "$commit")-$(date -u +%Y%m%dT%H%M%SZ).log"
echo "ci-time: .ci/run of $commit in $work, cold (CCACHE_DISABLE=1); log $log"
status=0
(cd "$work/proxima" && CI=true CCACHE_DISABLE=1 bash .ci/run </dev/null) 2>&1 | tee "$log" ||
  status=$?
echo
printTable "$log" || true
exit "$status"
