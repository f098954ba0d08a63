#!/bin/sh
# Capture ingest of a big mesh (docs/performance.md, "Capture ingest"):
# generates an N x N height field as a binary PLY (N = 4096, the default:
# 33.5M triangles, 704 MB; N = 12249: 300M triangles, 6.3 GB), captures one
# 1024x1024 view of it (Z and the point scalar "height") with
# `darkroom capture --profile` under /usr/bin/time -v, and prints the time to
# the first ray, the total, the peak RSS and the bytes per triangle.
#
#   bench/capture/run_ingest_bench.sh [--format ply|vtk|vtk51] BUILD_DIR [N]
#
# --format vtk writes the same mesh as BINARY legacy VTK (classic cells,
# make_height_field_vtk), vtk51 in VTK 5.1's OFFSETS/CONNECTIVITY layout.
# BUILD_DIR: a build with -DDARKROOM_BUILD_BENCH=ON (make_height_field_ply/_vtk).
# DARKROOM=path/to/darkroom times another build's runner on the same file
# (one without --profile reports no time to the first ray).
# DARKROOM_INGEST_DIR=dir keeps the generated mesh there and reuses it.
# The mesh is read from the page cache (it was just written or reused).
set -eu
format=ply
if [ "${1:-}" = --format ]; then
    format=${2:?--format takes ply, vtk or vtk51}
    shift 2
fi
build=${1:?usage: run_ingest_bench.sh [--format ply|vtk|vtk51] BUILD_DIR [N]}
n=${2:-4096}
darkroom=${DARKROOM:-$build/bin/darkroom}
if [ -n "${DARKROOM_INGEST_DIR:-}" ]; then
    dir=$DARKROOM_INGEST_DIR
    mkdir -p "$dir"
else
    dir=$(mktemp -d)
    trap 'rm -rf "$dir"' EXIT
fi
case $format in
    ply) file=heightfield-$n.ply; make="make_height_field_ply" ;;
    vtk) file=heightfield-$n.vtk; make="make_height_field_vtk" ;;
    vtk51) file=heightfield-$n-51.vtk; make="make_height_field_vtk" ;;
    *) echo "run_ingest_bench.sh: unknown format '$format' (ply, vtk or vtk51)" >&2; exit 2 ;;
esac
mesh=$dir/$file
if [ ! -f "$mesh" ]; then
    if [ "$format" = vtk51 ]; then "$build/bin/$make" "$mesh" "$n" --offsets
    else "$build/bin/$make" "$mesh" "$n"; fi
fi
cat > "$dir/scene.yaml" <<YAML
objects:
  - file: $file
cameras:
  resolution: [1024, 1024]
  list:
    - {position: [0, 2.5, 2.5], target: [0, 0, 0], up: [0, 1, 0]}
channels:
  scalars: [height]
YAML
rm -rf "$dir/out.cdb"
echo "load before: $(cat /proc/loadavg)"
profile=--profile
"$darkroom" capture --help | grep -q -- --profile || profile=
/usr/bin/time -v "$darkroom" capture $profile "$dir/scene.yaml" -o "$dir/out.cdb" 2> "$dir/time.txt" || {
    cat "$dir/time.txt"
    exit 1
}
echo "load after:  $(cat /proc/loadavg)"
grep '^darkroom: profile' "$dir/time.txt" || true
triangles=$(( 2 * (n - 1) * (n - 1) ))
wall=$(sed -n 's/.*Elapsed (wall clock) time (h:mm:ss or m:ss): //p' "$dir/time.txt")
rss=$(sed -n 's/.*Maximum resident set size (kbytes): //p' "$dir/time.txt")
first=$(sed -n 's/.*first ray at \([0-9.]*\) s.*/\1/p' "$dir/time.txt")
python3 - "$n" "$triangles" "$wall" "$rss" "${first:-}" "$(stat -c %s "$mesh")" "$format" <<'PY'
import sys
n, tris, wall, rss_kb, first, size, fmt = sys.argv[1:]
parts = [float(p) for p in wall.split(':')]
seconds = sum(p * 60 ** i for i, p in enumerate(reversed(parts)))
tris, rss = int(tris), int(rss_kb) * 1024
print(f"RESULT grid={n} triangles={tris} file_MB={int(size) / 1e6:.0f} first_ray_s={first or 'n/a'} "
      f"total_s={seconds:.2f} peak_rss_MB={rss / 1e6:.0f} bytes_per_triangle={rss / tris:.1f} format={fmt}")
PY
