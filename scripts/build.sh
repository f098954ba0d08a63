#!/usr/bin/env bash
# Configures and builds Darkroom into ${DARKROOM_BUILD_DIR:-build} with Ninja
# (and ccache when present). Extra arguments are passed to ninja (targets).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${DARKROOM_BUILD_DIR:-$root/build}
if [ ! -f "$build/build.ninja" ]; then
  cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo ${DARKROOM_CMAKE_ARGS:-} >/dev/null
fi
jobs=${DARKROOM_JOBS:-$(nproc)}
ninja -C "$build" -j "$jobs" "$@"
