#!/usr/bin/python3
"""The cohesion series' table (docs/cohesion-evidence.md): for each run of a sweep over a bond
strength (and seeds), the wedge at its end (height, tapers), its faults over the last quarter of
the run (orogen.analysis.faults: run it first in each run), and its bonds. Doubly-vergent wedges
(S, H, alpha_fit, beta_fit, Dp) and singly-vergent ones (shortening, height, taper, width: in the
columns of H, alpha, Dp; no retro taper) alike; the strength and the seed are read from each
run's config.toml (the first material's bond_tensile_strength). The late pro forethrusts' slip
over the picker's window and whole offset are their medians.

    python3 -m orogen.analysis.faults RUN            (each run of the sweep)
    scripts/cohesion_table.py runs/cohesion [runs/cohesion_h20 ...] [--figure series.png]
        [--rows KEPT.csv ...] [--save-rows KEPT.csv]

A Markdown table on standard output. Several sweeps (the same series at several resolutions)
give one table, grouped by h0 and strength; --figure draws the wedge's height, taper and the
forethrusts' spacing and offset against the cohesion, one colour per h0. Runs do not outlive
the machine they ran on, so --save-rows keeps every run's row in a CSV file (of the runs read
and of those --rows brought in) and --rows adds the rows of runs kept so (a run read from a
folder takes the place of a kept row of the same h0, strength and seed).
"""

import argparse
import csv
import glob
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "python"))
from orogen.analysis.faults import late_faults  # noqa: E402
from orogen.results import open_run  # noqa: E402
from orogen.tables import read_rows, read_table  # noqa: E402


def finite_mean(values):
    v = np.asarray(values, float)
    v = v[np.isfinite(v)]
    return float(v.mean()) if len(v) else math.nan


def h0_strength_seed(run):
    """(h0 [d], bond strength [rho g d], seed) of a run, from its config.toml."""
    config = open_run(run).config
    materials = config.get("materials", {})
    strength = next(iter(materials.values()))["bond_tensile_strength"] if materials else 0.0
    return float(config["layer"]["thickness"]), float(strength), int(config["run"]["seed"])


def row(run):
    cols, _ = read_table(os.path.join(run, "series.csv"))
    if "shortening" in cols:  # singly-vergent: its columns under the doubly-vergent names
        cols = {"S": cols["shortening"], "H": cols["height"], "alpha_fit": cols["taper"],
                "beta_fit": np.full(len(cols["taper"]), np.nan), "Dp": cols["width"]}
    last = -1
    s_end = cols["S"][last]
    late = cols["S"] >= 0.75 * s_end
    faults, _ = read_rows(os.path.join(run, "faults.csv"))
    late_pro = late_faults(faults, s_end)
    outputs = {f["output"] for f in faults if float(f["S"]) >= 0.75 * s_end}
    n_out = max(1, len({int(o) for o in outputs}))
    fore = [f for f in late_pro if f["kind"] == "forethrust"]
    back = [f for f in late_pro if f["kind"] == "backthrust"]
    spacing = [float(f["spacing"]) for f in fore if f["spacing"] not in ("", "nan")]
    spacing = [v for v in spacing if math.isfinite(v)]

    def median_of(key):  # the late pro forethrusts' median (old faults.csv files lack the column)
        v = np.array([float(f[key]) for f in fore if f.get(key, "") not in ("", None)], float)
        v = v[np.isfinite(v)]
        return float(np.median(v)) if len(v) else math.nan
    breaks = intact = 0
    path = os.path.join(run, "bond_breaks.csv")
    if os.path.isfile(path):
        with open(path) as fh:
            for line in fh:
                if line.startswith("# intact:"):
                    intact = int(line.split()[2])
                elif line.endswith(",tension\n") or line.endswith(",shear\n"):
                    breaks += 1
    h0, strength, seed = h0_strength_seed(run)
    return {"h0": h0, "strength": strength, "seed": seed, "H": cols["H"][last], "alpha": float(np.nanmean(cols["alpha_fit"][late])),
            "beta": finite_mean(cols["beta_fit"][late]), "Dp": cols["Dp"][last],
            "fore": len(fore) / n_out, "back": len(back) / n_out,
            "fore_dip": float(np.mean([float(f["dip_deg"]) for f in fore])) if fore else math.nan,
            "back_dip": float(np.mean([float(f["dip_deg"]) for f in back])) if back else math.nan,
            "spacing": float(np.median(spacing)) if spacing else math.nan, "slip": median_of("slip"),
            "offset": median_of("offset"), "breaks": breaks, "intact": intact}


FIGURE_PANELS = (("H", "wedge height H [h0]"), ("alpha", "surface taper, last quarter [deg]"),
                 ("spacing", "forethrust spacing [h0]"), ("offset", "forethrust offset [h0]"))


def figure(rows, path):
    """The series against the cohesion (strength d / h0, rho g h0): each run a faint dot, each
    resolution's mean over its seeds a line with the seeds' spread."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(1, len(FIGURE_PANELS), figsize=(4.2 * len(FIGURE_PANELS), 3.6), constrained_layout=True)
    for colour, h0 in zip(("tab:blue", "tab:orange", "tab:green", "tab:red"), sorted({r["h0"] for r in rows})):
        mine = [r for r in rows if r["h0"] == h0]
        cohesion = sorted({r["strength"] / h0 for r in mine})
        for ax, (key, label) in zip(axes, FIGURE_PANELS):
            ax.plot([r["strength"] / h0 for r in mine], [r[key] for r in mine], "o", color=colour, alpha=0.3, ms=4)
            stats = [np.array([r[key] for r in mine if r["strength"] / h0 == c], float) for c in cohesion]
            mean = [np.nanmean(v) if np.isfinite(v).any() else np.nan for v in stats]
            spread = [np.nanstd(v, ddof=1) if np.isfinite(v).sum() > 1 else 0.0 for v in stats]
            ax.errorbar(cohesion, mean, yerr=spread, color=colour, marker="s", capsize=3,
                        label="h0 = %g d (%d runs)" % (h0, len(mine)))
            ax.set_xlabel("cohesion: bond strength d / h0 [rho g h0]")
            ax.set_ylabel(label)
            ax.grid(alpha=0.3)
    axes[0].legend(fontsize=8)
    fig.suptitle("Singly-vergent cohesion series: the wedge at the end, the pro forethrusts over the last quarter",
                 fontsize=10)
    fig.savefig(path, dpi=120)


ROW_KEYS = ("h0", "strength", "seed", "H", "alpha", "beta", "Dp", "fore", "back", "fore_dip", "back_dip", "spacing",
            "slip", "offset", "breaks", "intact")


def read_kept_rows(path):
    """Rows saved by --save-rows (an empty field is an unknown value: NaN)."""
    with open(path, newline="") as fh:
        lines = [line for line in fh if not line.startswith("#")]
    rows = []
    for r in csv.DictReader(lines):
        row_ = {k: float(r[k]) if r.get(k, "") != "" else math.nan for k in ROW_KEYS}
        for count in ("seed", "breaks", "intact"):  # counts stay whole numbers (where known)
            if not math.isnan(row_[count]):
                row_[count] = int(row_[count])
        rows.append(row_)
    return rows


def save_rows(rows, path):
    """Written whole or not at all (a temporary file renamed): the file may be the one --rows read."""
    temporary = path + ".tmp"
    with open(temporary, "w", newline="") as fh:
        fh.write("# Orogen cohesion series, one row per run (scripts/cohesion_table.py --save-rows); columns as in "
                 "the script's table: h0 [d], bond strength [rho g d], seed, H [h0], pro and retro taper [deg], "
                 "Dp or width [h0], pro forethrusts and backthrusts per output, their dips [deg], forethrust spacing, "
                 "slip over the window and offset [h0], bonds broken and intact at the end\n")
        w = csv.DictWriter(fh, fieldnames=ROW_KEYS, extrasaction="ignore")
        w.writeheader()
        for r in rows:
            w.writerow({k: "" if isinstance(r[k], float) and math.isnan(r[k]) else r[k] for k in ROW_KEYS})
    os.replace(temporary, path)


def merged(rows, kept):
    """The rows of the runs read and the kept rows of other runs (by h0, strength and seed), in order."""
    def key(r):
        return (r["h0"], r["strength"], r["seed"])
    read = {key(r) for r in rows}
    return sorted(list(rows) + [r for r in kept if key(r) not in read], key=key)


def main(sweeps, figure_path=None, kept=(), save_path=None):
    runs = sorted((os.path.dirname(p) for sweep in sweeps
                   for p in glob.glob(os.path.join(sweep, "runs", "*", "faults.csv"))),
                  key=h0_strength_seed)  # the runs whose faults were picked (those still running are left out)
    rows = merged([row(run) for run in runs], [r for path in kept for r in read_kept_rows(path)])
    if save_path:
        save_rows(rows, save_path)
    print("| h0 [d] | bond strength [rho g d] | seed | H [h0] | pro taper alpha_fit [deg] | retro taper beta_fit [deg] "
          "| Dp or width [h0] | pro forethrusts per output | pro backthrusts per output | forethrust dip [deg] "
          "| backthrust dip [deg] | forethrust spacing [h0] | forethrust slip over the window [h0] "
          "| forethrust offset [h0] | bonds broken / made |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    for r in rows:
        made = r["breaks"] + r["intact"]  # NaN where a kept row does not know its bonds
        print("| %g | %g | %d | %.2f | %.1f | %.1f | %.2f | %.1f | %.1f | %.0f | %.0f | %.2f | %.3f | %.2f | %s |" % (
            r["h0"], r["strength"], r["seed"], r["H"], r["alpha"], r["beta"], r["Dp"], r["fore"], r["back"],
            r["fore_dip"], r["back_dip"], r["spacing"], r["slip"], r["offset"],
            "-" if math.isnan(made) else "%d / %d" % (r["breaks"], made) if made else "no bonds"))
    groups = sorted({(r["h0"], r["strength"]) for r in rows})
    if len(rows) > len(groups):  # seeds: each strength's mean and the spread between seeds
        print("\n| h0 [d] | bond strength [rho g d] | cohesion against the layer's weight: strength d / h0 [rho g h0] "
              "| seeds | H [h0] | taper [deg] | forethrusts per output "
              "| forethrust dip [deg] | forethrust spacing [h0] | forethrust slip over the window [h0] "
              "| forethrust offset [h0] |")
        print("|---|---|---|---|---|---|---|---|---|---|---|")
        for h0, strength in groups:
            group = [r for r in rows if (r["h0"], r["strength"]) == (h0, strength)]

            def both(key, fmt):
                v = np.array([r[key] for r in group], float)
                v = v[np.isfinite(v)]
                return (fmt + " +- " + fmt) % (v.mean(), v.std(ddof=1) if len(v) > 1 else 0.0) if len(v) else "-"
            print("| %g | %g | %.2f | %d | %s | %s | %s | %s | %s | %s | %s |" % (
                h0, strength, strength / h0, len(group), both("H", "%.2f"), both("alpha", "%.1f"),
                both("fore", "%.1f"), both("fore_dip", "%.0f"), both("spacing", "%.2f"), both("slip", "%.3f"),
                both("offset", "%.2f")))
    if figure_path:
        figure(rows, figure_path)


if __name__ == "__main__":
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("sweeps", nargs="*", help="sweep folders (their runs/*/ with faults.csv)")
    p.add_argument("--figure", default=None, help="also draw the series into this image")
    p.add_argument("--rows", action="append", default=[], help="add the rows of runs kept in this CSV file")
    p.add_argument("--save-rows", default=None, help="keep every run's row in this CSV file")
    a = p.parse_args()
    main(a.sweeps, a.figure, a.rows, a.save_rows)
