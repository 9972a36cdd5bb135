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
