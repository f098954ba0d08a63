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
# The editor is part of what is tested: fail loudly if it was not built or
# its GUI tests were not registered (a skipped editor once passed CI).
if [ ! -x bin/darkroom-editor ]; then
  echo "test.sh: bin/darkroom-editor was not built (see the CMake output about Qt 6)" >&2
  exit 1
fi
gui_tests=$(ctest -N -L gui | sed -n 's/^Total Tests: //p')
if [ "${gui_tests:-0}" -eq 0 ]; then
  echo "test.sh: no GUI tests are registered (ctest -L gui lists none)" >&2
  exit 1
fi
# Likewise the MPI tests (they run under mpirun -np 4 --oversubscribe).
mpi_tests=$(ctest -N -L mpi | sed -n 's/^Total Tests: //p')
if [ "${mpi_tests:-0}" -eq 0 ]; then
  echo "test.sh: no MPI tests are registered (ctest -L mpi lists none; see the CMake output about MPI)" >&2
  exit 1
fi
# And the Python module's tests (pytest, and the package as installed).
python_tests=$(ctest -N -L python | sed -n 's/^Total Tests: //p')
if [ "${python_tests:-0}" -eq 0 ]; then
  echo "test.sh: no Python tests are registered (ctest -L python lists none; see the CMake output about Python)" >&2
  exit 1
fi
ctest --output-on-failure -j "$(nproc)" --timeout 900
echo "test.sh: the editor was built and its ${gui_tests} GUI tests (ctest -L gui) were part of this run"
echo "test.sh: ${mpi_tests} MPI tests (ctest -L mpi) were part of this run"
echo "test.sh: ${python_tests} Python tests (ctest -L python) were part of this run"
