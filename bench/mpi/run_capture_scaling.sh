#!/usr/bin/env bash
# Strong and weak scaling of `darkroom capture` over MPI ranks
# (docs/scale-out.md). Usage:
#   bench/mpi/run_capture_scaling.sh [BUILD_DIR] [RANKS...]   (default ranks: 1 2 4)
# Strong: one scene (an isosurface of resolution 128 and 200,000 particles,
# four 1024 x 1024 views) captured by 1, 2, 4 ranks. Weak: 100,000 particles
# per rank, so each rank's share of the particles stays the same. Prints the runner's own
# split of the time (ray tracing and compositing: the slowest rank's).
# On a machine with fewer cores than ranks the ranks share the cores: say so
# with the figures.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
build=${1:-$here/../../build}
[ $# -gt 0 ] && shift
ranks=("$@")
[ ${#ranks[@]} -eq 0 ] && ranks=(1 2 4)
darkroom="$build/bin/darkroom"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
export OMPI_ALLOW_RUN_AS_ROOT=${OMPI_ALLOW_RUN_AS_ROOT:-1} OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=${OMPI_ALLOW_RUN_AS_ROOT_CONFIRM:-1}

scene() {  # particles per rank-share, ranks
  cat > "$tmp/scene.yaml" <<YAML
objects:
  - generator: isosurface
    parameters: {resolution: 128}
    fields: [height]
  - generator: particles
    parameters: {count: $1}
cameras:
  resolution: [1024, 1024]
  grid: {phi: 4, theta: [20]}
channels:
  scalars: [height, value]
  normals: true
YAML
}

run() {  # label, ranks
  local out="$tmp/db.cdb" log="$tmp/log"
  if [ "$2" = 0 ]; then
    /usr/bin/time -f "%e" "$darkroom" capture "$tmp/scene.yaml" -o "$out" --overwrite 2> "$log"
  else
    /usr/bin/time -f "%e" mpirun -np "$2" --oversubscribe "$darkroom" capture "$tmp/scene.yaml" -o "$out" --overwrite 2> "$log"
  fi
  local wall trace comp
  wall=$(tail -1 "$log")
  trace=$(sed -n 's/.*ray tracing \([0-9.]*\) s.*/\1/p' "$log")
  comp=$(sed -n 's/.*compositing \([0-9.]*\) s.*/\1/p' "$log")
  printf "%-8s %-22s %8s %12s %12s\n" "$1" "$([ "$2" = 0 ] && echo 'alone (no MPI)' || echo "mpirun -np $2")" "$wall" "${trace:--}" "${comp:--}"
}

echo "# $(nproc) cores; load: $(cut -d' ' -f1-3 /proc/loadavg)"
printf "%-8s %-22s %8s %12s %12s\n" scaling run "wall s" "trace s" "composite s"
scene 200000
run strong 0
for n in "${ranks[@]}"; do run strong "$n"; done
for n in "${ranks[@]}"; do
  scene $((100000 * n))
  run weak "$n"
done
echo "# load after: $(cut -d' ' -f1-3 /proc/loadavg)"
