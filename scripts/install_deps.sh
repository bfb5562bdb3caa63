#!/usr/bin/env bash
# Installs the Debian packages the project builds and tests with. Run as root on a fresh machine.
set -euo pipefail
packages=(
  build-essential cmake ninja-build pkg-config clang-format
  libeigen3-dev libomp-dev
  libzmq3-dev cppzmq-dev libprotobuf-dev protobuf-compiler
  libspdlog-dev nlohmann-json3-dev libcli11-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  libhwy-dev  # Google Highway, for benchmarks/simd_library_benchmark.cpp only
  libmsgpack-cxx-dev
  libglfw3-dev libgl-dev libepoxy-dev libimgui-dev libpng-dev xvfb xauth libxtst-dev
  gnuplot-nox python3-zmq python3-protobuf python3-numpy
  python3-pip python3-venv  # the Python client's install test (pip install with no index)
  help2man lintian  # the package's manual pages, and Debian's own checks of the package
  clang libclang-rt-14-dev
  dpkg-dev file  # cpack's Debian package: dpkg-shlibdeps finds the dependencies, file tells it the ELF files
)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install_deps: all ${#packages[@]} packages present"
  exit 0
fi
SUDO=""
[ "$(id -u)" -eq 0 ] || SUDO="sudo"
echo "install_deps: installing ${missing[*]}"
$SUDO apt-get update -qq
DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
