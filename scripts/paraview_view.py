"""A run in ParaView, ready to look at: run by ParaView's Python (pvpython, or the GUI's script
runner), not by the system python.

    pvpython scripts/paraview_view.py RUN [--field depth0] [--output -1] [--png OUT.png] [--width 1600]
    OROGEN_RUN=RUN paraview --script=scripts/paraview_view.py      # the same in the GUI

It opens RUN/snapshots.xmf with ParaView's XDMF reader (the one that reads it: docs/output-files.md)
and shows the discs to scale (Point Gaussian, scaled by `radius`) with the walls as lines, in a
2D view (parallel projection) fitted to the discs, not to the walls, whose clipped ends lie far
out. The discs are coloured by FIELD (default `depth0`, the initial depth: the horizons;
`max_rel_disp` shows the faults) over the 1st to 99th percentile of the shown output, so that a
few outliers do not turn the picture black. With --png it saves that view and exits. Without a
display, run it under `xvfb-run -a -s "-screen 0 1280x1024x24 -noreset"` (Debian's ParaView draws
through X).
"""
import argparse
import os
import sys

import numpy as np
from paraview import servermanager
from paraview.simple import (ColorBy, GetActiveViewOrCreate, GetColorTransferFunction, GetScalarBar, Render,
                             SaveScreenshot, Show, XDMFReader)
from vtkmodules.numpy_interface import dataset_adapter as dsa


def reader(run, grid):
    """The XDMF reader of RUN's snapshots.xmf with only the grids named `grid` (every output's)."""
    r = XDMFReader(FileNames=[os.path.join(run, "snapshots.xmf")])
    r.UpdatePipelineInformation()
    r.GridStatus = [g for g in r.GridStatus if g == grid or g.startswith(grid + "[")]
    return r


def point_values(data, name):
    """The values of point array `name` over every block of a (nested multiblock) dataset."""
    def flat(array):
        if hasattr(array, "Arrays"):  # a composite array: one per block, perhaps nested
            return [v for part in array.Arrays for v in flat(part)]
        return [np.asarray(array, dtype=float).ravel()] if np.ndim(array) else []
    parts = flat(dsa.WrapDataObject(data).PointData[name])
    return np.concatenate(parts) if parts else np.array([])


def show_run(run, field="depth0", output=-1, width=1600):
    """Builds the view; returns it."""
    discs = reader(run, "discs")
    times = list(discs.TimestepValues)
    if not times:
        raise SystemExit("%s: snapshots.xmf holds no outputs" % run)
    time = times[output]
    discs.UpdatePipeline(time)
    data = servermanager.Fetch(discs)
    if field not in discs.PointData.keys():
        raise SystemExit("%s: no per-disc field %r (fields: %s)" % (run, field, ", ".join(discs.PointData.keys())))
    values = point_values(data, field)
    values = values[np.isfinite(values)]
    lo, hi = (np.percentile(values, [1, 99]) if values.size else (0.0, 1.0))
    if hi <= lo:
        hi = lo + 1.0
    x_lo, x_hi, y_lo, y_hi = discs.GetDataInformation().GetBounds()[:4]

    view = GetActiveViewOrCreate("RenderView")
    view.ViewTime = time
    view.OrientationAxesVisibility = 0
    # As tall as the discs need at this width (a layer is long and thin), within reason.
    height = width * (y_hi - y_lo) / max(x_hi - x_lo, 1e-9) * 1.3 + 140
    view.ViewSize = [width, int(min(max(height, 200), 0.6 * width))]
    shown = Show(discs, view)
    shown.SetRepresentationType("Point Gaussian")
    shown.ScaleByArray = 1
    shown.SetScaleArray = ["POINTS", "radius"]
    shown.UseScaleFunction = 0
    shown.GaussianRadius = 1.0
    shown.ShaderPreset = "Plain circle"
    ColorBy(shown, ("POINTS", field))
    lut = GetColorTransferFunction(field)
    lut.ApplyPreset("Turbo" if field != "max_rel_disp" else "Inferno (matplotlib)", True)
    lut.RescaleTransferFunction(float(lo), float(hi))
    lut.AutomaticRescaleRangeMode = "Never"
    shown.SetScalarBarVisibility(view, True)
    bar = GetScalarBar(lut, view)  # above the discs, not over them
    bar.Orientation = "Horizontal"
    bar.WindowLocation = "Upper Left Corner"
    bar.Title = field

    walls = reader(run, "walls")
    lines = Show(walls, view)
    lines.SetRepresentationType("Surface")
    lines.LineWidth = 2
    lines.AmbientColor = lines.DiffuseColor = [0.3, 0.3, 0.3]

    Render(view)  # the first render resets the camera: set it after
    cx, cy = 0.5 * (x_lo + x_hi), 0.5 * (y_lo + y_hi)
    aspect = view.ViewSize[0] / float(view.ViewSize[1])
    view.CameraViewUp = [0.0, 1.0, 0.0]
    view.CameraParallelProjection = 1
    # Half the height shown: the discs' width at this aspect, with room for the colour bar above.
    view.CameraParallelScale = 0.5 * max((y_hi - y_lo) * 1.3, (x_hi - x_lo) / aspect) + 0.5
    view.CameraPosition = [cx, cy + 0.25 * view.CameraParallelScale, 1000.0]
    view.CameraFocalPoint = [cx, cy + 0.25 * view.CameraParallelScale, 0.0]
    Render(view)
    return view


def main(argv):
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("run", nargs="?", default=os.environ.get("OROGEN_RUN"), help="run folder (or $OROGEN_RUN)")
    p.add_argument("--field", default="depth0", help="per-disc field to colour by (default depth0)")
    p.add_argument("--output", type=int, default=-1, help="output index, Python style (default -1: the last)")
    p.add_argument("--png", help="save the view to this PNG and exit")
    p.add_argument("--width", type=int, default=1600, help="picture width in pixels")
    a = p.parse_args(argv)
    if not a.run or not os.path.isfile(os.path.join(a.run, "snapshots.xmf")):
        print("error: give a run folder holding snapshots.xmf (or set OROGEN_RUN)", file=sys.stderr)
        return 2
    view = show_run(a.run, a.field, a.output, a.width)
    if a.png:
        SaveScreenshot(a.png, view, ImageResolution=view.ViewSize)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
