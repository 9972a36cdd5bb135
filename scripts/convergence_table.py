#!/usr/bin/python3
"""Issue 38 point 3, convergence with resolution (docs/validity.md, docs/wedge-evidence.md): the
same wedge at several h0, one `orogen ensemble` folder each (examples/ensembles/main_convergence_h*.toml),
side by side. Per h0, over the members (mean +- standard deviation): the wedge at the last
output (H, the fronts Dp and Dr), the tapers over the last third of the run (the surface fits
alpha_fit, beta_fit, the theory's; the chords alpha, beta from the fronts to the peak, the
ensemble's alpha_late, beta_late), the power-law exponent b of the mean H, Dp
and Dr over S > 2 (orogen.stats' fit, once with the offset "none" and once "auto": the two
conventions of Table 5.1), the pro front's step-out spacing (orogen.stats' cycles), and the
pro forethrusts of the last quarter of the run (orogen.analysis.faults: their spacing along the
base and their dip; run it first in each member, members without faults.csv are left out of
those columns). Every length in h0, so a quantity that converges stays put as h0 doubles.

    python3 -m orogen.analysis.faults ENSEMBLE/members/NAME        (each member, for the faults)
    scripts/convergence_table.py runs/convergence_h10 runs/convergence_h20 [...]

A Markdown table on standard output: one row per ensemble, sorted by h0.
"""

import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "python"))
from orogen import stats  # noqa: E402
from orogen.analysis.faults import late_faults  # noqa: E402
from orogen.results import open_run  # noqa: E402
from orogen.tables import read_rows, read_table, to_float  # noqa: E402

S_MIN = 2.0  # the fits start here, as the ensembles' [ensemble.stats] s_min


def mean_sd(values, digits=2):
    v = np.asarray([x for x in values if math.isfinite(x)], float)
    if len(v) == 0:
        return "nan"
    if len(v) == 1:
        return f"{v[0]:.{digits}f}"
    return f"{v.mean():.{digits}f} +- {v.std(ddof=1):.{digits}f}"


def late_forethrusts(member):
    """(spacing, dip) of the pro forethrusts over the last quarter of the member's run, each the
    median over those faults; NaN without faults.csv."""
    path = os.path.join(member, "faults.csv")
    if not os.path.isfile(path):
        return math.nan, math.nan
    faults, _ = read_rows(path)
    if not faults:
        return math.nan, math.nan
    fore = [f for f in late_faults(faults, max(to_float(f["S"]) for f in faults)) if f["kind"] == "forethrust"]
    spacing = [to_float(f["spacing"]) for f in fore]
    spacing = [v for v in spacing if math.isfinite(v)]
    dips = [to_float(f["dip_deg"]) for f in fore]
    return (float(np.median(spacing)) if spacing else math.nan,
            float(np.median(dips)) if dips else math.nan)


def late_fits(member):
    """Mean surface-fit tapers (alpha_fit, beta_fit) over the last third of the member's run."""
    cols, _ = read_table(os.path.join(member, "series.csv"))
    late = cols["S"] >= cols["S"][-1] * 2 / 3
    return tuple(float(np.nanmean(cols[k][late])) for k in ("alpha_fit", "beta_fit"))


def exponents(folder):
    """b of the mean H, Dp, Dr (offset none, auto) from the ensemble's aggregate/mean_fronts.csv."""
    cols, _ = read_table(os.path.join(folder, "aggregate", "mean_fronts.csv"))
    out = {}
    for name in ("H", "Dp", "Dr"):
        for setting in ("none", "auto"):
            out[name, setting] = stats.fit_series(name, cols["S"], cols["mean_" + name], setting, S_MIN)["b"]
    return out


def summary(folder):
    rows, _ = read_rows(os.path.join(folder, "results.csv"))
    done = [r for r in rows if r["exit_status"] == "0"]
    members = [os.path.join(folder, "members", r["name"]) for r in done]
    h0 = float(open_run(members[0]).config["layer"]["thickness"])
    col = {k: [to_float(r[k]) for r in done] for k in ("final_S", "final_H", "final_Dp", "final_Dr", "alpha_late",
                                                     "beta_late", "pro_spacing")}
    fore = [late_forethrusts(m) for m in members]
    fits = [late_fits(m) for m in members]
    col["alpha_fit"], col["beta_fit"] = [f[0] for f in fits], [f[1] for f in fits]
    return dict(h0=h0, n=len(done), S=max(col["final_S"]), b=exponents(folder), col=col,
                spacing=[f[0] for f in fore], dip=[f[1] for f in fore], picked=sum(math.isfinite(f[0]) for f in fore))


def main(folders):
    if not folders:
        print(__doc__)
        return 2
    table = sorted((summary(f) for f in folders), key=lambda t: t["h0"])
    print("| h0 [d] | members | S | H [h0] | Dp [h0] | Dr [h0] | alpha: fit / chord [deg] | beta: fit / chord [deg] "
          "| b of H (none / auto) | b of Dp (none / auto) | b of Dr (none / auto) | pro step-out spacing in S [h0] "
          "| pro forethrust spacing [h0] | pro forethrust dip [deg] |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    for t in table:
        c, b = t["col"], t["b"]
        print(f"| {t['h0']:g} | {t['n']} | {t['S']:.2f} | {mean_sd(c['final_H'])} | {mean_sd(c['final_Dp'], 1)} "
              f"| {mean_sd(c['final_Dr'], 1)} | {mean_sd(c['alpha_fit'], 1)} / {mean_sd(c['alpha_late'], 1)} "
              f"| {mean_sd(c['beta_fit'], 1)} / {mean_sd(c['beta_late'], 1)} "
              f"| {b['H', 'none']:.2f} / {b['H', 'auto']:.2f} | {b['Dp', 'none']:.2f} / {b['Dp', 'auto']:.2f} "
              f"| {b['Dr', 'none']:.2f} / {b['Dr', 'auto']:.2f} | {mean_sd(c['pro_spacing'])} "
              f"| {mean_sd(t['spacing'])} ({t['picked']} picked) | {mean_sd(t['dip'], 0)} |")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
