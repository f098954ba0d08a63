#!/bin/sh
# Runs an editor benchmark under a virtual X server (Mesa llvmpipe), as the
# GUI tests run. Usage:
#   bench/editor/run_editor_bench.sh [BUILD_DIR] [bench_editor args...]
#   bench/editor/run_editor_bench.sh [BUILD_DIR] explorer [bench_explorer args...]
# Needs a build configured with -DDARKROOM_BUILD_BENCH=ON. The first form
# drags values on the demo pipeline (the demo scene is captured at
# 1024 x 1024, or --size 2048, --size 2048x1024, into
# BUILD_DIR/bench-editor/demo-WxH/ on the first run at that size); the second
# brushes and scrolls the explorer on a generated ensemble of 10,000
# entries (written into BUILD_DIR/bench-editor/ on the first run).
set -eu
here=$(cd "$(dirname "$0")" && pwd)
build=${1:-$here/../../build}
[ $# -gt 0 ] && shift
bench=bench_editor
if [ "${1:-}" = explorer ]; then
  bench=bench_explorer
  shift
fi
echo "load before: $(cat /proc/loadavg)"
QT_QPA_PLATFORM=xcb xvfb-run -a -s "-screen 0 1600x1000x24" \
  "$build/bin/$bench" --work "$build/bench-editor" "$@"
echo "load after: $(cat /proc/loadavg)"
