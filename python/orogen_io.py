"""Run and sweep folders for the chart scripts, on top of the orogen package's readers.

Used by python/granular_charts.py, wedge_charts.py, ensemble_stats.py, ensemble_charts.py and
exhumation_frames.py. The tables are read by pandas (orogen.read_csv, python/orogen/results.py:
rows with the wrong number of fields are skipped); what this module adds is what the charts need
on top: tables as float arrays, sweeps, a run's configuration by dotted key, snapshots.h5 frames,
the model's surface and fits, atomic output. Import it with python/ on sys.path:

    import orogen_io as oio
    runs = oio.collect_runs(["runs/sweep_repose_slump", "runs/one_run"], "repose")
    for run in runs:
        print(run.name, oio.config_value(run.config, "contact.mu"), run.summary.get("angle_deg"))

What is read (docs/output-files.md, docs/sweeps.md):

- series.csv, summary.csv, profile.csv: `# name: meaning` comment lines, a header row, numeric
  rows (`nan` for NaN) -> read_table / read_summary (dicts of float arrays / floats).
- config.toml: the resolved configuration (TOML) -> read_config, config_value("contact.mu").
- DIR/results.csv of a sweep: comment lines, header row, one row per run (`name`, each swept
  key, `exit_status`, `render_status`, then every summary.csv column; RFC 4180 quoting) ->
  read_results (text rows; read_rows for any such table). Its run folders are DIR/runs/NAME.
- snapshots.h5: file attributes (format, version, n_outputs, h0, experiment, ...), groups
  output_000000 ... of which the first n_outputs are complete, each with per-disc arrays
  x, y, radius, depth0, motion, cluster_id, ... and walls (n x 4: ax, ay, bx, by) ->
  read_frame, read_last_frame (orogen.frames, h5py; optional for everything else).

Also the surface of a set of discs as the model measures it (MODEL section 8: columns of width
2.3 mean radii, the top of the highest disc in each), the least-squares line and quadratic of a
profile (numpy.polyfit, as src/analysis/profile_fit.cpp) and the critical taper of a dry
Coulomb wedge (src/analysis/critical_taper.cpp; Dahlen 1984, MODEL section 9).
"""

import io
import math
import os
import sys
import tempfile
import tomllib

import numpy as np
import pandas as pd

import orogen.results  # the pandas readers of run folders (python/orogen; no compiled engine needed)

try:
    import h5py  # only read_frame needs it: the charts test `oio.h5py is None` to skip pictures
    import orogen.frames  # the package's snapshot reader
except ImportError:
    h5py = None

COLUMN_WIDTH_RADII = 2.3  # surface columns 2.3 mean radii wide (MODEL section 8)


class RunError(Exception):
    """A folder or file that is not what the caller asked for (the message says why)."""


# --------------------------------------------------------------------------------------------
# Tables (series.csv, summary.csv, results.csv)


def _to_float(v):
    try:
        return float(v)
    except (TypeError, ValueError):
        return float("nan")


def read_table(path):
    """A series-format CSV (series.csv, summary.csv, profile.csv) read by orogen.read_csv
    (pandas; rows with the wrong number of fields, such as a cut last row, are skipped).

    Returns (columns, descriptions): columns maps each header name to a float array (NaN for
    'nan', empty or non-numeric fields), descriptions maps names to their `# name: meaning`
    text (with its [unit])."""
    try:
        frame = orogen.results.read_complete_rows(path)
    except pd.errors.EmptyDataError:
        raise RunError("%s: no CSV header row" % path) from None
    columns = {name: pd.to_numeric(frame[name], errors="coerce").to_numpy(dtype=float) for name in frame.columns}
    return columns, _descriptions(path)


def read_summary(path):
    """summary.csv as (dict name -> float of its first row, descriptions); {} without rows."""
    columns, descriptions = read_table(path)
    return {k: float(v[0]) for k, v in columns.items() if len(v)}, descriptions


def read_results(path):
    """A sweep's results.csv: (rows, header, descriptions); rows are dicts name -> text ('' for
    an empty or missing field), header the column names in order (name, the swept keys,
    exit_status, ...)."""
    rows, header = read_rows(path)
    return rows, header, _descriptions(path)


def read_rows(path):
    """A CSV with `#` comment lines (results.csv, members.csv, fits.csv, ...) as text, by pandas:
    (rows: dicts name -> text, '' for an empty or missing field; header: the names in order).
    RFC 4180 quoting; a row longer than the header keeps its first fields."""
    with open(path, "r", encoding="utf-8", newline="") as f:
        body = "".join(line for line in f if not line.startswith("#"))  # not comment="#": '#' may be in a quoted field
    header = list(pd.read_csv(io.StringIO(body), nrows=0).columns)
    frame = pd.read_csv(io.StringIO(body), dtype=str, keep_default_na=False, engine="python",
                        on_bad_lines=lambda fields: fields[: len(header)])
    return frame.fillna("").to_dict("records"), header


def _descriptions(path):
    units, meanings = orogen.results.column_docs(path)
    return {name: "%s [%s]" % (text, units[name]) if name in units else text for name, text in meanings.items()}


# --------------------------------------------------------------------------------------------
# Configuration


def read_config(path):
    with open(path, "rb") as f:
        return tomllib.load(f)


def config_value(config, key, default=None):
    """A dotted key ("contact.mu") of a configuration read by read_config."""
    node = config
    for part in key.split("."):
        if not isinstance(node, dict) or part not in node:
            return default
        node = node[part]
    return node


# --------------------------------------------------------------------------------------------
# Runs and sweeps


class Run:
    """One run folder: its configuration, summary, series (read on demand) and files."""

    def __init__(self, folder, name=None, results_row=None, swept=()):
        """folder: the run folder (None: only a sweep's table row, no files); results_row: the
        run's row of a sweep's results.csv; swept: that table's swept configuration keys."""
        self.dir = os.path.abspath(folder) if folder else None
        self.name = name or (os.path.basename(os.path.normpath(folder)) if folder else "run")
        self.results_row = results_row or {}
        self.swept = tuple(swept)
        cfg = self.file("config.toml")
        self.config = read_config(cfg) if cfg else {}
        self.summary, self.summary_descriptions = {}, {}
        path = self.file("summary.csv")
        if path:
            self.summary, self.summary_descriptions = read_summary(path)
        elif self.results_row:
            # The sweep's table has the summary's columns too (after the fixed ones).
            for k, v in self.results_row.items():
                if k not in ("name", "exit_status", "render_status") and k not in self.swept and v != "":
                    self.summary[k] = _to_float(v)
        self._series = None

    @property
    def experiment(self):
        return config_value(self.config, "run.experiment")

    def value(self, key, default=None):
        """A configuration value, from config.toml or else the sweep's column of that key."""
        v = config_value(self.config, key)
        if v is None and key in self.results_row and self.results_row[key] != "":
            text = self.results_row[key]
            v = _to_float(text)
            if math.isnan(v):
                v = text
        return default if v is None else v

    def file(self, name):
        """Path of a file in the run folder, or None when it is not there."""
        if not self.dir:
            return None
        path = os.path.join(self.dir, name)
        return path if os.path.isfile(path) else None

    @property
    def series(self):
        if self._series is None:
            path = self.file("series.csv")
            self._series = read_table(path)[0] if path else {}
        return self._series

    def __repr__(self):
        return "Run(%r)" % self.dir


def warn(text):
    print("warning: %s" % text, file=sys.stderr)


def _sweep_runs(folder, experiment, results_csv):
    rows, header, _ = read_results(results_csv)
    # The swept keys: the columns between name and exit_status.
    end = header.index("exit_status") if "exit_status" in header else 1
    swept = header[1:end]
    runs = []
    unfinished, failed = [], []
    for row in rows:
        name = row.get("name", "")
        status = row.get("exit_status", "").strip()
        run_dir = os.path.join(folder, "runs", name)
        if status != "0":
            (unfinished if status == "" else failed).append(name if status == "" else "%s (%s)" % (name, status))
            continue
        run = Run(run_dir if os.path.isdir(run_dir) else None, name=name, results_row=row, swept=swept)
        if experiment and run.experiment not in (None, experiment):
            warn("%s: run %s is a '%s' run, not '%s'; left out" % (folder, name, run.experiment, experiment))
            continue
        runs.append(run)
    if unfinished:
        warn("%s: %d run(s) not finished (yet), left out: %s" % (folder, len(unfinished), ", ".join(unfinished)))
    if failed:
        warn("%s: %d run(s) failed (exit status), left out: %s" % (folder, len(failed), ", ".join(failed)))
    return runs


def collect_runs(paths, experiment=None):
    """Runs of the given folders, in order.

    Each path is a run folder (holds config.toml), a sweep folder (holds results.csv; its runs
    with exit_status 0, the others are reported and left out), a sweep's results.csv itself, or
    a folder of run folders (its sub-folders with a config.toml, by name). With `experiment`,
    a run folder of another experiment named directly is an error (RunError), one found in a
    sweep or parent folder is skipped."""
    runs = []
    for path in paths:
        if os.path.isfile(path) and os.path.basename(path) == "results.csv":
            runs += _sweep_runs(os.path.dirname(os.path.abspath(path)), experiment, path)
            continue
        if not os.path.isdir(path):
            raise RunError("%s: no such folder" % path)
        results = os.path.join(path, "results.csv")
        if os.path.isfile(os.path.join(path, "config.toml")):
            run = Run(path)
            if experiment and run.experiment != experiment:
                raise RunError("%s is a '%s' run, not a '%s' run (run.experiment in its config.toml)"
                               % (path, run.experiment, experiment))
            runs.append(run)
        elif os.path.isfile(results):
            runs += _sweep_runs(path, experiment, results)
        else:
            found = []
            for name in sorted(os.listdir(path)):
                sub = os.path.join(path, name)
                if os.path.isfile(os.path.join(sub, "config.toml")):
                    run = Run(sub)
                    if experiment is None or run.experiment == experiment:
                        found.append(run)
            if not found:
                raise RunError("%s holds no config.toml, results.csv or run folders%s" % (
                    path, " of '%s' runs" % experiment if experiment else ""))
            runs += found
    # Unique names (two sweeps both have a run 000_...): the later ones get a suffix.
    seen = {}
    for run in runs:
        if run.name in seen:
            seen[run.name] += 1
            run.name = "%s-%d" % (run.name, seen[run.name])
        else:
            seen[run.name] = 1
    return runs


# --------------------------------------------------------------------------------------------
# snapshots.h5


def read_frame(path, index=-1):
    """One complete output of snapshots.h5 (index as a Python index over the complete outputs:
    0 the first, -1 the last) as a dict: every per-disc dataset of the output (x, y, vx, vy,
    omega, theta, radius, depth0, x0, y0, motion, cluster_id, id, max_rel_disp, disp3_*, ...:
    each 1-D dataset of length n); walls (n x 4: ax, ay, bx, by); the group's attributes (step,
    time, S, ...) under 'attrs', the file's (h0, experiment, ...) under 'file_attrs'; 'output'
    (the group's number). None when the file has no such complete output. Groups beyond
    n_outputs (left by a killed run) are never read. Read by orogen.frames (the package's
    reader); the charts need x, y and radius, so an output without them is a RunError."""
    if h5py is None:
        raise RuntimeError("h5py is not installed")
    frame = orogen.frames.read_frame(path, index)
    for name in ("x", "y", "radius"):
        if frame is not None and name not in frame:
            raise RunError("%s: output %d has no '%s'" % (path, frame["output"], name))
    return frame


def read_last_frame(path):
    """The last complete output of snapshots.h5 (see read_frame), or None."""
    return read_frame(path, -1)


# --------------------------------------------------------------------------------------------
# Surface and profile fits (as src/analysis/surface.cpp and profile_fit.cpp)


def surface_columns(x, y, r, x_lo, x_hi, width=None):
    """Columns [x_lo + k w, x_lo + (k+1) w), w = 2.3 mean radii unless given, up to x_hi:
    returns (centres, heights) with the top y + r of the highest disc, NaN for empty columns."""
    x, y, r = (np.asarray(a, dtype=float) for a in (x, y, r))
    if width is None:
        width = COLUMN_WIDTH_RADII * (float(np.mean(r)) if r.size else 0.5)
    n = max(1, int(math.ceil((x_hi - x_lo) / width)))
    height = np.full(n, -np.inf)
    ok = np.isfinite(x) & np.isfinite(y) & np.isfinite(r) & (x >= x_lo) & (x < x_lo + n * width)
    k = np.clip(np.floor((x[ok] - x_lo) / width).astype(np.int64), 0, n - 1)
    np.maximum.at(height, k, y[ok] + r[ok])
    height[~np.isfinite(height)] = np.nan
    return x_lo + (np.arange(n) + 0.5) * width, height


def fit_line(x, y):
    """Least-squares line through (x, y) as profile_fit.cpp fits it: a dict with n, slope,
    intercept, r2, rms, concavity [rad] (descent angle of a quadratic's tangent at the upper end
    minus at the lower end), x_lo, x_hi; None with fewer than 3 points."""
    x = np.asarray(x, dtype=float)
    y = np.asarray(y, dtype=float)
    n = x.size
    if n < 3 or np.ptp(x) <= 0:
        return None
    slope, intercept = (float(c) for c in np.polyfit(x, y, 1))
    ss_res = float(np.sum((y - (intercept + slope * x)) ** 2))
    syy = float(np.sum((y - y.mean()) ** 2))
    x_lo, x_hi = float(x.min()), float(x.max())
    mx, half = x.mean(), max(0.5 * (x_hi - x_lo), 1e-12)
    q2, q1, _ = np.polyfit((x - mx) / half, y, 2)
    slope_lo = (q1 + 2 * q2 * (x_lo - mx) / half) / half
    slope_hi = (q1 + 2 * q2 * (x_hi - mx) / half) / half
    sign = -1.0 if slope <= 0 else 1.0
    upper, lower = (slope_lo, slope_hi) if slope <= 0 else (slope_hi, slope_lo)
    return dict(n=n, slope=slope, intercept=intercept, r2=1.0 - ss_res / syy if syy > 0 else 1.0,
                rms=math.sqrt(ss_res / n), concavity=math.atan(sign * upper) - math.atan(sign * lower),
                x_lo=x_lo, x_hi=x_hi)


# --------------------------------------------------------------------------------------------
# Critical taper (as src/analysis/critical_taper.cpp)


def critical_taper(phi, phi_b, beta=0.0):
    """Critical surface slope [rad] of a dry, non-cohesive Coulomb wedge of bulk friction angle
    phi on a base of friction angle phi_b dipping at beta (all radians; Dahlen 1984, MODEL
    section 9): solves alpha + beta = psi_b - psi_0 by bisection on (-phi, phi). Raises
    ValueError when phi is not in (0, 90 deg), phi_b not in [0, phi), or no root exists."""
    if not (0 < phi < math.pi / 2):
        raise ValueError("internal friction angle %.4g deg must be in (0, 90) deg" % math.degrees(phi))
    if not (0 <= phi_b < phi):
        raise ValueError("basal friction angle %.4g deg must be at least 0 and below the internal friction "
                         "angle %.4g deg" % (math.degrees(phi_b), math.degrees(phi)))
    psi_b = 0.5 * (math.asin(math.sin(phi_b) / math.sin(phi)) - phi_b)

    def residual(alpha):
        s = max(-1.0, min(1.0, math.sin(alpha) / math.sin(phi)))
        return alpha + beta - psi_b + 0.5 * (math.asin(s) - alpha)

    lo, hi = -phi * (1 - 1e-12), phi * (1 - 1e-12)
    if residual(lo) > 0 or residual(hi) < 0:
        raise ValueError("no critical taper for phi = %.4g deg, phi_b = %.4g deg, basal dip %.4g deg"
                         % (math.degrees(phi), math.degrees(phi_b), math.degrees(beta)))
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if residual(mid) > 0:
            hi = mid
        else:
            lo = mid
    return 0.5 * (lo + hi)


def critical_taper_deg(phi_deg, mu_b):
    """Critical taper [deg] on a flat base for bulk friction angle phi_deg and basal friction
    coefficient mu_b; NaN where there is none (phi_b = atan(mu_b) >= phi, or phi not finite),
    as the biaxial summary's taper_mub*_deg columns."""
    try:
        phi_deg, mu_b = float(phi_deg), float(mu_b)
        if not (math.isfinite(phi_deg) and math.isfinite(mu_b)):
            return float("nan")
        return math.degrees(critical_taper(math.radians(phi_deg), math.atan(mu_b)))
    except (TypeError, ValueError):
        return float("nan")


# --------------------------------------------------------------------------------------------
# Atomic output


def _umask_mode():
    mask = os.umask(0)
    os.umask(mask)
    return 0o666 & ~mask


def write_atomically(path, write, binary=False, suffix=".tmp"):
    """Calls write(file) on a temporary file in path's folder, then renames it to path."""
    folder = os.path.dirname(os.path.abspath(path))
    fd, tmp = tempfile.mkstemp(prefix=".tmp-", suffix=suffix, dir=folder)
    try:
        with os.fdopen(fd, "wb" if binary else "w", **({} if binary else {"encoding": "utf-8", "newline": ""})) as f:
            write(f)
        os.chmod(tmp, _umask_mode())  # mkstemp makes 0600; give the file ordinary permissions
        os.replace(tmp, path)
    except BaseException:
        if os.path.exists(tmp):
            os.unlink(tmp)
        raise


def write_text(path, text):
    write_atomically(path, lambda f: f.write(text))


def save_figure(fig, path):
    """Writes a matplotlib figure as PNG atomically, then closes it."""
    import matplotlib.pyplot as plt  # only the chart scripts call this; they set the backend
    try:
        write_atomically(path, lambda f: fig.savefig(f, format="png", dpi=110), binary=True, suffix=".png")
    finally:
        plt.close(fig)
