#!/usr/bin/env bash
# drivers/setup.sh: sourced by run.sh and test.sh (or run alone): install what is missing
# (Debian packages), configure and build. Idempotent: with everything installed and built it only
# checks and returns in seconds.
# Sets SIG_ROOT, SIG_BUILD and SIG_BIN.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/lib/environment.sh"
[ "${BASH_SOURCE[0]}" != "$0" ] || help_from_header "$@" # run, not sourced
SIG_ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
SIG_BUILD=${SIG_BUILD:-$SIG_ROOT/build}
SIG_BIN=$SIG_BUILD/bin
export SIG_ROOT SIG_BUILD SIG_BIN

# Build and run dependencies; FreeFem++, ParaView (with xvfb), GetFEM, meshio and Chromium (the
# scene index in a browser) serve tests and comparisons that skip when absent, but we install
# them so a fresh machine runs everything.
# MUMPS is Debian's MPI build (libmumps-dev, OpenMPI; mpi-default-bin gives mpirun).
packages=(cmake g++ make libeigen3-dev libsuitesparse-dev libmumps-dev mpi-default-bin
  mpi-default-dev libmetis-dev
  libopenblas-dev libvtk9-dev libgtest-dev gmsh python3 python3-numpy python3-matplotlib
  python3-pytest freefem++ paraview xvfb python3-getfem python3-meshio chromium
  clang libclang-rt-14-dev) # clang + libFuzzer: the readers' fuzz targets (tests/fuzz/run.sh)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "setup: installing ${missing[*]}"
  sudo_cmd=()
  [ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
  "${sudo_cmd[@]}" apt-get update -q
  DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -q --no-install-recommends \
    "${missing[@]}"
fi

jobs=$(nproc 2>/dev/null || echo 2)
if [ ! -f "$SIG_BUILD/CMakeCache.txt" ]; then
  # The unit tests are built and run in test.sh's sanitizer build (build-asan/), not here.
  cmake -S "$SIG_ROOT" -B "$SIG_BUILD" -DCMAKE_BUILD_TYPE=Release -DSIG_UNIT_TESTS=OFF
fi
cmake --build "$SIG_BUILD" -j "$jobs"

# ParaView's Python module for pvbatch: Debian's python3-paraview conflicts with python3-vtk9,
# which libvtk9-dev needs, so it is unpacked into the build folder instead of installed
# (never `apt-get install python3-paraview` on a build machine: it removes libvtk9-dev).
pvpy=$SIG_BUILD/paraview-python
if command -v pvbatch > /dev/null && [ ! -d "$pvpy/usr/lib/python3/dist-packages/paraview" ]; then
  download=$(mktemp -d)
  if (cd "$download" && apt-get download python3-paraview > /dev/null 2>&1) &&
    dpkg -x "$download"/python3-paraview_*.deb "$pvpy"; then
    echo "setup: unpacked ParaView's Python module into $pvpy"
  else
    echo "setup: could not unpack python3-paraview; the screenshot test will draw with plain VTK"
  fi
  rm -rf "$download"
fi
