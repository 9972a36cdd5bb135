"""What the foreland basins of a wedge run with deposition record (issue 40; Naylor and Sinclair
2008, "Pro- vs. retro-foreland basins"): per side of the S-point, the sediment discs laid, how
many are still in the model at the end, how long the others stayed, how old the survivors are;
and each parcel's subsidence history while it stays in its basin.

    python3 -m orogen.analysis.basins RUN [RUN ...] [--figure PNG]

A deposit's side is where it was first seen (the first output after it was laid): x < 0 the pro
side, x > 0 the retro side (the S-point is at x = 0). Its residence ends at the last output it
is in. A parcel is in its basin while it lies beyond its side's deformation front (x < Dp on the
pro side, x > Dr on the retro side, series.csv's fronts at that output); its subsidence is how far
it has sunk since it was first seen, the thickness of what buried it plus the base's deflection
under it. Lengths in h0, times in S (convergence) throughout. Prints Markdown tables;
docs/isostasy-evidence.md quotes them."""

import argparse

import h5py
import numpy as np
import pandas as pd

from ..markdown import md_table

SIDES = ("pro", "retro")


def base_under(walls, x):
    """The base's height at each x [d]: the snapshot's walls (x0, y0, x1, y1 rows) less the
    vertical ones and the far-off ones, as a line through their ends."""
    base = walls[(walls[:, 0] != walls[:, 2]) & (np.abs(walls[:, 0]) < 1e6)]
    nodes = np.concatenate([base[:, [0, 1]], base[:, [2, 3]]])
    nodes = nodes[np.argsort(nodes[:, 0], kind="stable")]
    return np.interp(x, nodes[:, 0], nodes[:, 1])


def deposit_tracks(run):
    """Every sediment disc at every output it is in, as a table: id, S, x and y [h0; x from the
    S-point], base (the base's height under it) [h0], laid (the S at which it was laid), side
    (where it was first seen) and in_basin (beyond its side's front at that output)."""
    series = pd.read_csv(f"{run}/series.csv", comment="#")
    rows = []
    with h5py.File(f"{run}/snapshots.h5", "r") as f:
        h0 = float(f.attrs["h0"])
        speed = None  # S per time unit
        for k in range(int(f.attrs["n_outputs"])):
            g = f["output_%06d" % k]
            s, t = float(g.attrs["S"]), float(g.attrs["time"])
            if speed is None and t > 0:
                speed = s / t
            if "deposition_time" not in g:
                continue
            laid = g["deposition_time"][()]
            keep = np.isfinite(laid)
            if not keep.any():
                continue
            x = g["x"][()][keep]
            rows.append(pd.DataFrame({"id": g["id"][()][keep], "output": k, "S": s, "x": x / h0,
                                      "y": g["y"][()][keep] / h0, "base": base_under(g["walls"][()], x) / h0,
                                      "laid": laid[keep] * (speed or 0.0)}))
    if not rows:
        return pd.DataFrame(columns=["id", "output", "S", "x", "y", "base", "laid", "side", "in_basin"])
    tracks = pd.concat(rows, ignore_index=True).sort_values(["id", "output"], kind="stable")
    first = tracks.groupby("id")["x"].transform("first")
    tracks["side"] = np.where(first < 0, "pro", "retro")
    fronts = series[["Dp", "Dr"]].reset_index(names="output")  # a row per output
    tracks = tracks.merge(fronts, on="output", how="left")
    tracks["in_basin"] = np.where(tracks["side"] == "pro", tracks["x"] < tracks["Dp"], tracks["x"] > tracks["Dr"])
    return tracks.drop(columns=["Dp", "Dr"])


def record(tracks):
    """Per side: deposits laid, kept at the end, the median S at which the kept ones were laid,
    the oldest kept, and how long the others stayed [S]."""
    s_end = tracks["S"].max()
    per = tracks.groupby("id").agg(side=("side", "first"), laid=("laid", "first"), last=("S", "max"))
    rows = []
    for side in SIDES:
        p = per[per["side"] == side]
        kept = p[p["last"] >= s_end]
        gone = p[p["last"] < s_end]
        rows.append({
            "side": side,
            "laid": len(p),
            "kept at the end": f"{len(kept)} ({100 * len(kept) / max(1, len(p)):.0f} %)",
            "median S laid of those kept": f"{kept['laid'].median():.1f}" if len(kept) else "-",
            "oldest kept (S laid)": f"{kept['laid'].min():.1f}" if len(kept) else "-",
            "median residence of the others [S]": f"{(gone['last'] - gone['laid']).median():.2f}" if len(gone) else "-",
        })
    return pd.DataFrame(rows)


def subsidence(tracks):
    """Each parcel's history while in its basin, from the first output it is seen in up to the
    first it is not (accreted into the wedge, eroded, or the run's end): id, side, laid, age (S
    since first seen), sunk (how far the parcel is below where it was first seen) and subsided
    (how far the base under it is below the base under it then: the basin's tectonic
    subsidence, without the compaction of what lies below the parcel) [h0]."""
    t = tracks.copy()
    # Up to the first output out of the basin: a parcel accreted and carried back out is not
    # the same basin's record any more.
    t["left"] = (~t["in_basin"]).groupby(t["id"]).cummax()
    t = t[~t["left"]]
    t["age"] = t["S"] - t.groupby("id")["S"].transform("first")
    t["sunk"] = t.groupby("id")["y"].transform("first") - t["y"]
    t["subsided"] = t.groupby("id")["base"].transform("first") - t["base"]
    return t[["id", "side", "laid", "age", "sunk", "subsided", "x"]]


def subsidence_summary(history, span=2.0):
    """Per side, of the parcels that stay in their basin at least `span` S: how many; after
    span/2 and span S, the median of how far the base under them has subsided and how far they
    have sunk [h0]; and the median ratio of the base's subsidence in the second half to the
    first (above 1: subsidence that accelerates, as Naylor and Sinclair's pro-basin parcel
    carried toward the wedge; about 1: steady)."""
    rows = []
    half = span / 2
    for side in SIDES:
        h = history[history["side"] == side]
        stay = h.groupby("id")["age"].max()
        ids = stay.index[stay >= span]
        near = h[h["id"].isin(ids)]
        at = {}
        for when in (half, span):
            pick = near.assign(off=(near["age"] - when).abs()).sort_values(["id", "off"]).groupby("id").first()
            at[when] = pick
        first = at[half]["subsided"]
        ratio = ((at[span]["subsided"] - first) / first)[first > 1e-3]
        shown = (lambda v: f"{v:.3f}") if len(ids) else (lambda v: "-")
        rows.append({
            "side": side,
            f"parcels in the basin >= {span:g} S": len(ids),
            f"base subsided after {half:g} S [h0]": shown(first.median()),
            f"base subsided after {span:g} S [h0]": shown(at[span]["subsided"].median()),
            f"parcel sunk after {half:g} S [h0]": shown(at[half]["sunk"].median()),
            f"parcel sunk after {span:g} S [h0]": shown(at[span]["sunk"].median()),
            "base's rate, 2nd half over 1st": f"{ratio.median():.2f}" if len(ratio) else "-",
        })
    return pd.DataFrame(rows)


def median_curves(history, column, step=0.5, max_age=8.0):
    """Per side, the median and quartiles of `column` (sunk or subsided) at each age (binned by
    `step` S), over the parcels still in their basin at that age (at least 5)."""
    out = []
    h = history[history["age"] <= max_age].copy()
    h["bin"] = (h["age"] / step).round() * step
    for side in SIDES:
        g = h[h["side"] == side].groupby("bin")[column]
        q = pd.DataFrame({"age": g.median().index, "median": g.median().values,
                          "q25": g.quantile(0.25).values, "q75": g.quantile(0.75).values, "n": g.size().values})
        q["side"] = side
        out.append(q[q["n"] >= 5])
    return pd.concat(out, ignore_index=True)


def plot_subsidence(histories, path):
    """The median parcel's history in each basin against its age, a column per side, a line per
    run (quartiles shaded): above, how far the base under it has subsided; below, how far the
    parcel itself has sunk. Written atomically."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from ..atomic import save_figure

    fig, axes = plt.subplots(2, 2, figsize=(10, 7), sharex="col", sharey="row")
    rows = (("subsided", "base under the parcel,\nsubsided since it was laid [h0]"),
            ("sunk", "the parcel, sunk below\nwhere it was laid [h0]"))
    for name, history in histories.items():
        for (column, _), ax_row in zip(rows, axes):
            curves = median_curves(history, column)
            for ax, side in zip(ax_row, SIDES):
                c = curves[curves["side"] == side]
                line, = ax.plot(c["age"], c["median"], label=name)
                ax.fill_between(c["age"], c["q25"], c["q75"], color=line.get_color(), alpha=0.2)
    for (_, label), ax_row in zip(rows, axes):
        ax_row[0].set_ylabel(label)
        ax_row[0].invert_yaxis()
        for ax in ax_row:
            ax.grid(alpha=0.3)
    for ax, side in zip(axes[0], SIDES):
        ax.set_title(f"{side}-foreland basin")
    for ax in axes[1]:
        ax.set_xlabel("time since the parcel was laid [S]")
    axes[0][1].legend(fontsize=8)
    fig.suptitle("Sediment parcels while they stay in their basin (median, quartiles shaded)")
    fig.tight_layout()
    save_figure(fig, path, dpi=150)


def depth_under_fronts(run, at=(5, 10, 15, 21)):
    """series.csv's basin_pro and basin_retro (the base's depth under each front) at a few S."""
    series = pd.read_csv(f"{run}/series.csv", comment="#")
    rows = []
    for s in at:
        row = series.iloc[(series["S"] - s).abs().idxmin()]
        rows.append({"S": f"{row['S']:.0f}", "basin_pro": f"{row['basin_pro']:.3f}",
                     "basin_retro": f"{row['basin_retro']:.3f}"})
    return pd.DataFrame(rows)


def _print(table):
    print(md_table(list(table.columns), table.values.tolist(), [False] + [True] * (len(table.columns) - 1)))


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("runs", nargs="+", help="wedge run folders with deposition")
    parser.add_argument("--figure", help="write the parcels' subsidence curves of every run to this PNG")
    args = parser.parse_args(argv)
    histories = {}
    for run in args.runs:
        tracks = deposit_tracks(run)
        histories[run.rstrip("/").split("/")[-1]] = history = subsidence(tracks)
        print(f"## {run}\n")
        _print(record(tracks))
        _print(subsidence_summary(history))
        if "basin_pro" in pd.read_csv(f"{run}/series.csv", comment="#", nrows=1).columns:
            _print(depth_under_fronts(run))
    if args.figure:
        plot_subsidence(histories, args.figure)


if __name__ == "__main__":
    main()
