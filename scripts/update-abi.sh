#!/usr/bin/env bash
# Records a library's ABI as the baseline for its current ABI version, which
# CI compares against (tests/sdk/check_abi.sh):
#   scripts/update-abi.sh [sdk|data]
# sdk (default): sdk/abi/darkroom-sdk-abi<N>.xml, N = DARKROOM_ABI_VERSION;
# data: framework/data/abi/darkroom-data-abi<N>.xml, N = DARKROOM_DATA_ABI_VERSION.
# Run it after a deliberate change: with a bump of the version when the change
# is incompatible.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${DARKROOM_BUILD_DIR:-$root/build}
component=${1:-sdk}
source "$root/scripts/abi_component.sh" "$root" "$component"
"$root/scripts/build.sh" "darkroom_$component" >/dev/null
lib=$(readlink -f "$build/lib/libdarkroom-$component.so")
mkdir -p "$baseline_dir"
abi_dump "$lib" "$baseline"
echo "Recorded the ABI of $lib as $baseline"
