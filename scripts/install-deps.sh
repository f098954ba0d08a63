#!/usr/bin/env bash
# Installs what Darkroom needs to build and test on Debian 12, from Debian's
# archive only. As root it installs; otherwise it prints the exact command.
# Extra package names given as arguments are installed too (scripts that need
# more than the build, e.g. scripts/accuracy.sh's plotting, pass theirs).
set -euo pipefail

packages=(
  # toolchain
  g++ cmake ninja-build ccache pkg-config git
  # libraries
  libembree-dev libtbb-dev libopenimageio-dev openimageio-tools libopenexr-dev libpng-dev
  libyaml-cpp-dev libfmt-dev libcli11-dev libexpat1-dev zlib1g-dev libzip-dev libsqlite3-dev
  nlohmann-json3-dev
  # the PNG writer's deflate (docs/performance.md, "Codecs")
  libdeflate-dev
  # pycinema's and ParaView's .h5 Cinema products (docs/formats.md)
  libhdf5-dev
  # text of ColorLegend and Annotation (pango, cairo; font: fonts-dejavu-core
  # below), and the Movie node's H.264 encoding (FFmpeg's libraries, libx264)
  libpango1.0-dev libcairo2-dev libavcodec-dev libavformat-dev libswscale-dev libavutil-dev
  # the editor (Qt Widgets, OpenGL and OpenGLWidgets, QTest), the X platform
  # plugin and Mesa's software OpenGL (llvmpipe), fonts for its labels, and a
  # virtual X server for the GUI tests
  qt6-base-dev qt6-base-dev-tools libqt6opengl6-dev qt6-qpa-plugins libgl-dev
  libgl1-mesa-dri fonts-dejavu-core xvfb xauth
  # tests and benchmarks; python3 writes the volume example's mesh and
  # normalises the examples' outputs (tests/examples/check_example_outputs.sh)
  libgtest-dev libgmock-dev libbenchmark-dev python3
  # scale-out: MPI (mpirun runs the distributed tests) and the in situ API's
  # Fortran module (docs/scale-out.md)
  libopenmpi-dev openmpi-bin gfortran
  # the Python module (python/, docs/python.md): pybind11, NumPy, pytest for
  # its tests, nbclient and ipykernel to run the example notebook
  pybind11-dev python3-dev python3-numpy python3-pytest python3-nbclient python3-ipykernel
  # h5py: the tests that write and read .h5 databases the way pycinema does
  python3-h5py
  # meshio: the example that captures a mesh of a format Darkroom has no reader for
  python3-meshio
  # SIMD kernels (plugins/ssao)
  libhwy-dev
  # the SDK ABI check (tests/sdk/check_abi.sh)
  abigail-tools
  # the readers' fuzz harnesses (tests/fuzz, ctest -L fuzz, scripts/fuzz.sh):
  # clang with AddressSanitizer/UBSan, and libFuzzer, which Debian 12 ships
  # apart from clang in libclang-rt-14-dev
  clang libclang-rt-14-dev
  "$@"
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi
if [ "$(id -u)" != 0 ]; then
  echo "Darkroom needs these Debian packages; run as root:" >&2
  echo "  apt-get update && apt-get install -y --no-install-recommends ${missing[*]}" >&2
  exit 1
fi
echo "Installing: ${missing[*]}" >&2
export DEBIAN_FRONTEND=noninteractive
apt-get update -qq
apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
