#!/usr/bin/python3
"""The variants of wedge sweeps side by side (docs/wedge-evidence.md, "Natural variability, window,
stiffness, speed and time step"): the runs of each `orogen sweep` folder grouped by their swept
keys other than run.seed, and per group, over the seeds (mean +- standard deviation; the single
values in brackets below three seeds): H at the last output and b of H = a S^b (S > 0.5), the
mean tapers alpha and beta over the last third of the run (chords, as the table's first
version), alpha_fit (the surface fit) and the fronts Dp and Dr at the last output, in h0 (the
numbers of `orogen.charts.wedge`'s summary.json).

    scripts/sweep_variants_table.py runs/sweep_wedge_window runs/sweep_wedge_soft [...]

A Markdown table on standard output, one row per variant.
"""

import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "python"))
from orogen.charts import wedge  # noqa: E402
from orogen.tables import read_results  # noqa: E402

SEED = "run.seed"
COLUMNS = ("H", "b", "alpha", "beta", "alpha_fit", "Dp", "Dr")


def run_numbers(folder):
    """The numbers of one finished wedge run."""
    run = wedge.load_runs([folder], os.path.basename(folder))[0]
    with np.errstate(invalid="ignore", divide="ignore"):
        s = wedge.summarize(run)
    series = run["series"]
    return {"H": s["final_H"], "b": s["b"], "alpha": s["mean_alpha_late"], "beta": s["mean_beta_late"],
            "alpha_fit": s["mean_alpha_fit_late"],
            "Dp": wedge.last_finite(wedge.front_values(series, "Dp")),
            "Dr": wedge.last_finite(wedge.front_values(series, "Dr"))}


def shown(values):
    v = [x for x in values if x is not None and math.isfinite(x)]
    if not v:
        return "–"
    if len(v) < 3:
        return "[" + ", ".join(f"{x:.2f}" for x in v) + "]"
    return f"{np.mean(v):.2f} ± {np.std(v, ddof=1):.2f}"


def variants(folder):
    """(variant label, [numbers of each finished run]) for one sweep folder, in the sweep's order."""
    rows, header, _ = read_results(os.path.join(folder, "results.csv"))
    swept = [k for k in header if "." in k and k != SEED]
    groups = {}
    for row in rows:
        if row.get("exit_status") != "0":
            continue
        label = os.path.basename(folder.rstrip("/")) + ": " + (", ".join(f"{k} = {row[k]}" for k in swept) or "base")
        groups.setdefault(label, []).append(run_numbers(os.path.join(folder, "runs", row["name"])))
    return groups.items()


def main(argv):
    if not argv:
        print(__doc__, file=sys.stderr)
        return 2
    print("| variant | seeds | " + " | ".join(COLUMNS) + " |")
    print("|---|---:|" + "---|" * len(COLUMNS))
    for folder in argv:
        for label, runs in variants(folder):
            cells = [shown([r[c] for r in runs]) for c in COLUMNS]
            print(f"| {label} | {len(runs)} | " + " | ".join(cells) + " |")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
