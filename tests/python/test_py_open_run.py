"""orogen.open_run reads every field of a CLI run, with the units the files carry; the chart
scripts run on a tiny run."""

import shutil
import subprocess

import h5py
import numpy as np
import pandas as pd
import xarray as xr

import orogen
from conftest import BINARY


def test_series_and_units(cli_wedge):
    r = orogen.open_run(cli_wedge)
    assert r.experiment == "wedge" and r.config["wedge"]["s_end"] == 0.1
    s = r.series
    assert isinstance(s, pd.DataFrame) and len(s) == 5
    assert r.units["H"] == "h0" and r.units["time"] == "sqrt(d/g)" and r.units["alpha"] == "deg"
    ds = r.series_dataset()
    assert isinstance(ds, xr.Dataset) and ds["H"].attrs["units"] == "h0" and ds.sizes["output"] == 5
    assert np.array_equal(ds["step"].values, s["step"].values)


def test_snapshots_every_field_lazily_with_units(cli_wedge):
    r = orogen.open_run(cli_wedge)
    snaps = r.snapshots
    files = sorted((cli_wedge / "snapshots").glob("output_*.h5"))
    assert snaps.sizes["output"] == len(files) == 5
    # lazy: nothing is read until asked
    assert not isinstance(snaps["x"].variable._data, np.ndarray)
    for k, path in enumerate(files):
        with h5py.File(path, "r") as f:
            names = {n for n in f if isinstance(f[n], h5py.Dataset)}
            assert names <= set(snaps.data_vars)
            n = f["x"].shape[0]
            assert int(snaps["n_discs"][k]) == n
            for name in names:
                want = f[name][()]
                got = snaps[name].isel(output=k).values
                got = got[: want.shape[0]]
                assert np.array_equal(got, want, equal_nan=want.dtype.kind == "f"), name
                units = f[name].attrs["units"]
                assert snaps[name].attrs["units"] == (units.decode() if isinstance(units, bytes) else units), name
            assert float(snaps["time"][k]) == f.attrs["time"]
    for name in ("vx", "vy", "omega", "theta", "max_rel_disp", "disp3_x", "disp3_y"):  # issue 19's missing ones
        assert name in snaps
    assert snaps["omega"].attrs["units"] == "rad / sqrt(d/g)" and snaps["x"].attrs["units"] == "d"
    assert np.isnan(snaps["x"].values[snaps["x"].values.shape[0] - 1, int(snaps["n_discs"].max()):]).all()


def test_one_output_by_id_and_removals(cli_wedge):
    r = orogen.open_run(cli_wedge)
    last = r.output(-1)
    assert last.sizes["particle"] == int(r.snapshots["n_discs"][-1])
    assert last.attrs["S"] > 0 and last["vx"].attrs["units"] == "sqrt(g d)"
    assert list(r.removals.columns) == ["step", "time", "id", "cluster_id", "x", "y", "reason"]
    assert r.summary["S_final"] > 0
    assert r.analysis is None


def test_chart_frames_keep_every_field(cli_wedge):
    from orogen import folders
    frame = folders.read_last_frame(cli_wedge / "snapshots.h5")
    for name in ("vx", "vy", "omega", "theta", "max_rel_disp", "disp3_x", "disp3_y", "x", "radius"):
        assert name in frame, name


def test_read_frame_is_every_dataset_of_the_output_file(cli_wedge):
    """orogen.folders.read_frame, through the package's reader (orogen.frames) and the links of
    snapshots.h5, gives each output's datasets and attributes exactly as h5py reads its file."""
    from orogen import folders
    files = sorted((cli_wedge / "snapshots").glob("output_*.h5"))
    for k, path in enumerate(files):
        frame = folders.read_frame(cli_wedge / "snapshots.h5", k)
        with h5py.File(path, "r") as f:
            # xy is a view of x and y for the XDMF sidecar, not a per-disc field of its own.
            datasets = {n: f[n][()] for n in f if isinstance(f[n], h5py.Dataset) and n != "xy"}
            attrs = dict(f.attrs)
        assert frame["output"] == k
        assert set(frame) == set(datasets) | {"output", "attrs", "file_attrs"}
        for name, want in datasets.items():
            got = frame[name]
            assert got.dtype == want.dtype and np.array_equal(got, want, equal_nan=want.dtype.kind == "f"), name
        assert frame["walls"].shape == (datasets["walls"].shape[0], 4)
        assert frame["attrs"] == {a: v.decode() if isinstance(v, bytes) else v for a, v in attrs.items()}
        assert frame["file_attrs"]["n_outputs"] == len(files) and frame["file_attrs"]["experiment"] == "wedge"


def test_outputs_past_n_outputs_are_never_read(cli_wedge, tmp_path):
    """A killed run: snapshots.h5 counts fewer outputs than its links and files; the outputs
    past n_outputs (here files that are not HDF5 at all) are never opened by any reader."""
    from orogen import folders
    from orogen.charts import wedge as wedge_charts
    run = tmp_path / "killed"
    shutil.copytree(cli_wedge, run)
    with h5py.File(run / "snapshots.h5", "r+") as f:
        n = int(f.attrs["n_outputs"]) - 2
        f.attrs["n_outputs"] = n
    for k in (n, n + 1):
        (run / "snapshots" / f"output_{k:06d}.h5").write_bytes(b"cut short by the kill")
    h5 = run / "snapshots.h5"
    assert folders.read_last_frame(h5)["output"] == n - 1
    assert folders.read_frame(h5, n) is None and folders.read_frame(h5, -n - 1) is None
    assert [p["output"] for p in wedge_charts.read_topography(h5)] == list(range(n))
    r = orogen.open_run(run)
    assert r.snapshots.sizes["output"] == n and np.isfinite(r.snapshots["x"].load().values[:, 0]).all()
    assert r.output(-1).attrs["step"] == folders.read_last_frame(h5)["attrs"]["step"]


def test_wedge_charts_on_a_tiny_run(cli_wedge, tmp_path):
    proc = subprocess.run(["/usr/bin/python3", "-m", "orogen.charts.wedge", str(cli_wedge), "--out",
                           str(tmp_path / "charts")], capture_output=True, text=True)
    assert proc.returncode == 0, proc.stderr
    assert (tmp_path / "charts" / "summary.json").exists() and list((tmp_path / "charts").glob("*.png"))


def test_orogen_charts_draws_what_the_module_draws(cli_wedge, tmp_path):
    """`orogen charts RUN` runs the package by module name: the same files, byte for byte, as
    `python3 -m orogen.charts.wedge`; a folder of no known run is refused with exit 2."""
    cli = subprocess.run([BINARY, "charts", str(cli_wedge), "--out", str(tmp_path / "cli")], capture_output=True,
                         text=True)
    assert cli.returncode == 0, cli.stderr
    module = subprocess.run(["/usr/bin/python3", "-m", "orogen.charts.wedge", str(cli_wedge), "--out",
                             str(tmp_path / "module")], capture_output=True, text=True)
    assert module.returncode == 0, module.stderr
    names = sorted(p.name for p in (tmp_path / "module").iterdir())
    assert names == sorted(p.name for p in (tmp_path / "cli").iterdir()) and "topography.png" in names
    for name in names:
        assert (tmp_path / "cli" / name).read_bytes() == (tmp_path / "module" / name).read_bytes(), name
    bad = subprocess.run([BINARY, "charts", str(tmp_path)], capture_output=True, text=True)
    assert bad.returncode == 2 and "holds no wedge" in bad.stderr


def test_read_csv_keeps_whole_rows_only(tmp_path):
    """A last row cut short (and a row too long) is skipped; an empty or `nan` field is NaN (and
    the charts' orogen.tables.read_table reads the same rows as float arrays)."""
    path = tmp_path / "series.csv"
    path.write_text("# S: shortening [h0]\n# H: height [h0]\n# n: discs\nS,H,n\n0.1,1.5,10\n\n"
                    "0.2,,11\n0.3,nan,12,99\n0.4,2.25,13\n0.5,2.5")
    frame, units, meanings = orogen.read_csv(path)
    assert list(frame["S"]) == [0.1, 0.2, 0.4] and frame["n"].dtype.kind == "i"
    assert np.isnan(frame["H"][1]) and frame["H"][2] == 2.25
    assert units == {"S": "h0", "H": "h0"} and meanings["n"] == "discs"
    from orogen import tables
    columns, descriptions = tables.read_table(path)
    assert columns["S"].tolist() == [0.1, 0.2, 0.4] and columns["n"].dtype == float
    assert descriptions["H"] == "height [h0]"
