#!/usr/bin/python3
"""The isostasy runs' table (docs/isostasy-evidence.md): for each wedge run in a folder, at
S = 2, 4, 6 and 8, the wedge's height and fronts (measured above the deflected base), the base's
deepest point and where, its height at the S-point, the foredeep's room under each front, the
pro forebulge, the sediment laid so far; then each run's pro thrust sheets (orogen.analysis.cycles:
step-outs of Dp of at least 0.5 h0, their number and mean length).

    scripts/isostasy_table.py /work/runs/isostasy [--at 8,16,21]   (Markdown tables on standard output)

--at: the S values of the first table (2, 4, 6, 8 unless given). --figure PNG: the runs' height
and the base's deepest point through S, one line per run (--runs picks runs by name).
"""

import argparse
import os

import numpy as np
import pandas as pd

from orogen.analysis.cycles import cycles

AT = (2, 4, 6, 8)


def series_of(path):
    return pd.read_csv(os.path.join(path, "series.csv"), comment="#")


def at_rows(name, s, at=AT):
    out = []
    for S in at:
        r = s.iloc[(s.S - S).abs().argmin()]
        get = lambda c: r[c] if c in r else np.nan  # noqa: E731
        out.append(dict(run=name, S=round(r.S, 2), H=r.H, Dp=r.Dp, Dr=r.Dr, deepest=get("deflection_max"),
                        x_deepest=get("x_deflection_max"), s_point=get("base_s_point"), basin_pro=get("basin_pro"),
                        basin_retro=get("basin_retro"), bulge_pro=get("forebulge_pro"),
                        deposited=get("area_deposited")))
    return out


def sheets(name, s):
    _, summary = cycles(s.S.values, s.time.values, s.Dp.values, "pro")
    return dict(run=name, pro_sheets=summary["n_steps"], mean_length=summary["mean_size"],
                mean_spacing=summary["mean_spacing"])


def finished_runs(folder, names=None):
    """(name, path) of the finished runs in a folder (those with summary.csv), by name."""
    for name in sorted(os.listdir(folder)):
        path = os.path.join(folder, name)
        if os.path.isfile(os.path.join(path, "summary.csv")) and (not names or name in names):
            yield name, path


def figure(folder, names, path):
    """H and the base's deepest point against S, a line per run."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from orogen.atomic import save_figure

    fig, (ax_h, ax_w) = plt.subplots(2, 1, figsize=(8, 6.5), sharex=True)
    for name, run in finished_runs(folder, names):
        s = series_of(run)
        line, = ax_h.plot(s.S, s.H, label=name)
        if "deflection_max" in s:
            ax_w.plot(s.S, -s.deflection_max, color=line.get_color())
    ax_h.set_ylabel("H, height above the base [h0]")
    ax_h.legend(fontsize=8)
    ax_w.set_ylabel("base's deepest point [h0]")
    ax_w.set_xlabel("S = v t / h0")
    for ax in (ax_h, ax_w):
        ax.grid(alpha=0.3)
    fig.suptitle("The wedge's height and the base under it through convergence")
    fig.tight_layout()
    save_figure(fig, path, dpi=130)


def main(folder, at=AT, names=None):
    shape, thrusts = [], []
    for name, path in finished_runs(folder, names):
        s = series_of(path)
        shape += at_rows(name, s, at)
        thrusts.append(sheets(name, s))
    fmt = lambda v: "-" if isinstance(v, float) and np.isnan(v) else (f"{v:.3g}" if isinstance(v, float) else str(v))  # noqa: E731
    for table in (shape, thrusts):
        frame = pd.DataFrame(table)
        print("| " + " | ".join(frame.columns) + " |")
        print("|" + "---|" * len(frame.columns))
        for _, r in frame.iterrows():
            print("| " + " | ".join(fmt(v) for v in r.values) + " |")
        print()


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("folder", nargs="?", default="runs/isostasy", help="a folder of wedge runs")
    parser.add_argument("--at", default=",".join(str(v) for v in AT), help="S values of the first table")
    parser.add_argument("--runs", help="comma-separated run names (all finished runs unless given)")
    parser.add_argument("--figure", help="also draw H and the deepest deflection through S into this PNG")
    args = parser.parse_args()
    names = args.runs.split(",") if args.runs else None
    main(args.folder, tuple(float(v) for v in args.at.split(",")), names)
    if args.figure:
        figure(args.folder, names, args.figure)
