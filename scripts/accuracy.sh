#!/usr/bin/env bash
# Regenerates docs/accuracy.md: builds the accuracy harness (bench_accuracy)
# and every plugin, runs every sweep on the stress scenes, and turns the CSV
# into the charts, tables and failure pictures of the page. Outside CI: 10–20
# minutes on 2 cores at the default size (192 x 192 scenes); 10 measured with
# a warm ccache on an idle machine.
#
#   scripts/accuracy.sh [--quick] [--size N] [--sweep NAME]...
#   scripts/accuracy.sh --report-only
#
# --sweep NAME (repeatable) runs only those sweeps and keeps the committed
# CSV files and pictures of the others: each sweep's figures still come from
# one run, and the page names the run of each.
#
# Writes docs/accuracy/data/*.csv, docs/images/accuracy/*.png and
# docs/accuracy.md (from bench/accuracy/accuracy.md.in). --report-only skips
# the build and the sweep and rewrites the page, charts and tables from the
# committed CSV files (seconds; for edits to the prose or the report).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
size=192
quick=()
only=()
report_only=0
while [ $# -gt 0 ]; do
  case "$1" in
    --quick) quick=(--quick); size=128 ;;
    --size) size=$2; shift ;;
    --report-only) report_only=1 ;;
    --sweep) only+=(--sweep "$2"); shift ;;
    *) echo "usage: scripts/accuracy.sh [--quick] [--size N] [--sweep NAME]... | --report-only" >&2; exit 2 ;;
  esac
  shift
done

"$root/scripts/install-deps.sh" python3-matplotlib python3-numpy python3-pil
data=$root/docs/accuracy/data
images=$root/docs/images/accuracy
if [ "$report_only" = 1 ]; then
  [ -f "$data/ao.csv" ] || { echo "accuracy.sh: no committed results in $data; run without --report-only first" >&2; exit 1; }
  /usr/bin/python3 "$root/bench/accuracy/report.py" --data "$data" --images "$images" \
    --template "$root/bench/accuracy/accuracy.md.in" --out "$root/docs/accuracy.md"
  exit 0
fi
export DARKROOM_BUILD_DIR=${DARKROOM_BUILD_DIR:-$root/build-accuracy}
export DARKROOM_CMAKE_ARGS="-DCMAKE_BUILD_TYPE=Release -DDARKROOM_BUILD_BENCH=ON -DDARKROOM_BUILD_EDITOR=OFF -DDARKROOM_BUILD_TESTS=OFF ${DARKROOM_CMAKE_ARGS:-}"
"$root/scripts/build.sh" runner bench_accuracy

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
# Sweep and report into a scratch copy of docs/ first, so a failed run leaves
# the committed results alone and the page's relative links are already right.
if [ ${#only[@]} -gt 0 ]; then
  # The other sweeps' committed results stay as they are.
  mkdir -p "$tmp/accuracy/data" "$tmp/images"
  cp "$data"/*.csv "$tmp/accuracy/data/"
  cp -r "$images" "$tmp/images/accuracy"
fi
"$DARKROOM_BUILD_DIR/bin/bench_accuracy" --size "$size" --repeats 2 "${quick[@]}" "${only[@]}" \
  --out "$tmp/accuracy/data" --images "$tmp/images/accuracy"
/usr/bin/python3 "$root/bench/accuracy/report.py" --data "$tmp/accuracy/data" --images "$tmp/images/accuracy" \
  --template "$root/bench/accuracy/accuracy.md.in" --out "$tmp/accuracy.md"
rm -rf "$data" "$images"
mkdir -p "$data" "$(dirname "$images")"
cp "$tmp"/accuracy/data/*.csv "$data/"
cp -r "$tmp/images/accuracy" "$images"
mv "$tmp/accuracy.md" "$root/docs/accuracy.md.tmp"
mv "$root/docs/accuracy.md.tmp" "$root/docs/accuracy.md"
echo "wrote docs/accuracy.md, $(ls "$data" | wc -l) CSV files and $(ls "$images" | wc -l) pictures" >&2
