#!/usr/bin/env bash
# Installs the Debian packages clrt needs (only those missing), then configures a Release tree in
# build/ and builds clrt. Idempotent: with everything in place it only runs an incremental build.
# Usage: bash tools/setup.sh            (as root, or with sudo available)
#        bash tools/setup.sh --tests    every target, the tests included, and the OpenCL
#                                       implementations the tests run on besides PoCL
#                                       (tools/lib/install_test_devices.sh)
set -euo pipefail

cd "$(dirname "${BASH_SOURCE[0]}")/.."

# What clrt itself needs: the first command installs only these.
packages=(
  cmake g++ make                 # the build
  ocl-icd-opencl-dev             # the OpenCL ICD loader (libOpenCL.so) and its CMake/pkg-config files
  opencl-headers                 # CL/cl.h
  pocl-opencl-icd                # PoCL: the CPU OpenCL device clrt runs and is tested on
  libboost-dev                   # Boost.Compute (header-only) for the host API
  libcli11-dev                   # the command line
  libpng-dev                     # PNG output and input
  zlib1g-dev                     # the PNG writer's compression, on every core (libpng-dev pulls it in too)
  libopenexr-dev                 # OpenEXR output and input (half or 32-bit float HDR, tiles' data windows)
  nlohmann-json3-dev             # JSON: --stats=json, --dump-scene and the experiment records
  libgif-dev                     # giflib: clrt-img convert's animated GIFs (the tree's configure needs it)
)
# What the tests and the other programs add (--tests).
test_packages=(
  catch2                         # the test framework (2.13 on Debian 12)
  python3-matplotlib             # the plots of clrt-experiment (and its test)
  libopenmpi-dev openmpi-bin     # clrt-mpi: one image across the ranks of an MPI job (and mpirun for its tests)
  libsdl2-dev                    # clrt-view's window (optional: built only when found; clrt never needs it)
  xvfb                           # the X server clrt-view's screenshot tests start (libsdl2-dev brings libx11-dev, which they read it with)
)

with_tests=0
case ${1:-} in
  --tests) with_tests=1 ;;
  "") ;;
  *) echo "usage: bash tools/setup.sh [--tests]" >&2; exit 2 ;;
esac

source tools/lib/install_missing.sh
source tools/lib/install_test_devices.sh
if ((with_tests)); then packages+=("${test_packages[@]}"); fi
install_missing "${packages[@]}"

# The tests are configured in only with --tests: a first picture needs neither Catch2 nor MPI.
# An existing tree keeps its other settings; --tests only switches the tests on.
configure=()
[[ -f build/CMakeCache.txt ]] || configure+=(-DCMAKE_BUILD_TYPE=Release -DCLRT_BUILD_TESTS=$((with_tests)))
((with_tests)) && configure+=(-DCLRT_BUILD_TESTS=ON)
if ((${#configure[@]})); then cmake -S . -B build "${configure[@]}"; fi
# Without --tests only clrt, all the first render needs: the test programs are most of the build
# and would keep a newcomer from a first picture for minutes.
targets=(--target clrt)
if ((with_tests)); then targets=(); fi
cmake --build build -j"$(nproc)" "${targets[@]}"
if ((with_tests)); then install_test_devices build; fi
