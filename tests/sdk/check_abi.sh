#!/usr/bin/env bash
# The plugin boundary is checked, not trusted: compares the ABI a library
# exports (as libabigail's abidw sees it, restricted to the types of its
# public headers) with the baseline committed for its current ABI version.
#
#   check_abi.sh LIBRARY SOURCE_DIR [sdk|data]
#
#   sdk  (default) libdarkroom-sdk: sdk/include/darkroom, DARKROOM_ABI_VERSION,
#        sdk/abi/darkroom-sdk-abi<N>.xml
#   data libdarkroom-data, which out-of-tree plugins may link to read Cinema
#        databases: framework/data/include/darkroom/data,
#        DARKROOM_DATA_ABI_VERSION, framework/data/abi/darkroom-data-abi<N>.xml
#
# Fails when the ABI changed without a bump of the version (an incompatible
# change), when a compatible change was not recorded, or when no baseline
# exists for the current version. scripts/update-abi.sh records one.
set -euo pipefail
lib=$1
src=$2
component=${3:-sdk}
# The baseline is the uninstrumented library's. Built with AddressSanitizer and
# UBSan (scripts/sanitize.sh), a library exports more: type information that
# UBSan's checks reference and template code ASan keeps out of line. Not an
# ABI change of the product; exit 77 is the test's skip (SKIP_RETURN_CODE).
if [ -n "${DARKROOM_SANITIZED:-}" ]; then
  echo "check_abi: skipped under the sanitizers: an instrumented library exports more than the uninstrumented baseline"
  exit 77
fi
source "$src/scripts/abi_component.sh" "$src" "$component"
if [ ! -f "$baseline" ]; then
  echo "check_abi: no ABI baseline for $macro $version ($baseline)." >&2
  echo "check_abi: after bumping the version, record the new ABI with scripts/update-abi.sh $component" >&2
  exit 1
fi
current=$(mktemp --suffix=.xml)
trap 'rm -f "$current"' EXIT
abi_dump "$lib" "$current"
set +e
report=$(abidiff --suppressions "$abi_suppressions" "$baseline" "$current" 2>&1)
status=$?
set -e
if [ $status -eq 0 ]; then
  echo "check_abi: the $component library's ABI matches the baseline of ABI version $version"
  exit 0
fi
echo "$report"
if [ $((status & 8)) -ne 0 ]; then
  echo "check_abi: the $component library's ABI changed incompatibly but $macro is still $version:" \
       "bump it in $version_header (compiled plugins must be refused) and run scripts/update-abi.sh $component" >&2
elif [ $((status & 4)) -ne 0 ]; then
  echo "check_abi: the $component library's ABI changed compatibly (additions); record it with" \
       "scripts/update-abi.sh $component (no bump needed)" >&2
else
  echo "check_abi: abidiff failed (exit status $status)" >&2
fi
exit 1
