#!/usr/bin/env bash
# The README's main command: installs dependencies, builds the runner and its
# plugins, captures the built-in demo scene (isosurface, streamlines,
# particles, maxima) into Cinema databases under out/demo/, and shades one
# view of it into out/demo.png with docs/examples/demo.yaml.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/install-deps.sh"
export DARKROOM_BUILD_DIR=${DARKROOM_BUILD_DIR:-$root/build}
"$root/scripts/build.sh" runner
darkroom="$DARKROOM_BUILD_DIR/bin/darkroom"
mkdir -p "$root/out/demo"
for part in surface flow particles; do
  db="$root/out/demo/$part.cdb"
  # out/demo is this script's own folder: a database there without the marker
  # file was written by a Darkroom older than it, which --overwrite refuses.
  if [ -d "$db" ] && [ ! -f "$db/.darkroom-database" ]; then rm -rf "$db"; fi
  "$darkroom" capture "$root/docs/examples/demo/$part.yaml" --output "$root/out/demo/$part.cdb" --overwrite
done
"$darkroom" run "$root/docs/examples/demo.yaml" --output "$root/out"
echo "Wrote $root/out/demo.png"
