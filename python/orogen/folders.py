"""The runs of the folders a chart is given: run folders, sweeps (their results.csv and
runs/NAME), and folders of runs, as RunFolder objects (orogen.results); and the snapshot frames
the charts draw (orogen.frames, with the fields they need checked).

    from orogen import folders
    runs = folders.collect_runs(["runs/sweep_repose_slump", "runs/one_run"], "repose")
    for run in runs:
        print(run.name, run.value("contact.mu"), run.summary.get("angle_deg"))

A sweep's DIR/results.csv (docs/sweeps.md): comment lines, a header row, one row per run
(`name`, each swept key, `exit_status`, `render_status`, then every summary.csv column; RFC
4180 quoting). Its run folders are DIR/runs/NAME. snapshots.h5: docs/output-files.md.
"""

import os
import sys

from .results import RunFolder
from .tables import RunError, read_results

try:
    import h5py  # only read_frame needs it: the charts test `folders.h5py is None` to skip pictures
    from . import frames  # the package's snapshot reader
except ImportError:
    h5py = None

__all__ = ["RunError", "collect_runs", "read_frame", "read_last_frame", "warn"]


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
        run = RunFolder(run_dir if os.path.isdir(run_dir) else None, name=name, results_row=row, swept=swept)
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
            run = RunFolder(path)
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
                    run = RunFolder(sub)
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
    frame = frames.read_frame(path, index)
    for name in ("x", "y", "radius"):
        if frame is not None and name not in frame:
            raise RunError("%s: output %d has no '%s'" % (path, frame["output"], name))
    return frame


def read_last_frame(path):
    """The last complete output of snapshots.h5 (see read_frame), or None."""
    return read_frame(path, -1)
