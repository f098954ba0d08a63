#!/usr/bin/env bash
# Records the SDK library's ABI as the baseline for the current
# DARKROOM_ABI_VERSION (sdk/abi/darkroom-sdk-abi<N>.xml), which CI compares
# against (tests/sdk/check_abi.sh). Run it after a deliberate SDK change:
# with a bump of DARKROOM_ABI_VERSION when the change is incompatible.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${DARKROOM_BUILD_DIR:-$root/build}
"$root/scripts/build.sh" darkroom_sdk >/dev/null
version=$(sed -n 's/^#define DARKROOM_ABI_VERSION \([0-9]*\)u\{0,1\}.*/\1/p' "$root/sdk/include/darkroom/version.h")
lib=$(readlink -f "$build/lib/libdarkroom-sdk.so")
out="$root/sdk/abi/darkroom-sdk-abi$version.xml"
src=$root
# The same options as tests/sdk/check_abi.sh.
abidw --headers-dir "$src/sdk/include/darkroom" --no-corpus-path --no-show-locs --drop-private-types --no-comp-dir-path --exported-interfaces-only --type-id-style hash --no-elf-needed --out-file "$out" "$lib"
echo "Recorded the ABI of $lib as $out"
