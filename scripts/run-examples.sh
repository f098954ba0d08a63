# Sourced, not run: the one definition of "run every example" (issue 27),
# shared by scripts/compare-outputs.sh (two builds, byte for byte) and
# tests/examples/check_example_outputs.sh (one build against a manifest).
#   run_all ROOT BUILD OUT [BLOBS_VTU]
# runs every capture scene and every example pipeline of ROOT/docs/examples
# with BUILD/bin/darkroom and writes everything under OUT. BLOBS_VTU, when
# given and present, is the tetrahedral mesh of the volume example
# (make_tetrahedra.py writes it); without it that capture and its pipeline
# are left out. A pipeline that fails prints "FAILED: <name>" and the rest run.
run_all() {
  local root=$1 darkroom="$2/bin/darkroom" out=$3 blobs=${4:-}
  # Scenes and pipelines name ../../out/... and ../../../shared/...: they run
  # from a copy of docs/examples placed so that those lead to this build's
  # outputs and to the shared data.
  mkdir -p "$out/demo" "$out/volume" "$out/publish" "$out/gallery" "$out/tree/docs"
  cp -r "$root/docs/examples" "$out/tree/docs/examples"
  ln -sfn "$out" "$out/tree/out"
  ln -sfn "$root/../shared" "$out/shared"
  local ex="$out/tree/docs/examples" part pipeline name
  for part in surface flow particles; do
    "$darkroom" -q capture "$ex/demo/$part.yaml" -o "$out/demo/$part.cdb"
  done
  "$darkroom" -q capture "$ex/publish/teaser-scene.yaml" -o "$out/publish/teaser.cdb"
  "$darkroom" -q capture "$ex/publish/particles-ao-scene.yaml" -o "$out/publish/particles.cdb"
  "$darkroom" -q capture "$ex/publish/nested-shells-scene.yaml" -o "$out/publish/shells.cdb"
  "$darkroom" -q capture "$ex/publish/nested-core-scene.yaml" -o "$out/publish/core.cdb"
  if [ -n "$blobs" ] && [ -f "$blobs" ]; then
    cp -p "$blobs" "$out/volume/blobs.vtu"  # same time: the marker records it
    "$darkroom" -q capture "$ex/volume/tetrahedra.yaml" -o "$out/volume/tetrahedra.cdb"
  fi
  for pipeline in "$ex"/*.yaml "$ex"/ttk/*.yaml "$ex"/volume/volume-*.yaml "$ex"/publish/*.yaml; do
    name=$(basename "$pipeline" .yaml)
    case "$name" in
      *-scene) continue ;;
      foreach-*) "$darkroom" -q run "$pipeline" --foreach read --output "$out/publish" || echo "FAILED: $name" ;;
      *) "$darkroom" -q run "$pipeline" --output "$out/gallery" || echo "FAILED: $name" ;;
    esac
  done
}
