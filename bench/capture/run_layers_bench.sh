#!/bin/sh
# Layered captures (issue 30): capture time for K = 1, 2, 4, 8 crossings per
# pixel by both methods, and flat against deep EXR storage of the result, on
# nested isosurfaces of the demo field and a stack of sheets. Usage:
#   bench/capture/run_layers_bench.sh [BUILD_DIR] [extra bench_layers args...]
# Needs a build configured with -DDARKROOM_BUILD_BENCH=ON. The figures in
# docs/capture.md ("Layers") come from one run of it.
set -eu
here=$(cd "$(dirname "$0")" && pwd)
build=${1:-$here/../../build}
[ $# -gt 0 ] && shift
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
echo "machine: $(nproc) cores, $(sed -n 's/^model name[[:space:]]*: //p' /proc/cpuinfo | head -1)"
"$build/bin/bench_layers" --out "$tmp" "$@"
