#!/usr/bin/python3
"""Is a wedge the critical wedge of its own base and interior? (issue 38, point 1)

For each run (made with `output.contacts = true` and `output.stress_grid`; a wedge or a
singly-vergent wedge), over its late outputs (orogen.analysis.traction): the friction the pro
base transmits under the wedge and the share of its contacts at the Coulomb limit, the
interior's mobilised friction angle and the angle of s1 to the base (medians over squares of
h0 / 4, orogen.analysis.stress), the solid fraction inside the wedge and in the layer ahead of
it, and the surface slope (the least-squares fit: a singly-vergent wedge's from its front to
its backstop, a wedge's pro slope `alpha_fit`); beside them Dahlen's critical taper and
s1 angle for that interior friction on that transmitted base friction, and for the material's
residual friction (--phi) on the base's own coefficient. One row per run, then the mean and the
standard deviation over the runs of each resolution.

    scripts/base_state_table.py runs/singly_base_state/runs/* [--phi 24.6]

A Markdown table on standard output.
"""

import argparse
import os
import sys

import pandas as pd

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "python"))
from orogen.analysis import stress, traction  # noqa: E402
from orogen.analysis.surface import critical_taper_deg  # noqa: E402
from orogen.charts.granular import markdown_table  # noqa: E402


def row(run, phi_residual):
    config, late, series, table, _, _ = traction.measure(run)
    _, packed, cells = stress.measure(run)
    mu_b = traction.base_friction(config)
    singly = traction.is_singly(config)
    phi_mob, psi = cells["phi_mob"].median(), cells["psi"].median()
    mu = table["mu_pro"].mean()
    tail = series.iloc[late]
    return {
        "run": os.path.basename(run.rstrip("/")),
        "h0": float(config["layer"]["thickness"]),
        "outputs": len(late),
        "mu transmitted": mu,
        "at limit": table["at_limit_pro"].mean(),
        "phi_mob": phi_mob,
        "psi": psi,
        "taper": tail["taper" if singly else "alpha_fit"].mean(),  # the surface fit, front to backstop or crest
        "solid fraction: wedge / ahead": f"{packed['solid_wedge'].mean():.3f} / {packed['solid_ahead'].mean():.3f}",
        "taper front / back half": (f"{tail['taper_front'].mean():.1f} / {tail['taper_back'].mean():.1f}"
                                    if singly else ""),
        "theory (phi_mob, mu transmitted): taper, psi":
            f"{critical_taper_deg(phi_mob, mu):.1f}, {stress.psi_base(phi_mob, mu):.1f}",
        f"theory (phi {phi_residual}, mu_b {mu_b}): taper, psi":
            f"{critical_taper_deg(phi_residual, mu_b):.1f}, {stress.psi_base(phi_residual, mu_b):.1f}",
    }


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("runs", nargs="+", help="run folders")
    p.add_argument("--phi", type=float, default=24.6, help="the material's residual bulk friction angle [deg]")
    args = p.parse_args()
    rows = pd.DataFrame([row(run, args.phi) for run in args.runs])
    numbers = ["mu transmitted", "at limit", "phi_mob", "psi", "taper"]
    lines = []
    for h0, group in rows.groupby("h0"):
        lines.append(group)
        if len(group) > 1:
            mean, sd = group[numbers].mean(), group[numbers].std()
            lines.append(pd.DataFrame([{"run": f"mean +- sd ({len(group)})", "h0": h0,
                                        **{k: f"{mean[k]:.3g} +- {sd[k]:.2g}" for k in numbers}}]))
    table = pd.concat(lines).fillna("")
    for k in numbers:
        table[k] = [f"{v:.3g}" if isinstance(v, float) else v for v in table[k]]
    print(markdown_table(list(table.columns), table.values.tolist(), [False] * len(table.columns)), end="")


if __name__ == "__main__":
    main()
