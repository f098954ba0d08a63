#!/usr/bin/env bash
# Runs every capture scene and every example pipeline of docs/examples with
# two builds of Darkroom and compares what they write, byte for byte: the
# check that a refactoring changed no output (issue 27). Each build's plugins
# are its own (<build>/lib/darkroom/plugins).
#   scripts/compare-outputs.sh OLD_BUILD NEW_BUILD [WORK_DIR]
# Prints one line per file that differs and exits 1 if any does.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
old=$(cd "$1" && pwd)
new=$(cd "$2" && pwd)
work=${3:-$(mktemp -d)}
mkdir -p "$work"

run_all() {  # BUILD OUT
  local darkroom="$1/bin/darkroom" out=$2
  # Scenes and pipelines name ../../out/... and ../../../shared/...: they run
  # from a copy of docs/examples placed so that those lead to this build's
  # outputs and to the shared data.
  mkdir -p "$out/demo" "$out/volume" "$out/publish" "$out/gallery" "$out/tree/docs"
  cp -r "$root/docs/examples" "$out/tree/docs/examples"
  ln -sfn "$out" "$out/tree/out"
  ln -sfn "$root/../shared" "$out/shared"
  local ex="$out/tree/docs/examples"
  for part in surface flow particles; do
    "$darkroom" -q capture "$ex/demo/$part.yaml" -o "$out/demo/$part.cdb"
  done
  "$darkroom" -q capture "$ex/publish/teaser-scene.yaml" -o "$out/publish/teaser.cdb"
  if [ -f "$work/blobs.vtu" ]; then
    cp -p "$work/blobs.vtu" "$out/volume/blobs.vtu"  # same time: the marker records it
    "$darkroom" -q capture "$ex/volume/tetrahedra.yaml" -o "$out/volume/tetrahedra.cdb"
  fi
  for pipeline in "$ex"/*.yaml "$ex"/ttk/*.yaml "$ex"/volume/volume-*.yaml "$ex"/publish/*.yaml; do
    name=$(basename "$pipeline" .yaml)
    case "$name" in
      teaser-scene) continue ;;
      foreach-*) "$darkroom" -q run "$pipeline" --foreach read --output "$out/publish" || echo "FAILED: $name" ;;
      *) "$darkroom" -q run "$pipeline" --output "$out/gallery" || echo "FAILED: $name" ;;
    esac
  done
}

python3 "$root/docs/examples/volume/make_tetrahedra.py" "$work/blobs.vtu" 2>/dev/null || true
# Both builds write into the same folder ($work/run, then moved), since
# databases record the paths of the files they were made from.
run_all "$old" "$work/run" > "$work/old.log" 2>&1 || true
mv "$work/run" "$work/old"
run_all "$new" "$work/run" > "$work/new.log" 2>&1 || true
mv "$work/run" "$work/new"
status=0
count=0
while IFS= read -r -d '' f; do
  rel=${f#"$work/old/"}
  case "$rel" in tree/* | shared/*) continue ;; esac
  count=$((count + 1))
  other="$work/new/$rel"
  if [ ! -f "$other" ]; then echo "only in the old build's output: $rel"; status=1; continue; fi
  cmp -s "$f" "$other" || { echo "differs: $rel"; status=1; }
done < <(find "$work/old" \( -path "$work/old/tree" -o -path "$work/old/shared" \) -prune -o -type f -print0)
while IFS= read -r -d '' f; do
  rel=${f#"$work/new/"}
  [ -f "$work/old/$rel" ] || { echo "only in the new build's output: $rel"; status=1; }
done < <(find "$work/new" \( -path "$work/new/tree" -o -path "$work/new/shared" \) -prune -o -type f -print0)
echo "compared $count files written by the old build ($old) with the new ($new): $([ $status -eq 0 ] && echo identical || echo DIFFERENT)"
grep -h "FAILED" "$work/old.log" "$work/new.log" || true
exit $status
