#!/bin/sh
# Darkroom's volume representations against VTK's readers and filters on the
# same tetrahedral .vtu (written by docs/examples/volume/make_tetrahedra.py,
# ascii, then converted by VTK to appended raw binary). Usage:
#   bench/volume/run_volume_bench.sh [BUILD_DIR] [CELLS_PER_AXIS]
# Needs a build configured with -DDARKROOM_BUILD_BENCH=ON and python3-vtk9.
set -eu
here=$(cd "$(dirname "$0")" && pwd)
build=${1:-$here/../../build}
n=${2:-48}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
python3 "$here/../../docs/examples/volume/make_tetrahedra.py" "$tmp/ascii.vtu" "$n"
/usr/bin/python3 "$here/vtk_volume_peer.py" "$tmp/ascii.vtu" --reps 1 --write-binary "$tmp/binary.vtu"
ls -l "$tmp/ascii.vtu" "$tmp/binary.vtu" | awk '{print $5, $9}'
uptime
for f in ascii binary; do
  echo "== $f"
  "$build/bin/bench_volume" "$tmp/$f.vtu" --field field --value 0.5 | tee "$tmp/ours.txt"
  /usr/bin/python3 "$here/vtk_volume_peer.py" "$tmp/$f.vtu" --field field --value 0.5 | tee "$tmp/vtk.txt"
  python3 - "$tmp/ours.txt" "$tmp/vtk.txt" <<'PY'
import re, sys
def result(p):
    line = [l for l in open(p) if l.startswith("RESULT")][0]
    return {k: float(v) for k, v in re.findall(r"(\w+)_ms=([0-9.]+)", line)}
ours, vtk = result(sys.argv[1]), result(sys.argv[2])
for k in ours:
    print(f"  {k:<11} ours {ours[k]:9.1f} ms   VTK {vtk[k]:9.1f} ms   VTK / ours = {vtk[k] / ours[k]:.2f}")
PY
done
