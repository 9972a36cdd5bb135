#!/usr/bin/python3
"""Charts of doubly-vergent wedge runs (Naylor 2004, chapters 4-5; docs MODEL.md sections 8-9).

Usage:
    python3 -m orogen.charts.wedge RUN_DIR [RUN_DIR ...] --out OUTDIR [--labels a,b]
                                   [--calibration calibration.json]

Each RUN_DIR is the folder of an `orogen run --set run.experiment=wedge` run: it must hold
series.csv and, for the topography chart, snapshots.h5. Writes into OUTDIR (each file
atomically: a temporary file in OUTDIR, then os.replace):

    height_peak.png  H/h0 and x_T/h0 against S, Simple Model, power-law fit (Figs 4.6, 4.9, 4.11)
    tapers.png       alpha, beta (alpha_fit, beta_fit dashed) against S (Figs 4.7, 4.12), with the
                     critical tapers of the run's calibrated material on its bases (shaded
                     between the residual and the peak friction; --calibration, or the shipped
                     calibration of the default material)
    fronts.png       Dp, Mp, Dr, Mr against S (Fig 5.14)
    topography.png   the upper surface through time with the fronts (Fig 5.13)
    slip.png         fraction of basal contacts at the Coulomb limit against S (stages of growth)
    summary.json     per run: final S and H, fitted exponent, late tapers, retro accretion onset

Several runs are overlaid, one colour per run. Only numpy, pandas (the tables, through
orogen.tables), matplotlib (Agg) and h5py (snapshots.h5, through the package's orogen.frames) are
used; without h5py the topography chart says so instead of drawing the surface.

Conventions: lengths are in units of h0 and x is measured from the S-point (x = 0), as in
series.csv. The program reports a front as exactly 0 (the S-point) while no disc is above the
front's height, so an exact 0 in Dp, Mp, Dr, Mr or T is read as "no front yet" and not drawn;
taper angles are drawn only where a deformation front exists.
"""

import argparse
import json
import math
import os
import sys

import numpy as np
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.lines import Line2D  # noqa: E402

from .. import atomic, folders, results, tables  # noqa: E402
from ..analysis import calibrated_taper, surface  # noqa: E402
from ..analysis.powerlaw import power_law_fit, simple_model_height  # noqa: E402,F401 (shared fits)

FIT_S_MIN = 0.5          # power-law fit of H over S > FIT_S_MIN (and H > 0)
LATE_FRACTION = 1.0 / 3  # late-time means over the last third of the run (in S)
RETRO_ONSET_X = 1.0      # Dr beyond +1 h0: retro-side accretion (Stage 3)
COLUMN_WIDTH_RADII = 2.3  # surface columns 2.3 mean radii wide (MODEL section 8)
MAX_PROFILES = 40        # at most this many stacked profiles in topography.png
FRONT_COLUMNS = ("Dp", "Mp", "Dr", "Mr", "T")


# --------------------------------------------------------------------------------------------
# Reading


def read_series(path):
    """Reads series.csv: returns (columns: dict name -> float array, descriptions: dict)."""
    return tables.read_table(path)


def column(series, name):
    """The named column, or NaNs when the run's series lacks it."""
    n = len(series["S"]) if "S" in series else 0
    return series.get(name, np.full(n, np.nan))


def front_values(series, name):
    """A front column with 'no front yet' (exactly 0, or not finite) as NaN."""
    v = np.array(column(series, name), dtype=float)
    v[(v == 0.0) | ~np.isfinite(v)] = np.nan
    return v


def has_wedge(series):
    """Rows where a deformation front exists (Dp or Dr away from the S-point default)."""
    dp = column(series, "Dp")
    dr = column(series, "Dr")
    return (np.isfinite(dp) & (dp != 0.0)) | (np.isfinite(dr) & (dr != 0.0))


def read_topography(h5_path, max_profiles=None):
    """Upper surface of every complete output of snapshots.h5.

    Columns of width 2.3 mean radii (of each output) on a grid anchored at the S-point; the top
    (y + r) of the highest disc in a column is the surface there. Returns a list of dicts with
    step, S, x_centres (h0), height (h0; NaN for empty columns), and h0 (world units)."""
    if folders.h5py is None:
        raise RuntimeError("h5py is not installed")
    from orogen.frames import Snapshots  # the package's reader (h5py): complete outputs only
    out = []
    with Snapshots(h5_path) as snaps:
        n = len(snaps)
        h0 = float(snaps.attrs.get("h0", 1.0))
        if not (h0 > 0):
            h0 = 1.0
        indices = list(range(n))
        if max_profiles and n > max_profiles:
            keep = np.unique(np.round(np.linspace(0, n - 1, max_profiles)).astype(int))
            indices = [int(k) for k in keep]
        for k in indices:
            frame = snaps.frame(k, fields=("x", "y", "radius"))  # a surface needs no other field
            x = np.asarray(frame["x"], dtype=float)
            y = np.asarray(frame["y"], dtype=float)
            r = np.asarray(frame["radius"], dtype=float)
            ok = np.isfinite(x) & np.isfinite(y) & np.isfinite(r)
            x, y, r = x[ok], y[ok], r[ok]
            step = int(frame["attrs"].get("step", k))
            s_value = float(frame["attrs"].get("S", np.nan))
            if x.size == 0:
                out.append(dict(output=k, step=step, S=s_value, x=np.array([]), height=np.array([]), h0=h0))
                continue
            width = COLUMN_WIDTH_RADII * float(np.mean(r))
            if not (width > 0):
                width = 1.0
            lo, hi = np.floor(x.min() / width), np.floor(x.max() / width) + 1  # grid anchored at x = 0
            centres, height = surface.surface_columns(x, y, r, lo * width, hi * width, width)
            out.append(dict(output=k, step=step, S=s_value, x=centres / h0, height=height / h0, h0=h0))
    return out


# --------------------------------------------------------------------------------------------
# Statistics


def late_rows(series, fraction=LATE_FRACTION):
    """Rows in the last `fraction` of the run, by S."""
    s = column(series, "S")
    if len(s) == 0 or not np.any(np.isfinite(s)):
        return np.zeros(len(s), dtype=bool)
    s_end = float(np.nanmax(s))
    return np.isfinite(s) & (s >= (1.0 - fraction) * s_end)


def late_mean(series, name, fraction=LATE_FRACTION):
    """Mean of a taper column over the last third of the run, rows with a wedge only."""
    v = column(series, name)
    ok = late_rows(series, fraction) & has_wedge(series) & np.isfinite(v)
    return float(np.mean(v[ok])) if ok.any() else float("nan")


def retro_onset(series, threshold=RETRO_ONSET_X):
    """First row where Dr > threshold: (output index, step, S), or (None, None, None)."""
    dr = column(series, "Dr")
    idx = np.nonzero(np.isfinite(dr) & (dr > threshold))[0]
    if idx.size == 0:
        return None, None, None
    i = int(idx[0])
    step = column(series, "step")[i]
    s = column(series, "S")[i]
    return i, (int(step) if np.isfinite(step) else None), finite_or_none(s)


def finite_or_none(v):
    try:
        v = float(v)
    except (TypeError, ValueError):
        return None
    return v if math.isfinite(v) else None


def last_finite(v):
    v = np.asarray(v, dtype=float)
    ok = np.nonzero(np.isfinite(v))[0]
    return float(v[ok[-1]]) if ok.size else float("nan")


def summarize(run):
    series = run["series"]
    fit = run["fit"]
    onset_output, onset_step, onset_s = retro_onset(series)
    return {
        "label": run["label"],
        "dir": run["dir"],
        "n_outputs": int(len(column(series, "S"))),
        "final_S": finite_or_none(last_finite(column(series, "S"))),
        "final_H": finite_or_none(last_finite(column(series, "H"))),
        "b": finite_or_none(fit["b"]) if fit else None,
        "b_se": finite_or_none(fit["b_se"]) if fit else None,
        "r2": finite_or_none(fit["r2"]) if fit else None,
        "a": finite_or_none(fit["a"]) if fit else None,
        "a_se": finite_or_none(fit["a_se"]) if fit else None,
        "fit_points": int(fit["n"]) if fit else 0,
        "fit_S_min": FIT_S_MIN,
        "mean_alpha_late": finite_or_none(late_mean(series, "alpha")),
        "mean_beta_late": finite_or_none(late_mean(series, "beta")),
        "mean_alpha_fit_late": finite_or_none(late_mean(series, "alpha_fit")),
        "mean_beta_fit_late": finite_or_none(late_mean(series, "beta_fit")),
        "retro_onset_step": onset_step,
        "retro_onset_output": onset_output,
        "retro_onset_S": onset_s,
        "critical_taper": run["critical"],
    }


# --------------------------------------------------------------------------------------------
# Output


def write_json(obj, path):
    text = json.dumps(obj, indent=2, allow_nan=False) + "\n"
    atomic.write_text(path, text)


def run_colors(n):
    cmap = plt.get_cmap("tab10")
    return [cmap(i % 10) for i in range(n)]


def s_limits(runs):
    """(min S, max S) over every run, or None."""
    values = [column(r["series"], "S") for r in runs]
    values = np.concatenate([v[np.isfinite(v)] for v in values]) if values else np.array([])
    if values.size == 0 or values.max() <= values.min():
        return None
    return float(values.min()), float(values.max())


def no_data(ax, text="no data"):
    ax.text(0.5, 0.5, text, transform=ax.transAxes, ha="center", va="center", color="0.4")


# --------------------------------------------------------------------------------------------
# Charts


def chart_height_peak(runs, path):
    fig, axes = plt.subplots(1, 3, figsize=(16, 5))
    ax_h, ax_log, ax_t = axes
    any_data = False
    for run in runs:
        s, c = column(run["series"], "S"), run["color"]
        h = column(run["series"], "H")
        ok = np.isfinite(s) & np.isfinite(h)
        if not ok.any():
            continue
        any_data = True
        ax_h.plot(s[ok], h[ok], "-", color=c, lw=1.6, label="%s: H" % run["label"])
        pos = ok & (s > 0) & (h > 0)
        ax_log.loglog(s[pos], h[pos], "o", color=c, ms=3, label="%s: H" % run["label"])
        fit = run["fit"]
        if fit:
            sf = np.linspace(max(FIT_S_MIN, np.nanmin(s[ok])), np.nanmax(s[ok]), 100)
            text = "%s: fit H = %.3g S^(%.3f ± %.3f), R² = %.3f" % (
                run["label"], fit["a"], fit["b"], fit["b_se"], fit["r2"])
            ax_h.plot(sf, fit["a"] * sf ** fit["b"], ":", color=c, lw=1.6, label=text)
            ax_log.loglog(sf, fit["a"] * sf ** fit["b"], "-", color=c, lw=1.2,
                          label="b = %.3f ± %.3f" % (fit["b"], fit["b_se"]))
        a_m, b_m = late_mean(run["series"], "alpha"), late_mean(run["series"], "beta")
        sm = simple_model_height(s[ok], a_m, b_m)
        if sm is not None:
            lab = "%s: Simple Model (α = %.1f°, β = %.1f°)" % (run["label"], a_m, b_m)
            ax_h.plot(s[ok], sm, "--", color=c, lw=1.2, alpha=0.8, label=lab)
        t = front_values(run["series"], "T")
        tok = np.isfinite(s) & np.isfinite(t)
        ax_t.plot(s[tok], t[tok], "-", color=c, lw=1.4, label=run["label"])
    ax_h.set(xlabel="S (convergence / h0)", ylabel="H / h0", title="Wedge height")
    ax_log.set(xlabel="S", ylabel="H / h0", title="Wedge height, log-log (fit over S > %g)" % FIT_S_MIN)
    ax_t.axhline(0.0, color="0.5", lw=0.8)
    ax_t.set(xlabel="S (convergence / h0)", ylabel="x_T / h0 (from the S-point)",
             title="Peak position")
    for ax in axes:
        ax.grid(True, alpha=0.3)
        if ax.get_legend_handles_labels()[0]:
            ax.legend(fontsize=7, loc="best")
    if not any_data:
        for ax in axes:
            no_data(ax)
    fig.tight_layout()
    atomic.save_figure(fig, path)


def chart_tapers(runs, path):
    fig, axes = plt.subplots(1, 2, figsize=(14, 5), sharey=True)
    for ax, (name, fit_name, title) in zip(axes, (("alpha", "alpha_fit", "Pro-wedge taper α"),
                                                   ("beta", "beta_fit", "Retro-wedge taper β"))):
        drawn = False
        for run in runs:
            series, c = run["series"], run["color"]
            s = column(series, "S")
            wedge = has_wedge(series)
            for col_name, style, suffix in ((name, "-", ""), (fit_name, "--", " (fit)")):
                v = np.where(wedge, column(series, col_name), np.nan)
                ok = np.isfinite(s) & np.isfinite(v)
                if ok.any():
                    drawn = True
                    ax.plot(s, np.where(ok, v, np.nan), style, color=c, lw=1.3,
                            label="%s: %s%s" % (run["label"], col_name, suffix))
            m = late_mean(series, name)
            if np.isfinite(m):
                ax.axhline(m, color=c, lw=0.8, ls=":", label="%s: late mean %.1f°" % (run["label"], m))
            side = run["critical"].get("pro" if name == "alpha" else "retro")
            if side and np.isfinite(side["peak"]) and np.isfinite(side["residual"]):
                lo, hi = sorted((side["peak"], side["residual"]))
                ax.axhspan(lo, hi, color=c, alpha=0.12, lw=0,
                           label="%s: critical taper %.1f-%.1f° (%s, mu_b %.2g)"
                           % (run["label"], lo, hi, run["critical"]["calibration"], side["mu_b"]))
        if s_limits(runs):
            ax.set_xlim(*s_limits(runs))
        ax.set(xlabel="S (convergence / h0)", ylabel="angle [deg]", title=title)
        ax.grid(True, alpha=0.3)
        if drawn:
            ax.legend(fontsize=7, loc="best")
        else:
            no_data(ax, "no deformation front yet")
    fig.tight_layout()
    atomic.save_figure(fig, path)


def chart_fronts(runs, path):
    fig, ax = plt.subplots(figsize=(10, 6))
    styles = {"Dp": "-", "Dr": "-", "Mp": "--", "Mr": "--"}
    drawn = False
    for run in runs:
        s, c = column(run["series"], "S"), run["color"]
        for name, style in styles.items():
            v = front_values(run["series"], name)
            if np.isfinite(v).any():
                drawn = True
                ax.plot(s, v, style, color=c, lw=1.4 if name[0] == "D" else 1.0)
    if s_limits(runs):
        ax.set_xlim(*s_limits(runs))
    ax.axhline(0.0, color="0.3", lw=0.8)
    ax.axhline(RETRO_ONSET_X, color="0.6", lw=0.6, ls=":")
    ax.set(xlabel="S (convergence / h0)", ylabel="x / h0 from the S-point (pro < 0 < retro)",
           title="Deformation fronts (D, solid) and marker fronts (M, dashed)")
    ax.grid(True, alpha=0.3)
    handles = [Line2D([], [], color=r["color"], lw=2, label=r["label"]) for r in runs]
    handles += [Line2D([], [], color="k", ls="-", label="Dp (x<0), Dr (x>0)"),
                Line2D([], [], color="k", ls="--", label="Mp (x<0), Mr (x>0)")]
    ax.legend(handles=handles, fontsize=8, loc="best")
    if not drawn:
        no_data(ax, "no front yet")
    fig.tight_layout()
    atomic.save_figure(fig, path)


def chart_slip(runs, path):
    fig, axes = plt.subplots(2, 1, figsize=(10, 7), sharex=True)
    for ax, name, title in ((axes[0], "slip_pro", "Pro-side base"), (axes[1], "slip_retro", "Retro-side base")):
        drawn = False
        for run in runs:
            s, c = column(run["series"], "S"), run["color"]
            v = column(run["series"], name)
            ok = np.isfinite(s) & np.isfinite(v)
            if ok.any():
                drawn = True
                ax.plot(s[ok], v[ok], "-", color=c, lw=1.2, label=run["label"])
            _, _, onset_s = retro_onset(run["series"])
            if onset_s is not None:
                ax.axvline(onset_s, color=c, ls=":", lw=1.0)
        ax.set(ylabel="fraction at Coulomb limit", title=title, ylim=(-0.05, 1.05))
        ax.grid(True, alpha=0.3)
        if drawn:
            ax.legend(fontsize=8, loc="best", title="dotted: Dr > %g h0" % RETRO_ONSET_X,
                      title_fontsize=7)
        else:
            no_data(ax)
    axes[1].set_xlabel("S (convergence / h0)")
    fig.tight_layout()
    atomic.save_figure(fig, path)


def surface_at(profile, x):
    """Surface height (h0) of the column holding x, NaN outside or empty."""
    xs = profile["x"]
    if xs.size == 0 or not np.isfinite(x):
        return np.nan
    i = int(np.argmin(np.abs(xs - x)))
    return profile["height"][i]


def series_row_by_step(series):
    steps = column(series, "step")
    return {int(v): i for i, v in enumerate(steps) if np.isfinite(v)}


def chart_topography(runs, path):
    n = len(runs)
    fig = plt.figure(figsize=(16, 4 + 3.2 * n))
    grid = fig.add_gridspec(n, 2, width_ratios=(1.0, 1.1))
    ax_p = fig.add_subplot(grid[:, 0])
    # Fronts in black and grey, apart from the run colours (pro and retro lie either side of 0).
    front_style = {"Dp": ("-", "k"), "Dr": ("-", "k"), "Mp": ("--", "k"), "Mr": ("--", "k"),
                   "T": (":", "0.35")}

    # x range: around the fronts of every run (nothing happens far outside them).
    lo, hi = [], []
    for run in runs:
        for name in ("Dp", "Mp"):
            v = front_values(run["series"], name)
            if np.isfinite(v).any():
                lo.append(np.nanmin(v))
        for name in ("Dr", "Mr"):
            v = front_values(run["series"], name)
            if np.isfinite(v).any():
                hi.append(np.nanmax(v))
    x_lo = (min(lo) if lo else 0.0) - 2.0
    x_hi = (max(hi) if hi else 0.0) + 2.0

    profiles_all = []
    h_max = 0.2
    for run in runs:
        profiles = None
        if run["h5"] is not None:
            try:
                profiles = read_topography(run["h5"], MAX_PROFILES)
            except Exception as e:  # unreadable file: say so in the chart, draw the rest
                print("warning: %s: %s" % (run["h5"], e), file=sys.stderr)
                run["topo_error"] = str(e)
        profiles_all.append(profiles)
        for p in profiles or []:
            sel = (p["x"] >= x_lo) & (p["x"] <= x_hi)
            if sel.any() and np.isfinite(p["height"][sel]).any():
                h_max = max(h_max, float(np.nanmax(p["height"][sel])) - 1.0)
    n_prof = max([len(p) for p in profiles_all if p] or [1])
    # Offset between profiles: the stack is about 2.5 wedge heights tall, but at least 1.5 times
    # the column-to-column roughness (of the order of a disc), so rough thin layers stay legible.
    rough = [np.nanmedian(np.abs(np.diff(p["height"]))) for ps in profiles_all if ps for p in ps
             if p["height"].size > 1 and np.isfinite(p["height"]).sum() > 1]
    roughness = float(np.nanmedian(rough)) if rough else 0.0
    offset = max(2.5 * h_max / max(n_prof - 1, 1), 1.5 * roughness if np.isfinite(roughness) else 0.0)
    bottom = -1.0 - 2.0 * h_max  # the white fill under a profile reaches below every profile

    # Left: stacked profiles (height above the undeformed layer + offset by output index).
    any_profile = False
    for run, profiles in zip(runs, profiles_all):
        if not profiles:
            continue
        rows = series_row_by_step(run["series"])
        fronts = {name: front_values(run["series"], name) for name in front_style}
        track = {name: ([], []) for name in front_style}
        for j, p in enumerate(profiles):
            if p["x"].size == 0:
                continue
            any_profile = True
            sel = (p["x"] >= x_lo) & (p["x"] <= x_hi)
            base = j * offset
            yv = p["height"][sel] - 1.0 + base
            # Earlier (lower) profiles in front: their white fill hides later ones dipping below.
            ax_p.fill_between(p["x"][sel], bottom, yv, color="white", zorder=2 * (n_prof - j))
            ax_p.plot(p["x"][sel], yv, "-", color=run["color"], lw=0.8, zorder=2 * (n_prof - j) + 1)
            i = rows.get(p["step"])
            if i is None:
                continue
            for name in front_style:
                xf = fronts[name][i]
                if np.isfinite(xf):
                    track[name][0].append(xf)
                    track[name][1].append(surface_at(p, xf) - 1.0 + base)
        for name, (style, colour) in front_style.items():
            if track[name][0]:
                ax_p.plot(track[name][0], track[name][1], style, color=colour, lw=1.4, zorder=10 * n_prof,
                          marker="o" if name != "T" else None, ms=2.5)
    if any_profile:
        first = [np.nanmin(ps[0]["height"][(ps[0]["x"] >= x_lo) & (ps[0]["x"] <= x_hi)])
                 for ps in profiles_all if ps and ps[0]["x"].size
                 and ((ps[0]["x"] >= x_lo) & (ps[0]["x"] <= x_hi)).any()]
        first = [v for v in first if np.isfinite(v)]
        if first:
            ax_p.set_ylim(bottom=min(first) - 1.0 - 0.05 * (offset * max(n_prof - 1, 1) + h_max))
    ax_p.set(xlim=(x_lo, x_hi), xlabel="x / h0 from the S-point",
             ylabel="surface height above h0 [h0], profiles offset by %.3g h0 per output" % offset,
             title="Upper surface through time (later outputs higher)")
    handles = [Line2D([], [], color=r["color"], lw=1.5, label=r["label"]) for r in runs]
    handles += [Line2D([], [], ls=front_style[name][0], color=front_style[name][1], label=text)
                for name, text in (("Dp", "Dp, Dr"), ("Mp", "Mp, Mr"), ("T", "T (peak)"))]
    ax_p.legend(handles=handles, fontsize=7, loc="upper left")
    if not any_profile:
        no_data(ax_p, "no snapshots.h5 (or no h5py)" if folders.h5py is None or all(p is None for p in profiles_all)
                else "no discs")

    # Right: S-x image coloured by elevation, one panel per run, fronts on top.
    for r_i, (run, profiles) in enumerate(zip(runs, profiles_all)):
        ax = fig.add_subplot(grid[r_i, 1])
        if not profiles or all(p["x"].size == 0 for p in profiles):
            no_data(ax, "%s: %s" % (run["label"], run.get("topo_error", "no snapshots.h5")))
            ax.set_xticks([])
            ax.set_yticks([])
            continue
        width = min(float(np.median(np.diff(p["x"]))) for p in profiles if p["x"].size > 1) \
            if any(p["x"].size > 1 for p in profiles) else 0.2
        xe = np.arange(x_lo, x_hi + width, width)
        xc = 0.5 * (xe[:-1] + xe[1:])
        s_vals = np.array([p["S"] if np.isfinite(p["S"]) else j for j, p in enumerate(profiles)], dtype=float)
        image = np.full((len(profiles), xc.size), np.nan)
        for j, p in enumerate(profiles):
            if p["x"].size:
                image[j] = np.interp(xc, p["x"], np.where(np.isfinite(p["height"]), p["height"], 0.0),
                                     left=np.nan, right=np.nan)
        if len(s_vals) > 1:
            mid = 0.5 * (s_vals[:-1] + s_vals[1:])
            se = np.concatenate(([s_vals[0] - (mid[0] - s_vals[0])], mid, [s_vals[-1] + (s_vals[-1] - mid[-1])]))
        else:
            se = np.array([s_vals[0] - 0.5, s_vals[0] + 0.5])
        if s_vals[0] >= 0:
            se[0] = max(se[0], 0.0)  # no negative convergence below the first output
        mesh = ax.pcolormesh(xe, se, image, cmap="terrain", shading="flat",
                             vmin=min(0.8, np.nanmin(image)) if np.isfinite(image).any() else 0.0)
        fig.colorbar(mesh, ax=ax, label="surface elevation / h0", pad=0.01)
        s = column(run["series"], "S")
        for name, (style, colour) in front_style.items():
            v = front_values(run["series"], name)
            ok = np.isfinite(v) & np.isfinite(s)
            if ok.any():
                label = {"Dp": "Dp, Dr", "Mp": "Mp, Mr", "T": "T"}.get(name)  # one entry per kind
                ax.plot(v[ok], s[ok], style, color=colour, lw=1.4, label=label)
        ax.set(xlim=(x_lo, x_hi), ylim=(se[0], se[-1]), ylabel="S", title="%s: elevation through time" % run["label"])
        if r_i == n - 1:
            ax.set_xlabel("x / h0 from the S-point")
        ax.legend(fontsize=7, loc="upper left", ncol=5)
    fig.tight_layout()
    atomic.save_figure(fig, path)


# --------------------------------------------------------------------------------------------
# Driver


def unique_labels(dirs, labels):
    if labels is not None:
        out = [l.strip() for l in labels.split(",")]
        if len(out) != len(dirs):
            raise SystemExit("error: --labels gives %d labels for %d run folders" % (len(out), len(dirs)))
    else:
        out = [os.path.basename(os.path.normpath(d)) or d for d in dirs]
    seen = {}
    for i, l in enumerate(out):
        if l in seen:
            seen[l] += 1
            out[i] = "%s (%d)" % (l, seen[l])
        else:
            seen[l] = 1
    return out


def critical(d, calibration):
    """The critical tapers of the run's bases for its calibrated material, or why there are none."""
    if not os.path.isfile(os.path.join(d, "config.toml")):
        return {"calibration": None, "why": "no config.toml"}
    config = results.open_run(d).config
    cal, why = calibrated_taper.calibration_for(config, calibration)
    if cal is None:
        return {"calibration": None, "why": why}
    wedge = config.get("wedge", {})
    out = {"calibration": why, "phi_peak_deg": cal["peak"]["phi_deg"], "phi_residual_deg": cal["residual"]["phi_deg"]}
    for side, key in (("pro", "mu_bp"), ("retro", "mu_br")):
        if key in wedge:
            out[side] = dict(calibrated_taper.critical_tapers(cal, wedge[key]), mu_b=wedge[key])
    return out


def load_runs(dirs, labels, calibration=None):
    runs = []
    colors = run_colors(len(dirs))
    for d, label, color in zip(dirs, unique_labels(dirs, labels), colors):
        csv = os.path.join(d, "series.csv")
        if not os.path.isfile(csv):
            raise SystemExit("error: %s not found: give the folder of a wedge run" % csv)
        series, desc = read_series(csv)
        if "S" not in series or "H" not in series:
            raise SystemExit("error: %s has no S or H column: not a wedge run?" % csv)
        h5 = os.path.join(d, "snapshots.h5")
        runs.append(dict(dir=os.path.abspath(d), label=label, color=color, series=series,
                         descriptions=desc, h5=h5 if os.path.isfile(h5) else None,
                         critical=critical(d, calibration),
                         fit=power_law_fit(series["S"], series["H"])))
    return runs


CHARTS = (
    ("height_peak.png", chart_height_peak),
    ("tapers.png", chart_tapers),
    ("fronts.png", chart_fronts),
    ("topography.png", chart_topography),
    ("slip.png", chart_slip),
)


def make_charts(dirs, out_dir, labels=None, calibration=None):
    """Draws every chart and summary.json for the runs in `dirs` into out_dir; returns the summary.
    calibration: a calibration.json of the runs' material (default: the shipped one, where it fits)."""
    os.makedirs(out_dir, exist_ok=True)
    runs = load_runs(dirs, labels, calibration)
    with np.errstate(invalid="ignore", divide="ignore"):
        for name, draw in CHARTS:
            draw(runs, os.path.join(out_dir, name))
        summary = {"generated_by": "orogen.charts.wedge", "runs": [summarize(r) for r in runs]}
    write_json(summary, os.path.join(out_dir, "summary.json"))
    return summary


def main(argv=None):
    p = argparse.ArgumentParser(description="Charts of doubly-vergent wedge runs (thesis chapters 4-5).")
    p.add_argument("runs", nargs="+", metavar="RUN_DIR", help="folder of an orogen wedge run")
    p.add_argument("--out", required=True, metavar="OUTDIR", help="folder for the PNGs and summary.json")
    p.add_argument("--labels", default=None, help="comma-separated run labels (default: folder names)")
    p.add_argument("--calibration", default=None, metavar="JSON",
                   help="calibration.json of the runs' material (orogen calibrate) for the critical tapers; "
                        "default: the shipped calibration of the default material, where the runs are of it")
    args = p.parse_args(argv)
    if args.calibration is not None and not os.path.isfile(args.calibration):
        raise SystemExit("error: --calibration %s: no such file" % args.calibration)
    summary = make_charts(args.runs, args.out, args.labels, args.calibration)
    for r in summary["runs"]:
        b = "b = %.3f ± %.3f (R² %.3f)" % (r["b"], r["b_se"], r["r2"]) if r["b"] is not None else "no fit"
        print("%s: S = %s, H = %s, %s, retro onset step %s" % (
            r["label"], r["final_S"], r["final_H"], b, r["retro_onset_step"]))
    print("charts written to %s" % args.out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
