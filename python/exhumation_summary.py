#!/usr/bin/python3
"""The chapter-6 indicators of analysed eroding wedge runs, one Markdown row each (thesis 6.2-6.4;
docs/exhumation-evidence.md is made of these).

Usage:
    /usr/bin/python3 python/exhumation_summary.py RUN [RUN ...] [--json FILE]

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
"""

import argparse
import json
import os
import sys
import warnings

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import orogen  # noqa: E402  (the readers only: no compiled engine needed)
import orogen_analysis as oa  # noqa: E402



def read_series(run, n):
    """S, Dp and Dr of the first n outputs of series.csv (a running run's series may be ahead)."""
    series = orogen.read_csv(os.path.join(run, "series.csv"))[0].iloc[:n]
    return {k: series[k].to_numpy(dtype=float) for k in ("S", "Dp", "Dr")}


def slope(x, y):
    ok = np.isfinite(x) & np.isfinite(y)
    return float(np.polyfit(x[ok], y[ok], 1)[0]) if ok.sum() >= 3 else float("nan")


def corr(x, y):
    ok = np.isfinite(x) & np.isfinite(y)
    return float(np.corrcoef(x[ok], y[ok])[0, 1]) if ok.sum() >= 3 else float("nan")


def indicators(run, closure=0.3):
    ds = oa.load(run)
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
    eroding = cum > 0.05 * np.nanmax(cum)
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


def main(argv):
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("runs", nargs="+")
    p.add_argument("--closure", type=float, default=0.3, help="closure depth of the age figures [h0] (nearest)")
    p.add_argument("--json", help="also write the numbers here")
    a = p.parse_args(argv)
    for run in a.runs:
        if not os.path.exists(oa.analysis_path(run)):
            print(f"exhumation_summary: {run} has no analysis.h5 (run `orogen analyze {run}` first)", file=sys.stderr)
            return 2
    rows = [indicators(run, a.closure) for run in a.runs]
    sys.stdout.write(markdown(rows))
    if a.json:
        with open(a.json, "w") as f:
            json.dump(rows, f, indent=1)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
