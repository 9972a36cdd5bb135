#!/usr/bin/python3
"""Cross-sections of a wedge run (doubly- or singly-vergent) for a reader: every output's discs
as horizon bands, as active faults and as displacement vectors (thesis Figs 4.5, 5.3, 5.7,
5.11), drawn with matplotlib.

Usage:
    orogen sections RUN [RUN ...]             # the same as the line below
    python3 -m orogen.charts.sections RUN [RUN ...] [--kinds horizons,faults] [--every N] [--stills -1]
        [--formats png,pdf] [--exaggeration auto|E] [--strain-max X] [--width PX] [--fps F] [--jobs J]

Several runs (an ensemble's members, runs to compare side by side) are drawn with one view and
one scale of each kind, so that their frames line up. Writes into each RUN (each file atomically):

    frames/frame_NNNNNN.png          horizons of output NNNNNN; animation.mp4, animation.gif
    frames_faults/frame_NNNNNN.png   incremental shear strain; animation_frames_faults.mp4, .gif
    frames_vectors/frame_NNNNNN.png  (with --kinds ...,vectors) displacement over three outputs
    sections/KIND_NNNNNN.png, .pdf   the still outputs (--stills, default the last) of every kind,
                                     in every format of --formats (png, pdf, svg: vector output)
    sections/sections.json           what the figures share: the view, the vertical
                                     exaggeration, the band thickness, the strain scale

What a reader sees:
- **Horizons**: bands of initial depth h0/5 thick (--band), alternating dark and light; the
  middle band of the layer is a red marker bed. Material that started on the pro side
  (x0 < 0) is blue, retro-side material brown, both at full contrast. A run of two or more named
  materials (docs/materials.md) colours each material its own hue instead, in the same bands,
  with the materials' names as the key.
- **Faults**: the incremental maximum shear strain of each disc since the previous output
  (below), from white through orange to black on one scale for the whole run (the 99.5th
  percentile of every output's strain, or --strain-max to share one scale across runs).
  Where `python3 -m orogen.analysis.faults RUN` has written RUN/faults.csv, the faults it
  picked are drawn on each frame: forethrusts cyan, backthrusts green, dashed when inactive.
- **Vectors**: each disc's displacement over the last three outputs (the snapshots' disp3_x,
  disp3_y) relative to the S-point, one arrow per cell of h0/4, darker where it moved further,
  on a scale fixed over the run (thesis Fig 5.11).
- Every frame of a run shares one view: x from the S-point and y in h0, cropped to the wedge
  (every disc standing higher than a quarter h0 above the undeformed layer, with 3 h0 to
  spare on each side) from the base to above the highest disc; the vertical exaggeration is
  chosen so that the section is at least a fifth as tall as it is wide, and stated on the y
  axis. The S-point is a black triangle on the base.

Strain: for disc i with neighbours j (centres within 0.2 h0, at least 1.5 d, of it at the previous
output),
F = (sum dx_ij dX_ij^T)(sum dX_ij dX_ij^T)^-1 over the displacements' change between two
outputs (the least-squares deformation gradient, as OVITO's atomic strain), E = (F^T F - I)/2,
and the maximum shear strain is sqrt(((E_xx - E_yy)/2)^2 + E_xy^2), the radius of Mohr's circle.
It is NaN where a disc is new or has fewer than two neighbours.
"""

import argparse
import json
import math
import multiprocessing
import os
import sys

import numpy as np
import matplotlib

matplotlib.use("Agg")
matplotlib.rcParams["svg.hashsalt"] = "orogen.charts.sections"  # the same ids in every SVG
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.collections import EllipseCollection, LineCollection  # noqa: E402
from matplotlib.colors import ListedColormap, Normalize  # noqa: E402

from ..atomic import save_figure, write_text  # noqa: E402
from ..frames import Snapshots  # noqa: E402
from ..tables import read_rows  # noqa: E402
from ..analysis.strain import shear_strain  # noqa: E402,F401  (sections.shear_strain: the tests' name)
from .animation import animate  # noqa: E402

KINDS = ("horizons", "faults", "vectors")
FRAME_FOLDERS = {"horizons": "frames", "faults": "frames_faults", "vectors": "frames_vectors"}
ANIMATION_STEMS = {"horizons": "animation", "faults": "animation_frames_faults",
                   "vectors": "animation_frames_vectors"}
FORMATS = ("png", "pdf", "svg")

# Horizon colours: (light, dark) per side, and the marker bed shared by both sides.
PRO_COLOURS = ("#c9dcef", "#24548a")
RETRO_COLOURS = ("#f1dfb6", "#8a5526")
MARKER_COLOUR = "#c8102e"
# A run of named materials (docs/materials.md): (light, dark) per material, in material order.
MATERIAL_COLOURS = (("#f3e3a1", "#b8952b"), ("#c9dcef", "#24548a"), ("#d5e8c4", "#4d7a2a"),
                    ("#e7d1ea", "#7b3f86"), ("#f6cfb5", "#a9552a"), ("#d9d9d9", "#555555"))
MISSING_COLOUR = "#9a9a9a"
BANDS_PER_LAYER = 5          # default band thickness h0 / 5
MARKER_BAND = 2              # the middle of the five bands of the layer
STRAIN_PERCENTILE = 99.5
CROP_RISE = 0.25             # h0 above the layer's surface: a disc higher than this is wedge
CROP_MARGIN = 3.0            # h0 beyond the wedge on each side
MIN_HEIGHT_FRACTION = 0.2    # the section's height at least this fraction of its width
VECTOR_CELL = 0.25           # h0: one arrow per square cell of this size
DPI = 100
# The figures carry no date, so the same run draws the same bytes.
METADATA = {"png": {"Software": None}, "pdf": {"CreationDate": None, "Producer": None},
            "svg": {"Date": None}}
FAULT_CMAP = "inferno_r"
VECTOR_CMAP = "Greys"


class SectionError(Exception):
    """Bad input: the message names the run, option or value; exit code 2."""


# --------------------------------------------------------------------------------------------
# Reading


def read_outputs(run):
    """Every complete output of RUN/snapshots.h5 as a dict of arrays in h0 (x from the S-point),
    with 'h0', 'S', 'output' and the walls; raises SectionError for a folder without a wedge."""
    path = os.path.join(run, "snapshots.h5")
    if not os.path.isfile(path):
        raise SectionError("%s not found: %s holds no run (orogen run --out DIR)" % (path, run))
    try:
        return _read_outputs(path, run)
    except (OSError, KeyError, ValueError) as e:  # h5py's word for a damaged or foreign file
        raise SectionError("%s is not a readable orogen snapshot file: %s" % (path, e)) from e


def _read_outputs(path, run):
    fields = ("x", "y", "radius", "id", "depth0", "x0", "disp3_x", "disp3_y", "material")
    outputs = []
    with Snapshots(path) as snaps:
        h0 = float(snaps.attrs.get("h0", 0.0))
        experiment = snaps.attrs.get("experiment", "")
        if experiment not in ("wedge", "singly_vergent"):
            raise SectionError("%s: a run of experiment '%s'; sections draw doubly- and singly-vergent wedge "
                               "runs (orogen render draws any run)" % (run, experiment))
        if not h0 > 0:
            raise SectionError("%s: no layer thickness h0 in snapshots.h5" % path)
        if len(snaps) == 0:
            raise SectionError("%s: no complete output yet" % path)
        for k in range(len(snaps)):
            f = snaps.frame(k, fields)
            o = {name: f[name] / h0 for name in ("x", "y", "radius", "x0") if name in f}
            o["depth0"] = f["depth0"] / h0
            o["id"] = f["id"]
            for name in ("disp3_x", "disp3_y"):
                o[name] = f[name] / h0 if name in f else np.full(len(f["x"]), np.nan)
            if "material" in f:  # a run of named materials: their names, in index order
                o["material"] = f["material"].astype(np.int64)
                o["materials"] = [n for n in str(snaps.attrs.get("materials_names", "")).split("\n") if n]
            o["walls"] = f["walls"] / h0
            o["S"] = float(f["attrs"].get("S", np.nan))
            o["output"] = f["output"]
            o["h0"] = h0
            o["singly"] = experiment == "singly_vergent"  # x from the far wall, no S-point
            outputs.append(o)
    return outputs


# --------------------------------------------------------------------------------------------
# What every frame shares: the view, the exaggeration, the colour scales


def run_view(outputs, exaggeration="auto"):
    """The view box (in h0) that every frame of the run shares, and the vertical exaggeration."""
    x_all = np.concatenate([o["x"] for o in outputs])
    r_all = np.concatenate([o["radius"] for o in outputs])
    y_all = np.concatenate([o["y"] for o in outputs])
    wedge = y_all - r_all > 1.0 + CROP_RISE
    if wedge.any():
        lo = x_all[wedge].min() - CROP_MARGIN
        hi = x_all[wedge].max() + CROP_MARGIN
    else:  # no wedge yet: the S-point's surroundings
        lo, hi = -2 * CROP_MARGIN, 2 * CROP_MARGIN
    lo = max(lo, float((x_all - r_all).min()))
    hi = min(hi, float((x_all + r_all).max()))
    in_x = (x_all >= lo) & (x_all <= hi)
    top = float((y_all + r_all)[in_x].max()) if in_x.any() else 1.0
    view = {"x_min": lo, "x_max": hi, "y_min": min(0.0, float((y_all - r_all).min())),
            "y_max": top + 0.15 * max(top, 1.0)}
    width, height = view["x_max"] - view["x_min"], view["y_max"] - view["y_min"]
    if exaggeration == "auto":
        exaggeration = max(1, math.ceil(MIN_HEIGHT_FRACTION * width / height - 1e-9))
    view["exaggeration"] = float(exaggeration)
    return view


def round_up(v):
    """v rounded up to 1, 2 or 5 times a power of ten (a colour bar's end)."""
    if not v > 0:
        return 1.0
    p = 10.0 ** math.floor(math.log10(v))
    return next(m * p for m in (1, 2, 5, 10) if m * p >= v * (1 - 1e-12))


# --------------------------------------------------------------------------------------------
# Horizons


def horizon_colours(depth0, x0, band=1.0 / BANDS_PER_LAYER):
    """RGBA per disc: bands of initial depth `band` thick (h0) alternating light and dark, blue
    for pro-side material (x0 < 0), brown for retro; the band MARKER_BAND red."""
    rgba = np.empty((len(depth0), 4))
    index = np.floor(np.where(np.isfinite(depth0), depth0, 0) / band).astype(np.int64)
    dark = index % 2 == 1
    pro = x0 < 0
    for side, colours in ((pro, PRO_COLOURS), (~pro, RETRO_COLOURS)):
        for shade, colour in enumerate(colours):
            rgba[side & (dark == bool(shade))] = matplotlib.colors.to_rgba(colour)
    rgba[index % BANDS_PER_LAYER == MARKER_BAND] = matplotlib.colors.to_rgba(MARKER_COLOUR)
    rgba[~np.isfinite(depth0)] = matplotlib.colors.to_rgba(MISSING_COLOUR)
    return rgba


def material_colours(depth0, material, band=1.0 / BANDS_PER_LAYER):
    """RGBA per disc of a run of named materials: each material its hue (MATERIAL_COLOURS, in
    material order), in bands of initial depth `band` thick alternating light and dark; the
    band MARKER_BAND red, as in horizon_colours."""
    rgba = np.empty((len(depth0), 4))
    index = np.floor(np.where(np.isfinite(depth0), depth0, 0) / band).astype(np.int64)
    dark = index % 2 == 1
    for m in np.unique(material):
        colours = MATERIAL_COLOURS[int(m) % len(MATERIAL_COLOURS)]
        for shade, colour in enumerate(colours):
            rgba[(material == m) & (dark == bool(shade))] = matplotlib.colors.to_rgba(colour)
    rgba[index % BANDS_PER_LAYER == MARKER_BAND] = matplotlib.colors.to_rgba(MARKER_COLOUR)
    rgba[~np.isfinite(depth0)] = matplotlib.colors.to_rgba(MISSING_COLOUR)
    return rgba


def material_legend(cax, names):
    """The materials' key in the colour bar's place: one cell per material, light and dark, and
    the red marker bed below them (it crosses every material)."""
    rows = len(names) + 1
    cells = np.zeros((rows, 2, 4))
    for k in range(len(names)):
        for c in range(2):
            cells[k, c] = matplotlib.colors.to_rgba(MATERIAL_COLOURS[k % len(MATERIAL_COLOURS)][c])
    cells[-1, :] = matplotlib.colors.to_rgba(MARKER_COLOUR)
    cax.imshow(cells, aspect="auto", extent=(0, 2, rows, 0), interpolation="nearest")
    cax.set_xticks([])
    cax.set_yticks([k + 0.5 for k in range(rows)], list(names) + ["marker bed"], fontsize=8)
    cax.yaxis.tick_right()
    cax.yaxis.set_label_position("right")
    cax.set_ylabel("material")


# --------------------------------------------------------------------------------------------
# Faults: incremental shear strain


def attach_fault_picks(run, outputs):
    """The faults that orogen.analysis.faults picked (RUN/faults.csv, when there is one) onto
    the outputs they belong to, as o["faults"]: ((x_top, y_top), (x_bottom, y_bottom), kind,
    active) in h0."""
    path = os.path.join(run, "faults.csv")
    if not os.path.isfile(path):
        return
    rows, _ = read_rows(path)
    by_output = {}
    for r in rows:
        try:
            seg = ((float(r["x_top"]), float(r["y_top"])), (float(r["x_bottom"]), float(r["y_bottom"])))
            by_output.setdefault(int(r["output"]), []).append((*seg, r["kind"], r["active"] == "1"))
        except (KeyError, ValueError):
            continue  # a row cut by a kill: the file is rewritten whole by the next analysis
    for o in outputs:
        o["faults"] = by_output.get(o["output"], [])


def draw_fault_picks(ax, o):
    """The picked faults on a fault frame: forethrusts cyan, backthrusts green, dashed when
    inactive."""
    for top, bottom, kind, active in o.get("faults", []):
        ax.plot([top[0], bottom[0]], [top[1], bottom[1]], color="#00b8d4" if kind == "forethrust" else "#2e9e3e",
                lw=2.2, ls="-" if active else "--", solid_capstyle="round")


def run_strains(outputs):
    """The incremental shear strain of every output (the first: NaN, nothing before it)."""
    strains = [np.full(len(outputs[0]["x"]), np.nan)]
    for before, after in zip(outputs, outputs[1:]):
        strains.append(shear_strain(before, after))
    return strains


def fixed_scale(values, percentile):
    """One colour scale's top for the whole run: the percentile of every finite value, rounded up."""
    finite = np.concatenate([v[np.isfinite(v)] for v in values]) if values else np.zeros(0)
    return round_up(float(np.percentile(finite, percentile))) if finite.size else 1.0


# --------------------------------------------------------------------------------------------
# Drawing


def figure_for(view, width_px):
    """A figure and its axes sized so that x and y are to scale times the exaggeration."""
    margin_l, margin_r, margin_t, margin_b = 0.9, 1.85, 0.6, 0.6  # inches: labels, colour bar and its labels (a material's name)
    width_in = width_px / DPI
    plot_w = width_in - margin_l - margin_r
    span_x = view["x_max"] - view["x_min"]
    span_y = (view["y_max"] - view["y_min"]) * view["exaggeration"]
    plot_h = plot_w * span_y / span_x
    height_in = plot_h + margin_t + margin_b
    fig = plt.figure(figsize=(width_in, height_in), dpi=DPI)
    ax = fig.add_axes([margin_l / width_in, margin_b / height_in, plot_w / width_in, plot_h / height_in])
    ax.set_xlim(view["x_min"], view["x_max"])
    ax.set_ylim(view["y_min"], view["y_max"])
    ax.set_aspect(view["exaggeration"], adjustable="box")
    cax = fig.add_axes([(margin_l + plot_w + 0.2) / width_in, margin_b / height_in, 0.35 / width_in,
                        plot_h / height_in])
    return fig, ax, cax


def draw_discs(ax, o, colours):
    """The discs at their true size (ellipses where the section is exaggerated)."""
    d = 2 * o["radius"]
    ax.add_collection(EllipseCollection(d, d, np.zeros_like(d), units="xy", offsets=np.column_stack([o["x"], o["y"]]),
                                        offset_transform=ax.transData, facecolors=colours, edgecolors="none"))


def draw_frame_furniture(ax, o, view, title):
    """Walls, the S-point, the axes' labels and the title."""
    walls = o["walls"]
    if len(walls):
        ax.add_collection(LineCollection(walls.reshape(-1, 2, 2), colors="black", linewidths=1.5))
    if o.get("singly"):  # a singly-vergent wedge: its far wall at x = 0, the backstop on the right
        ax.set_xlabel("x from the far wall [h0]")
    else:
        # The S-point: a triangle over the section pointing down at x = 0, clear of discs and ticks.
        ax.plot([0.0], [view["y_max"]], marker="v", color="black", markersize=9, clip_on=False, zorder=5)
        ax.annotate("S", (0.0, view["y_max"]), xytext=(7, 2), textcoords="offset points", ha="left", va="bottom",
                    fontsize=10, fontweight="bold", annotation_clip=False)
        ax.axvline(0.0, color="black", linewidth=0.6, linestyle=(0, (4, 4)), alpha=0.5, zorder=4)
        ax.set_xlabel("x from the S-point [h0]")
    ve = view["exaggeration"]
    ax.set_ylabel("height [h0]" + ("" if ve == 1 else "  (vertical exaggeration %g\u00d7)" % ve))
    ax.set_title(title, loc="left", fontsize=11, pad=14)
    ax.tick_params(direction="out")


def legend_bar(cax, band):
    """The horizons' key in the colour bar's place: the bands of one layer, pro and retro."""
    n = BANDS_PER_LAYER
    cells = np.zeros((n, 2, 4))
    for k in range(n):
        for c, colours in enumerate((PRO_COLOURS, RETRO_COLOURS)):
            colour = MARKER_COLOUR if k == MARKER_BAND else colours[k % 2]
            cells[k, c] = matplotlib.colors.to_rgba(colour)
    cax.imshow(cells, aspect="auto", extent=(0, 2, n * band, 0), interpolation="nearest")
    cax.set_xticks([0.5, 1.5], ["pro", "retro"], fontsize=7, rotation=90)
    cax.yaxis.tick_right()
    cax.yaxis.set_label_position("right")
    cax.set_ylabel("initial depth [h0]")


def in_view(o, view, value=None):
    """Output o (and value) cut to the discs that reach into the view: the PDF and SVG stills
    hold only what is seen, and frames draw faster."""
    margin = 2 * float(o["radius"].max()) if len(o["radius"]) else 0.0
    keep = (o["x"] >= view["x_min"] - margin) & (o["x"] <= view["x_max"] + margin)
    cut = {k: (v[keep] if k != "walls" and isinstance(v, np.ndarray) else v) for k, v in o.items()}
    return cut, (value[keep] if value is not None else None)


def draw(kind, o, view, scale, value, band, width_px):
    """One frame of `kind` for output o as a figure (the caller saves it)."""
    o, value = in_view(o, view, value)
    fig, ax, cax = figure_for(view, width_px)
    title = ("shortening %.2f h0   output %d" if o.get("singly") else "S = %.2f   output %d") % (o["S"], o["output"])
    if kind == "horizons" and "material" in o and len(o["materials"]) > 1:
        draw_discs(ax, o, material_colours(o["depth0"], o["material"], band))
        names = o["materials"] or ["material %d" % m for m in range(int(o["material"].max(initial=0)) + 1)]
        material_legend(cax, names)
        title += "   materials, in horizon bands of %.2g h0 initial depth" % band
    elif kind == "horizons":
        draw_discs(ax, o, horizon_colours(o["depth0"], o["x0"], band))
        legend_bar(cax, band)
        title += ("   horizons: initial depth, bands of %.2g h0" % band +
                  ("" if o.get("singly") else "; blue pro-side, brown retro-side material"))
    elif kind == "faults":
        norm = Normalize(0.0, scale)
        cmap = matplotlib.colormaps[FAULT_CMAP].copy()
        cmap.set_bad(MISSING_COLOUR)
        colours = cmap(norm(np.ma.masked_invalid(value)))
        draw_discs(ax, o, colours)
        fig.colorbar(matplotlib.cm.ScalarMappable(norm, cmap), cax=cax, extend="max",
                     label="shear strain since the previous output")
        title += "   faults: incremental maximum shear strain (scale fixed over the run)"
        if o.get("faults"):
            draw_fault_picks(ax, o)
            title += "; picked: forethrusts cyan, backthrusts green"
        if not np.isfinite(value).any():
            title += "; the first output: no strain yet"
    else:
        draw_discs(ax, o, np.tile(matplotlib.colors.to_rgba("#dcdcdc"), (len(o["x"]), 1)))
        u, v = o["disp3_x"], o["disp3_y"]
        keep = arrow_discs(o, view)
        norm = Normalize(0.0, scale)
        cmap = ListedColormap(matplotlib.colormaps[VECTOR_CMAP](np.linspace(0.45, 1.0, 256)))
        ax.quiver(o["x"][keep], o["y"][keep], u[keep], v[keep], np.hypot(u[keep], v[keep]), cmap=cmap, norm=norm,
                  angles="xy", scale_units="xy", scale=1.0, width=0.0016, headwidth=3.5, headlength=4)
        fig.colorbar(matplotlib.cm.ScalarMappable(norm, cmap), cax=cax, extend="max",
                     label="displacement over three outputs [h0]")
        title += "   displacement over the last three outputs, true length"
    draw_frame_furniture(ax, o, view, title)
    return fig


def arrow_discs(o, view):
    """One disc per square cell of VECTOR_CELL h0 inside the view (the first of each cell), with
    a finite displacement."""
    ok = np.isfinite(o["disp3_x"]) & np.isfinite(o["disp3_y"])
    ok &= (o["x"] >= view["x_min"]) & (o["x"] <= view["x_max"])
    idx = np.flatnonzero(ok)
    cell = np.floor(o["x"][idx] / VECTOR_CELL).astype(np.int64) * 1_000_003 + \
        np.floor(o["y"][idx] / VECTOR_CELL).astype(np.int64)
    _, first = np.unique(cell, return_index=True)
    return idx[np.sort(first)]


# --------------------------------------------------------------------------------------------
# The run's frames and stills

_shared = {}  # what the worker processes read (set before forking)


def _draw_job(job):
    run, kind, k, path, fmt = job
    s = _shared
    value = s["strains"][run][k] if kind == "faults" else None
    scale = s["scales"].get(kind)
    save_figure(draw(kind, s["outputs"][run][k], s["view"], scale, value, s["band"], s["width"]), path, fmt, DPI,
                METADATA[fmt])
    return path


def draw_all(jobs, processes):
    """Draws each (run, kind, output index, path, format); in `processes` forked workers when > 1."""
    if processes > 1 and len(jobs) > 1:
        with multiprocessing.get_context("fork").Pool(processes) as pool:
            return list(pool.imap(_draw_job, jobs, chunksize=4))
    return [_draw_job(j) for j in jobs]


def run_jobs(run, outputs, kinds, every, stills, formats):
    """The drawing jobs of one run: its frames, then its stills in every format."""
    n = len(outputs)
    still_index = sorted({s % n for s in stills if -n <= s < n})
    jobs = []
    os.makedirs(os.path.join(run, "sections"), exist_ok=True)
    for kind in kinds:
        folder = os.path.join(run, FRAME_FOLDERS[kind])
        os.makedirs(folder, exist_ok=True)
        jobs += [(run, kind, k, os.path.join(folder, "frame_%06d.png" % outputs[k]["output"]), "png")
                 for k in range(0, n, every)]
        for k in still_index:
            for fmt in formats:
                name = "%s_%06d.%s" % (kind, outputs[k]["output"], fmt)
                jobs.append((run, kind, k, os.path.join(run, "sections", name), fmt))
    return jobs, [outputs[k]["output"] for k in still_index]


def make_sections(runs, kinds=("horizons", "faults"), every=1, stills=(-1,), formats=("png", "pdf"),
                  exaggeration="auto", strain_max=None, band=1.0 / BANDS_PER_LAYER, width_px=1600, fps=12,
                  jobs=None, animations=True):
    """Draws the frames, animations and stills of each run (module docstring); several runs (an
    ensemble, runs to compare) share one view and one scale of each kind, so that their frames
    line up. Returns the summary written to each RUN/sections/sections.json."""
    runs = [runs] if isinstance(runs, str) else list(runs)
    outputs = {run: read_outputs(run) for run in runs}
    for run in runs:
        attach_fault_picks(run, outputs[run])
    every_output = [o for run in runs for o in outputs[run]]
    view = run_view(every_output, exaggeration)
    strains = {run: run_strains(outputs[run]) for run in runs} if "faults" in kinds else {}
    scales = {}
    if "faults" in kinds:
        scales["faults"] = strain_max or fixed_scale([v for run in runs for v in strains[run][1:]], STRAIN_PERCENTILE)
    if "vectors" in kinds:
        scales["vectors"] = fixed_scale([np.hypot(o["disp3_x"], o["disp3_y"]) for o in every_output],
                                        STRAIN_PERCENTILE)
    _shared.update(outputs=outputs, view=view, strains=strains, scales=scales, band=band, width=width_px)
    jobs_list, still_outputs = [], {}
    for run in runs:
        run_list, still_outputs[run] = run_jobs(run, outputs[run], kinds, every, stills, formats)
        jobs_list += run_list
    draw_all(jobs_list, jobs if jobs else min(2, os.cpu_count() or 1))
    summary = {
        "generated_by": "orogen.charts.sections",
        "runs_sharing_view_and_scales": [os.path.abspath(r) for r in runs],
        "view_h0": {k: view[k] for k in ("x_min", "x_max", "y_min", "y_max")},
        "vertical_exaggeration": view["exaggeration"],
        "band_thickness_h0": band,
        "bands_per_layer_marker": MARKER_BAND,
        "scales": {"faults_shear_strain_max": scales.get("faults"),
                   "vectors_displacement_max_h0": scales.get("vectors")},
        "frames": {kind: FRAME_FOLDERS[kind] for kind in kinds},
    }
    for run in runs:
        made = {kind: animate(run, FRAME_FOLDERS[kind], fps, stem=ANIMATION_STEMS[kind]) for kind in kinds} \
            if animations else {}
        mine = dict(summary, outputs_drawn=len(range(0, len(outputs[run]), every)), stills=still_outputs[run],
                    animations=made)
        write_text(os.path.join(run, "sections", "sections.json"), json.dumps(mine, indent=1) + "\n")
    return dict(summary, outputs_drawn=sum(len(range(0, len(outputs[r]), every)) for r in runs))


def parse_list(text, allowed, option):
    items = [s.strip() for s in text.split(",") if s.strip()]
    bad = [s for s in items if s not in allowed]
    if bad or not items:
        raise SectionError("%s '%s': allowed are %s (comma-separated)" % (option, text, ", ".join(allowed)))
    return tuple(items)


def main(argv=None):
    p = argparse.ArgumentParser(prog="python3 -m orogen.charts.sections", description=__doc__.split("\n")[0])
    p.add_argument("runs", nargs="+", metavar="RUN",
                   help="wedge run folders (orogen run --out RUN); several share one view and scales")
    p.add_argument("--kinds", default="horizons,faults", help="of horizons, faults, vectors (default horizons,faults)")
    p.add_argument("--every", type=int, default=1, help="draw every n-th output as a frame")
    p.add_argument("--stills", default="-1", help="outputs drawn in every format, as Python indices (default -1: the last)")
    p.add_argument("--formats", default="png,pdf", help="formats of the stills, of png, pdf, svg (default png,pdf)")
    p.add_argument("--exaggeration", default="auto", help="vertical exaggeration: auto or a number from 1 to 20")
    p.add_argument("--strain-max", type=float, default=None, help="top of the fault scale (default: the run's 99.5th percentile)")
    p.add_argument("--band", type=float, default=1.0 / BANDS_PER_LAYER, help="horizon band thickness [h0] (default 0.2)")
    p.add_argument("--width", type=int, default=1600, help="frame width in pixels (400 to 8000)")
    p.add_argument("--fps", type=int, default=12, help="animation frames per second (1 to 240)")
    p.add_argument("--jobs", type=int, default=None, help="drawing processes (default: up to 2)")
    p.add_argument("--no-animation", action="store_true", help="frames only")
    a = p.parse_args(argv)
    try:
        kinds = parse_list(a.kinds, KINDS, "--kinds")
        formats = parse_list(a.formats, FORMATS, "--formats")
        try:
            stills = tuple(int(s) for s in a.stills.split(",") if s.strip())
        except ValueError:
            raise SectionError("--stills '%s': output indices, comma-separated (-1 the last)" % a.stills)
        if a.exaggeration != "auto":
            try:
                ve = float(a.exaggeration)
            except ValueError:
                ve = float("nan")
            if not 1 <= ve <= 20:
                raise SectionError("--exaggeration '%s': auto or a number from 1 to 20" % a.exaggeration)
            a.exaggeration = ve
        checks = (("--every", a.every, a.every >= 1, "a whole number, at least 1"),
                  ("--width", a.width, 400 <= a.width <= 8000, "400 to 8000 pixels"),
                  ("--fps", a.fps, 1 <= a.fps <= 240, "1 to 240"),
                  ("--band", a.band, 0.01 <= a.band <= 1.0, "0.01 to 1 h0"),
                  ("--strain-max", a.strain_max, a.strain_max is None or a.strain_max > 0, "above 0"),
                  ("--jobs", a.jobs, a.jobs is None or 1 <= a.jobs <= 64, "1 to 64"))
        for option, value, ok, allowed in checks:
            if not ok:
                raise SectionError("%s %s: must be %s" % (option, value, allowed))
        for run in a.runs:
            if not os.path.isdir(run):
                raise SectionError("%s: no such folder; sections take the folder of a wedge run" % run)
        summary = make_sections(a.runs, kinds, a.every, stills, formats, a.exaggeration, a.strain_max, a.band,
                                a.width, a.fps, a.jobs, not a.no_animation)
    except SectionError as e:
        print("error: %s" % e, file=sys.stderr)
        return 2
    except OSError as e:  # a frame, still or animation that cannot be written
        print("error: %s" % e, file=sys.stderr)
        return 1
    print("sections of %d outputs in %s: %s (vertical exaggeration %g, fault scale %s)" %
          (summary["outputs_drawn"], ", ".join(a.runs), ", ".join(summary["frames"].values()),
           summary["vertical_exaggeration"], summary["scales"]["faults_shear_strain_max"]))
    return 0


if __name__ == "__main__":
    sys.exit(main())
