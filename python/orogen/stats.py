#!/usr/bin/python3
"""Statistics of an ensemble (Naylor 2004, 5.4.6 and Table 5.1; 5.4.5-5.4.7; docs/ensembles.md).

Usage:
    python3 -m orogen.stats DIR

DIR is an `orogen ensemble` folder: ensemble.toml (the plan), members.csv (what became of
each member) and members/NAME/series.csv. `orogen ensemble` runs this at the end; run it by
hand to redo the statistics (say with other [stats] settings edited into DIR/ensemble.toml).

Writes, each file atomically and the same bytes for the same members (no paths, no dates):

    DIR/aggregate/[GROUP/]mean_fronts.csv    per output: mean, standard deviation and count of
                                            Dp, Mp, Dr, Mr, H, T over the members (Fig 5.16)
    .../fits.csv, fits.md                   power law x = x0 + a S^b per series (Table 5.1)
    .../trend.csv                           the fitted trends with envelopes at 1 and 2
                                            residual standard errors (Figs 5.17-5.22)
    .../simple_model.csv                    eq. 5.4 from the measured tapers beside the mean H
    .../cycles.csv, cycles.md               step-outs of every member's Dp and Dr (5.4.5-5.4.7)
    DIR/results.csv, results.md             one row per member: status and its numbers

One aggregate per group of members that differ only in the seed (a [[member]] entry): in
DIR/aggregate itself when there is one group, else in DIR/aggregate/GROUP. Exit 0, or 2 with
a message when DIR is not an ensemble folder.
"""

import csv
import io
import math
import os
import sys
import tomllib

import numpy as np

from . import atomic, tables
from .markdown import md_table, shown  # noqa: F401  (md_table: scripts import it from here)
from .analysis import cycles as thrust_cycles, powerlaw

SERIES = ("Dp", "Mp", "Dr", "Mr", "H", "T")
FRONTS = ("Dp", "Mp", "Dr", "Mr", "T")  # an exact 0 means "no front yet" (docs/output-files.md)
PRO = ("Dp", "Mp")                        # negative x: fitted on -x
LATE_FRACTION = 1.0 / 3                   # late tapers: the last third of the run in S
UNITS = {"Dp": "h0, x from the S-point", "Mp": "h0, x from the S-point", "Dr": "h0, x from the S-point",
         "Mr": "h0, x from the S-point", "H": "h0", "T": "h0, x of the peak from the S-point"}
NAMES = {"Dp": "pro deformation front", "Mp": "pro marker front", "Dr": "retro deformation front",
         "Mr": "retro marker front", "H": "wedge height", "T": "peak position"}


class Usage(Exception):
    pass


# --------------------------------------------------------------------------------------------
# Reading


def read_plan(folder):
    path = os.path.join(folder, "ensemble.toml")
    if not os.path.isfile(path):
        raise Usage(f"{folder} is not an ensemble folder: it has no ensemble.toml (orogen ensemble writes it)")
    with open(path, "rb") as f:
        return tomllib.load(f)


def read_members_csv(folder):
    path = os.path.join(folder, "members.csv")
    if not os.path.isfile(path):
        raise Usage(f"{path} is missing: run `orogen ensemble` on this folder first")
    return {row["name"]: row for row in tables.read_rows(path)[0]}


def read_member(folder, name):
    """A finished member's series (dict of arrays), or None."""
    path = os.path.join(folder, "members", name, "series.csv")
    if not os.path.isfile(path):
        return None
    series, _ = tables.read_table(path)
    if "S" not in series or len(series["S"]) == 0:
        return None
    return {k: np.asarray(v, dtype=float) for k, v in series.items()}


def values(series, name):
    v = np.array(series.get(name, np.full(len(series["S"]), np.nan)), dtype=float)
    if name in FRONTS:
        v[v == 0.0] = np.nan
    v[~np.isfinite(v)] = np.nan
    return v


# --------------------------------------------------------------------------------------------
# Statistics


def common_grid(members):
    """The S of the first member, cut where the shortest member ends."""
    s = members[0][1]["S"]
    end = min(float(np.nanmax(m["S"])) for _, m in members)
    return s[np.isfinite(s) & (s <= end)]


def on_grid(series, name, s):
    v = values(series, name)
    if len(series["S"]) >= len(s) and np.array_equal(series["S"][: len(s)], s):
        return v[: len(s)]  # the usual case: the same outputs, no interpolation
    ok = np.isfinite(v) & np.isfinite(series["S"])
    if ok.sum() < 2:
        return np.full(len(s), np.nan)
    return np.interp(s, series["S"][ok], v[ok], left=np.nan, right=np.nan)


def mean_std(stack):
    n = np.sum(np.isfinite(stack), axis=0)
    with np.errstate(invalid="ignore", divide="ignore"):
        total = np.nansum(stack, axis=0)
        mean = np.where(n > 0, total / np.maximum(n, 1), np.nan)
        dev = np.where(np.isfinite(stack), stack - mean, 0.0)
        std = np.where(n > 1, np.sqrt(np.sum(dev ** 2, axis=0) / np.maximum(n - 1, 1)), np.nan)
    return mean, std, n


def sign_of(name, mean):
    if name in PRO:
        return -1.0
    if name == "T":  # the peak may sit on either side: fit its magnitude on the side it ends on
        ok = np.isfinite(mean)
        return -1.0 if ok.any() and mean[ok][-1] < 0 else 1.0
    return 1.0


def fit_series(name, s, mean, setting, s_min):
    """Offset and power law of one mean series: dict (row of Table 5.1)."""
    sign = sign_of(name, mean)
    m = sign * mean
    if setting == "auto":
        m0 = powerlaw.auto_offset(s, m, s_min)
        how = "auto"
        if not math.isfinite(m0):
            m0, how = 0.0, "auto (no optimum: none)"
    elif setting == "none":
        m0, how = 0.0, "none"
    else:
        m0, how = sign * float(setting), "given"
    fit = powerlaw.power_law_fit(s, m - m0, s_min)
    row = dict(series=name, sign=sign, offset=sign * m0, offset_how=how, s_min=s_min)
    for k in ("a", "a_se", "log_a", "log_a_se", "b", "b_se", "r2", "residual_se", "n"):
        row[k] = fit[k] if fit else float("nan")
    return row


def trend(row, s, k=0.0):
    """The fitted trend at S, moved by k residual standard errors outward (in log space)."""
    with np.errstate(invalid="ignore", divide="ignore"):
        mag = row["a"] * np.power(s, row["b"]) * math.exp(k * row["residual_se"])
    return row["offset"] + row["sign"] * mag


def late_mean(series, name):
    s = series["S"]
    v = values(series, name)
    dp, dr = values(series, "Dp"), values(series, "Dr")
    ok = np.isfinite(v) & (np.isfinite(dp) | np.isfinite(dr)) & (s >= (1 - LATE_FRACTION) * np.nanmax(s))
    return float(np.mean(v[ok])) if ok.any() else float("nan")


def last_value(v):
    ok = np.nonzero(np.isfinite(v))[0]
    return float(v[ok[-1]]) if ok.size else float("nan")


def within(series, name, row, k=2.0):
    """Fraction of a member's outputs (S > s_min, front present) inside the k-error envelope."""
    s = series["S"]
    v = values(series, name)
    ok = np.isfinite(v) & (s > row["s_min"])
    if not ok.any() or not np.isfinite(row["a"]):
        return float("nan")
    lo, hi = trend(row, s[ok], -k), trend(row, s[ok], k)
    lo, hi = np.minimum(lo, hi), np.maximum(lo, hi)
    return float(np.mean((v[ok] >= lo) & (v[ok] <= hi)))


# --------------------------------------------------------------------------------------------
# Writing: series-format CSV (# column: meaning lines, then a header) and Markdown


def num(x):
    if isinstance(x, (int, np.integer)):
        return str(int(x))
    x = float(x)
    return repr(x) if math.isfinite(x) else ""


def csv_text(title, columns, rows):
    """columns: [(name, meaning)]; rows: lists of numbers or strings."""
    out = io.StringIO()
    out.write(f"# {title}\n")
    for name, meaning in columns:
        out.write(f"# {name}: {meaning}\n")
    w = csv.writer(out, lineterminator="\n")
    w.writerow([c[0] for c in columns])
    for r in rows:
        w.writerow([v if isinstance(v, str) else num(v) for v in r])
    return out.getvalue()


def write(path, text):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    atomic.write_text(path, text)


# --------------------------------------------------------------------------------------------
# One group


def aggregate(out, title, members, stats):
    """members: [(name, series)] of finished members. Returns per-member numbers for results."""
    s_min = float(stats["s_min"])
    s = common_grid(members)
    n_members = len(members)
    mean, std, count = {}, {}, {}
    for name in SERIES:
        stack = np.array([on_grid(series, name, s) for _, series in members])
        mean[name], std[name], count[name] = mean_std(stack)

    cols = [("S", "normalised convergence: plate displacement / h0")]
    data = [s]
    for name in SERIES:
        cols += [(f"mean_{name}", f"mean over the members of {name}, the {NAMES[name]} [{UNITS[name]}]"),
                 (f"std_{name}", f"standard deviation over the members of {name} (n - 1) [{UNITS[name].split(',')[0]}]"),
                 (f"n_{name}", f"members with a value of {name} at this output (a front exactly 0 = not yet)")]
        data += [mean[name], std[name], count[name].astype(int)]
    write(os.path.join(out, "mean_fronts.csv"),
          csv_text(f"{title}: fronts averaged over {n_members} members per output (thesis Fig 5.16)", cols,
                   [list(r) for r in zip(*data)]))

    offsets = stats.get("offset", {})
    rows = [fit_series(name, s, mean[name], offsets.get(name, "auto"), s_min) for name in SERIES]
    fit_cols = [
        ("series", "the mean series fitted (Dp, Mp, Dr, Mr fronts; H height; T peak position)"),
        ("offset", "x0 removed before the fit [h0, signed like the series]"),
        ("offset_how", "auto: the power law's value at S = 0 (best 1 - R^2 over x0); none: 0; given: from the file"),
        ("a", "exp(a'): coefficient of |x - x0| = a S^b [h0]"),
        ("log_a", "a' = ln a"), ("log_a_se", "standard error of a'"), ("a_se", "standard error of a (delta method)"),
        ("b", "exponent"), ("b_se", "standard error of b"), ("r2", "R^2 of the log-log fit"),
        ("residual_se", "residual standard error of the log-log fit (natural log units: a relative scatter)"),
        ("n", "outputs fitted"), ("s_min", "fit over S > s_min [h0]")]
    write(os.path.join(out, "fits.csv"),
          csv_text(f"{title}: power-law trends of the mean series, ln|x - x0| = a' + b ln S (thesis Table 5.1)",
                   fit_cols, [[r[c] for c, _ in fit_cols] for r in rows]))

    # The Simple Model from the members' measured late tapers (eq. 5.4).
    alphas = [late_mean(series, "alpha") for _, series in members]
    betas = [late_mean(series, "beta") for _, series in members]
    alpha = float(np.nanmean(alphas)) if np.isfinite(alphas).any() else float("nan")
    beta = float(np.nanmean(betas)) if np.isfinite(betas).any() else float("nan")
    c = powerlaw.simple_model_coefficient(alpha, beta)
    h_sm = c * np.sqrt(np.clip(s, 0, None)) if c is not None else np.full(len(s), np.nan)
    write(os.path.join(out, "simple_model.csv"),
          csv_text(f"{title}: Simple Model (eq. 5.4) with the mean late tapers alpha = {shown(alpha)} deg, "
                   f"beta = {shown(beta)} deg (C = {shown(c if c is not None else float('nan'))}) against the mean H",
                   [("S", "normalised convergence [h0]"), ("H_mean", "mean measured height [h0]"),
                    ("H_simple", "sqrt(2 tan(alpha) tan(beta) / (tan(alpha) + tan(beta)) S) [h0]"),
                    ("ratio", "H_mean / H_simple")],
                   [[s_k, h_k, sm_k, (h_k / sm_k if sm_k > 0 else float("nan"))]
                    for s_k, h_k, sm_k in zip(s, mean["H"], h_sm)]))

    tr_cols = [("S", "normalised convergence [h0]")]
    tr_data = [s]
    for r in rows:
        n = r["series"]
        tr_cols += [(f"trend_{n}", f"x0 + sign a S^b for {n} [{UNITS[n]}]"),
                    (f"lo1_{n}", "the trend moved 1 residual standard error inward"),
                    (f"hi1_{n}", "1 residual standard error outward"),
                    (f"lo2_{n}", "2 residual standard errors inward"), (f"hi2_{n}", "2 outward")]
        tr_data += [trend(r, s), trend(r, s, -1), trend(r, s, 1), trend(r, s, -2), trend(r, s, 2)]
    write(os.path.join(out, "trend.csv"),
          csv_text(f"{title}: fitted trends and their envelopes (thesis Figs 5.17-5.22; the envelope at 2 "
                   "standard errors is the Normal Variability)", tr_cols, [list(x) for x in zip(*tr_data)]))

    md = f"# {title}: power-law trends (Table 5.1)\n\n"
    md += (f"{n_members} members, fronts averaged per output, offset removed, then ln|x - x0| = a' + b ln S "
           f"fitted for S > {shown(s_min)} h0.\n\n")
    md += md_table(["Trend", "Offset removed [h0]", "exp(a')", "st. err. a'", "b", "st. err. b", "R²",
                    "Residual st. err.", "n"],
                   [[r["series"], r["offset"], r["a"], r["log_a_se"], r["b"], r["b_se"], r["r2"], r["residual_se"],
                     r["n"]] for r in rows], [False] + [True] * 8)
    md += ("\nOffsets: " + ", ".join(f"{r['series']} {r['offset_how']}" for r in rows) + ". Thesis Table 5.1 "
           "(N(I)-N(IV), t > 50 outputs): b = 0.498, 0.492, 0.516, 0.483 for Dp, Mp, Dr, Mr.\n\n")
    md += (f"Simple Model (eq. 5.4) with the members' mean late tapers alpha = {shown(alpha)} deg, beta = "
           f"{shown(beta)} deg: H = C S^0.5 with C = {shown(c if c is not None else float('nan'))}; "
           f"the fit of the mean H gives a = {shown(rows[4]['a'])}, b = {shown(rows[4]['b'])} "
           "(simple_model.csv compares them per output).\n")
    write(os.path.join(out, "fits.md"), md)

    # Thrust-sheet cycles of every member.
    step_min = float(stats["step_min"])
    reference = float(stats["sheet_reference"])
    cyc_rows, sum_rows, per_member = [], [], {}
    for name, series in members:
        per_member[name] = {}
        time = series.get("time", np.full(len(series["S"]), np.nan))
        for front, side in (("Dp", "pro"), ("Dr", "retro")):
            events, summ = thrust_cycles.cycles(series["S"], time, values(series, front), side, step_min)
            for k, e in enumerate(events):
                cyc_rows.append([name, side, k + 1, e["first"], e["S"], e["size"], e["spacing"], e["time_scale"]])
            s_range = float(np.nanmax(series["S"]) - np.nanmin(series["S"]))
            sum_rows.append([name, side, summ["n_steps"], summ["mean_spacing"], summ["std_spacing"],
                             summ["mean_size"], summ["mean_time_scale"], summ["retreat_rate"], summ["speed"],
                             reference, s_range / reference])
            per_member[name][side] = summ
        for r in rows:
            per_member[name]["within2_" + r["series"]] = within(series, r["series"], r)
    write(os.path.join(out, "cycles.csv"),
          csv_text(f"{title}: step-outs of the deformation fronts (new thrust sheets; thesis 5.4.5-5.4.7); a "
                   f"step-out is a rise of the front's outward distance by more than {shown(step_min)} h0 between "
                   "outputs (docs/ensembles.md)",
                   [("member", "member name"), ("front", "pro (Dp) or retro (Dr)"), ("k", "step-out number"),
                    ("output", "output index where the jump is first seen"), ("S", "S there [h0]"),
                    ("size", "outward jump: the implied sheet length l [h0]"),
                    ("spacing", "S since the previous step-out of this front [h0]"),
                    ("time_scale", "l / v: the sheet length over the convergence speed [model time, sqrt(d/g)]")],
                   cyc_rows))
    sum_cols = ["member", "front", "step-outs", "mean spacing in S [h0]", "st. dev. spacing [h0]",
                "mean l [h0]", "mean l/v [sqrt(d/g)]", "retreat dp/dS", "v [h0 per sqrt(d/g)]",
                "thesis: S per sheet [h0]", "thesis: sheets expected"]
    md = f"# {title}: thrust-sheet cycles\n\n"
    md += (f"Step-out: the front's outward distance rises by more than {shown(step_min)} h0 from one output to the "
           "next (consecutive such outputs are one step-out); l is the jump, the spacing the S between step-outs, "
           "l/v its time-scale at the convergence speed v; the retreat is the slope of the outward distance "
           "between step-outs (negative: carried inward). The thesis's reference: one pro thrust sheet per "
           f"about {shown(reference)} h0 of convergence (ensemble.stats.sheet_reference).\n\n")
    md += md_table(sum_cols, sum_rows, [False, False] + [True] * 9)
    write(os.path.join(out, "cycles.md"), md)
    write(os.path.join(out, "cycles_summary.csv"),
          csv_text(f"{title}: thrust-sheet cycles per member and front (see cycles.md)",
                   [("member", "member name"), ("front", "pro or retro"), ("n_steps", "step-outs found"),
                    ("mean_spacing", "mean S between step-outs [h0]"), ("std_spacing", "its standard deviation [h0]"),
                    ("mean_size", "mean jump l [h0]"), ("mean_time_scale", "mean l / v [sqrt(d/g)]"),
                    ("retreat_rate", "slope of the outward distance against S between step-outs"),
                    ("speed", "v = dS/dt [h0 per sqrt(d/g)]"),
                    ("sheet_reference", "thesis: convergence per new pro sheet [h0]"),
                    ("expected_sheets", "S range / sheet_reference")], sum_rows))
    fit_h = {name: powerlaw.power_law_fit(series["S"], values(series, "H"), s_min) for name, series in members}
    for name, series in members:
        per_member[name]["fit_H"] = fit_h[name]
        per_member[name]["alpha"] = late_mean(series, "alpha")
        per_member[name]["beta"] = late_mean(series, "beta")
    return per_member


# --------------------------------------------------------------------------------------------
# The results table: one row per member


def results(folder, plan, status, per_member, series_of):
    cols = [("name", "member folder under members/"), ("group", "its [[member]] entry"), ("seed", "run.seed"),
            ("exit_status", "0 finished, 2 bad input, 3 unstable, 128+N killed by signal N; empty: not run")]
    cols += [("final_S", "S at the last output [h0]")]
    cols += [(f"final_{n}", f"{NAMES[n]} at the last output [{UNITS[n]}]") for n in SERIES]
    cols += [("H_a", "power law H = a S^b of this member over S > s_min: a [h0]"), ("H_b", "b"),
             ("H_b_se", "standard error of b"), ("alpha_late", "mean pro taper over the last third in S [deg]"),
             ("beta_late", "mean retro taper over the last third in S [deg]"),
             ("pro_steps", "step-outs of Dp (new pro thrust sheets)"),
             ("pro_spacing", "mean S between them [h0]"), ("retro_steps", "step-outs of Dr"),
             ("within2_Dp", "fraction of outputs (S > s_min) with Dp inside the 2-standard-error envelope"),
             ("within2_Dr", "the same for Dr"), ("error", "a failed member: the last line of its log")]
    rows = []
    for m in plan.get("member", []):
        name = m["name"]
        st = status.get(name, {})
        series = series_of.get(name)
        pm = per_member.get(name, {})
        row = [name, m.get("group", ""), str(m["seed"]) if "seed" in m else "", st.get("exit_status", "")]
        if series is not None:
            row += [last_value(series["S"])] + [last_value(values(series, n)) for n in SERIES]
        else:
            row += [float("nan")] * (1 + len(SERIES))
        fit = pm.get("fit_H")
        row += [fit["a"] if fit else float("nan"), fit["b"] if fit else float("nan"),
                fit["b_se"] if fit else float("nan"), pm.get("alpha", float("nan")), pm.get("beta", float("nan")),
                pm["pro"]["n_steps"] if "pro" in pm else "", pm["pro"]["mean_spacing"] if "pro" in pm else float("nan"),
                pm["retro"]["n_steps"] if "retro" in pm else "", pm.get("within2_Dp", float("nan")),
                pm.get("within2_Dr", float("nan")), st.get("error", "")]
        rows.append(row)
    title = plan["ensemble"].get("title", "ensemble")
    write(os.path.join(folder, "results.csv"),
          csv_text(f"Orogen ensemble results of {title}: one row per member", cols, rows))
    md = f"# {title}: ensemble results\n\n"
    status = [c[0] for c in cols].index("exit_status")
    done = sum(1 for r in rows if r[status] == "0")
    md += f"{len(rows)} members, {done} finished. Aggregate statistics in `aggregate/` (docs/ensembles.md).\n\n"
    md += md_table([c[0] for c in cols], rows, [False, False, False] + [True] * (len(cols) - 4) + [False])
    md += "\nNumbers are rounded to 4 significant digits here; `results.csv` has them exactly.\n\n"
    md += "".join(f"- `{c}`: {d}\n" for c, d in cols)
    write(os.path.join(folder, "results.md"), md)


def main(argv):
    if len(argv) != 1:
        print(__doc__.strip().splitlines()[2].strip(), file=sys.stderr)
        return 2
    folder = argv[0]
    try:
        plan = read_plan(folder)
        status = read_members_csv(folder)
    except Usage as e:
        print(f"orogen.stats: {e}", file=sys.stderr)
        return 2
    stats = plan.get("stats", {})
    stats.setdefault("s_min", 2.0)
    stats.setdefault("step_min", 0.5)
    stats.setdefault("sheet_reference", 5.0)
    members = plan.get("member", [])
    series_of = {}
    for m in members:
        if status.get(m["name"], {}).get("exit_status") == "0":
            series = read_member(folder, m["name"])
            if series is not None:
                series_of[m["name"]] = series
    groups = []
    for m in members:
        if m.get("group", "") not in groups:
            groups.append(m.get("group", ""))
    per_member = {}
    title = plan["ensemble"].get("title", "ensemble")
    for g in groups:
        finished = [(m["name"], series_of[m["name"]]) for m in members if m.get("group", "") == g and m["name"] in series_of]
        if not finished:
            continue
        out = os.path.join(folder, "aggregate", g) if len(groups) > 1 else os.path.join(folder, "aggregate")
        per_member.update(aggregate(out, f"{title} {g}".strip(), finished, stats))
    results(folder, plan, status, per_member, series_of)
    print(f"orogen.stats: {len(series_of)} of {len(members)} members aggregated in "
          f"{os.path.join(folder, 'aggregate')}; results in {os.path.join(folder, 'results.md')}", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
