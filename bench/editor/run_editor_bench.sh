#!/bin/sh
# Runs the editor benchmark under a virtual X server (Mesa llvmpipe), as the
# GUI tests run. Usage:
#   bench/editor/run_editor_bench.sh [BUILD_DIR] [bench_editor args...]
# Needs a build configured with -DDARKROOM_BUILD_BENCH=ON. The demo scene is
# captured at 1024 x 1024 into BUILD_DIR/bench-editor/ on the first run.
set -eu
here=$(cd "$(dirname "$0")" && pwd)
build=${1:-$here/../../build}
[ $# -gt 0 ] && shift
echo "load before: $(cat /proc/loadavg)"
QT_QPA_PLATFORM=xcb xvfb-run -a -s "-screen 0 1600x1000x24" \
  "$build/bin/bench_editor" --work "$build/bench-editor" "$@"
echo "load after: $(cat /proc/loadavg)"
