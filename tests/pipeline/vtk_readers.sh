#!/usr/bin/env bash
# Pipeline test (issue 17): our VTK output opens in every common reader that is installed.
# Two chains: the static cantilever (one .vtu) and a vibrating block marched in time
# (tests/pipeline/data/vibrating_block.dat: a .pvd of 5 states). Each reader then reads every
# .vtu (the .pvd's list) and must find the mesh sig-mesh wrote (nodes, triangles), the point field
# displacement (3 components), the cell field von_mises, the title as field data (UTF-8 bytes)
# and, for a series, TimeValue equal to the .pvd's time; the readers must agree with each other
# to the last bit on displacement. Readers: meshio (python3-meshio), VTK's own Python reader
# (python3-vtk9), pyvista (not a Debian 12 package: used when installed). ParaView reads the
# same files in paraview_screenshot.sh. Exit 77 (skipped) only when none of the readers is
# installed.
set -euo pipefail
source "$(dirname "$0")/lib/common.sh"
require_stages post

for deck in datafiles/cantilever.dat tests/pipeline/data/vibrating_block.dat; do
  name=$(basename "$deck" .dat)
  SIG_BIN=$bin bash "$root/drivers/chain.sh" "$root/$deck" -o "$work/$name" >"$work/$name.log" 2>&1 || {
    cat "$work/$name.log"
    die "the chain of $deck failed"
  }
  "$bin/sig-dump" --json "$work/$name/case.nopo" >"$work/$name/mesh.json"
done

PYTHONDONTWRITEBYTECODE=1 "$python" - "$work" <<'PY'
import json, sys
import xml.etree.ElementTree as ET
from pathlib import Path
import numpy as np

from pipeline_checks import check, finish

work = Path(sys.argv[1])
cases = {"cantilever": ("cantilever.pvd", "Cantilever beam, linear elasticity"),
         "vibrating_block": ("block.pvd", 'Vibrating block, "midpoint" rule')}


def read_meshio(path):
    import meshio
    m = meshio.read(path)
    return {"points": m.points, "triangles": m.cells_dict.get("triangle"),
            "displacement": m.point_data.get("displacement"),
            "von_mises": m.cell_data_dict.get("von_mises", {}).get("triangle"),
            "title": bytes(np.asarray(m.field_data.get("title", []), dtype=np.uint8)).decode(),
            "time": m.field_data.get("TimeValue")}


def read_vtk(path):
    from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader
    from vtkmodules.util.numpy_support import vtk_to_numpy
    reader = vtkXMLUnstructuredGridReader()
    reader.SetFileName(str(path))
    reader.Update()
    grid = reader.GetOutput()
    cells = vtk_to_numpy(grid.GetCells().GetConnectivityArray()).reshape(-1, 3)
    field = grid.GetFieldData()
    get = lambda data, name: vtk_to_numpy(data.GetArray(name)) if data.GetArray(name) else None
    return {"points": vtk_to_numpy(grid.GetPoints().GetData()), "triangles": cells,
            "displacement": get(grid.GetPointData(), "displacement"),
            "von_mises": get(grid.GetCellData(), "von_mises"),
            "title": bytes(get(field, "title")).decode(), "time": get(field, "TimeValue")}


def read_pyvista(path):
    import pyvista
    m = pyvista.read(path)
    return {"points": np.asarray(m.points), "triangles": np.asarray(m.cells).reshape(-1, 4)[:, 1:],
            "displacement": np.asarray(m.point_data["displacement"]),
            "von_mises": np.asarray(m.cell_data["von_mises"]),
            "title": bytes(np.asarray(m.field_data["title"], dtype=np.uint8)).decode(),
            "time": m.field_data.get("TimeValue")}


readers = {}
for name, module, function in (("meshio", "meshio", read_meshio), ("vtk", "vtkmodules", read_vtk),
                               ("pyvista", "pyvista", read_pyvista)):
    try:
        __import__(module)
        readers[name] = function
    except ImportError:
        print(f"skip  {name}: not installed")
if not readers:
    print("vtk_readers: skipped, none of meshio, vtk, pyvista is installed")
    sys.exit(77)

for case, (pvd, title) in cases.items():
    folder = work / case
    mesh = json.loads((folder / "mesh.json").read_text())
    steps = [(float(d.get("timestep")), d.get("file"))
             for d in ET.parse(folder / pvd).getroot().iter("DataSet")]
    check(len(steps) == (1 if case == "cantilever" else 5), f"{case}: {len(steps)} states in {pvd}")
    for time, file in steps:
        results = {}
        for reader, read in readers.items():
            label = f"{case}/{file} ({reader})"
            try:
                r = read(folder / file)
            except Exception as error:  # a reader that cannot read the file is the failure
                check(False, f"{label}: {type(error).__name__}: {error}")
                continue
            results[reader] = r
            check(r["points"].shape == (mesh["nodes"], 3), f"{label}: {mesh['nodes']} points")
            check(r["triangles"] is not None and len(r["triangles"]) == mesh["triangles"],
                  f"{label}: {mesh['triangles']} triangles")
            check(r["displacement"] is not None and r["displacement"].shape == (mesh["nodes"], 3)
                  and np.all(np.isfinite(r["displacement"])), f"{label}: displacement (n, 3)")
            check(r["von_mises"] is not None and len(r["von_mises"]) == mesh["triangles"],
                  f"{label}: von_mises per triangle")
            check(r["title"] == title, f"{label}: title '{r['title']}'")
            if case != "cantilever":
                check(r["time"] is not None and abs(float(np.ravel(r["time"])[0]) - time) <= 1e-12,
                      f"{label}: TimeValue {None if r['time'] is None else np.ravel(r['time'])[0]}"
                      f" = .pvd time {time}")
        names = list(results)
        for other in names[1:]:
            same = np.array_equal(results[names[0]]["displacement"], results[other]["displacement"])
            check(same, f"{case}/{file}: {names[0]} and {other} read the same displacement")
    if case != "cantilever" and "meshio" in results:
        moved = np.abs(results["meshio"]["displacement"]).max()
        check(moved > 0, f"{case}: the last state has moved ({moved:.3g})")

finish("vtk_readers")
print(f"vtk_readers: ok with {', '.join(readers)}")
PY
