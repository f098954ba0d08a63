#!/usr/bin/env bash
# Configures and builds Darkroom into ${DARKROOM_BUILD_DIR:-build} with Ninja
# (and ccache when present). Extra arguments are passed to ninja (targets).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${DARKROOM_BUILD_DIR:-$root/build}
# install-deps.sh installs the Python module's packages (python3-numpy,
# python3-pytest, ...) for Debian's interpreter; a pyenv or conda python3
# earlier on PATH cannot import them, so build against Debian's unless told.
python_arg=""
if [[ "${DARKROOM_CMAKE_ARGS:-}" != *Python3_EXECUTABLE* ]] && [ -x /usr/bin/python3 ]; then
  python_arg="-DPython3_EXECUTABLE=/usr/bin/python3"
fi
if [ ! -f "$build/build.ninja" ]; then
  cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo $python_arg ${DARKROOM_CMAKE_ARGS:-} >/dev/null
fi
jobs=${DARKROOM_JOBS:-$(nproc)}
ninja -C "$build" -j "$jobs" "$@"
