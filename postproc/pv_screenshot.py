"""Screenshot of a solved case: the mesh warped by its displacement, coloured by von Mises stress.

    xvfb-run -a pvbatch postproc/pv_screenshot.py OUTDIR/case.pvd OUT.png [--scale S]
    xvfb-run -a /usr/bin/python3 postproc/pv_screenshot.py OUTDIR/case.pvd OUT.png

Under pvbatch (Debian's paraview package ships pvbatch but no pvpython) it uses ParaView's
`paraview.simple`, which Debian packages as python3-paraview. That package conflicts with
python3-vtk9, hence with libvtk9-dev, which the code needs to build: on a build machine the same
picture is drawn with plain VTK under the system Python instead (second line above).

The last time step of the collection is shown. The warp factor defaults to 10 % of the mesh size
over the largest displacement, so that small-strain cases stay readable; --scale sets it.
Prints the point and cell array names. Exit status 2 if the file cannot be read or has no point
array "displacement", 3 if neither ParaView nor VTK is importable.
"""
import argparse
import math
import os
import sys
import xml.etree.ElementTree as ElementTree


def arguments():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("pvd", help=".pvd (or .vtu) written by sig-post")
    parser.add_argument("png", help="screenshot to write")
    parser.add_argument("--scale", type=float, default=None, help="warp factor")
    parser.add_argument("--size", default="1200x800", help="image size WxH in pixels")
    args = parser.parse_args()
    args.width, args.height = (int(v) for v in args.size.lower().split("x"))
    return args


def fail(message, status=2):
    print(f"pv_screenshot: {message}", file=sys.stderr)
    return status


def warp_factor(args, bounds, largest_displacement):
    """Largest displacement drawn as 10 % of the mesh diagonal, unless --scale says otherwise."""
    if args.scale is not None:
        return args.scale
    diagonal = math.hypot(bounds[1] - bounds[0], bounds[3] - bounds[2])
    return 0.1 * diagonal / largest_displacement if largest_displacement > 0 else 1.0


def print_arrays(points, cells):
    print("point arrays:", ", ".join(points))
    print("cell arrays:", ", ".join(cells))


def render_paraview(pv, args):
    try:
        source = pv.OpenDataFile(args.pvd)
    except RuntimeError as error:  # no reader for this kind of file
        return fail(str(error).strip())
    if source is None:
        return fail(f"cannot open {args.pvd}")
    times = list(getattr(source, "TimestepValues", None) or [])
    source.UpdatePipeline(times[-1] if times else 0.0)
    points, cells = list(source.PointData.keys()), list(source.CellData.keys())
    print_arrays(points, cells)
    if "displacement" not in points:
        return fail(f"{args.pvd} has no point array 'displacement'")

    largest = source.PointData["displacement"].GetRange(-1)[1]  # component -1: magnitude
    scale = warp_factor(args, source.GetDataInformation().GetBounds(), largest)
    warped = pv.WarpByVector(Input=source, Vectors=["POINTS", "displacement"], ScaleFactor=scale)
    view = pv.CreateView("RenderView", ViewSize=[args.width, args.height])
    if times:
        view.ViewTime = times[-1]
    view.OrientationAxesVisibility = 0
    view.UseColorPaletteForBackground = 0
    view.Background = [1, 1, 1]
    display = pv.Show(warped, view)
    if "von_mises" in cells:
        pv.ColorBy(display, ("CELLS", "von_mises"))
        display.RescaleTransferFunctionToDataRange(True, False)
        display.SetScalarBarVisibility(view, True)
        bar = pv.GetScalarBar(pv.GetColorTransferFunction("von_mises"), view)
        bar.TitleColor = bar.LabelColor = [0, 0, 0]
    view.InteractionMode = "2D"
    pv.ResetCamera(view)
    pv.SaveScreenshot(args.png, view, ImageResolution=[args.width, args.height])
    # Release the render window while X is still there: left to interpreter shutdown, it ends
    # in a GLXBadContext error and exit status 1 under xvfb-run.
    pv.Delete(view)
    del view
    print(f"warp factor {scale:.6g} -> {args.png}")
    return 0


def last_vtu(pvd):
    """The file of the last DataSet of a .pvd collection (or the file itself if it is a .vtu)."""
    if not pvd.endswith(".pvd"):
        return pvd
    steps = ElementTree.parse(pvd).getroot().iter("DataSet")
    steps = sorted(steps, key=lambda step: float(step.get("timestep", "0")))
    if not steps:
        raise ValueError(f"{pvd} lists no DataSet")
    return os.path.join(os.path.dirname(pvd), steps[-1].get("file"))


def render_vtk(vtk, args):
    try:
        vtu = last_vtu(args.pvd)
    except (OSError, ValueError, ElementTree.ParseError) as error:
        return fail(f"cannot read {args.pvd}: {error}")
    if not vtu.endswith(".vtu") or not os.path.isfile(vtu):
        return fail(f"cannot open {vtu}: not a .vtu file (or a .pvd of them)")
    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(vtu)
    reader.Update()
    grid = reader.GetOutput()
    if reader.GetErrorCode() != 0 or grid.GetNumberOfPoints() == 0:
        return fail(f"cannot read {vtu}")
    point_data, cell_data = grid.GetPointData(), grid.GetCellData()
    points = [point_data.GetArrayName(i) for i in range(point_data.GetNumberOfArrays())]
    cells = [cell_data.GetArrayName(i) for i in range(cell_data.GetNumberOfArrays())]
    print_arrays(points, cells)
    if "displacement" not in points:
        return fail(f"{vtu} has no point array 'displacement'")

    point_data.SetActiveVectors("displacement")
    largest = point_data.GetArray("displacement").GetRange(-1)[1]
    scale = warp_factor(args, grid.GetBounds(), largest)
    warp = vtk.vtkWarpVector()
    warp.SetInputData(grid)
    warp.SetScaleFactor(scale)
    mapper = vtk.vtkDataSetMapper()
    mapper.SetInputConnection(warp.GetOutputPort())
    renderer = vtk.vtkRenderer()
    renderer.SetBackground(1, 1, 1)
    if "von_mises" in cells:
        low, high = cell_data.GetArray("von_mises").GetRange()
        colours = vtk.vtkColorTransferFunction()  # ParaView's "Cool to Warm"
        colours.SetColorSpaceToDiverging()
        colours.AddRGBPoint(low, 0.231, 0.298, 0.753)
        colours.AddRGBPoint(high if high > low else low + 1, 0.706, 0.016, 0.150)
        mapper.SetLookupTable(colours)
        mapper.SetScalarModeToUseCellFieldData()
        mapper.SelectColorArray("von_mises")
        mapper.SetScalarRange(low, high)
        bar = vtk.vtkScalarBarActor()
        bar.SetLookupTable(colours)
        bar.SetTitle("von_mises")
        bar.SetWidth(0.08)
        bar.SetHeight(0.7)
        bar.SetPosition(0.88, 0.1)
        for text in (bar.GetTitleTextProperty(), bar.GetLabelTextProperty()):
            text.SetColor(0, 0, 0)
            text.ItalicOff()
            text.ShadowOff()
        renderer.AddActor2D(bar)
    else:
        mapper.ScalarVisibilityOff()
    actor = vtk.vtkActor()
    actor.SetMapper(mapper)
    renderer.AddActor(actor)
    renderer.GetActiveCamera().ParallelProjectionOn()
    renderer.ResetCamera()

    window = vtk.vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetSize(args.width, args.height)
    window.AddRenderer(renderer)
    window.Render()
    image = vtk.vtkWindowToImageFilter()
    image.SetInput(window)
    image.Update()
    writer = vtk.vtkPNGWriter()
    writer.SetFileName(args.png)
    writer.SetInputConnection(image.GetOutputPort())
    writer.Write()
    window.Finalize()
    print(f"warp factor {scale:.6g} -> {args.png}")
    return 0


def main():
    args = arguments()
    try:
        from paraview import simple as pv
    except ImportError:
        pv = None
    if pv is not None:
        return render_paraview(pv, args)
    # pvbatch without its Python package: loading the system VTK into it next to ParaView's own
    # VTK libraries crashes, so only an ordinary Python takes the VTK path.
    if not os.path.basename(sys.executable).startswith("python"):
        return fail("this ParaView has no Python module 'paraview' (Debian: python3-paraview); "
                    "run the script with /usr/bin/python3 and python3-vtk9 instead", 3)
    try:
        import vtkmodules.all as vtk
    except ImportError:
        return fail("neither paraview.simple nor vtkmodules can be imported", 3)
    return render_vtk(vtk, args)


if __name__ == "__main__":
    sys.exit(main())
