#!/usr/bin/env bash
# Pipeline test (issue 17): Signorini installed and used from elsewhere.
#  - cmake --install of the build into a temporary prefix: bin/ stages, share/signorini/ drivers,
#    datafiles, postproc; the cantilever chain runs from there with no SIG_BIN (the installed
#    drivers find PREFIX/bin) and no source tree, and --version works from bin/;
#  - a downstream CMake project (tests/pipeline/data/downstream) finds the package, links
#    Signorini::mesh only, builds, and reads the mesh the installed chain wrote: the counts of
#    sig-dump;
#  - BUILD_TESTING=OFF configures with GoogleTest hidden (CMAKE_DISABLE_FIND_PACKAGE_GTest);
#  - the project as a subdirectory of another (tests/pipeline/data/parent) configures and builds
#    Signorini::core into the parent's program.
# Run from the repository root with SIG_BUILD set (ctest does both); exit 77 (skipped) without a
# built tree.
set -euo pipefail
source "$(dirname "$0")/lib/common.sh"
build=${SIG_BUILD:-$root/build}
[ -x "$build/bin/sig-mesh" ] || skip "no built tree in $build"
# A configure or build step, its output shown only when it fails.
quiet() {
  "$@" >"$work/step.log" 2>&1 || {
    cat "$work/step.log"
    die "$*"
  }
}

# 1. Install and run the chain from the prefix, away from the source tree.
prefix=$work/prefix
quiet cmake --install "$build" --prefix "$prefix"
for stage in mesh material contact assemble solve march post dump; do
  [ -x "$prefix/bin/sig-$stage" ] || die "no bin/sig-$stage in the prefix"
done
for file in drivers/chain.sh drivers/scenes.sh drivers/lib/installed.sh datafiles/cantilever.dat \
  postproc/scene_index.py postproc/sigreport/__init__.py; do
  [ -e "$prefix/share/signorini/$file" ] || die "no share/signorini/$file in the prefix"
done
"$prefix/bin/sig-solve" --version | grep -q "^sig-solve (Signorini) " || die "sig-solve --version"
(cd "$work" && env -u SIG_BIN PATH=/usr/bin:/bin \
  "$prefix/share/signorini/drivers/chain.sh" "$prefix/share/signorini/datafiles/cantilever.dat" \
  -o "$work/run" >"$work/chain.log" 2>&1) || {
  cat "$work/chain.log"
  die "the cantilever chain from the prefix"
}
for file in case.nopo case.b summary.json cantilever.pvd; do
  [ -s "$work/run/$file" ] || die "the installed chain wrote no $file"
done
grep -q '"converged": true' "$work/run/summary.json" || die "the installed chain did not converge"
echo "install: the cantilever chain ran from $prefix"

# The package exports only what the public headers need: beyond our own modules, Eigen is the one
# package a user's compile line gets; SuiteSparse, MUMPS, METIS, BLAS/LAPACK and VTK are link-only,
# and no installed header includes theirs.
targets=$prefix/lib/cmake/Signorini/SignoriniTargets.cmake
[ -f "$targets" ] || die "no $targets"
public=$(sed -n 's/^ *INTERFACE_LINK_LIBRARIES "\(.*\)"/\1/p' "$targets" | tr ';' '\n' |
  grep -v '^\\\$<LINK_ONLY:' | grep -v '^Signorini::' | sort -u | tr '\n' ' ')
[ "$public" = "Eigen3::Eigen " ] || die "public link dependencies beyond Eigen: $public"
for target in core mesh material assembly contact_laws contact solver integrator stages post; do
  grep -q "add_library(Signorini::$target STATIC IMPORTED)" "$targets" || die "no Signorini::$target"
done
if grep -rlE '#include [<"](vtk|cholmod|umfpack|dmumps|metis|cblas|lapacke)' "$prefix/include"; then
  die "an installed header includes a private dependency's header"
fi
echo "install: the package's public dependencies: $public(the rest link-only)"

# 2. A downstream project: find_package(Signorini), Signorini::mesh, read the mesh.
quiet cmake -S "$root/tests/pipeline/data/downstream" -B "$work/downstream" \
  -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_BUILD_TYPE=Release
quiet cmake --build "$work/downstream"
counts=$("$work/downstream/read_mesh" "$work/run/case.nopo") || die "read_mesh failed"
expected=$("$prefix/bin/sig-dump" --json "$work/run/case.nopo" |
  /usr/bin/python3 -c 'import json, sys; m = json.load(sys.stdin); print("nodes", m["nodes"], "triangles", m["triangles"])')
[ "$counts" = "$expected" ] || die "read_mesh printed '$counts', sig-dump says '$expected'"
echo "install: a downstream project linked Signorini::mesh and read $counts"

# 3. No tests, no GoogleTest.
quiet cmake -S "$root" -B "$work/notest" -DBUILD_TESTING=OFF -DCMAKE_DISABLE_FIND_PACKAGE_GTest=ON
grep -q "^GTest_DIR" "$work/notest/CMakeCache.txt" && die "BUILD_TESTING=OFF still looks for GTest"
echo "install: BUILD_TESTING=OFF configures without GoogleTest"

# 4. As a subdirectory of another project.
# Unoptimised (no build type): that it builds is what is checked, not its speed.
quiet cmake -S "$root/tests/pipeline/data/parent" -B "$work/parent" -DSIGNORINI_DIR="$root" \
  -DCMAKE_BUILD_TYPE=None
quiet cmake --build "$work/parent" --target parse_deck -j 2
cards=$("$work/parent/parse_deck" "$root/datafiles/cantilever.dat" | tr '\n' ' ')
[ "$cards" = "TITLE MESH MATERIAL DIRICHLET TRACTION SOLVER OUTPUT " ] ||
  die "parse_deck printed '$cards'"
echo "install: as a subdirectory, Signorini::core parsed the cantilever deck: $cards"
echo "install: ok"
