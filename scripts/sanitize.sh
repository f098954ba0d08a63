#!/usr/bin/env bash
# The sanitizer run of issue 26: the whole product (SDK, libraries, runner,
# plugins, in situ, editor, MPI) and its test suite built with AddressSanitizer
# and UndefinedBehaviorSanitizer into ${DARKROOM_ASAN_BUILD_DIR:-build-asan},
# then every test but the fuzz label (the harnesses are sanitized builds of
# their own) run under them. Too long for CI's budget next to the normal build
# (docs/formats.md, "Sanitizers", gives the time measured); run it before
# resolving an issue that touches native code. Extra arguments go to ctest.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/install-deps.sh"
build=${DARKROOM_ASAN_BUILD_DIR:-$root/build-asan}
if [ ! -f "$build/build.ninja" ]; then
  cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DDARKROOM_SANITIZE=ON \
    -DDARKROOM_WERROR=ON >/dev/null
fi
ninja -C "$build" -j "${DARKROOM_JOBS:-$(nproc)}"
# Leaks of the libraries we load but do not own (OpenMPI, D-Bus, fontconfig)
# are suppressed by name in tests/sanitizers/lsan.supp; ours are reported.
# asan.supp names the one library whose string use strict_string_checks
# misreads. intercept_tls_get_addr=0: GCC 12's runtime takes some dynamic TLS
# blocks for glibc 2.19's layout and LeakSanitizer's tracer then crashes at
# exit ("Tracer caught signal 11", a third of the runs of a test with worker
# threads); the blocks stay reachable through glibc's own pointers.
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1:strict_string_checks=1:detect_stack_use_after_return=1:intercept_tls_get_addr=0:suppressions=$root/tests/sanitizers/asan.supp}
export LSAN_OPTIONS=${LSAN_OPTIONS:-suppressions=$root/tests/sanitizers/lsan.supp:print_suppressions=0}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-halt_on_error=1:print_stacktrace=1:suppressions=$root/tests/sanitizers/ubsan.supp}
export DARKROOM_SANITIZED=1
cd "$build"
ctest --output-on-failure -j "$(nproc)" --timeout 1800 -LE fuzz "$@"
