#!/bin/sh
# Runs the capture benchmark and the VTK peer on the same mesh, camera and
# resolution, and prints the ratios. Usage:
#   bench/capture/run_capture_bench.sh [BUILD_DIR] [extra bench_capture args...]
# Needs a build configured with -DDARKROOM_BUILD_BENCH=ON, python3-vtk9 and xvfb.
set -eu
here=$(cd "$(dirname "$0")" && pwd)
build=${1:-$here/../../build}
[ $# -gt 0 ] && shift
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

"$build/bin/bench_capture" --camera-json "$tmp/camera.json" "$@" | tee "$tmp/capture.txt"
echo
xvfb-run -a -s "-screen 0 1920x1200x24" /usr/bin/python3 "$here/vtk_peer.py" --camera "$tmp/camera.json" | tee "$tmp/vtk.txt"
echo
cap=$(sed -n 's/^RESULT capture_ms=\([0-9.]*\).*/\1/p' "$tmp/capture.txt")
vtk=$(sed -n 's/^RESULT vtk_ms=\([0-9.]*\).*/\1/p' "$tmp/vtk.txt")
python3 -c "import sys; c, v = float(sys.argv[1]), float(sys.argv[2]); print('capture (Z + scalar + normals) %.2f ms per frame, VTK render + z read-back %.2f ms: capture is %.2fx %s' % (c, v, max(v/c, c/v), 'faster' if c < v else 'slower'))" "$cap" "$vtk"
