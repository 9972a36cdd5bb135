"""Run by pvpython or pvbatch (ParaView's Python), not by the system python: opens a run
folder's snapshots.xmf with ParaView's stock XDMF reader and its run.pvd, prints what ParaView
sees as one JSON line, and renders the last output to a PNG.

    pvpython --force-offscreen-rendering tests/python/paraview_open_run.py RUN_DIR OUT.png
"""
import json
import os
import sys

from paraview import servermanager
from paraview.simple import (ColorBy, GetActiveViewOrCreate, OpenDataFile, PVDReader, Render, SaveScreenshot,
                             Show, XDMFReader)
from vtkmodules.vtkCommonDataModel import vtkCompositeDataSet


def blocks(data):
    """{grid name: dataset} of a multiblock dataset's leaves."""
    out = {}
    it = data.NewIterator()
    it.InitTraversal()
    while not it.IsDoneWithTraversal():
        name = it.GetCurrentMetaData().Get(vtkCompositeDataSet.NAME())
        out[name.split("[")[0]] = it.GetCurrentDataObject()  # the reader adds "[time index]"
        it.GoToNextItem()
    return out


def leaves(data):
    """Every leaf dataset of a composite dataset, in order (the default reader names none)."""
    out = []
    it = data.NewIterator()
    it.InitTraversal()
    while not it.IsDoneWithTraversal():
        out.append(it.GetCurrentDataObject())
        it.GoToNextItem()
    return out


def describe(ds):
    pd, cd = ds.GetPointData(), ds.GetCellData()
    return {
        "points": ds.GetNumberOfPoints(),
        "cells": ds.GetNumberOfCells(),
        "cell_types": sorted({ds.GetCellType(i) for i in range(ds.GetNumberOfCells())}),
        "arrays": sorted(pd.GetArrayName(i) for i in range(pd.GetNumberOfArrays())),
        "cell_arrays": sorted(cd.GetArrayName(i) for i in range(cd.GetNumberOfArrays())),
        "bounds": list(ds.GetBounds()),
    }


def main(run_dir, png):
    report = {}
    xmf = XDMFReader(FileNames=[run_dir + "/snapshots.xmf"])
    xmf.UpdatePipelineInformation()
    times = list(xmf.TimestepValues)
    report["xmf_times"] = times
    xmf.UpdatePipeline(times[-1])
    parts = blocks(servermanager.Fetch(xmf))
    report["xmf_blocks"] = {name: describe(ds) for name, ds in parts.items()}
    # The wall end points of a cell, to compare with the stored walls.
    walls = parts.get("walls")
    if walls is not None:
        report["xmf_wall_points"] = [list(walls.GetPoint(i))[:2] for i in range(walls.GetNumberOfPoints())]

    # The reader ParaView picks for a double-clicked .xmf (5.11: Xdmf3ReaderS) reads the same.
    default = OpenDataFile(run_dir + "/snapshots.xmf")
    default.UpdatePipelineInformation()
    report["default_reader"] = default.GetXMLName()
    report["default_times"] = list(default.TimestepValues)
    default.UpdatePipeline(times[-1])
    report["default_blocks"] = [describe(ds) for ds in leaves(servermanager.Fetch(default))]

    # A packing run's packing.h5 has a sidecar of its own (one output, in a group of the file).
    if os.path.exists(run_dir + "/packing.xmf"):
        packing = XDMFReader(FileNames=[run_dir + "/packing.xmf"])
        packing.UpdatePipelineInformation()
        report["packing_times"] = list(packing.TimestepValues)
        packing.UpdatePipeline(report["packing_times"][-1])
        report["packing_blocks"] = {name: describe(ds) for name, ds in blocks(servermanager.Fetch(packing)).items()}
        default_packing = OpenDataFile(run_dir + "/packing.xmf")
        default_packing.UpdatePipeline(report["packing_times"][-1])
        report["default_packing_blocks"] = [describe(ds) for ds in leaves(servermanager.Fetch(default_packing))]

    pvd = PVDReader(FileName=run_dir + "/run.pvd")
    pvd.UpdatePipelineInformation()
    report["pvd_times"] = list(pvd.TimestepValues)
    pvd.UpdatePipeline(report["pvd_times"][-1])
    vtp = servermanager.Fetch(pvd)
    report["pvd_last"] = describe(vtp)
    report["pvd_lines"] = vtp.GetNumberOfLines()

    # The last output: discs as round points, walls as lines, coloured by initial depth; the
    # camera on the discs. (For discs drawn to scale use the Point Gaussian representation
    # scaled by `radius`: docs/rendering.md.)
    view = GetActiveViewOrCreate("RenderView")
    view.ViewSize = [480, 240]
    view.ViewTime = times[-1]
    view.OrientationAxesVisibility = 0
    shown = Show(xmf, view)
    shown.SetRepresentationType("Surface")
    shown.PointSize = 4
    shown.RenderPointsAsSpheres = 1
    shown.LineWidth = 2
    ColorBy(shown, ("POINTS", "depth0"))
    Render(view)  # the first render resets the camera; set it after
    b = report["xmf_blocks"]["discs"]["bounds"]
    cx, cy = 0.5 * (b[0] + b[1]), 0.5 * (b[2] + b[3])
    view.CameraPosition = [cx, cy, 100.0]
    view.CameraFocalPoint = [cx, cy, 0.0]
    view.CameraViewUp = [0.0, 1.0, 0.0]
    view.CameraParallelProjection = 1
    view.CameraParallelScale = 0.3 * max(b[3] - b[2], 0.5 * (b[1] - b[0])) + 2.0
    Render(view)
    SaveScreenshot(png, view, ImageResolution=[480, 240])
    print("OROGEN_PARAVIEW " + json.dumps(report))



if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
