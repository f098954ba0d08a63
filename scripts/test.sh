#!/usr/bin/env bash
# The README's test command: installs dependencies, builds everything with
# warnings as errors, and runs the whole test suite through ctest.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/install-deps.sh"
export DARKROOM_BUILD_DIR=${DARKROOM_BUILD_DIR:-$root/build}
export DARKROOM_CMAKE_ARGS="-DDARKROOM_WERROR=ON ${DARKROOM_CMAKE_ARGS:-}"
"$root/scripts/build.sh"
cd "$DARKROOM_BUILD_DIR"
ctest --output-on-failure -j "$(nproc)" --timeout 900
