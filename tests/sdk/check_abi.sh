#!/usr/bin/env bash
# The plugin boundary is checked, not trusted: compares the ABI the SDK
# library exports (as libabigail's abidw sees it, restricted to the types of
# the public headers) with the baseline committed for the current
# DARKROOM_ABI_VERSION (sdk/abi/darkroom-sdk-abi<N>.xml).
#
#   check_abi.sh LIBRARY SOURCE_DIR
#
# Fails when the ABI changed without a bump of DARKROOM_ABI_VERSION (an
# incompatible change), when a compatible change was not recorded, or when no
# baseline exists for the current version. scripts/update-abi.sh records one.
set -euo pipefail
lib=$1
src=$2
# The baseline is the uninstrumented library's. Built with AddressSanitizer and
# UBSan (scripts/sanitize.sh), the SDK exports more: type information that
# UBSan's checks reference and template code ASan keeps out of line. Not an
# ABI change of the product; exit 77 is the test's skip (SKIP_RETURN_CODE).
if [ -n "${DARKROOM_SANITIZED:-}" ]; then
  echo "check_abi: skipped under the sanitizers: an instrumented SDK exports more than the uninstrumented baseline"
  exit 77
fi
version=$(sed -n 's/^#define DARKROOM_ABI_VERSION \([0-9]*\)u\{0,1\}.*/\1/p' "$src/sdk/include/darkroom/version.h")
baseline="$src/sdk/abi/darkroom-sdk-abi$version.xml"
if [ ! -f "$baseline" ]; then
  echo "check_abi: no ABI baseline for DARKROOM_ABI_VERSION $version ($baseline)." >&2
  echo "check_abi: after bumping the version, record the new ABI with scripts/update-abi.sh" >&2
  exit 1
fi
current=$(mktemp --suffix=.xml)
trap 'rm -f "$current"' EXIT
# The same options as scripts/update-abi.sh.
abidw --headers-dir "$src/sdk/include/darkroom" --no-corpus-path --no-show-locs --drop-private-types --no-comp-dir-path --exported-interfaces-only --type-id-style hash --no-elf-needed --out-file "$current" "$lib"
set +e
report=$(abidiff "$baseline" "$current" 2>&1)
status=$?
set -e
if [ $status -eq 0 ]; then
  echo "check_abi: the SDK's ABI matches the baseline of ABI version $version"
  exit 0
fi
echo "$report"
if [ $((status & 8)) -ne 0 ]; then
  echo "check_abi: the SDK's ABI changed incompatibly but DARKROOM_ABI_VERSION is still $version:" \
       "bump it in sdk/include/darkroom/version.h (compiled plugins must be refused) and run scripts/update-abi.sh" >&2
elif [ $((status & 4)) -ne 0 ]; then
  echo "check_abi: the SDK's ABI changed compatibly (additions); record it with scripts/update-abi.sh" \
       "(no bump needed)" >&2
else
  echo "check_abi: abidiff failed (exit status $status)" >&2
fi
exit 1
