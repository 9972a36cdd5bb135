#!/usr/bin/python3
"""The chapter-6 indicators of analysed eroding wedge runs, one Markdown row each (thesis 6.2-6.4;
docs/exhumation-evidence.md is made of these).

Usage:
    python3 -m orogen.analysis.exhumation_summary RUN [RUN ...] [--json FILE] [--cycle] [--ages N]
                                                   [--flux-table WIDTH]

Each RUN is a wedge run folder that `orogen analyze` has analysed (analysis.h5, series.csv).
Per run, with "after" meaning the outputs from the flux steady state on:

    steady        output and S of the flux steady state (analysis.h5 attribute steady_output)
    Dr rate       growth of the retro deformation front per unit S before and after: the
                  retro-wedge going dormant is a rate that falls to near zero
    Dp cycle      pro step-outs after (Dp moving outward by more than 0.5 h0 in one output), the
                  eroded flux in the outputs of a step-out against the others, as a fraction of
                  the incoming flux, and the outputs of low erosion (below a quarter of the
                  incoming flux) that lie within 2 outputs of a step-out, against the fraction
                  of all outputs after that do so by chance (the thesis: low erosion from the
                  axial zone while a new sheet is accreted, Figs 6.6, 6.7)
    skew          x of the largest cumulative erosion against x of the deepest time-averaged
                  surface maximum depth after (pro-ward skew: the first is the smaller)
    ages settle   surface age at the closure depth h (default 0.3 h0) over the axial columns
                  after: the drift of its mean per unit S (no steady state: not near zero) and
                  its scatter against its mean
    jumps         correlation of x with the jump count and with the mean jump at h over the
                  eroding columns retro-ward of the column with the most jumps (the thesis: count
                  falls and mean jump rises toward the retro side)

With --cycle, each run also gets the pro-front cycle before and after the steady state, counted
from the step-outs: how many step-outs have an output of low erosion at the step-out or in the
two outputs before it, against the chance that a window of three outputs of that phase holds
one; the outputs of low erosion; the eroded flux at step-outs against the other outputs.

With --ages N, each run also gets the surface ages at N positions spread evenly over the eroding
columns (pro to retro), per closure depth: the S at which reset material (surface_unreset 0)
first reaches the surface there, and the mean surface age from then on, with the means of the
first and second halves of that time (about equal: the age oscillates about a constant value,
thesis 6.5.2, Fig. 6.17).

With --flux-table WIDTH, each run also gets a table of its eroded flux against the incoming
flux (flux_ratio: the mean over the analysis's flux_window) in stretches of WIDTH in S from the
first erosion on: mean (min-max) per stretch.
"""

import argparse
import json
import os
import sys
import warnings

import numpy as np

from ..tables import read_csv
from . import exhumation as oa



def read_series(run, n):
    """S, Dp and Dr of the first n outputs of series.csv (a running run's series may be ahead)."""
    series = read_csv(os.path.join(run, "series.csv"))[0].iloc[:n]
    return {k: series[k].to_numpy(dtype=float) for k in ("S", "Dp", "Dr")}


def slope(x, y):
    ok = np.isfinite(x) & np.isfinite(y)
    return float(np.polyfit(x[ok], y[ok], 1)[0]) if ok.sum() >= 3 else float("nan")


def corr(x, y):
    ok = np.isfinite(x) & np.isfinite(y)
    return float(np.corrcoef(x[ok], y[ok])[0, 1]) if ok.sum() >= 3 else float("nan")


def eroding_columns(ds):
    """Mask of the columns with at least 5% of the largest cumulative erosion at the last output."""
    cum = ds.cum_eroded_area.isel(time=-1).values
    return cum > 0.05 * np.nanmax(cum)


def indicators(run, closure=0.3, ds=None):
    ds = oa.load(run) if ds is None else ds
    series = read_series(run, ds.sizes["time"])
    s = ds.S.values
    k0 = oa.steady_output(ds)
    out = {"run": os.path.basename(os.path.normpath(run)), "outputs": int(ds.sizes["time"]),
           "steady_output": k0, "steady_S": float(s[k0]) if k0 is not None else None}
    after = slice(k0, None) if k0 is not None else slice(len(s) // 2, None)
    before = slice(0, k0) if k0 is not None else slice(0, len(s) // 2)

    # The retro-wedge: front growth per unit S before and after the steady state.
    out["Dr_rate_before"] = slope(series["S"][before], series["Dr"][before])
    out["Dr_rate_after"] = slope(series["S"][after], series["Dr"][after])

    # The pro cycle against the erosion: flux in outputs where Dp steps out versus the rest.
    cycle = oa.pro_cycle(run, ds)
    m = len(cycle)
    step, flux = cycle.step_out.to_numpy(), cycle.flux.to_numpy()
    a = np.arange(m) >= (k0 if k0 is not None else len(s) // 2)
    out["pro_steps_after"] = int((step & a).sum())
    out["flux_at_steps"] = float(np.nanmean(flux[step & a])) if (step & a).any() else float("nan")
    out["flux_otherwise"] = float(np.nanmean(flux[~step & a]))
    near_step = np.array([bool((step & a)[max(k - 2, 0):k + 3].any()) for k in range(m)])
    low = a & cycle.low.to_numpy()
    out["low_erosion_outputs"] = int(low.sum())
    out["low_erosion_near_step"] = int((low & near_step).sum())
    out["near_step_by_chance"] = float(near_step[a].mean())

    # Skew: where most was eroded against where the deepest material reaches the surface.
    x = ds.column.values
    cum = ds.cum_eroded_area.isel(time=-1).values
    with np.errstate(all="ignore"), warnings.catch_warnings():
        warnings.simplefilter("ignore", RuntimeWarning)  # columns never at the surface: NaN
        maxdepth = np.nanmean(ds.surface_max_depth.isel(time=after).values, axis=0)
    out["x_max_erosion"] = float(x[np.nanargmax(cum)])
    out["x_deepest"] = float(x[np.nanargmax(maxdepth)])

    # Surface ages over the eroding columns after the steady state.
    eroding = eroding_columns(ds)
    age = ds.surface_age.sel(closure=closure, method="nearest").isel(time=after).values[:, eroding]
    mean_age = np.nanmean(age, axis=1)
    out["closure"] = float(ds.closure.sel(closure=closure, method="nearest"))
    out["age_drift"] = slope(s[after], mean_age)
    out["age_mean"] = float(np.nanmean(mean_age))
    out["age_scatter"] = float(np.nanstd(mean_age))

    # Jumps across the eroding columns at the end.
    last = ds.isel(time=-1).sel(closure=closure, method="nearest")
    count = last.jump_count.values.astype(float)
    x_peak = x[np.nanargmax(np.where(eroding, count, -1))]
    retro = eroding & (x >= x_peak)
    out["eroding_x"] = [float(x[eroding].min()), float(x[eroding].max())]
    out["x_most_jumps"] = float(x_peak)
    out["corr_x_jump_count"] = corr(x[retro], count[retro])
    out["corr_x_jump_mean"] = corr(x[retro], last.jump_mean.values[retro])
    return out


def fmt(v, digits=3):
    if v is None or (isinstance(v, float) and not np.isfinite(v)):
        return "-"
    return f"{v:.{digits}g}" if isinstance(v, float) else str(v)


def whole(v):
    return f"{v:.0f}" if np.isfinite(v) else "-"


def markdown(rows):
    head = ("| run | steady output (S) | Dr rate before / after | pro step-outs after | flux at step-outs / "
            "otherwise [flux in] | low-erosion outputs near a step-out (chance) | x max erosion / deepest [h0] | "
            "age drift per S / mean / scatter | corr(x, jump count) / corr(x, mean jump), retro of the most jumps |\n"
            "|---|---|---|---:|---|---|---|---|---|\n")
    lines = []
    for r in rows:
        steady = f"{r['steady_output']} ({r['steady_S']:.1f})" if r["steady_output"] is not None else "not reached"
        lines.append(
            f"| {r['run']} | {steady} | {fmt(r['Dr_rate_before'])} / {fmt(r['Dr_rate_after'])} | "
            f"{r['pro_steps_after']} | {fmt(r['flux_at_steps'])} / {fmt(r['flux_otherwise'])} | "
            f"{r['low_erosion_near_step']} of {r['low_erosion_outputs']} ({fmt(r['near_step_by_chance'], 2)}) | "
            f"{fmt(r['x_max_erosion'])} / {fmt(r['x_deepest'])} | {fmt(r['age_drift'])} / {fmt(r['age_mean'])} / "
            f"{fmt(r['age_scatter'])} | {fmt(r['corr_x_jump_count'])} / {fmt(r['corr_x_jump_mean'])} |")
    return head + "\n".join(lines) + "\n"


def cycle_phases(run, ds=None):
    """The pro-front cycle counted from its step-outs, before and after the flux steady state
    (before: from the first erosion; without a steady state, "before" is every output from the
    first erosion on and "after" is empty): a dict per phase."""
    ds = oa.load(run) if ds is None else ds
    return phases_of_cycle(oa.pro_cycle(run, ds), oa.steady_output(ds))


def phases_of_cycle(cycle, k0):
    """cycle_phases of an orogen_analysis.pro_cycle table with steady output k0 (None: none)."""
    m = len(cycle)
    step, low, flux = cycle.step_out.to_numpy(), cycle.low.to_numpy(), cycle.flux.to_numpy()
    begun = np.flatnonzero(cycle.eroded_area.to_numpy() > 0)
    first = int(begun[0]) if begun.size else m
    k0 = m if k0 is None else min(k0, m)
    # A window of three outputs ending at k: k - 2 .. k.
    low_in_window = np.array([bool(low[max(k - 2, 0):k + 1].any()) for k in range(m)])
    phases = {}
    for name, lo, hi in (("before", first, max(first, k0)), ("after", max(first, k0), m)):
        a = np.zeros(m, dtype=bool)
        a[lo:hi] = True
        steps = step & a
        phases[name] = {
            "outputs": [lo, hi - 1] if hi > lo else None,
            "step_outs": int(steps.sum()),
            "step_outs_after_low": int((steps & low_in_window).sum()),
            "window_chance": float(low_in_window[a].mean()) if a.any() else float("nan"),
            "low_outputs": int((low & a).sum()),
            "flux_at_steps": float(np.nanmean(flux[steps])) if steps.any() else float("nan"),
            "flux_otherwise": float(np.nanmean(flux[a & ~step])) if (a & ~step).any() else float("nan"),
        }
    return phases


def cycle_table(run, ds=None):
    name = os.path.basename(os.path.normpath(run))
    head = (f"| {name}: phase | outputs | step-outs | after low erosion (chance) | low-erosion outputs | "
            "flux at step-outs / otherwise [flux in] |\n|---|---|---:|---|---:|---|\n")
    lines = []
    for phase, r in cycle_phases(run, ds).items():
        span = f"{r['outputs'][0]}-{r['outputs'][1]}" if r["outputs"] else "-"
        lines.append(f"| {phase} the steady state | {span} | {r['step_outs']} | {r['step_outs_after_low']} "
                     f"({fmt(r['window_chance'], 2)}) | {r['low_outputs']} | {fmt(r['flux_at_steps'], 2)} / "
                     f"{fmt(r['flux_otherwise'], 2)} |")
    return head + "\n".join(lines) + "\n"


def eroding_positions(ds, n):
    """n x values spread evenly from the pro to the retro edge of the eroding columns (those
    with at least 5% of the largest cumulative erosion at the last output), at their columns;
    none in a run that has eroded nothing."""
    x = ds.column.values
    eroding = x[eroding_columns(ds)]
    if eroding.size == 0:
        return []
    return [float(x[np.argmin(np.abs(x - v))]) for v in np.linspace(eroding.min(), eroding.max(), n)]


def age_settling(ds, xs):
    """Per closure depth and x (nearest column): {closure, x, S_reset, mean, first_half,
    second_half}, S_reset the S of the first output with reset material at the surface (None:
    never), the means over the outputs from then on (NaN ages, empty columns, left out)."""
    s = ds.S.values
    rows = []
    for h in ds.closure.values:
        for x in xs:
            col = dict(closure=h, column=x)
            age = ds.surface_age.sel(col, method="nearest").values.astype(float)
            reset = ds.surface_unreset.sel(col, method="nearest").values == 0
            reset &= np.isfinite(age)
            row = {"closure": float(h), "x": float(x), "S_reset": None, "mean": float("nan"),
                   "first_half": float("nan"), "second_half": float("nan")}
            if reset.any():
                k = int(np.argmax(reset))
                later = age[k:][np.isfinite(age[k:])]
                half = len(later) // 2
                row.update(S_reset=float(s[k]), mean=float(later.mean()),
                           first_half=float(later[:half].mean()) if half else float("nan"),
                           second_half=float(later[half:].mean()))
            rows.append(row)
    return rows


def ages_table(run, n, ds=None):
    ds = oa.load(run) if ds is None else ds
    xs = eroding_positions(ds, n)
    name = os.path.basename(os.path.normpath(run))
    if not xs:
        return f"{name}: no column has eroded, so no surface ages to settle\n"
    rows = age_settling(ds, xs)
    closures = [float(h) for h in ds.closure.values]
    head = (f"| {name}: x [h0] | " + " | ".join(f"h = {h:g} h0: S reset, mean age (halves)" for h in closures)
            + " |\n|---|" + "---|" * len(closures) + "\n")
    lines = []
    for x in xs:
        cells = []
        for h in closures:
            r = next(r for r in rows if r["x"] == x and r["closure"] == h)
            cells.append("never reset" if r["S_reset"] is None else
                         f"{r['S_reset']:.1f}, {r['mean']:.0f} ({whole(r['first_half'])}, {whole(r['second_half'])})")
        lines.append(f"| {x:.2f} | " + " | ".join(cells) + " |")
    return head + "\n".join(lines) + "\n"


def flux_stretches(run, width, ds=None):
    """(S from, S to, mean, min, max) of flux_ratio per stretch of `width` in S, from the stretch
    in which erosion begins to the last analysed output."""
    ds = oa.load(run) if ds is None else ds
    s, ratio = ds.S.values, ds.flux_ratio.values
    begun = np.flatnonzero(ds.cum_eroded_area.sum("column").values > 0)
    if begun.size == 0:
        return []
    rows = []
    lo = np.floor(s[begun[0]] / width) * width
    while lo < s[-1]:
        hi = min(lo + width, s[-1])
        r = ratio[(s >= lo) & (s < lo + width)]
        r = r[np.isfinite(r)]
        if r.size:
            rows.append((float(lo), float(hi), float(r.mean()), float(r.min()), float(r.max())))
        lo += width
    return rows


def flux_table(run, width, ds=None):
    rows = flux_stretches(run, width, ds)
    name = os.path.basename(os.path.normpath(run))
    return (f"| {name}: S | " + " | ".join(f"{r[0]:.3g}-{r[1]:.3g}" for r in rows) + " |\n"
            "|---|" + "---|" * len(rows) + "\n"
            "| flux out / flux in, mean (min-max) | "
            + " | ".join(f"{m:.2f} ({a:.2g}-{b:.2g})" for _, _, m, a, b in rows) + " |\n")


def main(argv):
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("runs", nargs="+")
    p.add_argument("--closure", type=float, default=0.3, help="closure depth of the age figures [h0] (nearest)")
    p.add_argument("--json", help="also write the numbers here")
    p.add_argument("--cycle", action="store_true",
                   help="also print each run's pro-front cycle before and after the steady state")
    p.add_argument("--ages", type=int, metavar="N",
                   help="also print each run's surface ages at N positions across the eroding columns")
    p.add_argument("--flux-table", type=float, metavar="WIDTH",
                   help="also print each run's flux out / flux in by stretches of WIDTH in S")
    a = p.parse_args(argv)
    if a.ages is not None and a.ages < 1:
        print(f"exhumation_summary: --ages {a.ages}: must be at least 1 (positions)", file=sys.stderr)
        return 2
    if a.flux_table is not None and not a.flux_table > 0:
        print(f"exhumation_summary: --flux-table {a.flux_table}: must be a width in S above 0", file=sys.stderr)
        return 2
    for run in a.runs:
        if not os.path.exists(oa.analysis_path(run)):
            print(f"exhumation_summary: {run} has no analysis.h5 (run `orogen analyze {run}` first)", file=sys.stderr)
            return 2
    # Each analysis is loaded once (a long run's analysis.h5 is over a gigabyte).
    rows, tables = [], []
    for run in a.runs:
        ds = oa.load(run)
        rows.append(indicators(run, a.closure, ds))
        if a.cycle:
            tables.append(cycle_table(run, ds))
        if a.ages:
            tables.append(ages_table(run, a.ages, ds))
        if a.flux_table:
            tables.append(flux_table(run, a.flux_table, ds))
    sys.stdout.write(markdown(rows))
    for table in tables:
        sys.stdout.write("\n" + table)
    if a.json:
        with open(a.json, "w") as f:
            json.dump(rows, f, indent=1)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
