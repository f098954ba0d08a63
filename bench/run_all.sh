#!/usr/bin/env bash
# Every speed figure of docs/performance.md from one run, one benchmark after
# the other on the same machine: the passes against memcpy, the capture
# against Embree's plain loop and VTK, SSAO against VTK's vtkSSAOPass, the
# demo pipeline's edits, the codecs, batch shading (--foreach), capture
# ingest of a 33.5M-triangle PLY and the editor at 2048². Writes the raw
# outputs and the machine's load into DIR (default bench-results/) for the
# page's tables. DARKROOM_BENCH_300M=1 adds the 300M-triangle capture (about
# 3 minutes and 17 GB).
#
#   bench/run_all.sh [BUILD_DIR] [DIR]
#
# Needs a build configured with -DDARKROOM_BUILD_BENCH=ON; installs the
# peers' packages (python3-vtk9, xvfb) through scripts/install-deps.sh.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
build=${1:-$here/../build}
out=${2:-$here/../bench-results}
mkdir -p "$out"
"$here/../scripts/install-deps.sh" python3-vtk9 xvfb xauth
log() { echo "$(date -Is) $(cut -d' ' -f1-3 /proc/loadavg) $*" | tee -a "$out/load.txt"; }
: > "$out/load.txt"
log "start; $(nproc) CPUs"
"$build/bin/bench_passes" --benchmark_out="$out/passes.json" --benchmark_out_format=json > "$out/passes.txt"
log "after bench_passes"
/usr/bin/python3 "$here/passes/report.py" "$out/passes.json" > "$out/passes.md"
"$here/capture/run_capture_bench.sh" "$build" > "$out/capture.txt" 2>&1
log "after the capture bench and its VTK peer"
"$here/ssao-peer/run_ssao_peer.sh" "$build" > "$out/ssao-peer.txt" 2>&1
log "after the SSAO peer"
"$build/bin/bench_edits" 1024 5 > "$out/edits.md"
log "after bench_edits"
"$build/bin/bench_codecs" --benchmark_repetitions=3 --benchmark_report_aggregates_only=true > "$out/codecs.txt"
log "after bench_codecs"
"$here/batch/run_foreach_bench.sh" "$build" 5 > "$out/batch.md"
log "after the --foreach batch"
"$here/capture/run_ingest_bench.sh" "$build" 4096 > "$out/ingest.txt" 2>&1
log "after capture ingest (4096)"
if [ "${DARKROOM_BENCH_300M:-0}" = 1 ]; then
  "$here/capture/run_ingest_bench.sh" "$build" 12249 > "$out/ingest-300m.txt" 2>&1
  log "after capture ingest (12249)"
fi
"$here/editor/run_editor_bench.sh" "$build" --size 2048 > "$out/editor-2048.txt" 2>&1
log "after the editor at 2048²"
echo "results in $out" >&2
