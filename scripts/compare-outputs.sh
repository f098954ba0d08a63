#!/usr/bin/env bash
# Runs every capture scene and every example pipeline of docs/examples with
# two builds of Darkroom and compares what they write, byte for byte: the
# check that a refactoring changed no output (issue 27). Each build's plugins
# are its own (<build>/lib/darkroom/plugins).
#   scripts/compare-outputs.sh OLD_BUILD NEW_BUILD [WORK_DIR]
# Prints one line per file that differs and exits 1 if any does. With one
# build, tests/examples/check_example_outputs.sh compares against a manifest.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
old=$(cd "$1" && pwd)
new=$(cd "$2" && pwd)
work=${3:-$(mktemp -d)}
mkdir -p "$work"

# run_all ROOT BUILD OUT [BLOBS_VTU]: every capture scene and example pipeline.
source "$root/scripts/run-examples.sh"

python3 "$root/docs/examples/volume/make_tetrahedra.py" "$work/blobs.vtu" 2>/dev/null || true
# Both builds write into the same folder ($work/run, then moved), since
# databases record the paths of the files they were made from.
run_all "$root" "$old" "$work/run" "$work/blobs.vtu" > "$work/old.log" 2>&1 || true
mv "$work/run" "$work/old"
run_all "$root" "$new" "$work/run" "$work/blobs.vtu" > "$work/new.log" 2>&1 || true
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
