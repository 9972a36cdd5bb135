#!/usr/bin/python3
"""Figures of an ensemble (Naylor 2004, Figs 5.14, 5.16-5.22 and the thrust-sheet cycles of 5.4.5-5.4.7).

Usage:
    python3 -m orogen.charts.ensemble DIR

DIR is an `orogen ensemble` folder whose statistics are made (aggregate/, written by
`orogen ensemble` or python3 -m orogen.stats). For each aggregate (DIR/aggregate, or
DIR/aggregate/GROUP with several groups) writes into its charts/ folder, atomically:

    fig5_14_fronts_members.png   Dp, Mp, Dr, Mr, T of every member against S on one chart
    fig5_16_mean_fronts.png      the fronts averaged over the members, +- 1 standard deviation
    fig5_17_18_fits.png          |mean - offset| against S on log-log axes with the fitted power laws
    fig5_19_22_NAME.png          one per member: its fronts against the mean trends with the
                                 envelopes at 1 (dashed) and 2 (solid) residual standard errors
    cycles.png                   the saw-tooth: each member's pro and retro outward distance with
                                 its step-outs marked (5.4.5-5.4.7; numbers in cycles.md)
    simple_model.png             the mean H against the Simple Model of eq. 5.4

Exit 0, or 2 with a message when DIR holds no statistics.
"""

import os
import sys

import numpy as np
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from .. import atomic, stats as es, tables  # noqa: E402

FRONT_STYLE = {"Dp": ("C0", "-"), "Mp": ("C0", "--"), "Dr": ("C3", "-"), "Mr": ("C3", "--"), "T": ("0.4", ":")}


def table(path):
    cols, _ = tables.read_table(path)
    return {k: np.asarray(v, dtype=float) for k, v in cols.items()}


def text_rows(path):
    return tables.read_rows(path)[0]


def save(fig, path):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    atomic.save_figure(fig, path)


def charts(agg, folder, names, title):
    mean = table(os.path.join(agg, "mean_fronts.csv"))
    trend = table(os.path.join(agg, "trend.csv"))
    fits = {r["series"]: r for r in text_rows(os.path.join(agg, "fits.csv"))}
    out = os.path.join(agg, "charts")
    members = [(n, es.read_member(folder, n)) for n in names]
    members = [(n, s) for n, s in members if s is not None]
    colors = [plt.get_cmap("tab10")(i % 10) for i in range(len(members))]

    fig, ax = plt.subplots(figsize=(9, 6))
    for (name, s), c in zip(members, colors):
        for f in ("Dp", "Mp", "Dr", "Mr", "T"):
            ax.plot(s["S"], es.values(s, f), color=c, ls=FRONT_STYLE[f][1], lw=0.9,
                    label=name if f == "Dp" else None)
    ax.axhline(0, color="k", lw=0.5)
    ax.set(xlabel="S (convergence / h0)", ylabel="x from the S-point (h0)",
           title=f"Fig 5.14: fronts of every member, {title}\n(solid Dp, Dr; dashed Mp, Mr; dotted T)")
    ax.legend(fontsize=7, ncol=2)
    save(fig, os.path.join(out, "fig5_14_fronts_members.png"))

    fig, ax = plt.subplots(figsize=(9, 6))
    for f in ("Dp", "Mp", "Dr", "Mr", "T"):
        c, ls = FRONT_STYLE[f]
        m, sd = mean[f"mean_{f}"], mean[f"std_{f}"]
        ax.plot(mean["S"], m, color=c, ls=ls, label=f)
        ax.fill_between(mean["S"], m - sd, m + sd, color=c, alpha=0.12, lw=0)
    ax.axhline(0, color="k", lw=0.5)
    ax.set(xlabel="S (h0)", ylabel="mean x (h0)", title=f"Fig 5.16: fronts averaged over {len(members)} members, "
           f"{title} (bands: +-1 st. dev.)")
    ax.legend()
    save(fig, os.path.join(out, "fig5_16_mean_fronts.png"))

    fig, axes = plt.subplots(1, 2, figsize=(12, 5))
    for ax, group in zip(axes, (("Dp", "Mp", "H"), ("Dr", "Mr", "T"))):
        for f in group:
            r = fits.get(f)
            if r is None:
                continue
            sign, x0 = (-1.0 if f in es.PRO else 1.0), float(r["offset"] or 0)
            if f == "T":
                sign = 1.0 if not np.isfinite(mean["mean_T"]).any() or mean["mean_T"][np.isfinite(mean["mean_T"])][-1] >= 0 else -1.0
            mag = sign * (mean[f"mean_{f}"] - x0)
            ok = (mean["S"] > 0) & (mag > 0)
            c = FRONT_STYLE.get(f, ("k", "-"))[0]
            ax.loglog(mean["S"][ok], mag[ok], ".", ms=3, color=c if f != "H" else "k")
            if r["a"] and r["b"]:
                a, b = float(r["a"]), float(r["b"])
                s = mean["S"][mean["S"] > float(r["s_min"])]
                ax.loglog(s, a * s ** b, "-", color=c if f != "H" else "k",
                          label=f"{f}: a = {a:.3g}, b = {b:.3f} +- {float(r['b_se']):.3f}, R² = {float(r['r2']):.3f}")
        ax.set(xlabel="S (h0)", ylabel="|mean x - offset| (h0)")
        ax.legend(fontsize=7)
    fig.suptitle(f"Figs 5.17, 5.18: power laws fitted to the mean fronts, {title} (Table 5.1: fits.md)")
    save(fig, os.path.join(out, "fig5_17_18_fits.png"))

    for name, s in members:
        fig, axes = plt.subplots(2, 2, figsize=(11, 7), sharex=True)
        for ax, f in zip(axes.flat, ("Dp", "Dr", "Mp", "Mr")):
            if f"trend_{f}" in trend and np.isfinite(trend[f"trend_{f}"]).any():
                ax.plot(trend["S"], trend[f"trend_{f}"], "k-", lw=1)
                for k, ls in ((1, "--"), (2, "-")):
                    ax.plot(trend["S"], trend[f"lo{k}_{f}"], color="0.5", ls=ls, lw=0.7)
                    ax.plot(trend["S"], trend[f"hi{k}_{f}"], color="0.5", ls=ls, lw=0.7)
            ax.plot(s["S"], es.values(s, f), color=FRONT_STYLE[f][0], lw=1)
            ax.set(title=f, ylabel="x (h0)")
        for ax in axes[1]:
            ax.set_xlabel("S (h0)")
        fig.suptitle(f"Figs 5.19-5.22: {name} against the mean trends of {title}\n"
                     "(dashed: +-1, solid: +-2 residual standard errors)")
        save(fig, os.path.join(out, f"fig5_19_22_{name}.png"))

    cyc = text_rows(os.path.join(agg, "cycles.csv"))
    fig, axes = plt.subplots(2, 1, figsize=(10, 7), sharex=True)
    for ax, (front, side) in zip(axes, (("Dp", "pro"), ("Dr", "retro"))):
        for (name, s), c in zip(members, colors):
            p = es.thrust_cycles.outward(es.values(s, front), side)
            ax.plot(s["S"], p, color=c, lw=0.9, label=name)
            steps = [r for r in cyc if r["member"] == name and r["front"] == side]
            for r in steps:
                i = int(r["output"])
                ax.annotate("", xy=(s["S"][i], p[i]), xytext=(s["S"][i - 1], p[i - 1]),
                            arrowprops=dict(arrowstyle="->", color=c, lw=1.2))
        ax.set(ylabel=f"{side} outward distance (h0)", title=f"{side} front ({front}); arrows: step-outs")
    axes[1].set_xlabel("S (h0)")
    axes[0].legend(fontsize=7, ncol=2)
    fig.suptitle(f"Thrust-sheet cycles (thesis 5.4.5-5.4.7, Fig 5.23 saw-tooth), {title}")
    save(fig, os.path.join(out, "cycles.png"))

    sm = table(os.path.join(agg, "simple_model.csv"))
    fig, ax = plt.subplots(figsize=(7, 5))
    ax.plot(sm["S"], sm["H_mean"], "k-", label="mean H")
    ax.plot(sm["S"], sm["H_simple"], "C2--", label="Simple Model, eq. 5.4 (mean late tapers)")
    ax.set(xlabel="S (h0)", ylabel="H (h0)", title=f"Eq. 5.4: Simple Model against the mean height, {title}")
    ax.legend()
    save(fig, os.path.join(out, "simple_model.png"))
    return out


def main(argv):
    if len(argv) != 1:
        print("usage: python3 -m orogen.charts.ensemble DIR", file=sys.stderr)
        return 2
    folder = argv[0]
    try:
        plan = es.read_plan(folder)
    except es.Usage as e:
        print(f"ensemble_charts: {e}", file=sys.stderr)
        return 2
    title = plan["ensemble"].get("title", "ensemble")
    groups = []
    for m in plan.get("member", []):
        if m.get("group", "") not in groups:
            groups.append(m.get("group", ""))
    done = 0
    for g in groups:
        agg = os.path.join(folder, "aggregate", g) if len(groups) > 1 else os.path.join(folder, "aggregate")
        if not os.path.isfile(os.path.join(agg, "mean_fronts.csv")):
            continue
        names = [m["name"] for m in plan["member"] if m.get("group", "") == g]
        print(f"ensemble_charts: {charts(agg, folder, names, f'{title} {g}'.strip())}", file=sys.stderr)
        done += 1
    if not done:
        print(f"ensemble_charts: {folder} holds no statistics (aggregate/mean_fronts.csv): run "
              "python3 -m orogen.stats on it first", file=sys.stderr)
        return 2
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
