#!/usr/bin/env bash
# Batch shading throughput (issue 32): `darkroom run --foreach` of a
# colour-mapping pipeline (CinemaReader -> ColorMapping -> CinemaWriter, PNG)
# over 2048² EXR entries, one entry at a time and with entries in flight.
#
#   bench/batch/run_foreach_bench.sh [BUILD_DIR] [RUNS]
#
# The entries: the demo's isosurface (docs/examples/demo/surface.yaml)
# captured at 2048 x 2048 for 12 cameras (phi 0-330 by 30, theta 15), Z and
# `height`, float, zip; captured once into BUILD_DIR/bench-foreach/. Prints
# each node's mean time per entry (--profile, one entry at a time), then
# for --in-flight 1 and the default (3): wall time per entry (least and
# median of RUNS whole processes, start-up included), CPU per entry and peak
# memory, with the load average before and after.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
build=$(cd "${1:-$here/../../build}" && pwd)
runs=${2:-5}
darkroom=$build/bin/darkroom
work=$build/bench-foreach
mkdir -p "$work"
cd "$work"
entries=12
if [ ! -f db.cdb/data.csv ]; then
  sed -e 's/resolution: \[768, 768\]/resolution: [2048, 2048]/' \
      -e 's/phi: \[.*\]/phi: [0, 30, 60, 90, 120, 150, 180, 210, 240, 270, 300, 330]/' \
      -e 's/theta: \[.*\]/theta: [15]/' "$here/../../docs/examples/demo/surface.yaml" > scene.yaml
  grep -q 'resolution: \[2048, 2048\]' scene.yaml || { echo "scene.yaml: the demo's resolution line changed" >&2; exit 1; }
  "$darkroom" capture scene.yaml -o db.cdb --overwrite >&2
fi
cat > map.yaml <<'YAML'
darkroom: 1
nodes:
  read:
    type: CinemaReader
    parameters: {database: db.cdb}
  colour:
    type: ColorMapping
    parameters: {channel: height, colormap: cool-to-warm}
  write:
    type: CinemaWriter
    parameters: {database: out.cdb, format: png, mode: overwrite}
edges:
  - read.image -> colour.image
  - read.row -> write.row
  - colour.image -> write.image
YAML
echo "load before: $(cut -d' ' -f1-3 /proc/loadavg); $(nproc) CPUs"
# Each node's mean per entry, one entry at a time.
"$darkroom" run map.yaml --foreach read --in-flight 1 --profile 2>&1 |
  awk '$2 ~ /^(CinemaReader|ColorMapping|CinemaWriter)$/ && $3 == "ran" {sum[$2] += $4; n[$2]++}
       END {printf "per entry, one at a time (--profile means):"; for (k in sum) printf " %s %.1f ms", k, sum[k] / n[k]; print ""}'
median() { sort -n | awk '{v[NR] = $1} END {print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2}'; }
printf '\n| --in-flight | wall ms per entry, least | median | CPU ms per entry, median | peak RSS MiB, median |\n|---|---:|---:|---:|---:|\n'
for inflight in 1 0; do
  : > times.txt
  for _ in $(seq "$runs"); do
    /usr/bin/time -f '%e %U %S %M' -a -o times.txt "$darkroom" run map.yaml --foreach read --in-flight "$inflight" 2>/dev/null
  done
  least=$(awk -v n=$entries '{print $1 * 1000 / n}' times.txt | sort -n | head -1)
  med=$(awk -v n=$entries '{print $1 * 1000 / n}' times.txt | median)
  cpu=$(awk -v n=$entries '{print ($2 + $3) * 1000 / n}' times.txt | median)
  rss=$(awk '{print $4 / 1024}' times.txt | median)
  label=$inflight; [ "$inflight" = 0 ] && label="3 (default)"
  printf '| %s | %.0f | %.0f | %.0f | %.0f |\n' "$label" "$least" "$med" "$cpu" "$rss"
done
echo
echo "load after: $(cut -d' ' -f1-3 /proc/loadavg)"
