#!/usr/bin/env bash
# Renders the example gallery: captures the demo scene (if out/demo is
# missing), then runs every pipeline in docs/examples/*.yaml (and those on other inputs in docs/examples/ttk/ and volume/), writing its
# pictures into docs/gallery/ (scaled to 512 pixels wide).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
export DARKROOM_BUILD_DIR=${DARKROOM_BUILD_DIR:-$root/build}
darkroom="$DARKROOM_BUILD_DIR/bin/darkroom"
[ -x "$darkroom" ] || "$root/scripts/build.sh" runner
mkdir -p "$root/out/demo" "$root/docs/gallery"
for part in surface flow particles; do
  [ -d "$root/out/demo/$part.cdb" ] ||
    "$darkroom" capture "$root/docs/examples/demo/$part.yaml" --output "$root/out/demo/$part.cdb"
done
# The volume example: a tetrahedral .vtu written by an independent script, then captured.
if [ ! -d "$root/out/volume/tetrahedra.cdb" ]; then
  mkdir -p "$root/out/volume"
  [ -f "$root/out/volume/blobs.vtu" ] || python3 "$root/docs/examples/volume/make_tetrahedra.py" "$root/out/volume/blobs.vtu"
  "$darkroom" capture "$root/docs/examples/volume/tetrahedra.yaml" --output "$root/out/volume/tetrahedra.cdb"
fi
status=0
# The pipelines on other inputs (the shared TTK database, the volume example) live in subfolders.
for pipeline in "$root"/docs/examples/*.yaml "$root"/docs/examples/ttk/*.yaml "$root"/docs/examples/volume/volume-*.yaml; do
  name=$(basename "$pipeline" .yaml)
  if "$darkroom" run "$pipeline" --output "$root/docs/gallery"; then
    echo "rendered $name"
  else
    echo "FAILED: $name" >&2
    status=1
  fi
done
# Keep the committed pictures small.
for png in "$root"/docs/gallery/*.png; do
  oiiotool "$png" --resize 512x0 -o "$png"
done
exit $status
