"""The worked examples of docs/python.md run (tiny versions) and do what they say."""

import subprocess
import sys

import orogen
from conftest import REPO


def run_example(name, out):
    proc = subprocess.run([sys.executable, str(REPO / "examples" / "python" / name), "--out", str(out), "--tiny"],
                          capture_output=True, text=True)
    assert proc.returncode == 0, proc.stderr
    return proc.stdout


def test_sandbox_backstop_pulses(tmp_path):
    run_example("sandbox_backstop.py", tmp_path / "sb")
    r = orogen.open_run(tmp_path / "sb")
    assert r.series["shortening"].iloc[-1] >= 0.3 - 1e-9
    walls = r.snapshots["walls"]  # the backstop (right wall) moved left from output to output
    right = walls.sel(end="ax").values.max(axis=1)
    assert (right[1:] < right[:-1]).all()


def test_foreland_recycling(tmp_path):
    out = run_example("foreland_recycling.py", tmp_path / "fr")
    r = orogen.open_run(tmp_path / "fr")
    assert (r.removals["reason"] == "eroded").sum() > 0
    assert "deposited" in out
    ids = r.snapshots["id"].values
    first_new = int(r.snapshots["id"].isel(output=0).max()) + 1
    assert (ids >= first_new).any()  # deposited discs are in the outputs


def test_column_collapse(tmp_path):
    out = run_example("column_collapse.py", tmp_path / "cc")
    r = orogen.open_run(tmp_path / "cc")
    assert r.experiment == "scripted" and "runout" in out
    s = r.series
    assert (s["n_discs"] == s["n_discs"].iloc[0]).all() and s["n_discs"].iloc[0] > 50  # built in Python, none lost
    first, last = r.output(0), r.output(-1)
    free = lambda o: o["x"].values[o["motion"].values == 0]  # the base is pinned
    assert free(last).max() > free(first).max() + 2  # the column spread along the base
    assert s["y_max"].iloc[-1] < s["y_max"].iloc[0] - 2  # and came down
    walls = r.snapshots["walls"].sel(end="ax")  # NaN where an output has fewer walls
    assert int(walls.isel(output=0).notnull().sum()) == 4 and int(walls.isel(output=-1).notnull().sum()) == 3
    # the gate was opened: a switched-off wall is not in the output
