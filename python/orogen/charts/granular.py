#!/usr/bin/python3
"""Charts of the granular material experiments (Naylor 2004, chapter 3 and Appendix A).

Usage:
    python3 -m orogen.charts.granular repose  RUN_OR_SWEEP_DIR... --out OUTDIR
    python3 -m orogen.charts.granular singly  RUN_OR_SWEEP_DIR... --out OUTDIR [--bulk BIAXIAL...]
    python3 -m orogen.charts.granular biaxial RUN_OR_SWEEP_DIR... --out OUTDIR

Each argument is a run folder of `orogen run` (config.toml, series.csv, summary.csv,
snapshots.h5), a sweep folder of `orogen sweep` (results.csv and runs/NAME/: its finished runs;
the others are reported and left out), a sweep's results.csv, or a folder of run folders (those
of the subcommand's experiment). Configuration values (packing, frictions) are read from each
run's config.toml. Writes into OUTDIR, each file atomically (a temporary file in OUTDIR, then
os.replace):

  repose (run.experiment = "repose"; thesis 3.2.1-3.2.2, Fig 3.4):
    repose_profile_NAME.png  per run: the particles at rest coloured by initial-depth horizons,
                             the surface columns, the fitted ones highlighted, the fitted line
                             with its angle
    repose_grid.png          rows packings (and variant), columns contact friction: each panel
                             the surface profile and fitted line with the angle
    repose_angle_vs_mu.png   angle of repose against contact friction, one line per packing
    repose_table.md, .csv    packing, variant, mu, angle, R², concavity, removed fraction
  singly (run.experiment = "singly_vergent"; thesis 3.2.3, Fig 3.23, Appendix A):
    singly_taper.png         taper against shortening, a panel per packing, black mu 0.3, grey
                             mu 0.2, a line style per basal friction mu_b; with --bulk the
                             critical taper from the biaxial bulk friction beside the curves
    singly_profiles.png      the final surface of each run, stacked, with the fitted taper line
    singly_table.md, .csv    steady, final, front and back tapers; with --bulk the bulk
                             friction and the critical taper; the thesis's value where known
  biaxial (run.experiment = "biaxial"; the bulk friction that the critical taper needs):
    biaxial_stress_strain.png  mobilised friction angle and volumetric strain against axial
                               strain, peak and residual marked
    biaxial_friction_vs_mu.png peak and residual bulk friction angle against contact friction
    biaxial_table.md, .csv     per run: bulk friction, dilatancy, critical tapers

Only numpy, pandas, matplotlib (Agg) and h5py are used (readers in orogen.folders and orogen.tables, over
the package orogen); without h5py the pictures of particles and final surfaces say so. Lengths
are in units of the largest disc diameter d unless an axis says h0 (layer thickness); angles in
degrees. Exit status 0, or 2
with a message when an argument is not a folder of the subcommand's runs.
"""

import argparse
import math
import os
import re
import sys

import numpy as np
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.collections import EllipseCollection  # noqa: E402
from matplotlib.lines import Line2D  # noqa: E402

from .. import atomic, folders, tables  # noqa: E402
from ..analysis import surface  # noqa: E402

NAN = float("nan")
PACKING_ORDER = ("hexagonal", "random_discs", "random_clusters")
PACKING_COLOURS = {"hexagonal": "tab:blue", "random_discs": "tab:orange", "random_clusters": "tab:green"}
PACKING_MAPS = {"hexagonal": "Blues", "random_discs": "Oranges", "random_clusters": "Greens"}
# Horizon colours of `orogen render` (src/render/colormap.cpp): sand, dark brown, ochre, slate
# green, in bands of 1/8 of the file's h0.
HORIZON_COLOURS = ((230, 200, 140), (115, 77, 51), (204, 128, 64), (89, 102, 84))
HORIZON_BAND_FRACTION = 0.125
FIXED_COLOUR = (0.12, 0.12, 0.14)  # held (kinematic) discs
RUNNING_MEAN = 5  # outputs in the running mean of a taper curve
# Appendix A of the thesis: steady taper [deg] by (packing, contact mu, basal mu_b), where known.
THESIS_TAPER = {("random_clusters", 0.3, 0.3): 11.75}
MU_B_STYLES = {0.1: ":", 0.2: "--", 0.3: "-"}
MU_B_MARKERS = {0.1: "^", 0.2: "s", 0.3: "o"}
OTHER_STYLES = ("-.", (0, (5, 1, 1, 1, 1, 1)), (0, (1, 3)), (0, (8, 2)))
OTHER_MARKERS = ("D", "v", "P", "X", "*")


# --------------------------------------------------------------------------------------------
# Small helpers


def fnum(v):
    try:
        return float(v)
    except (TypeError, ValueError):
        return NAN


def finite(v):
    return v is not None and isinstance(v, (int, float)) and math.isfinite(v)


def same(a, b):
    return finite(a) and finite(b) and abs(a - b) <= 1e-9 * max(1.0, abs(a), abs(b))


def packing_key(p):
    p = str(p)
    return (PACKING_ORDER.index(p) if p in PACKING_ORDER else len(PACKING_ORDER), p)


def packing_label(p):
    return str(p).replace("_", " ")


def safe_name(name):
    return re.sub(r"[^A-Za-z0-9._+=-]", "-", name)


def no_data(ax, text="no data"):
    ax.text(0.5, 0.5, text, transform=ax.transAxes, ha="center", va="center", color="0.4")


def show(v, digits=2):
    """A number for a Markdown table: fixed decimals, '–' when not a finite number."""
    return ("%.*f" % (digits, v)) if finite(v) else "–"


def markdown_table(header, rows, numeric):
    out = "| " + " | ".join(header) + " |\n"
    out += "|" + "".join("---:|" if n else "---|" for n in numeric) + "\n"
    for r in rows:
        out += "| " + " | ".join(str(c).replace("|", "\\|") for c in r) + " |\n"
    return out


def csv_text(header, rows):
    def field(v):
        if isinstance(v, float):
            return repr(v)  # 'nan' for NaN, as orogen writes
        s = str(v)
        return '"%s"' % s.replace('"', '""') if any(c in s for c in ',"\r\n') else s
    return "\n".join(",".join(field(v) for v in row) for row in [header] + rows) + "\n"


def running_mean(v, window=RUNNING_MEAN):
    """Centred running mean over the finite values within +-window//2 rows (NaN stays NaN)."""
    v = np.asarray(v, dtype=float)
    out = np.full(v.size, np.nan)
    half = window // 2
    for i in range(v.size):
        if not np.isfinite(v[i]):
            continue
        w = v[max(0, i - half):i + half + 1]
        out[i] = np.mean(w[np.isfinite(w)])
    return out


def mean_sd(values):
    v = np.array([x for x in values if finite(x)], dtype=float)
    if v.size == 0:
        return NAN, NAN, 0
    return float(v.mean()), (float(v.std(ddof=1)) if v.size > 1 else NAN), int(v.size)


def group_mean(items, key, value):
    """{key(item): (mean, sd, n)} of value(item)."""
    groups = {}
    for it in items:
        groups.setdefault(key(it), []).append(value(it))
    return {k: mean_sd(v) for k, v in groups.items()}


# --------------------------------------------------------------------------------------------
# Particles


def horizon_colours(depth0, h0):
    """RGB (n x 3) of the horizon bands of `orogen render --color horizons`."""
    n = len(depth0)
    band = HORIZON_BAND_FRACTION * h0 if finite(h0) and h0 > 0 else NAN
    out = np.full((n, 3), 0.6)
    if not finite(band):
        return out
    d = np.asarray(depth0, dtype=float)
    ok = np.isfinite(d)
    k = np.floor(np.maximum(d[ok], 0.0) / band).astype(np.int64) % len(HORIZON_COLOURS)
    out[ok] = np.array(HORIZON_COLOURS, dtype=float)[k] / 255.0
    return out


def draw_discs(ax, frame):
    """The discs of a snapshot frame, coloured by horizon, held discs dark grey, walls black."""
    x, y, r = (np.asarray(frame[k], dtype=float) for k in ("x", "y", "radius"))
    h0 = fnum(frame["file_attrs"].get("h0"))
    colours = horizon_colours(frame.get("depth0", np.full(x.size, np.nan)), h0)
    if "motion" in frame:
        colours[np.asarray(frame["motion"]) != 0] = FIXED_COLOUR
    coll = EllipseCollection(2 * r, 2 * r, np.zeros(x.size), units="xy", offsets=np.column_stack([x, y]),
                             offset_transform=ax.transData, facecolors=colours, edgecolors="none")
    ax.add_collection(coll)
    for ax_, ay, bx, by in frame["walls"]:
        ax.plot([ax_, bx], [ay, by], "-", color="k", lw=2.5, solid_capstyle="butt", zorder=3)
    if x.size:
        return float(np.min(x - r)), float(np.max(x + r)), float(np.min(y - r)), float(np.max(y + r))
    return 0.0, 1.0, 0.0, 1.0


# --------------------------------------------------------------------------------------------
# Angle of repose


def repose_profile(run):
    """The run's surface at rest: dict x, height, fitted (bool), fit (surface.fit_line of the fitted
    columns), source ('profile.csv' or 'computed from snapshots.h5'); None if neither file."""
    path = run.file("profile.csv")
    if path:
        cols, _ = tables.read_table(path)
        x, h = cols.get("x", np.array([])), cols.get("height", np.array([]))
        fitted = cols.get("fitted", np.zeros(x.size)) == 1
        return dict(x=x, height=h, fitted=fitted, fit=surface.fit_line(x[fitted], h[fitted]), source="profile.csv")
    h5 = run.file("snapshots.h5")
    if not h5 or folders.h5py is None:
        return None
    # As ReposeExperiment::profile: columns of [0, size]; the slope is the columns above the held
    # layer (slump) or the lip (ledge) plus d_max and below the settled top minus 1.5 d_max.
    first, last = folders.read_frame(h5, 0), folders.read_frame(h5, -1)
    if first is None:
        return None
    size = fnum(run.value("repose.size"))
    d_max = fnum(run.value("particles.d_max", 1.0))
    _, h_first = surface.surface_columns(first["x"], first["y"], first["radius"], 0.0, size)
    top = float(np.nanmean(h_first)) if np.isfinite(h_first).any() else size
    if run.value("repose.variant") == "ledge":
        base = fnum(run.value("repose.ledge_fraction")) * top + d_max
    else:
        base = fnum(run.value("repose.fixed_height")) + d_max
    x, h = surface.surface_columns(last["x"], last["y"], last["radius"], 0.0, size)
    with np.errstate(invalid="ignore"):
        fitted = np.isfinite(h) & (h > base) & (h < top - 1.5 * d_max)
    return dict(x=x, height=h, fitted=fitted, fit=surface.fit_line(x[fitted], h[fitted]),
                source="computed from snapshots.h5")


def fit_angle(fit):
    return math.degrees(-math.atan(fit["slope"])) if fit else NAN


def load_repose(run):
    s = run.summary
    prof = None
    try:
        prof = repose_profile(run)
    except Exception as e:  # an unreadable file: drawn as 'no profile', the table still filled
        folders.warn("%s: %s" % (run.dir, e))
    angle = s.get("angle_deg", NAN)
    if not finite(angle) and prof:
        angle = fit_angle(prof["fit"])
    return dict(run=run, name=run.name, packing=str(run.value("particles.packing", "?")),
                variant=str(run.value("repose.variant", "slump")), mu=fnum(run.value("contact.mu")),
                angle=angle, r2=s.get("angle_r2", prof["fit"]["r2"] if prof and prof["fit"] else NAN),
                concavity=s.get("concavity_deg", math.degrees(prof["fit"]["concavity"]) if prof and prof["fit"] else NAN),
                removed=s.get("removed_fraction", NAN), at_rest=s.get("at_rest", NAN),
                from_summary="angle_deg" in s, profile=prof)


def draw_fit_line(ax, prof, colour, label):
    fit = prof["fit"]
    if not fit:
        return
    pad = 0.05 * (fit["x_hi"] - fit["x_lo"])
    xs = np.array([fit["x_lo"] - pad, fit["x_hi"] + pad])
    ax.plot(xs, fit["intercept"] + fit["slope"] * xs, "--", color=colour, lw=1.8, label=label, zorder=6)


def chart_repose_profile(item, path):
    run, prof = item["run"], item["profile"]
    fig, ax = plt.subplots(figsize=(11, 6.5))
    frame = None
    h5 = run.file("snapshots.h5")
    if h5 and folders.h5py is not None:
        try:
            frame = folders.read_last_frame(h5)
        except Exception as e:
            folders.warn("%s: %s" % (h5, e))
    x_lo, x_hi, y_lo, y_hi = 0.0, fnum(run.value("repose.size", 40.0)), 0.0, fnum(run.value("repose.size", 40.0))
    if frame is not None:
        bx_lo, bx_hi, by_lo, by_hi = draw_discs(ax, frame)
        x_lo, x_hi, y_lo, y_hi = min(x_lo, bx_lo), max(x_hi, bx_hi), min(y_lo, by_lo), by_hi
    else:
        no_data(ax, "no snapshots.h5 (or no h5py): particles not drawn")
    if prof is not None:
        ax.plot(prof["x"], prof["height"], "-", color="tab:blue", lw=1.0, marker="o", ms=2.5,
                label="surface columns (top of the highest disc)", zorder=5)
        f = prof["fitted"]
        ax.plot(prof["x"][f], prof["height"][f], "o", color="tab:red", ms=4.5, mfc="none", mew=1.3,
                label="fitted columns (%d)" % int(f.sum()), zorder=6)
        fit = prof["fit"]
        if fit:
            draw_fit_line(ax, prof, "tab:red", "fitted line: %.1f° (R² %.3f, concavity %.1f°)" % (
                fit_angle(fit), fit["r2"], math.degrees(fit["concavity"])))
        if prof["source"] != "profile.csv":
            ax.text(0.99, 0.01, "profile %s" % prof["source"], transform=ax.transAxes, ha="right", va="bottom",
                    fontsize=8, color="0.3")
    else:
        no_data(ax, "no profile.csv or snapshots.h5")
    ax.set_xlim(x_lo - 1.0, x_hi + 1.0)
    ax.set_ylim(min(y_lo, 0.0) - 1.0, y_hi + 2.0)
    ax.set_aspect("equal")
    summary = (" — summary angle %.2f°" % item["angle"]) if item["from_summary"] and finite(item["angle"]) else ""
    ax.set(xlabel="x [d]", ylabel="y [d]",
           title="%s: %s, μ = %g, %s%s" % (item["name"], packing_label(item["packing"]), item["mu"],
                                            item["variant"], summary))
    handles, labels = ax.get_legend_handles_labels()
    handles.append(Line2D([], [], ls="", marker="o", mfc=FIXED_COLOUR, mec=FIXED_COLOUR, ms=6))
    labels.append("held discs (colours: initial-depth horizons)")
    ax.legend(handles, labels, fontsize=8, loc="upper right")
    fig.tight_layout()
    atomic.save_figure(fig, path)


def row_key(item, variants):
    return (packing_key(item["packing"]), item["variant"] if len(variants) > 1 else "")


def chart_repose_grid(items, path):
    variants = sorted({it["variant"] for it in items})
    rows = sorted({row_key(it, variants) for it in items})
    mus = sorted({it["mu"] for it in items if finite(it["mu"])}) or [NAN]
    nr, nc = len(rows), len(mus)
    fig, axes = plt.subplots(nr, nc, figsize=(3.4 * nc + 0.6, 3.3 * nr + 0.8), squeeze=False)
    cmap = plt.get_cmap("tab10")
    # The same square extent with equal scales in every panel: slopes look as steep as they are.
    profs = [it["profile"] for it in items if it["profile"] is not None and np.isfinite(it["profile"]["height"]).any()]
    extent = max([float(np.nanmax(p["x"])) for p in profs] + [float(np.nanmax(p["height"])) for p in profs] + [1.0])
    for i, rk in enumerate(rows):
        for j, mu in enumerate(mus):
            ax = axes[i][j]
            cell = [it for it in items if row_key(it, variants) == rk and (same(it["mu"], mu) or
                                                                         (not finite(mu) and not finite(it["mu"])))]
            angles = []
            for k, it in enumerate(cell):
                prof, c = it["profile"], cmap(k % 10)
                angles.append(it["angle"])
                if prof is None:
                    continue
                ax.plot(prof["x"], prof["height"], "-", color="0.5", lw=0.8)
                f = prof["fitted"]
                ax.plot(prof["x"][f], prof["height"][f], "o", color=c, ms=2.5)
                draw_fit_line(ax, prof, c, "%s: %.1f°" % (it["name"], it["angle"]))
            label = "%s%s" % (packing_label(rk[0][1]), (", " + rk[1]) if rk[1] else "")
            if not cell:
                no_data(ax, "no run")
                ax.set_xticks([])
                ax.set_yticks([])
            elif not any(it["profile"] for it in cell):
                no_data(ax, "no profile")
            m, sd, n = mean_sd(angles)
            text = ("%.1f°" % m if n == 1 else "%.1f ± %.1f° (%d runs)" % (m, sd, n)) if n else "–"
            ax.set_title("μ = %g: %s" % (mu, text), fontsize=9)
            if j == 0:
                ax.set_ylabel("%s\nheight [d]" % label, fontsize=9)
            if i == nr - 1:
                ax.set_xlabel("x [d]", fontsize=9)
            ax.set_xlim(-1.0, extent + 1.0)
            ax.set_ylim(-1.0, extent + 1.0)
            ax.set_aspect("equal", adjustable="box")
            ax.tick_params(labelsize=7)
            ax.grid(True, alpha=0.3)
            if len(cell) > 1:
                ax.legend(fontsize=6, loc="upper right")
    fig.suptitle("Angle of repose: surface at rest (grey), fitted columns (dots) and line (dashed)", fontsize=11)
    fig.tight_layout()
    atomic.save_figure(fig, path)


def chart_repose_angle_vs_mu(items, path):
    fig, ax = plt.subplots(figsize=(8, 5.5))
    variants = sorted({it["variant"] for it in items})
    styles = {"slump": ("-", "o"), "ledge": ("--", "s")}
    drawn = False
    for packing in sorted({it["packing"] for it in items}, key=packing_key):
        colour = PACKING_COLOURS.get(packing, "tab:purple")
        for v in variants:
            sel = [it for it in items if it["packing"] == packing and it["variant"] == v
                   and finite(it["mu"]) and finite(it["angle"])]
            if not sel:
                continue
            drawn = True
            ls, marker = styles.get(v, ("-.", "D"))
            label = packing_label(packing) + (" (%s)" % v if len(variants) > 1 else "")
            plot_runs_and_means(ax, sel, "angle", colour, ls, marker, label)
    ax.set(xlabel="contact friction μ", ylabel="angle of repose [deg]",
           title="Angle of repose against contact friction (cf. thesis Fig 3.4, after Oger et al.)")
    finish_mu_chart(fig, ax, drawn, path, fontsize=9)


REPOSE_COLUMNS = ("run", "packing", "variant", "mu", "angle_deg", "angle_r2", "concavity_deg",
                  "removed_fraction", "at_rest", "profile")


def repose_rows(items):
    return [[it["name"], it["packing"], it["variant"], it["mu"], it["angle"], it["r2"], it["concavity"],
             it["removed"], it["at_rest"], it["profile"]["source"] if it["profile"] else "none"] for it in items]


def repose_markdown(items):
    out = "# Angle of repose\n\nWritten by `python3 -m orogen.charts.granular repose`. Angle: straight-line fit of " \
          "the surface columns on the slope (summary.csv `angle_deg`); R² of that line; concavity: " \
          "descent angle at the top of the slope minus at its foot from a quadratic fit (> 0 concave); " \
          "removed: fraction of the discs that left the box.\n\n"
    rows = [[it["name"], packing_label(it["packing"]), it["variant"], "%g" % it["mu"], show(it["angle"]),
             show(it["r2"], 3), show(it["concavity"], 1), show(it["removed"], 3),
             "yes" if it["at_rest"] == 1 else ("no" if it["at_rest"] == 0 else "–")] for it in items]
    out += markdown_table(["run", "packing", "variant", "mu", "angle [deg]", "R²", "concavity [deg]",
                           "removed fraction", "at rest"], rows, [False, False, False] + [True] * 5 + [False])
    g = group_mean(items, lambda it: (packing_key(it["packing"]), it["variant"], it["mu"]), lambda it: it["angle"])
    if any(n > 1 for _, _, n in g.values()):
        out += "\n## Mean over runs\n\n"
        rows = [[packing_label(k[0][1]), k[1], "%g" % k[2], str(n), show(m), show(sd)]
                for k, (m, sd, n) in sorted(g.items(), key=lambda kv: (kv[0][0], kv[0][1], kv[0][2]))]
        out += markdown_table(["packing", "variant", "mu", "runs", "mean angle [deg]", "sd [deg]"], rows,
                              [False, False, True, True, True, True])
    computed = [it["name"] for it in items if it["profile"] and it["profile"]["source"] != "profile.csv"]
    if computed:
        out += "\nProfiles recomputed from snapshots.h5 (no profile.csv): %s.\n" % ", ".join(computed)
    return out


def make_repose(paths, out_dir):
    runs = folders.collect_runs(paths, "repose")
    items = sorted((load_repose(r) for r in runs),
                   key=lambda it: (packing_key(it["packing"]), it["variant"], it["mu"], it["name"]))
    os.makedirs(out_dir, exist_ok=True)
    written = []
    with np.errstate(invalid="ignore", divide="ignore"):
        for it in items:
            if it["run"].dir is None:
                continue
            name = os.path.join(out_dir, "repose_profile_%s.png" % safe_name(it["name"]))
            chart_repose_profile(it, name)
            written.append(name)
        for name, draw in (("repose_grid.png", chart_repose_grid), ("repose_angle_vs_mu.png", chart_repose_angle_vs_mu)):
            draw(items, os.path.join(out_dir, name))
            written.append(os.path.join(out_dir, name))
    atomic.write_text(os.path.join(out_dir, "repose_table.md"), repose_markdown(items))
    atomic.write_text(os.path.join(out_dir, "repose_table.csv"), csv_text(list(REPOSE_COLUMNS), repose_rows(items)))
    written += [os.path.join(out_dir, n) for n in ("repose_table.md", "repose_table.csv")]
    return dict(items=items, written=written)


# --------------------------------------------------------------------------------------------
# Biaxial test


def residual_from(run):
    """Axial strain where the residual state begins: from the summary's description of
    phi_residual_deg ('... beyond axial strain X ...'), else 2/3 of biaxial.strain_end."""
    desc = run.summary_descriptions.get("phi_residual_deg", "")
    m = re.search(r"beyond axial strain ([0-9.eE+-]+)", desc)
    if m:
        v = fnum(m.group(1))
        if finite(v):
            return v
    return 2.0 / 3.0 * fnum(run.value("biaxial.strain_end", 0.2))


def preparation(run):
    """The layer's preparation (docs/model.md, Packings): (particles.placement, settle.mu); runs
    made before the placement key were placed on the grid."""
    return str(run.value("particles.placement", "grid")), fnum(run.value("settle.mu", 0.0))


def same_preparation(a, b):
    return a[0] == b[0] and same(a[1], b[1])


def preparation_text(prep):
    """'' for the default preparation (grid, frictionless), else ', rain, settle.mu 0.3'."""
    return "" if same_preparation(prep, ("grid", 0.0)) else ", %s, settle.mu %g" % prep


def load_biaxial(run):
    s = run.summary
    tapers = {}
    for k, v in s.items():
        m = re.fullmatch(r"taper_mub([0-9.eE+-]+)_(peak|residual)_deg", k)
        if m and finite(fnum(m.group(1))):
            tapers[(fnum(m.group(1)), m.group(2))] = v
    return dict(run=run, name=run.name, packing=str(run.value("particles.packing", "?")),
                mu=fnum(run.value("contact.mu")), prep=preparation(run), phi_peak=s.get("phi_peak_deg", NAN),
                phi_residual=s.get("phi_residual_deg", NAN), strain_peak=s.get("axial_strain_peak", NAN),
                tapers=tapers, residual_from=residual_from(run), summary=s)


def biaxial_colours(items):
    """A colour per run: the packing's colour map, darker for larger contact friction."""
    out = {}
    for packing in {it["packing"] for it in items}:
        sel = [it for it in items if it["packing"] == packing]
        mus = sorted({it["mu"] for it in sel if finite(it["mu"])})
        cmap = plt.get_cmap(PACKING_MAPS.get(packing, "Purples"))
        for it in sel:
            k = mus.index(it["mu"]) if it["mu"] in mus else 0
            out[it["name"]] = cmap(0.45 + 0.5 * (k + 1) / max(len(mus), 1))
    return out


def chart_biaxial_stress_strain(items, path):
    fig, (ax_p, ax_v) = plt.subplots(2, 1, figsize=(10, 8.5), sharex=True, gridspec_kw={"height_ratios": (3, 2)})
    colours = biaxial_colours(items)
    drawn = False
    unsheared = []
    for it in items:
        s, c = it["run"].series_columns, colours[it["name"]]
        if "axial_strain" not in s:
            unsheared.append(it["name"])
            continue
        shear = s["phase"] >= 1 if "phase" in s else np.ones(len(s["axial_strain"]), dtype=bool)
        e = s["axial_strain"][shear]
        if e.size == 0:
            unsheared.append(it["name"])
            continue
        drawn = True
        label = "%s: %s, μ = %g" % (it["name"], packing_label(it["packing"]), it["mu"])
        ax_p.plot(e, s.get("phi_deg", np.full(len(shear), np.nan))[shear], "-", color=c, lw=1.3, label=label)
        ax_v.plot(e, s.get("vol_strain", np.full(len(shear), np.nan))[shear], "-", color=c, lw=1.3)
        if finite(it["phi_peak"]):
            ax_p.plot([it["strain_peak"]], [it["phi_peak"]], "v", color=c, mec="k", ms=8, zorder=5)
        if finite(it["phi_residual"]):
            e_end = float(np.nanmax(e))
            ax_p.plot([it["residual_from"], e_end], [it["phi_residual"]] * 2, "-", color=c, lw=5, alpha=0.35,
                      solid_capstyle="butt")
    ax_p.set(ylabel="mobilised friction angle φ [deg]",
             title="Biaxial test: φ = asin((σ1 − σ3)/(σ1 + σ3)) and area change while shearing")
    ax_v.axhline(0.0, color="0.5", lw=0.8)
    ax_v.set(xlabel="axial strain (H0 − H)/H0", ylabel="volumetric strain (A − A0)/A0\n(> 0 dilating)")
    for ax in (ax_p, ax_v):
        ax.grid(True, alpha=0.3)
    if drawn:
        handles, labels = ax_p.get_legend_handles_labels()
        handles += [Line2D([], [], ls="", marker="v", color="0.5", mec="k", ms=8),
                    Line2D([], [], color="0.5", lw=5, alpha=0.35)]
        labels += ["peak", "residual mean (over its strain range)"]
        ax_p.legend(handles, labels, fontsize=7, loc="lower right", ncol=2 if len(items) > 8 else 1)
    else:
        no_data(ax_p)
        no_data(ax_v)
    if unsheared:
        ax_p.text(0.01, 0.99, "not sheared (no rows with phase >= 1): %s" % ", ".join(unsheared),
                  transform=ax_p.transAxes, ha="left", va="top", fontsize=7, color="tab:red")
    fig.tight_layout()
    atomic.save_figure(fig, path)


def plot_runs_and_means(ax, items, key, colour, ls, marker, label, mfc=None):
    """Each run as an open marker at (mu, item[key]), and the mean ± sd over runs per mu as a line."""
    ax.plot([it["mu"] for it in items], [it[key] for it in items], marker, color=colour, ms=4, alpha=0.45,
            mfc="none")
    g = group_mean(items, lambda it: it["mu"], lambda it: it[key])
    mus = sorted(g)
    ax.errorbar(mus, [g[m][0] for m in mus], yerr=[g[m][1] if finite(g[m][1]) else 0.0 for m in mus],
                fmt=ls, marker=marker, color=colour, lw=1.6, ms=6, capsize=3, mfc=mfc, label=label)


def finish_mu_chart(fig, ax, drawn, path, fontsize):
    """Axes from zero, grid, legend (or 'no data'), then the PNG."""
    ax.set_xlim(left=0)
    ax.set_ylim(bottom=0)
    ax.grid(True, alpha=0.3)
    if drawn:
        ax.legend(fontsize=fontsize, loc="lower right", title="mean ± sd over runs; open: each run",
                  title_fontsize=8)
    else:
        no_data(ax)
    fig.tight_layout()
    atomic.save_figure(fig, path)


def chart_biaxial_friction_vs_mu(items, path):
    fig, ax = plt.subplots(figsize=(8, 5.5))
    drawn = False
    all_mu = [it["mu"] for it in items if finite(it["mu"])]
    for packing in sorted({it["packing"] for it in items}, key=packing_key):
        colour = PACKING_COLOURS.get(packing, "tab:purple")
        sel = [it for it in items if it["packing"] == packing and finite(it["mu"])]
        for key, ls, marker, what in (("phi_peak", "-", "o", "peak"), ("phi_residual", "--", "s", "residual")):
            pts = [it for it in sel if finite(it[key])]
            if not pts:
                continue
            drawn = True
            plot_runs_and_means(ax, pts, key, colour, ls, marker, "%s, %s" % (packing_label(packing), what),
                                mfc=colour if what == "peak" else "white")
    if all_mu:
        m = np.linspace(0, max(all_mu) * 1.05, 50)
        ax.plot(m, np.degrees(np.arctan(m)), ":", color="0.4", lw=1.2, label="atan(μ): contact friction angle")
    ax.set(xlabel="contact friction μ", ylabel="bulk friction angle φ [deg]",
           title="Bulk friction of the packings (biaxial test): peak and residual")
    finish_mu_chart(fig, ax, drawn, path, fontsize=8)


BIAXIAL_VALUES = ("phi_peak_deg", "axial_strain_peak", "phi_residual_deg", "mu_bulk_peak", "mu_bulk_residual",
                  "dilatancy_peak", "psi_peak_deg", "vol_strain_end", "sigma3", "sigma3_mean", "sigma3_max_dev",
                  "solid_fraction_start", "coordination_start", "inertial_number", "n_discs")


def biaxial_taper_bases(items):
    return sorted({mb for it in items for (mb, _) in it["tapers"]})


def biaxial_taper(it, mu_b, which):
    """Critical taper [deg] of a biaxial run for basal friction mu_b from its peak or residual
    bulk friction: the summary's column when it has one for mu_b, else computed here."""
    for (mb, w), v in it["tapers"].items():
        if w == which and same(mb, mu_b):
            return v
    return surface.critical_taper_deg(it["phi_" + which], mu_b)


def biaxial_tables(items):
    bases = biaxial_taper_bases(items) or [0.1, 0.2, 0.3]
    header = ["run", "packing", "mu"] + list(BIAXIAL_VALUES)
    header += ["critical_taper_mub%g_%s_deg" % (mb, w) for mb in bases for w in ("peak", "residual")]
    rows = []
    for it in items:
        rows.append([it["name"], it["packing"], it["mu"]] + [it["summary"].get(k, NAN) for k in BIAXIAL_VALUES]
                    + [biaxial_taper(it, mb, w) for mb in bases for w in ("peak", "residual")])
    md = "# Biaxial tests: bulk friction\n\nWritten by `python3 -m orogen.charts.granular biaxial`. φ: mobilised " \
         "friction angle asin((σ1 − σ3)/(σ1 + σ3)), at its peak and its mean in the residual state; ψ: " \
         "dilatancy angle at the peak; σ3 dev: largest relative deviation of the confining stress from its " \
         "target; I: inertial number (quasi-static below about 1e-3); α_c: critical taper of a dry wedge on " \
         "a flat base of friction μ_b from the peak / residual φ (– : none, the base is not weaker than " \
         "the material).\n\n"
    mdh = ["run", "packing", "mu", "φ peak [deg]", "strain at peak", "φ residual [deg]", "ψ peak [deg]",
           "vol. strain end", "σ3 dev", "I"] + ["α_c μ_b=%g [deg]" % mb for mb in bases]
    mdr = []
    for it in items:
        s = it["summary"]
        mdr.append([it["name"], packing_label(it["packing"]), "%g" % it["mu"], show(it["phi_peak"]),
                    show(it["strain_peak"], 3), show(it["phi_residual"]), show(s.get("psi_peak_deg", NAN), 1),
                    show(s.get("vol_strain_end", NAN), 3), show(s.get("sigma3_max_dev", NAN), 3),
                    ("%.1e" % s["inertial_number"]) if finite(s.get("inertial_number")) else "–"]
                   + ["%s / %s" % (show(biaxial_taper(it, mb, "peak")), show(biaxial_taper(it, mb, "residual")))
                      for mb in bases])
    md += markdown_table(mdh, mdr, [False, False] + [True] * (len(mdh) - 2))
    return md, csv_text(header, rows)


def make_biaxial(paths, out_dir):
    runs = folders.collect_runs(paths, "biaxial")
    items = sorted((load_biaxial(r) for r in runs), key=lambda it: (packing_key(it["packing"]), it["mu"], it["name"]))
    os.makedirs(out_dir, exist_ok=True)
    written = []
    with np.errstate(invalid="ignore", divide="ignore"):
        for name, draw in (("biaxial_stress_strain.png", chart_biaxial_stress_strain),
                           ("biaxial_friction_vs_mu.png", chart_biaxial_friction_vs_mu)):
            draw(items, os.path.join(out_dir, name))
            written.append(os.path.join(out_dir, name))
    md, csv = biaxial_tables(items)
    atomic.write_text(os.path.join(out_dir, "biaxial_table.md"), md)
    atomic.write_text(os.path.join(out_dir, "biaxial_table.csv"), csv)
    written += [os.path.join(out_dir, n) for n in ("biaxial_table.md", "biaxial_table.csv")]
    return dict(items=items, written=written)


class Bulk:
    """Bulk friction of biaxial runs by (packing, contact mu, preparation): means over the runs
    (seeds). A wedge's critical taper comes from the biaxial test of its own preparation."""

    def __init__(self, items):
        self.items = items

    def _group(self, packing, mu, prep):
        return [it for it in self.items
                if it["packing"] == packing and same(it["mu"], mu) and same_preparation(it["prep"], prep)]

    def phi(self, packing, mu, prep, which):
        return mean_sd([it["phi_" + which] for it in self._group(packing, mu, prep)])[0]

    def taper(self, packing, mu, prep, mu_b, which):
        g = self._group(packing, mu, prep)
        return mean_sd([biaxial_taper(it, mu_b, which) for it in g])[0] if g else NAN


# --------------------------------------------------------------------------------------------
# Singly-vergent wedge


def load_singly(run):
    s = run.summary
    return dict(run=run, name=run.name, packing=str(run.value("particles.packing", "?")),
                mu=fnum(run.value("contact.mu")), mu_b=fnum(run.value("singly.mu_b")), prep=preparation(run),
                h0=fnum(run.value("layer.thickness", 10.0)), d_max=fnum(run.value("particles.d_max", 1.0)),
                steady=s.get("taper_steady_deg", NAN), steady_sd=s.get("taper_steady_sd_deg", NAN),
                final=s.get("taper_final_deg", NAN), front=s.get("taper_front_final_deg", NAN),
                back=s.get("taper_back_final_deg", NAN), summary=s)


def mu_colour(mu, mus):
    if same(mu, 0.3):
        return "k"
    if same(mu, 0.2):
        return "0.55"
    others = [m for m in sorted(mus) if not (same(m, 0.3) or same(m, 0.2))]
    greys = ("0.3", "0.72", "0.15", "0.82", "0.42")
    return greys[others.index(mu) % len(greys)] if mu in others else "0.5"


def mu_b_style(mu_b, mu_bs):
    for k, v in MU_B_STYLES.items():
        if same(mu_b, k):
            return v, MU_B_MARKERS[k]
    others = [m for m in sorted(mu_bs) if not any(same(m, k) for k in MU_B_STYLES)]
    i = others.index(mu_b) if mu_b in others else 0
    return OTHER_STYLES[i % len(OTHER_STYLES)], OTHER_MARKERS[i % len(OTHER_MARKERS)]


def thesis_taper(packing, mu, mu_b):
    for (p, m, mb), v in THESIS_TAPER.items():
        if p == packing and same(m, mu) and same(mb, mu_b):
            return v
    return NAN


def chart_singly_taper(items, path, bulk=None):
    packings = sorted({it["packing"] for it in items}, key=packing_key) or ["?"]
    mus = sorted({it["mu"] for it in items if finite(it["mu"])})
    mu_bs = sorted({it["mu_b"] for it in items if finite(it["mu_b"])})
    n = len(packings)
    fig, axes = plt.subplots(n, 1, figsize=(11, 4.4 * n + 0.6), squeeze=False)
    s_max = max([float(np.nanmax(it["run"].series_columns["shortening"])) for it in items
                 if "shortening" in it["run"].series_columns and np.isfinite(it["run"].series_columns["shortening"]).any()] or [1.0])
    for p_i, packing in enumerate(packings):
        ax = axes[p_i][0]
        sel = [it for it in items if it["packing"] == packing]
        drawn = False
        for it in sorted(sel, key=lambda it: (it["mu"], it["mu_b"], it["name"])):
            s = it["run"].series_columns
            if "shortening" not in s or "taper" not in s:
                continue
            x, t = s["shortening"], s["taper"]
            if not np.isfinite(t).any():
                continue
            drawn = True
            c = mu_colour(it["mu"], mus)
            ls, marker = mu_b_style(it["mu_b"], mu_bs)
            ax.plot(x, t, "-", color=c, lw=0.6, alpha=0.3)
            smooth = running_mean(t)
            ax.plot(x, smooth, linestyle=ls, color=c, lw=1.6, marker=marker, ms=4,
                    markevery=max(1, len(x) // 12), mfc="white")
            last = np.nonzero(np.isfinite(smooth) & np.isfinite(x))[0]
            twins = sum(1 for o in sel if same(o["mu"], it["mu"]) and same(o["mu_b"], it["mu_b"]))
            if twins > 1 and last.size:  # runs drawn alike (seeds): named at their ends
                ax.text(x[last[-1]], smooth[last[-1]], " " + it["name"], fontsize=6, color="0.35", va="center")
        # Critical tapers (and the thesis's value) in a margin right of the curves.
        x0, x1 = 1.03 * s_max, 1.16 * s_max
        margin = False
        labels = []  # (y, text, colour), placed apart at the end
        for (mu, mu_b, prep) in sorted({(it["mu"], it["mu_b"], it["prep"]) for it in sel}):
            c = mu_colour(mu, mus)
            _, marker = mu_b_style(mu_b, mu_bs)
            if bulk is not None:
                for which, ls in (("peak", "--"), ("residual", (0, (1, 1.5)))):
                    v = bulk.taper(packing, mu, prep, mu_b, which)
                    if finite(v):
                        margin = True
                        ax.plot([x0, x1], [v, v], linestyle=ls, color=c, lw=1.8)
                        ax.plot([x1], [v], marker=marker, color=c, ms=5, mfc="white")
                        labels.append((v, "μ %g, μb %g%s, %s %.1f°" % (mu, mu_b, preparation_text(prep),
                                                                     "peak" if which == "peak" else "res.", v),
                                       c if c != "0.82" else "0.5"))
            v = thesis_taper(packing, mu, mu_b)
            if finite(v):
                margin = True
                ax.plot([0.5 * (x0 + x1)], [v], "*", color="tab:red", ms=11, mec="k", zorder=6)
        if labels:
            y_lo, y_hi = ax.get_ylim()
            gap = 0.045 * (y_hi - y_lo)
            labels.sort()
            placed = []
            for v, text, c in labels:
                y = max(v, placed[-1] + gap) if placed else v
                placed.append(y)
                ax.text(x1 + 0.015 * s_max, y, text, fontsize=6, va="center", color=c)
        if margin:
            ax.axvline(1.015 * s_max, color="0.6", lw=0.8)
            ax.text(0.5 * (x0 + x1), 1.0, "critical taper", transform=ax.get_xaxis_transform(), ha="center",
                    va="bottom", fontsize=7, color="0.3")
            ax.set_xlim(0, 1.42 * s_max)
        else:
            ax.set_xlim(0, 1.02 * s_max)
        ax.axhline(0.0, color="0.6", lw=0.6)
        ax.set(ylabel="taper [deg]", title="(%s) %s" % ("abcdefghij"[p_i % 10], packing_label(packing)))
        ax.grid(True, alpha=0.3)
        if not drawn:
            no_data(ax, "no taper (no wedge yet)")
    axes[-1][0].set_xlabel("shortening (backstop displacement / h0)")
    handles = [Line2D([], [], color=mu_colour(m, mus), lw=2, label="contact μ = %g" % m) for m in mus]
    handles += [Line2D([], [], color="0.4", linestyle=mu_b_style(mb, mu_bs)[0], marker=mu_b_style(mb, mu_bs)[1],
                       mfc="white", label="basal μb = %g" % mb) for mb in mu_bs]
    handles.append(Line2D([], [], color="0.4", lw=0.6, alpha=0.5, label="each output (faint); lines: running mean "
                          "of %d" % RUNNING_MEAN))
    if bulk is not None:
        handles += [Line2D([], [], color="0.4", ls="--", label="critical taper, peak bulk φ (biaxial)"),
                    Line2D([], [], color="0.4", ls=(0, (1, 1.5)), label="critical taper, residual bulk φ")]
    if any(finite(thesis_taper(it["packing"], it["mu"], it["mu_b"])) for it in items):
        handles.append(Line2D([], [], ls="", marker="*", color="tab:red", mec="k", ms=11,
                              label="thesis Appendix A"))
    axes[0][0].legend(handles=handles, fontsize=7, loc="upper left", ncol=2)
    fig.suptitle("Singly-vergent wedge: taper against shortening (cf. thesis Fig 3.23)", fontsize=11)
    fig.tight_layout()
    atomic.save_figure(fig, path)


def final_surface(it):
    """The run's final surface from snapshots.h5 as the experiment measures it: dict xb (x from
    the backstop [h0]), elevation (height - h0 [h0]), front (x from the backstop [h0]) and fit
    (the least-squares line of the columns from the front to d_max before the backstop, in
    world units), or None."""
    run = it["run"]
    h5 = run.file("snapshots.h5")
    if not h5 or folders.h5py is None:
        return None
    frame = folders.read_last_frame(h5)
    if frame is None:
        return None
    walls = frame["walls"]
    backstop = float(walls[2][0]) if len(walls) > 2 else NAN
    s = run.series_columns
    if not finite(backstop) and "backstop" in s and np.isfinite(s["backstop"]).any():
        backstop = float(s["backstop"][np.isfinite(s["backstop"])][-1]) * it["h0"]
    if not finite(backstop):
        backstop = float(np.max(frame["x"] + frame["radius"]))
    x, h = surface.surface_columns(frame["x"], frame["y"], frame["radius"], 0.0, backstop)
    front = NAN
    if "front" in s and len(s["front"]) and finite(float(s["front"][-1])):
        front = float(s["front"][-1]) * it["h0"]
    fit = None
    if finite(front):
        sel = np.isfinite(h) & (x >= front) & (x <= backstop - it["d_max"])
        fit = surface.fit_line(x[sel], h[sel])
    h0 = it["h0"]
    return dict(xb=(x - backstop) / h0, elevation=h / h0 - 1.0, front=(front - backstop) / h0 if finite(front) else NAN,
                fit=fit, backstop=backstop)


def chart_singly_profiles(items, path):
    surfaces = []
    for it in items:
        try:
            surfaces.append(final_surface(it))
        except Exception as e:
            folders.warn("%s: %s" % (it["run"].dir, e))
            surfaces.append(None)
    n = len(items)
    fig, ax = plt.subplots(figsize=(11, 1.2 + 1.1 * max(n, 1)))
    tops = [float(np.nanmax(s["elevation"])) for s in surfaces if s is not None and np.isfinite(s["elevation"]).any()]
    offset = max(1.2, 1.3 * max(tops)) if tops else 1.2
    fronts = [s["front"] for s in surfaces if s is not None and finite(s["front"])]
    x_lo = (min(fronts) - 3.0) if fronts else -8.0
    for i, (it, s) in enumerate(zip(items, surfaces)):
        base = (n - 1 - i) * offset  # the first run on top
        label = "%s: %s, μ %g, μb %g" % (it["name"], packing_label(it["packing"]), it["mu"], it["mu_b"])
        if s is None:
            ax.text(x_lo + 0.2, base + 0.2, label + " (no snapshots.h5)", fontsize=7, color="0.4")
            continue
        sel = s["xb"] >= x_lo
        c = mu_colour(it["mu"], [i_["mu"] for i_ in items])
        ax.fill_between(s["xb"][sel], base - 0.5 * offset + 0.3, s["elevation"][sel] + base, color="0.9", lw=0)
        ax.plot(s["xb"][sel], s["elevation"][sel] + base, "-", color=c if c != "0.82" else "0.5", lw=1.1)
        ax.axhline(base, color="0.7", lw=0.5, ls=":")
        if finite(s["front"]):
            ax.plot([s["front"]], [base], "|", color="tab:blue", ms=12, mew=2)
        fit = s["fit"]
        text = label
        if fit:
            xs = np.array([fit["x_lo"], fit["x_hi"]])
            ys = (fit["intercept"] + fit["slope"] * xs) / it["h0"] - 1.0 + base
            xs_b = (xs - s["backstop"]) / it["h0"]
            ax.plot(xs_b, ys, "--", color="tab:red", lw=1.3)
            text += " — taper %.1f°" % math.degrees(math.atan(fit["slope"]))
        ax.text(x_lo + 0.2, base + 0.15 * offset, text, fontsize=7, va="bottom")
    ax.axvline(0.0, color="k", lw=2)
    ax.set_xlim(x_lo, 0.5)
    ax.set_ylim(-0.6 * offset, (n - 1) * offset + max(tops + [0.5]) + 0.3)
    ax.set(xlabel="x from the backstop [h0]",
           ylabel="surface above the initial layer [h0], runs offset by %.2g h0" % offset,
           title="Singly-vergent wedges: final surface (columns of 2.3 mean radii); blue tick: deformation front; "
                 "red dashed: least-squares taper line", )
    ax.title.set_fontsize(9)
    if not items:
        no_data(ax)
    fig.tight_layout()
    atomic.save_figure(fig, path)


SINGLY_COLUMNS = ("run", "packing", "mu", "mu_b", "taper_steady_deg", "taper_steady_sd_deg", "taper_final_deg",
                  "taper_front_final_deg", "taper_back_final_deg", "phi_peak_deg", "phi_residual_deg",
                  "critical_taper_peak_deg", "critical_taper_residual_deg", "thesis_appendix_a_deg")


def singly_rows(items, bulk):
    """One dict per run, keyed by SINGLY_COLUMNS (the columns of singly_table.csv)."""
    rows = []
    for it in items:
        p, mu, mb = it["packing"], it["mu"], it["mu_b"]
        prep = it["prep"]
        b = (bulk.phi(p, mu, prep, "peak"), bulk.phi(p, mu, prep, "residual"), bulk.taper(p, mu, prep, mb, "peak"),
             bulk.taper(p, mu, prep, mb, "residual")) if bulk is not None else (NAN,) * 4
        values = [it["name"], p, mu, mb, it["steady"], it["steady_sd"], it["final"], it["front"], it["back"]] \
            + list(b) + [thesis_taper(p, mu, mb)]
        rows.append(dict(zip(SINGLY_COLUMNS, values)))
    return rows


def singly_markdown(rows, with_bulk):
    out = "# Singly-vergent wedge: tapers\n\nWritten by `python3 -m orogen.charts.granular singly`. Steady: mean ± sd " \
          "of the taper over the outputs after singly.steady_from of the run (summary.csv); final: the " \
          "taper at the end, and over the front and back (at the backstop) halves of the wedge. "
    if with_bulk:
        out += "Bulk φ: biaxial peak / residual friction angle of the same packing and contact μ; critical " \
               "taper: Dahlen's for that φ and basal μb on a flat base (– : none, the base is not weaker). "
    out += "Thesis: Appendix A's measured taper, where known.\n\n"
    header = ["run", "packing", "mu", "mu_b", "steady [deg]", "final [deg]", "front half [deg]", "back half [deg]"]
    if with_bulk:
        header += ["bulk φ peak / residual [deg]", "critical taper peak / residual [deg]"]
    header.append("thesis [deg]")
    md = []
    for r in rows:
        steady = r["taper_steady_deg"]
        line = [r["run"], packing_label(r["packing"]), "%g" % r["mu"], "%g" % r["mu_b"],
                ("%s ± %s" % (show(steady), show(r["taper_steady_sd_deg"]))) if finite(steady) else "–",
                show(r["taper_final_deg"]), show(r["taper_front_final_deg"]), show(r["taper_back_final_deg"])]
        if with_bulk:
            line += ["%s / %s" % (show(r["phi_peak_deg"], 1), show(r["phi_residual_deg"], 1)),
                     "%s / %s" % (show(r["critical_taper_peak_deg"]), show(r["critical_taper_residual_deg"]))]
        line.append(show(r["thesis_appendix_a_deg"]))
        md.append(line)
    return out + markdown_table(header, md, [False, False] + [True] * (len(header) - 2))


def make_singly(paths, out_dir, bulk_paths=None):
    runs = folders.collect_runs(paths, "singly_vergent")
    items = sorted((load_singly(r) for r in runs),
                   key=lambda it: (packing_key(it["packing"]), it["mu"], it["mu_b"], it["name"]))
    bulk = None
    if bulk_paths:
        bulk = Bulk([load_biaxial(r) for r in folders.collect_runs(bulk_paths, "biaxial")])
        missing = sorted({(it["packing"], it["mu"], it["prep"]) for it in items
                          if not bulk._group(it["packing"], it["mu"], it["prep"])})
        for p, mu, prep in missing:
            folders.warn("no biaxial run of %s, contact mu %g%s among --bulk: no critical taper for it"
                     % (p, mu, preparation_text(prep)))
    os.makedirs(out_dir, exist_ok=True)
    written = []
    with np.errstate(invalid="ignore", divide="ignore"):
        chart_singly_taper(items, os.path.join(out_dir, "singly_taper.png"), bulk)
        chart_singly_profiles(items, os.path.join(out_dir, "singly_profiles.png"))
    written += [os.path.join(out_dir, n) for n in ("singly_taper.png", "singly_profiles.png")]
    rows = singly_rows(items, bulk)
    atomic.write_text(os.path.join(out_dir, "singly_table.md"), singly_markdown(rows, bulk is not None))
    atomic.write_text(os.path.join(out_dir, "singly_table.csv"), csv_text(list(SINGLY_COLUMNS), [[r[c] for c in SINGLY_COLUMNS] for r in rows]))
    written += [os.path.join(out_dir, n) for n in ("singly_table.md", "singly_table.csv")]
    return dict(items=items, rows=rows, written=written)


# --------------------------------------------------------------------------------------------
# Driver


def main(argv=None):
    p = argparse.ArgumentParser(description="Charts of the granular material experiments (thesis chapter 3, "
                                            "Appendix A).")
    sub = p.add_subparsers(dest="command", required=True)
    for name, text in (("repose", "angle of repose runs"), ("singly", "singly-vergent wedge runs"),
                       ("biaxial", "biaxial test runs")):
        q = sub.add_parser(name, help=text)
        q.add_argument("runs", nargs="+", metavar="RUN_OR_SWEEP_DIR",
                       help="run folder, sweep folder (results.csv), results.csv, or folder of run folders")
        q.add_argument("--out", required=True, metavar="OUTDIR", help="folder for the charts and tables")
        if name == "singly":
            q.add_argument("--bulk", action="append", metavar="BIAXIAL_SWEEP_DIR_OR_RESULTS_CSV",
                           help="biaxial runs (sweep folder, results.csv or run folders) giving the bulk friction "
                                "and critical taper; may be repeated")
    args = p.parse_args(argv)
    try:
        if args.command == "repose":
            result = make_repose(args.runs, args.out)
            for it in result["items"]:
                print("%s: %s, mu %g, %s: angle %s deg" % (it["name"], it["packing"], it["mu"], it["variant"],
                                                          show(it["angle"])))
        elif args.command == "singly":
            result = make_singly(args.runs, args.out, args.bulk)
            for r in result["rows"]:
                print("%s: %s, mu %g, mu_b %g: steady taper %s deg, critical (peak/residual) %s/%s deg"
                      % (r["run"], r["packing"], r["mu"], r["mu_b"], show(r["taper_steady_deg"]),
                         show(r["critical_taper_peak_deg"]), show(r["critical_taper_residual_deg"])))
        else:
            result = make_biaxial(args.runs, args.out)
            for it in result["items"]:
                print("%s: %s, mu %g: phi peak %s, residual %s deg" % (it["name"], it["packing"], it["mu"],
                                                                     show(it["phi_peak"]), show(it["phi_residual"])))
    except folders.RunError as e:
        print("error: %s" % e, file=sys.stderr)
        return 2
    if not result["items"]:
        folders.warn("no finished runs: the charts say 'no data'")
    print("written to %s: %s" % (args.out, ", ".join(os.path.basename(w) for w in result["written"])))
    return 0


if __name__ == "__main__":
    sys.exit(main())
