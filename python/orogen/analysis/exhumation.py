#!/usr/bin/python3
"""Loader of `orogen analyze` results (docs/exhumation.md, docs/output-files.md).

    from orogen.analysis import exhumation as orogen_analysis
    ds = orogen_analysis.load("runs/E5")        # the run folder or its analysis.h5
    ds.elevation.sel(column=2.0, method="nearest").plot()

`load` returns an xarray.Dataset with the dimensions time, column, closure, particle,
trajectory and removal; every variable carries `units` and `description` attributes. The
helpers below return xarray objects too. Needs python3-xarray and python3-h5netcdf (Debian).
"""

import os
import sys
import warnings

import numpy as np
import xarray as xr

from ..tables import read_csv

STEP_OUT = 0.5      # h0: Dp moving outward by more than this in one output is a pro step-out
LOW_EROSION = 0.25  # of the incoming flux: an output eroding less erodes "little" (Figs 6.6, 6.7)


def analysis_path(path):
    """The analysis.h5 of a run folder, or the path itself if it is a file."""
    return os.path.join(path, "analysis.h5") if os.path.isdir(path) else path


def found(run):
    """True if the run has its analysis.h5; else False, after saying on stderr what to run first."""
    path = analysis_path(run)
    if os.path.isfile(path):
        return True
    print("error: %s not found: run `orogen analyze %s` first" % (path, run), file=sys.stderr)
    return False


def load(path):
    """The whole analysis as an xarray.Dataset (loaded into memory; the file is closed)."""
    with xr.open_dataset(analysis_path(path), engine="h5netcdf") as ds:
        return ds.load()


def steady_output(ds):
    """Index of the flux steady-state output, or None if not reached."""
    k = int(ds.attrs["steady_output"])
    return None if k < 0 else k


def pro_cycle(run, ds):
    """The pro-wedge's thrust cycle against the erosion, one row per analysed output (thesis
    Figs 6.6, 6.7), as a pandas.DataFrame: S; Dp and Mp, the pro deformation and marker fronts
    from series.csv [h0]; front_gap = Mp - Dp, the thesis's proxy of the pro-wedge's steepness;
    step_out, Dp moved outward by more than STEP_OUT since the output before; flux, the eroded
    flux as a fraction of the incoming flux; eroded_area, the area eroded so far [d^2]; low,
    the flux below LOW_EROSION once erosion has begun. `run` is the run folder (or its
    analysis.h5), `ds` its analysis. A running run's series may hold outputs the analysis has
    not reached yet: the rows stop at the analysis's last output."""
    folder = run if os.path.isdir(run) else os.path.dirname(os.path.abspath(run))
    series = read_csv(os.path.join(folder, "series.csv"))[0]
    n = min(len(series), ds.sizes["time"])
    df = series.iloc[:n][["S", "Dp", "Mp"]].astype(float).reset_index(drop=True)
    df["front_gap"] = df.Mp - df.Dp
    step = np.zeros(n, dtype=bool)
    step[1:] = np.diff(-df.Dp.to_numpy()) > STEP_OUT
    df["step_out"] = step
    df["flux"] = ds.flux_out.values[:n] / float(ds.attrs["flux_in"])
    df["eroded_area"] = ds.cum_eroded_area.isel(time=slice(0, n)).sum("column").values
    begun = np.cumsum(df.eroded_area.to_numpy() > 0) > 0
    df["low"] = begun & (df.flux.to_numpy() < LOW_EROSION)
    return df


def jump_mean_final(ds):
    """Per closure depth and column: the mean jump size up to the last output (NaN: no jump)."""
    return ds.jump_mean.isel(time=-1)


def surface_age_stats(ds, after=None):
    """Mean and standard deviation of surface age per closure depth and column over the
    outputs from `after` on (default: the steady output, or all outputs if none)."""
    start = steady_output(ds) if after is None else after
    sub = ds.surface_age.isel(time=slice(start or 0, None))
    with warnings.catch_warnings():  # columns empty at every output give NaN, as they should
        warnings.simplefilter("ignore", RuntimeWarning)
        return xr.Dataset({"mean": sub.mean("time"), "std": sub.std("time")})


def at_positions(da, xs):
    """`da` (time x column) at the columns nearest to the x values `xs` [h0]."""
    return da.sel(column=np.asarray(xs, dtype=float), method="nearest")
