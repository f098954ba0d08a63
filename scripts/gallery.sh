#!/usr/bin/env bash
# Renders the example gallery: captures the demo scene (if out/demo is
# missing), then runs every pipeline in docs/examples/*.yaml (and those on other inputs in docs/examples/ttk/, volume/
# and publish/), writing its pictures into docs/gallery/ (scaled to 512 pixels wide, but the teaser).
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
# The volume example: a tetrahedral .vtu written by an independent script, then captured
# (volume-normals.yaml captures it itself, through Capture nodes).
mkdir -p "$root/out/volume"
[ -f "$root/out/volume/blobs.vtu" ] || python3 "$root/docs/examples/volume/make_tetrahedra.py" "$root/out/volume/blobs.vtu"
[ -d "$root/out/volume/tetrahedra.cdb" ] ||
  "$darkroom" capture "$root/docs/examples/volume/tetrahedra.yaml" --output "$root/out/volume/tetrahedra.cdb"
# The publishing examples (docs/examples/publish): the teaser's scene, captured
# at 2048 x 1024 with its maxima kept as a point list.
if [ ! -d "$root/out/publish/teaser.cdb" ]; then
  mkdir -p "$root/out/publish"
  "$darkroom" capture "$root/docs/examples/publish/teaser-scene.yaml" --output "$root/out/publish/teaser.cdb"
fi
# The nested-isosurface figure's two captures: translucent shells with 4
# layers, and the opaque core.
for part in shells core; do
  [ -d "$root/out/publish/$part.cdb" ] ||
    "$darkroom" capture "$root/docs/examples/publish/nested-$part-scene.yaml" --output "$root/out/publish/$part.cdb"
done
# The particle AO figure's scene: tracers kept as a point list over a floor.
if [ ! -d "$root/out/publish/particles.cdb" ]; then
  "$darkroom" capture "$root/docs/examples/publish/particles-ao-scene.yaml" --output "$root/out/publish/particles.cdb"
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
# Publishing: every pipeline but the scene file and the --foreach ones, which
# write a database and a movie into out/publish; the orbit's theta = 40
# frames, in azimuth order, become one contact sheet.
for pipeline in "$root"/docs/examples/publish/*.yaml; do
  name=$(basename "$pipeline" .yaml)
  case "$name" in
    *-scene) continue ;;
    foreach-*) args=(--foreach read --output "$root/out/publish") ;;
    *) args=(--output "$root/docs/gallery") ;;
  esac
  if "$darkroom" run "$pipeline" "${args[@]}"; then
    echo "rendered $name"
  else
    echo "FAILED: $name" >&2
    status=1
  fi
done
if [ -d "$root/out/publish/orbit.cdb" ]; then
  frames=()
  for phi in 0 45 90 135 180 225 270 315; do frames+=("$root/out/publish/orbit.cdb/phi=${phi}_theta=40.png"); done
  oiiotool "${frames[@]}" --mosaic 4x2 -o "$root/docs/gallery/publish-orbit.png"
fi
# The particle AO figure: SSAO and PointListAO side by side.
if [ -f "$root/docs/gallery/particles-ssao.png" ] && [ -f "$root/docs/gallery/particles-listao.png" ]; then
  oiiotool "$root/docs/gallery/particles-ssao.png" "$root/docs/gallery/particles-listao.png" --mosaic 2x1 \
    -o "$root/docs/gallery/publish-particles-ao.png"
  rm "$root/docs/gallery/particles-ssao.png" "$root/docs/gallery/particles-listao.png"
fi
# Keep the committed pictures small: 512 pixels wide, the orbit's contact
# sheet 1024, the normals' before and after two halves of 384; the teaser
# stays at the 2048 x 1024 it is rendered at.
for png in "$root"/docs/gallery/*.png; do
  case "$(basename "$png")" in
    publish-teaser.png|publish-nested-translucent.png) continue ;;
    publish-orbit.png) width=1024 ;;
    publish-particles-ao.png) width=1200 ;;  # the difference is per particle
    volume-normals.png) width=768 ;;
    *) width=512 ;;
  esac
  oiiotool "$png" --resize ${width}x0 -o "$png"
done
exit $status
