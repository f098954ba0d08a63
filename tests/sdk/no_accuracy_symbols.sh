#!/usr/bin/env bash
# The accuracy harness (metrics, ray-traced references, stress scenes:
# tests/support/accuracy) is for tests and benchmarks only: no installed
# shared library may define one of its symbols (issue 27).
#   no_accuracy_symbols.sh BUILD_DIR
set -euo pipefail
build=$1
prefix=$(mktemp -d)
trap 'rm -rf "$prefix"' EXIT
cmake --install "$build" --prefix "$prefix" > /dev/null
libs=$(find "$prefix" -name '*.so*' -type f)
[ -n "$libs" ] || { echo "no shared library was installed under $prefix" >&2; exit 1; }
found=0
for lib in $libs; do
  # Demangled names of the defined dynamic symbols in the harness's namespaces.
  hits=$(nm -D --defined-only -C "$lib" | grep -E 'darkroom::(metrics|reference|stress)::' || true)
  if [ -n "$hits" ]; then
    echo "$lib defines accuracy-harness symbols:" >&2
    echo "$hits" | head -5 >&2
    found=1
  fi
done
count=$(echo "$libs" | wc -l)
[ $found -eq 0 ] && echo "no accuracy-harness symbol in the $count installed shared libraries"
exit $found
