#!/usr/bin/python3
"""All figures of the exhumation analysis (thesis chapter 6) of one wedge run, one command.

Usage:
    build/release/orogen analyze RUN_DIR
    python3 -m orogen.charts.exhumation RUN_DIR [--out DIR] [--closure 0.5]
                                                 [--positions -1,0,1] [--frames 4]

Reads RUN_DIR/analysis.h5 (orogen.analysis.exhumation) and writes into DIR (default
RUN_DIR/charts/exhumation), each file atomically (temporary name, then os.replace):

    spacetime_elevation.png     x, time, coloured by elevation (thesis Figs 6.10, 6.11)
    spacetime_max_depth.png     coloured by the maximum depth of the surface disc (6.12, 6.15)
    spacetime_cum_erosion.png   coloured by cumulative eroded area per column (6.16)
    spacetime_surface_age.png   coloured by surface age at the chosen closure depth (6.20, 6.21)
    max_depth_positions.png     maximum depth of the surface disc through time at fixed x (6.13)
    age_positions.png           surface age through time at fixed x (6.17)
    age_jump_stats.png          surface age mean and spread, jump count and mean jump across x (6.18, 6.19)
    trajectories.png            surface discs of the chosen output back in time, x against
                                elevation and against depth, coloured by time, with isochrons (6.9)
    horizon_frames.png          discs coloured by their starting elevation at a few outputs,
                                with the area eroded per column so far (6.1-6.4)
    flux.png                    eroded flux against the incoming flux v h0, steady output marked
    pro_cycle.png               the pro deformation and marker fronts against the area eroded so
                                far, outputs of low erosion in grey, step-outs marked; below, the
                                gap between the two fronts, a proxy of the pro-wedge's steepness
                                (6.6, 6.7)

A run that laid sediment (surface.deposition, docs/surface.md) adds:

    spacetime_deposits.png      x, S, coloured by the sediment's thickness in each column
    basin_strata.png            the last output's discs: crust grey, sediment coloured by the S at
                                which it was laid (growth strata), with the sediment's mean age per column

A run on a deflecting base ([isostasy], docs/isostasy.md) adds:

    base_deflection.png         the base at the S-point, its deepest point and under each front
                                against S; below, the base's profile at a few outputs
"""

import argparse
import os
import sys

import h5py
import pandas as pd

import numpy as np
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from .. import atomic  # noqa: E402
from ..analysis import exhumation as orogen_analysis  # noqa: E402

FIGURES = ("spacetime_elevation.png", "spacetime_max_depth.png", "spacetime_cum_erosion.png",
           "spacetime_surface_age.png", "max_depth_positions.png", "age_positions.png",
           "age_jump_stats.png", "trajectories.png", "horizon_frames.png", "flux.png",
           "pro_cycle.png")


BASIN_FIGURES = ("spacetime_deposits.png", "basin_strata.png")
BASE_FIGURES = ("base_deflection.png",)


def save(fig, out, name):
    atomic.save_figure(fig, os.path.join(out, name))


def spacetime(ds, da, title, label, cmap, out, name):
    fig, ax = plt.subplots(figsize=(8, 5))
    m = ax.pcolormesh(ds.column.values, ds.S.values, np.ma.masked_invalid(da.values), shading="nearest", cmap=cmap)
    # Only the columns that ever held the surface: a long foreland window would squeeze the wedge.
    held = np.flatnonzero(np.isfinite(da.values).any(axis=0))
    if held.size:
        x = ds.column.values
        pad = 0.5 * float(np.median(np.diff(x))) if x.size > 1 else 0.5
        ax.set_xlim(x[held[0]] - pad, x[held[-1]] + pad)
    fig.colorbar(m, ax=ax, label=label)
    ax.set_xlabel("x from the S-point [h0]")
    ax.set_ylabel("S = v t / h0")
    ax.set_title(title)
    save(fig, out, name)


def through_time(ds, da, xs, ylabel, title, out, name):
    fig, ax = plt.subplots(figsize=(8, 4))
    for x in xs:
        series = da.sel(column=x, method="nearest")
        ax.plot(ds.S.values, series.values, label="x = %.2f h0" % float(series.column))
    ax.set_xlabel("S = v t / h0")
    ax.set_ylabel(ylabel)
    ax.set_title(title)
    ax.legend(fontsize=8)
    save(fig, out, name)


def trajectories(ds, out, every):
    fig, axes = plt.subplots(2, 1, figsize=(8, 8), sharex=True)
    s = ds.S.values
    tx, ty, td = ds.trajectory_x.values, ds.trajectory_y.values, ds.trajectory_depth.values
    for ax, v, label in ((axes[0], ty, "elevation [h0]"), (axes[1], td, "depth below the surface [h0]")):
        for j in range(tx.shape[1]):
            ax.plot(tx[:, j], v[:, j], color="0.8", lw=0.5, zorder=1)
        sc = ax.scatter(tx.ravel(), v.ravel(), c=np.repeat(s, tx.shape[1]), s=3, cmap="viridis", zorder=2)
        for k in range(0, len(s), every):  # isochrons: the discs at one output joined along x
            order = np.argsort(tx[k])
            ax.plot(tx[k][order], v[k][order], color="k", lw=0.6, zorder=3)
        ax.set_ylabel(label)
        fig.colorbar(sc, ax=ax, label="S")
    axes[1].invert_yaxis()
    axes[1].set_xlabel("x from the S-point [h0]")
    axes[0].set_title("surface discs of output %d back in time; black: isochrons" % int(ds.attrs["trajectory_output"]))
    save(fig, out, "trajectories.png")


def horizon_frames(ds, out, frames):
    nt = ds.sizes["time"]
    picks = sorted(set(int(round(k)) for k in np.linspace(0, nt - 1, frames)))
    fig, axes = plt.subplots(len(picks), 1, figsize=(9, 2.2 * len(picks)), sharex=True, squeeze=False)
    ys = ds.y.values
    seen = np.isfinite(ys)
    first_y = ys[np.argmax(seen, axis=0), np.arange(ys.shape[1])]  # each disc's elevation when first seen
    for ax, k in zip(axes[:, 0], picks):
        x, y = ds.x.isel(time=k).values, ds.y.isel(time=k).values
        ok = np.isfinite(x)
        ax.scatter(x[ok], y[ok], c=np.floor(first_y[ok] * 5) % 2, s=2, cmap="coolwarm")
        area = ds.cum_eroded_area.isel(time=k).values
        width = float(ds.column[1] - ds.column[0]) if ds.sizes["column"] > 1 else 1.0
        h0 = float(ds.attrs["h0"])
        ax.bar(ds.column.values, area / (width * h0 * h0), bottom=np.nan_to_num(ds.elevation.isel(time=k).values),
               width=width, color="tab:orange", alpha=0.5)
        ax.set_ylabel("y [h0]")
        ax.set_title("S = %.2f: horizons (bands of starting elevation); orange: eroded area as a height" %
                     float(ds.S[k]), fontsize=9)
    axes[-1, 0].set_xlabel("x from the S-point [h0]")
    save(fig, out, "horizon_frames.png")


def flux(ds, out):
    fig, ax = plt.subplots(figsize=(8, 4))
    ax.plot(ds.S.values, ds.flux_out.values, color="0.6", lw=0.8, label="eroded flux")
    ax.plot(ds.S.values, ds.flux_out_mean.values, color="tab:red",
            label="eroded flux, mean of %d outputs" % int(ds.attrs["flux_window"]))
    ax.axhline(float(ds.attrs["flux_in"]), color="k", label="incoming flux v h0 phi0")
    k = orogen_analysis.steady_output(ds)
    if k is not None:
        ax.axvline(float(ds.S[k]), color="tab:blue", ls="--", label="steady state (output %d)" % k)
    ax.set_xlabel("S = v t / h0")
    ax.set_ylabel("flux [d^2 / sqrt(d/g)]")
    ax.legend(fontsize=8)
    save(fig, out, "flux.png")


def shade_low_erosion(ax, cycle):
    """Grey bands over the outputs of low erosion, each as wide as one output spacing."""
    s = cycle.S.to_numpy()
    half = 0.5 * (s[1] - s[0]) if len(s) > 1 else 0.0
    for k in np.flatnonzero(cycle.low.to_numpy()):
        ax.axvspan(s[k] - half, s[k] + half, color="0.85", lw=0)


def pro_cycle(run, ds, out):
    cycle = orogen_analysis.pro_cycle(run, ds)
    fig, (top, bottom) = plt.subplots(2, 1, figsize=(8, 6.5), sharex=True, height_ratios=(3, 2))
    for ax in (top, bottom):
        shade_low_erosion(ax, cycle)
    top.plot(cycle.S, cycle.Dp, color="tab:blue", lw=1, label="pro deformation front Dp")
    top.plot(cycle.S, cycle.Mp, color="tab:green", lw=1, label="pro marker front Mp")
    steps = cycle[cycle.step_out]
    top.plot(steps.S, steps.Dp, "v", color="tab:blue", ms=4, label="step-out (> %.1f h0)" % orogen_analysis.STEP_OUT)
    top.set_ylabel("x from the S-point [h0]")
    eroded = top.twinx()
    eroded.plot(cycle.S, cycle.eroded_area, color="tab:red", lw=1)
    eroded.set_ylabel("area eroded so far [d^2]", color="tab:red")
    top.legend(fontsize=8, loc="lower left")
    top.set_title("grey: outputs eroding below %.2f of the incoming flux" % orogen_analysis.LOW_EROSION, fontsize=9)
    bottom.plot(cycle.S, cycle.front_gap, color="k", lw=1)
    bottom.set_ylabel("Mp - Dp [h0]")
    bottom.set_xlabel("S = v t / h0")
    save(fig, out, "pro_cycle.png")


def age_jump_stats(ds, ci, out):
    stats = orogen_analysis.surface_age_stats(ds)
    fig, axes = plt.subplots(3, 1, figsize=(8, 8), sharex=True)
    x = ds.column.values
    axes[0].errorbar(x, stats["mean"].isel(closure=ci).values, yerr=stats["std"].isel(closure=ci).values, fmt=".")
    axes[0].set_ylabel("surface age [sqrt(d/g)]")
    axes[1].plot(x, ds.jump_count.isel(time=-1, closure=ci).values, ".")
    axes[1].set_ylabel("jump count")
    axes[2].plot(x, orogen_analysis.jump_mean_final(ds).isel(closure=ci).values, ".")
    axes[2].set_ylabel("mean jump [sqrt(d/g)]")
    axes[2].set_xlabel("x from the S-point [h0]")
    axes[0].set_title("closure depth %.2f h0" % float(ds.closure[ci]))
    save(fig, out, "age_jump_stats.png")


def has_deposits(ds):
    return "deposition_time" in ds and bool(np.isfinite(ds.deposition_time.values).any())


def basin_strata(ds, out):
    """The last output's discs, the sediment coloured by the S at which it was laid."""
    last = ds.sizes["time"] - 1
    x, y = ds.x.isel(time=last).values, ds.y.isel(time=last).values
    laid = ds.deposition_time.values
    here = np.isfinite(x)
    crust, sediment = here & ~np.isfinite(laid), here & np.isfinite(laid)
    laid_s = np.interp(laid[sediment], ds.time.values, ds.S.values)
    fig, (ax, ax_age) = plt.subplots(2, 1, figsize=(10, 5.5), sharex=True, gridspec_kw={"height_ratios": [3, 1]})
    ax.scatter(x[crust], y[crust], s=2, c="0.75", lw=0)
    m = ax.scatter(x[sediment], y[sediment], s=5, c=laid_s, cmap="viridis", lw=0)
    fig.colorbar(m, ax=ax, label="S when laid")
    ax.set_ylabel("y [h0]")
    ax.set_title("S = %.2f: growth strata (sediment by the S it was laid at; crust grey; vertical exaggeration)"
                 % float(ds.S[last]), fontsize=10)
    ys = y[here]
    ax.set_ylim(ys.min() - 0.2, ys.max() + 0.3)  # vertically exaggerated: the strata are thin
    ax_age.plot(ds.column.values, ds.deposit_thickness.isel(time=last).values, color="tab:brown")
    ax_age.set_ylabel("sediment [h0]", color="tab:brown")
    twin = ax_age.twinx()
    twin.plot(ds.column.values, ds.deposit_age.isel(time=last).values, color="tab:blue", lw=0.8)
    twin.set_ylabel("mean age [sqrt(d/g)]", color="tab:blue")
    ax_age.set_xlabel("x from the S-point [h0]")
    save(fig, out, "basin_strata.png")


def base_deflection(run, out, profiles=4):
    """The deflecting base through time (series.csv) and its profile at a few outputs (the
    snapshots' walls, lengths over h0)."""
    series = pd.read_csv(os.path.join(run, "series.csv"), comment="#")
    fig, (ax, ax_p) = plt.subplots(2, 1, figsize=(9, 6.5))
    ax.plot(series.S, series.base_s_point, label="at the S-point")
    ax.plot(series.S, -series.deflection_max, label="deepest")
    ax.plot(series.S, -series.basin_pro, label="under the pro front")
    ax.plot(series.S, -series.basin_retro, label="under the retro front")
    ax.set_xlabel("S = v t / h0")
    ax.set_ylabel("base height [h0]")
    ax.set_title("the base under the wedge through time (negative: sunk)", fontsize=10)
    ax.legend(fontsize=8)
    with h5py.File(os.path.join(run, "snapshots.h5"), "r") as f:
        h0 = float(f.attrs["h0"])
        names = sorted(k for k in f if k.startswith("output_"))
        for k in sorted(set(int(round(v)) for v in np.linspace(0, len(names) - 1, profiles))):
            walls = f[names[k]]["walls"][()]
            walls = walls[(walls[:, 0] != walls[:, 2]) & (np.abs(walls[:, 0]) < 1e6)]
            walls = walls[np.argsort(walls[:, 0])]
            ax_p.plot(np.append(walls[:, 0], walls[-1, 2]) / h0, np.append(walls[:, 1], walls[-1, 3]) / h0,
                      label="S = %.2f" % float(f[names[k]].attrs.get("S", np.nan)))
    ax_p.set_xlabel("x from the S-point [h0]")
    ax_p.set_ylabel("base [h0]")
    ax_p.set_title("the base's profile at a few outputs (vertical exaggeration)", fontsize=10)
    ax_p.legend(fontsize=8)
    save(fig, out, "base_deflection.png")


def has_deflecting_base(run):
    path = os.path.join(run, "series.csv")
    return os.path.isfile(path) and "base_s_point" in pd.read_csv(path, comment="#", nrows=1).columns


def make_all(run, out=None, closure=0.5, positions=None, frames=4):
    ds = orogen_analysis.load(run)
    out = out or os.path.join(run if os.path.isdir(run) else os.path.dirname(run), "charts", "exhumation")
    os.makedirs(out, exist_ok=True)
    ci = int(np.argmin(np.abs(ds.closure.values - closure)))
    xs = positions if positions is not None else list(np.percentile(ds.column.values, [40, 55, 70]))
    spacetime(ds, ds.elevation, "elevation", "elevation [h0]", "terrain", out, "spacetime_elevation.png")
    spacetime(ds, ds.surface_max_depth, "maximum depth of the surface disc", "max depth [h0]", "magma", out,
              "spacetime_max_depth.png")
    spacetime(ds, ds.cum_eroded_area, "cumulative erosion", "eroded area [d^2]", "viridis", out,
              "spacetime_cum_erosion.png")
    spacetime(ds, ds.surface_age.isel(closure=ci), "surface age, closure depth %.2f h0" % float(ds.closure[ci]),
              "age [sqrt(d/g)]", "cividis", out, "spacetime_surface_age.png")
    through_time(ds, ds.surface_max_depth, xs, "max depth of the surface disc [h0]",
                 "maximum depth at fixed positions", out, "max_depth_positions.png")
    through_time(ds, ds.surface_age.isel(closure=ci), xs, "surface age [sqrt(d/g)]",
                 "surface age at fixed positions (closure %.2f h0)" % float(ds.closure[ci]), out, "age_positions.png")
    age_jump_stats(ds, ci, out)
    trajectories(ds, out, max(1, ds.sizes["time"] // 8))
    horizon_frames(ds, out, frames)
    flux(ds, out)
    pro_cycle(run, ds, out)
    run_dir = run if os.path.isdir(run) else os.path.dirname(run)
    if has_deposits(ds):
        spacetime(ds, ds.deposit_thickness, "sediment in each column", "sediment [h0]", "YlOrBr", out,
                  "spacetime_deposits.png")
        basin_strata(ds, out)
    if has_deflecting_base(run_dir):
        base_deflection(run_dir, out)
    return out


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("run", help="run folder holding analysis.h5 (orogen analyze), or the file")
    p.add_argument("--out", help="output folder (default RUN/charts/exhumation)")
    p.add_argument("--closure", type=float, default=0.5, help="closure depth [h0] of the age figures (nearest)")
    p.add_argument("--positions", help="x values [h0] of the through-time figures, comma-separated")
    p.add_argument("--frames", type=int, default=4, help="outputs in horizon_frames.png")
    a = p.parse_args(argv)
    if not orogen_analysis.found(a.run):
        return 2
    positions = None
    if a.positions:
        try:
            positions = [float(v) for v in a.positions.split(",")]
        except ValueError:
            print("error: --positions %s: not a comma-separated list of numbers" % a.positions, file=sys.stderr)
            return 2
    if a.frames < 1:
        print("error: --frames %d: must be at least 1" % a.frames, file=sys.stderr)
        return 2
    out = make_all(a.run, a.out, a.closure, positions, a.frames)
    print("wrote %d figures to %s" % (len([f for f in os.listdir(out) if f.endswith(".png")]), out))
    return 0


if __name__ == "__main__":
    sys.exit(main())
