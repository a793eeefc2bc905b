#!/usr/bin/env bash
# Pipeline test: a solved case opens in ParaView. Runs drivers/chain.sh on datafiles/patch.dat (or the
# small block of tests/pipeline/data/post_rectangle.dat), checks sig-dump's JSON of the mesh, then
# renders postproc/pv_screenshot.py under xvfb and requires
#  - the renderer to find the point array "displacement" and the cell array "von_mises";
#  - a PNG file larger than 5 kB (a blank image compresses to far less).
# Run from the repository root with SIG_BIN set (ctest does both); exit 77 (skipped) when the
# executables or xvfb-run are missing, or when there is neither a pvbatch with its paraview
# Python module nor the system Python with VTK.
set -euo pipefail

root=$(cd "$(dirname "$0")/../.." && pwd)
bin=${SIG_BIN:-$root/build/bin}
for stage in mesh material contact assemble solve post dump; do
  [ -x "$bin/sig-$stage" ] || { echo "paraview_screenshot: skipped, no $bin/sig-$stage"; exit 77; }
done
command -v xvfb-run >/dev/null || { echo "paraview_screenshot: skipped, no xvfb-run"; exit 77; }

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# Renderer: pvbatch when it has its Python module (Debian: python3-paraview, which conflicts with
# libvtk9-dev), otherwise the script's plain-VTK path under the system Python (python3-vtk9).
# drivers/setup.sh unpacks python3-paraview into the build folder; pvbatch finds it there.
echo 'import paraview.simple' >"$work/probe.py"
pvbatch=$(command -v pvbatch || command -v pvpython || true)
pvpy=${SIG_BUILD:-$root/build}/paraview-python/usr/lib/python3/dist-packages
renderer_env=()
[ -d "$pvpy/paraview" ] && renderer_env=(env "PYTHONPATH=$pvpy")
if [ -n "$pvbatch" ] && "${renderer_env[@]}" xvfb-run -a "$pvbatch" "$work/probe.py" >/dev/null 2>&1; then
  renderer=$pvbatch
elif /usr/bin/python3 -c 'import vtkmodules.vtkRenderingOpenGL2' 2>/dev/null; then
  renderer=/usr/bin/python3
else
  echo "paraview_screenshot: skipped, neither pvbatch with paraview.simple nor python3-vtk9"
  exit 77
fi
echo "paraview_screenshot: rendering with $renderer"

deck=$root/datafiles/patch.dat
[ -r "$deck" ] || deck=$root/tests/pipeline/data/post_rectangle.dat
stem=$(basename "$deck" .dat)
out=$work/out
SIG_BIN=$bin bash "$root/drivers/chain.sh" "$deck" -o "$out" >"$work/chain.log" 2>&1 || {
  cat "$work/chain.log" >&2
  echo "paraview_screenshot: the chain failed on $deck" >&2
  exit 1
}
if [ ! -s "$out/$stem.pvd" ] || [ ! -s "${out}/${stem}_0000.vtu" ]; then
  echo "paraview_screenshot: sig-post wrote no $stem.pvd / ${stem}_0000.vtu" >&2
  exit 1
fi

# sig-dump --json of the mesh: the counts sig-mesh printed, NOPO kind, sorted references.
"$bin/sig-dump" --json "$out/case.nopo" >"$work/mesh.json"
python3 - "$work/mesh.json" "$out/summary.json" <<'PY'
import json, sys
mesh = json.load(open(sys.argv[1]))
summary = json.load(open(sys.argv[2]))
assert mesh["kind"] == "NOPO", mesh
assert mesh["nodes"] == summary["nodes"] and mesh["triangles"] == summary["triangles"], (mesh, summary)
assert mesh["references"] == sorted(mesh["references"]), mesh
assert summary["converged"] is True, summary
PY

png=$work/shot.png
[ "$renderer" = "$pvbatch" ] || renderer_env=()
# On a loaded machine Xvfb may not accept connections by the time the renderer starts ("bad X
# server connection"): that, and only that, is retried with a fresh server.
for attempt in 1 2 3; do
  if "${renderer_env[@]}" xvfb-run -a "$renderer" "$root/postproc/pv_screenshot.py" "$out/$stem.pvd" "$png" >"$work/pv.log" 2>&1; then
    break
  fi
  if [ "$attempt" -lt 3 ] && grep -q "bad X server connection" "$work/pv.log"; then
    echo "paraview_screenshot: the X server was not ready (attempt $attempt), retrying"
    continue
  fi
  cat "$work/pv.log" >&2
  echo "paraview_screenshot: pv_screenshot.py failed" >&2
  exit 1
done
cat "$work/pv.log"
grep -q '^point arrays:.*displacement' "$work/pv.log" || { echo "no displacement array" >&2; exit 1; }
grep -q '^cell arrays:.*von_mises' "$work/pv.log" || { echo "no von_mises array" >&2; exit 1; }
[ -f "$png" ] || { echo "paraview_screenshot: no $png" >&2; exit 1; }
size=$(stat -c %s "$png")
[ "$(head -c 8 "$png" | od -An -tx1 | tr -d ' \n')" = 89504e470d0a1a0a ] || {
  echo "paraview_screenshot: $png is not a PNG" >&2
  exit 1
}
[ "$size" -gt 5120 ] || { echo "paraview_screenshot: $png has only $size bytes" >&2; exit 1; }
echo "paraview_screenshot: ok, $png $size bytes"
