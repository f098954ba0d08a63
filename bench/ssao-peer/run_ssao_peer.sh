#!/bin/sh
# SSAO against VTK's vtkSSAOPass (ParaView's ambient occlusion) on the same
# mesh, camera, resolution, radius and sample count, one after the other in
# one run, and the ratio. Usage:
#   bench/ssao-peer/run_ssao_peer.sh [BUILD_DIR] [extra bench_ssao_peer args...]
# Needs a build configured with -DDARKROOM_BUILD_BENCH=ON (targets
# bench_ssao_peer, ssao, capture-embree); installs python3-vtk9, xvfb and
# xauth through scripts/install-deps.sh (as root; otherwise it prints the
# apt-get command).
set -eu
here=$(cd "$(dirname "$0")" && pwd)
build=${1:-$here/../../build}
[ $# -gt 0 ] && shift
"$here/../../scripts/install-deps.sh" python3-vtk9 xvfb xauth
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

echo "load: $(uptime)"
"$build/bin/bench_ssao_peer" --camera-json "$tmp/camera.json" "$@" | tee "$tmp/ours.txt"
echo
xvfb-run -a -s "-screen 0 1920x1200x24" /usr/bin/python3 "$here/vtk_ssao_peer.py" --camera "$tmp/camera.json" \
  | tee "$tmp/vtk.txt"
echo
echo "load: $(uptime)"
vtk=$(sed -n 's/^RESULT vtk_ssao_ms=\([0-9.-]*\).*/\1/p' "$tmp/vtk.txt")
for setting in hemisphere16 horizon4x8 hemisphere16-full horizon4x8-full; do
  ours=$(sed -n "s/^RESULT ssao_ms $setting=\([0-9.]*\).*/\1/p" "$tmp/ours.txt")
  python3 -c "import sys; o, v = float(sys.argv[1]), float(sys.argv[2]); print('SSAO %-17s %7.2f ms per frame, vtkSSAOPass (kernel 16, blur) %7.2f ms: ours is %.2fx %s' % (sys.argv[3], o, v, max(v/o, o/v), 'faster' if o < v else 'slower'))" "$ours" "$vtk" "$setting"
done
