#!/usr/bin/env bash
# Long fuzz runs of the readers' harnesses (tests/fuzz, docs/formats.md
# "Fuzzing"), one core, niced:
#   scripts/fuzz.sh [HARNESS|all] [EXECUTIONS]     e.g. scripts/fuzz.sh ply 1000000
# Builds the harnesses with clang into ${DARKROOM_BUILD_DIR:-build}/fuzz, then
# runs each to EXECUTIONS (default 1,000,000) over the committed corpus and
# the generated seeds. What it finds (crash-*, timeout-*, oom-*, leak-*) and
# the inputs it grew go OUTSIDE the repository, to
# ${DARKROOM_FUZZ_OUT:-$HOME/.cache/darkroom-fuzz}/<harness>/; a summary line
# per harness (executions, exec/s, seconds, findings) is appended to summary.txt there.
# DARKROOM_FUZZ_SECONDS, when set, also bounds each harness's run in time.
# Stops a harness at its first finding; reproduce one with
#   <build>/fuzz/fuzz_<harness> <finding file>
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
which=${1:-all}
runs=${2:-1000000}
build=${DARKROOM_BUILD_DIR:-$root/build}/fuzz
out=${DARKROOM_FUZZ_OUT:-$HOME/.cache/darkroom-fuzz}
clangxx=$(command -v clang++ || true)
if [ -z "$clangxx" ]; then
  echo "fuzz.sh: clang++ not found: install the Debian packages clang and libclang-rt-14-dev" >&2
  exit 1
fi
cmake -DSOURCE="$root/tests/fuzz" -DBINARY="$build" -DCXX="$clangxx" -P "$root/tests/fuzz/build.cmake" >/dev/null

harnesses=$(sed -n 's/^set(DARKROOM_FUZZ_HARNESSES \(.*\))$/\1/p' "$root/tests/fuzz/harnesses.cmake")
if [ "$which" != all ]; then
  if ! printf '%s\n' $harnesses | grep -qx "$which"; then
    echo "fuzz.sh: no harness '$which'; there are: $harnesses" >&2
    exit 2
  fi
  harnesses=$which
fi

status=0
for h in $harnesses; do
  dir=$out/$h
  mkdir -p "$dir/corpus"
  corpora=("$dir/corpus")
  [ -d "$root/tests/fuzz/corpus/$h" ] && corpora+=("$root/tests/fuzz/corpus/$h")
  [ -d "$build/seeds/$h" ] && corpora+=("$build/seeds/$h")
  log=$dir/run-$(date +%Y%m%d-%H%M%S).log
  echo "fuzz.sh: $h to $runs executions; log $log" >&2
  start=$(date +%s)
  rc=0
  nice "$build/fuzz_$h" -runs="$runs" -max_total_time="${DARKROOM_FUZZ_SECONDS:-0}" -timeout=25 -print_final_stats=1 \
    -artifact_prefix="$dir/" "${corpora[@]}" >"$log" 2>&1 || rc=$?
  seconds=$(( $(date +%s) - start ))
  execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
  rate=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$log" | tail -1)
  finding=$(sed -n 's/.*Test unit written to //p' "$log" | tail -1)
  line="$(date -u +%FT%TZ) $h executions=${execs:-?} exec/s=${rate:-?} seconds=$seconds rc=$rc finding=${finding:-none}"
  echo "$line" | tee -a "$out/summary.txt"
  [ "$rc" -eq 0 ] || status=1
done
exit $status
