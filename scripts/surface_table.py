#!/usr/bin/python3
"""The surface-law runs' table (docs/surface-evidence.md): for each wedge run in a folder, the
wedge at its end (height, tapers, fronts), the eroded flux over the last quarter of the run
against the inflow (orogen analyze's flux_in: 1 = flux steady state) and the S from which
analyze calls it steady, where the erosion fell (the share of the eroded discs on the pro side
of the peak, each removal against the peak interpolated between outputs), where exhumation
peaks at the end (the x from the peak, in h0, of the column whose surface disc came from
deepest, and that depth), what was laid and recycled, and the area ledger's largest imbalance.

    orogen analyze RUN                                  (each run first)
    scripts/surface_table.py /work/runs/surface        (a Markdown table on standard output)
"""

import math
import os
import re
import sys

import numpy as np
import pandas as pd



def row(path):
    series_file = os.path.join(path, "series.csv")
    with open(series_file, encoding="utf-8") as f:
        h0 = float(re.search(r"# h0 = ([0-9.eE+-]+) d", f.read(2000)).group(1))
    series = pd.read_csv(series_file, comment="#")
    removals = pd.read_csv(os.path.join(path, "removals.csv"), comment="#")
    with_ledger = "area_eroded" in series
    eroded = removals[removals.reason.str.startswith("eroded")]
    end = series.iloc[-1]
    imbalance = math.nan
    if with_ledger:
        imbalance = (series.area_model - (series.area_entered - series.area_eroded + series.area_deposited
                                          - series.area_left)).abs().max()
    flux_file = os.path.join(path, "analysis_flux.csv")
    flux = pd.read_csv(flux_file, comment="#")
    late = flux[flux.S >= 0.75 * end.S]
    with open(flux_file, encoding="utf-8") as f:
        flux_in = float(re.search(r"flux_in = ([0-9.eE+-]+)", f.readline()).group(1))
    ratio = late.flux_out.mean() / flux_in if len(late) else math.nan
    steady = flux[flux.steady == 1].S.min() if (flux.steady == 1).any() else math.nan
    columns = pd.read_csv(os.path.join(path, "analysis_columns.csv"), comment="#")
    last = columns[columns.output == columns.output.max()].dropna(subset=["surface_max_depth"])
    deepest = last.loc[last.surface_max_depth.idxmax()] if len(last) else None
    # Pro share: each removal against the peak x (T h0) of the first output at or after it.
    peak = np.interp(eroded.time, series.time, series["T"] * h0) if len(eroded) else []
    pro = float(np.mean(eroded.x < peak)) if len(eroded) else math.nan
    laws = eroded.reason.value_counts().to_dict()
    return {"run": os.path.basename(path.rstrip("/")), "S": end.S, "H": end.H, "alpha_fit": end.alpha_fit,
            "beta_fit": end.beta_fit, "Dp": end.Dp, "Dr": end.Dr, "flux out/in": ratio, "steady from S": steady, "pro share": pro,
            "deepest at x - T": (deepest.x - end["T"]) if deepest is not None else math.nan,
            "from depth": deepest.surface_max_depth if deepest is not None else math.nan,
            "removals": ", ".join(f"{k.replace('eroded_', '').replace('eroded', 'threshold')} {n}"
                                  for k, n in sorted(laws.items())),
            "deposited": series.area_deposited.iloc[-1] if with_ledger else 0.0,
            "recycled": series.area_recycled.iloc[-1] if with_ledger else 0.0,
            "imbalance": imbalance}


def main(folder):
    rows = [row(os.path.join(folder, d)) for d in sorted(os.listdir(folder))
            if os.path.isfile(os.path.join(folder, d, "summary.csv"))]
    if not rows:
        sys.exit(f"{folder}: no finished runs")
    cell = lambda v: f"{v:.3g}" if isinstance(v, float) else str(v)  # noqa: E731
    print("| " + " | ".join(rows[0]) + " |")
    print("|" + "---|" * len(rows[0]))
    for r in rows:
        print("| " + " | ".join(cell(v) for v in r.values()) + " |")


if __name__ == "__main__":
    main(sys.argv[1])
