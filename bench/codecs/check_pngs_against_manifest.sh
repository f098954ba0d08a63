#!/usr/bin/env bash
# Do the examples' PNGs, written by a new encoder, hold the pixels of the
# PNGs recorded in the manifest by the encoder before it? Each PNG of a kept
# run (check_example_outputs.sh check BUILD MANIFEST WORK_DIR) is decoded and
# encoded again as the manifest's encoder did (png_reencode_before AS:
# libpng-z2, libdeflate-l1, or runs, the default: the writer's run encoder,
# which recorded the manifest's PNGs since 29 November); its SHA-256 must be the
# manifest's. Prints one line per PNG; exits 1 if any differs.
#   check_pngs_against_manifest.sh BUILD MANIFEST WORK_DIR [AS]
set -euo pipefail
build=$1 manifest=$2 run=$3/run as=${4:-runs}
tool=$build/bench/codecs/png_reencode_before
[ -x "$tool" ] || tool=$build/bin/png_reencode_before
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
status=0
while read -r rel recorded; do
  [[ $rel == *.png ]] || continue
  if [ ! -f "$run/$rel" ]; then echo "missing: $rel"; status=1; continue; fi
  "$tool" "$as" "$run/$rel" "$tmp/before.png"
  again=$(sha256sum "$tmp/before.png" | cut -d' ' -f1)
  bytes_now=$(stat -c %s "$run/$rel"); bytes_before=$(stat -c %s "$tmp/before.png")
  if [ "$again" = "$recorded" ]; then
    echo "same pixels: $rel ($bytes_before -> $bytes_now bytes)"
  else
    echo "DIFFERENT pixels: $rel"; status=1
  fi
done < <(grep -v '^#' "$manifest")
exit $status
