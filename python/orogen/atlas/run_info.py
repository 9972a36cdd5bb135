"""What the atlas shows of one run folder, read from its files (no HDF5 needed)."""
import datetime
import os
import re

from . import config_table, csv_series, figures, presets as preset_match

_TIMESTAMP = re.compile(r"^\[(\d{4})-(\d\d)-(\d\d) (\d\d):(\d\d):(\d\d)\]")
_FRAME = re.compile(r"^frame_(\d+)\.png$")

# Index columns: (label, config key) shown for the experiments that have the key.
PARAMS = [("seed", "run.seed"), ("h0 [d]", "layer.thickness"), ("mu", "contact.mu"), ("mu_bp", "wedge.mu_bp"),
          ("mu_br", "wedge.mu_br"), ("erosion [h0]", "wedge.erosion_height"), ("S end", "wedge.s_end")]
# Headline results: (label, summary.csv column, unit).
RESULTS = [("S", "S_final", ""), ("H [h0]", "H_final", "h0"), ("b", "H_b", ""),
           ("alpha [deg]", "alpha_late_deg", "deg"), ("beta [deg]", "beta_late_deg", "deg"),
           ("repose [deg]", "angle_deg", "deg")]
RAW = ["config.toml", "series.csv", "summary.csv", "run.log", "removals.csv", "analysis_flux.csv",
       "analysis_columns.csv", "analysis_removals.csv", "analysis.h5", "snapshots.h5", "snapshots.xmf", "run.pvd",
       "packing.h5", "sweep.failed"]


_PIECE_START = re.compile(r"^\[[^]]*\] orogen \S+ (run|resume) in ")


def _wall_seconds(lines):
    """Seconds the run ran: the first to the last timestamp of each piece of run.log (a run and
    each of its resumes), summed, so that a resumed run counts every piece and not the pause
    between them. None without two timestamps."""
    total, piece, seen = 0.0, None, 0
    for line in lines:
        m = _TIMESTAMP.match(line)
        if not m:
            continue
        t = datetime.datetime(*map(int, m.groups()))
        seen += 1
        if piece is None or _PIECE_START.match(line):
            if piece is not None:
                total += (piece[1] - piece[0]).total_seconds()
            piece = [t, t]
        piece[1] = t
    if seen < 2:
        return None
    return total + (piece[1] - piece[0]).total_seconds()


def _status_and_wall(run_dir, names):
    """('finished' | 'stopped' | 'failed' | 'unstable' | 'incomplete', wall seconds or None)."""
    status = "failed" if "sweep.failed" in names else "incomplete"
    try:
        with open(os.path.join(run_dir, "run.log"), encoding="utf-8", errors="replace") as f:
            lines = f.read().splitlines()
    except OSError:
        return status, None
    wall = _wall_seconds(lines)
    last = lines[-1] if lines else ""
    if re.search(r"finished at step .* in ([0-9.]+) s", last):
        return "finished", wall
    if "stopped by" in last:
        return "stopped", wall
    if "unstable" in last.lower():
        return "unstable", wall
    if "stopped:" in last or "error" in last.lower():
        return "failed", wall
    return status, wall


def _frames(run_dir, names):
    """{frames folder: [output index, ...]} of every rendered frames folder."""
    out = {}
    order = list(figures.ANIMATIONS)  # horizons, faults, then the exhumation's, then any other
    for d in sorted((n for n in names if n.startswith("frames")),
                    key=lambda n: (order.index(n) if n in order else len(order), n)):
        path = os.path.join(run_dir, d)
        if not os.path.isdir(path):
            continue
        idx = sorted(int(m.group(1)) for m in map(_FRAME.match, os.listdir(path)) if m)
        if idx:
            out[d] = idx
    return out


def _animations(names, frames):
    """[(frames folder, gif or '', mp4 or '')]: 'frames' -> animation.*, 'frames_X' -> animation_frames_X.*."""
    out = []
    for d in frames:
        stem = "animation" if d == "frames" else "animation_" + d
        out.append((d, stem + ".gif" if stem + ".gif" in names else "", stem + ".mp4" if stem + ".mp4" in names else ""))
    return out


def _charts(run_dir):
    """[(path relative to the run, title, thesis figures)] of charts/*.png and charts/*/*.png."""
    out = []
    base = os.path.join(run_dir, "charts")
    if not os.path.isdir(base):
        return out
    for here, dirs, files in os.walk(base):
        dirs.sort()
        for f in sorted(files):
            if f.endswith(".png") and not f.startswith("."):
                title, fig = figures.chart(f)
                out.append((os.path.relpath(os.path.join(here, f), run_dir), title, fig))
    return out


def read(run_dir, rel, group, presets):
    names = set(os.listdir(run_dir))
    with open(os.path.join(run_dir, "config.toml"), encoding="utf-8", errors="replace") as f:
        config_text = f.read()
    config = config_table.flat(config_text)
    experiment = str(config.get("run.experiment", "?"))
    summary = csv_series.first_row(os.path.join(run_dir, "summary.csv"))
    status, wall = _status_and_wall(run_dir, names)
    if status == "incomplete" and summary:
        status = "finished"
    frames = _frames(run_dir, names)
    params = {label: config[key] for label, key in PARAMS
              if key in config and (key.split(".")[0] in ("run", "layer", "contact") or experiment == "wedge")}
    results = {label: summary[col] for label, col, _ in RESULTS if isinstance(summary.get(col), float)}
    return {
        "rel": rel, "group": group, "name": os.path.basename(rel), "experiment": experiment,
        "preset": preset_match.match(presets, config), "branch": config_table.branch_of(config_text),
        "params": params, "results": results, "status": status, "wall_s": wall,
        "config_rows": config_table.rows(config_text), "frames": frames,
        "animations": _animations(names, frames), "charts": _charts(run_dir),
        "raw": [n for n in RAW if n in names], "has_analysis": "analysis.h5" in names,
    }


def series(run_dir):
    """series.csv as {columns, units, docs, data: {column: [numbers]}} ({} when absent)."""
    path = os.path.join(run_dir, "series.csv")
    if not os.path.isfile(path):
        return {}
    t = csv_series.read(path)
    return {"columns": t["columns"], "units": t["units"], "docs": t["docs"], "data": csv_series.columns_as_numbers(t)}
