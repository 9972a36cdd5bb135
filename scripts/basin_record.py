#!/usr/bin/python3
"""What each foreland basin of a wedge run with deposition records (issue 40; Naylor and
Sinclair 2008): per side of the S-point, the sediment discs laid, how many of them are still in
the model at the end, how long the others stayed, how old the survivors are, and the basins'
depth under each front through S (series.csv's basin_pro, basin_retro).

    /usr/bin/python3 scripts/basin_record.py RUN [RUN ...]

A deposit's side is where it was first seen (an output after it was laid): x < 0 the pro side,
x > 0 the retro side (the S-point is at x = 0). Its residence ends at the last output it is in.
Prints a Markdown table per run; docs/isostasy-evidence.md quotes them."""

import sys

import h5py
import numpy as np
import pandas as pd

from orogen.stats import md_table


def deposits(run):
    """{id: (S laid, side, S last seen)} over every output, and the run's last S."""
    seen = {}
    with h5py.File(f"{run}/snapshots.h5", "r") as f:
        h0 = float(f.attrs["h0"])
        count = int(f.attrs["n_outputs"])
        speed = None
        for k in range(count):
            g = f["output_%06d" % k]
            s, t = float(g.attrs["S"]), float(g.attrs["time"])
            if speed is None and t > 0:
                speed = s * h0 / t
            laid = g["deposition_time"][()] if "deposition_time" in g else None
            if laid is None:
                continue
            ids, x = g["id"][()], g["x"][()]
            for i in np.flatnonzero(np.isfinite(laid)):
                key = int(ids[i])
                if key in seen:
                    seen[key][2] = s
                else:
                    seen[key] = [laid[i] * speed / h0, "pro" if x[i] < 0 else "retro", s]
    return seen, s


def summary(run):
    seen, s_end = deposits(run)
    rows = []
    for side in ("pro", "retro"):
        laid = [(a, last) for a, sd, last in seen.values() if sd == side]
        kept = [a for a, last in laid if last >= s_end]
        gone = [last - a for a, last in laid if last < s_end]
        rows.append({
            "side": side,
            "laid": len(laid),
            "kept at the end": f"{len(kept)} ({100 * len(kept) / max(1, len(laid)):.0f} %)",
            "median S laid of those kept": f"{np.median(kept):.1f}" if kept else "-",
            "oldest kept (S laid)": f"{min(kept):.1f}" if kept else "-",
            "median residence of the others [S]": f"{np.median(gone):.2f}" if gone else "-",
        })
    series = pd.read_csv(f"{run}/series.csv", comment="#")
    depth = []
    for s in (5, 10, 15, 21):
        row = series.iloc[(series["S"] - s).abs().idxmin()]
        depth.append({"S": f"{row['S']:.0f}", "basin_pro": f"{row['basin_pro']:.3f}", "basin_retro": f"{row['basin_retro']:.3f}"})
    return pd.DataFrame(rows), pd.DataFrame(depth)


def main(runs):
    for run in runs:
        record, depth = summary(run)
        print(f"## {run}\n")
        for table in (record, depth):
            print(md_table(list(table.columns), table.values.tolist(), [False] + [True] * (len(table.columns) - 1)))


if __name__ == "__main__":
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    main(sys.argv[1:])
