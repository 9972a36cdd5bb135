"""A scripted experiment: the geometry written in Python (setup=), the rest the CLI's driver:
its files, `orogen render` on them, a stopped or killed run resumed bit for bit without calling
setup again, and the refusals (no scripted.duration, discs too small for the time step)."""

import os
import signal
import subprocess
import sys

import numpy as np
import pytest

import orogen
from conftest import BINARY, REPO, run_cli
from test_py_run import assert_same_bits

# A little box with a few dozen discs falling onto its floor: a second on one core.
TINY_SCRIPTED = {
    "run": {"experiment": "scripted", "threads": 1},
    "output": {"progress": "never", "checkpoint_every": 1},
    "particles": {"d_min": 0.8},
    "scripted": {"duration": 3.0, "outputs": 5},
}


def build_box(world):
    """A box 10 d wide and a block of 5 x 6 discs with seeded radii above its floor."""
    world.add_wall("floor", -1.0, 0.0, 11.0, 0.0, friction="rough", mu=0.5)
    world.add_wall("left", 0.0, -1.0, 0.0, 20.0)
    world.add_wall("right", 10.0, -1.0, 10.0, 20.0)
    rng = np.random.default_rng(7)
    for row in range(6):
        for col in range(5):
            world.add_disc(1.0 + 1.05 * col + 0.3 * (row % 2), 0.6 + 1.05 * row, 0.5 * rng.uniform(0.8, 1.0))


def no_setup(world):
    raise AssertionError("setup must not be called on a resume")


@pytest.fixture(scope="module")
def scripted_run(tmp_path_factory):
    out = tmp_path_factory.mktemp("scripted") / "run"
    assert orogen.run(TINY_SCRIPTED, out=out, setup=build_box) == orogen.FINISHED
    return out


def test_scripted_run_writes_the_cli_files(scripted_run, tmp_path):
    # The files of every CLI run. The CLI itself refuses a scripted run: without a setup function
    # it could only run empty (issue 35), and it writes nothing.
    assert {"config.toml", "run.lock", "run.log", "series.csv", "snapshots.h5", "snapshots", "snapshots.xmf",
            "removals.csv", "checkpoint.bin"} <= {p.name for p in scripted_run.iterdir()}
    with pytest.raises(subprocess.CalledProcessError) as refused:
        run_cli(tmp_path / "cli", TINY_SCRIPTED)
    assert refused.value.returncode == 2 and "Python setup function" in refused.value.stderr
    assert not (tmp_path / "cli").exists()
    r = orogen.open_run(scripted_run)
    assert r.experiment == "scripted"
    s = r.series
    assert list(s["n_discs"]) == [30] * 6 and s["time"].iloc[-1] == pytest.approx(3.0, abs=0.01)
    assert s["y_max"].iloc[-1] < s["y_max"].iloc[0]  # the block fell and settled
    assert s["kinetic_energy"].iloc[0] == 0.0 and s["kinetic_energy"].iloc[2] > 0.0
    walls = r.snapshots["walls"]
    assert walls.sizes["wall"] == 3  # the walls the setup built are in every output


def test_render_draws_a_scripted_run(scripted_run):
    subprocess.run([BINARY, "render", str(scripted_run), "--width", "320"], check=True, capture_output=True)
    assert any(scripted_run.glob("*.mp4")) or any(scripted_run.glob("frames/*.png")) or \
        any(p.suffix in (".mp4", ".png", ".gif") for p in scripted_run.rglob("*"))


def test_stopped_by_hook_and_resumed_equals_the_uninterrupted_run(scripted_run, tmp_path):
    out = tmp_path / "stopped"
    assert orogen.run(TINY_SCRIPTED, out=out, setup=build_box, hook=lambda w: w.step == 900, every=100) \
        == orogen.STOPPED
    assert orogen.resume(out, setup=no_setup) == orogen.FINISHED
    assert_same_bits(scripted_run, out)


KILLED_RUN = """
import os, signal, sys
sys.path.insert(0, {tests!r})
import orogen
from test_py_scripted import TINY_SCRIPTED, build_box

def kill_after_two_outputs(world):  # like a kill -9: no cleanup, the last checkpoint stays
    if len(list(orogen.open_run({out!r}).series.index)) >= 3:
        os.kill(os.getpid(), signal.SIGKILL)

orogen.run(TINY_SCRIPTED, out={out!r}, setup=build_box, hook=kill_after_two_outputs, every=200)
"""


def test_killed_and_resumed_equals_the_uninterrupted_run(scripted_run, tmp_path):
    out = tmp_path / "killed"
    code = KILLED_RUN.format(tests=str(REPO / "tests" / "python"), out=str(out))
    proc = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                          env={**os.environ, "PYTHONPATH": os.pathsep.join([str(REPO / "python"),
                                                                           os.environ.get("PYTHONPATH", "")])})
    assert proc.returncode == -signal.SIGKILL, proc.stderr
    assert (out / "checkpoint.bin").exists()
    assert orogen.resume(out, setup=no_setup) == orogen.FINISHED
    assert_same_bits(scripted_run, out)


TWO_THREADS_RUN = """
import sys
sys.path.insert(0, {tests!r})
import orogen
from test_py_scripted import TINY_SCRIPTED, build_box
orogen.run(TINY_SCRIPTED, out={out!r}, setup=build_box, threads=2)
"""


def test_two_threads_give_the_bits_of_one(scripted_run, tmp_path):
    # In a process of its own: the engine reads OROGEN_MIN_PARALLEL_ITEMS once, and a few dozen
    # discs must be split between the threads for the test to mean anything.
    out = tmp_path / "two_threads"
    code = TWO_THREADS_RUN.format(tests=str(REPO / "tests" / "python"), out=str(out))
    proc = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                          env={**os.environ, "OROGEN_MIN_PARALLEL_ITEMS": "4", "OMP_NUM_THREADS": "2",
                               "PYTHONPATH": os.pathsep.join([str(REPO / "python"), os.environ.get("PYTHONPATH", "")])})
    assert proc.returncode == 0, proc.stderr
    assert "2 thread(s)" in (out / "run.log").read_text()
    assert_same_bits(scripted_run, out)


def test_simulation_with_setup_steps_as_the_run(scripted_run):
    last = orogen.open_run(scripted_run).output(-1).sortby("particle")
    sim = orogen.Simulation(TINY_SCRIPTED, setup=build_box)
    sim.step(int(last.attrs["step"]))
    order = np.argsort(sim.world.id)
    assert np.array_equal(sim.world.x[order], last["x"].values)
    assert np.array_equal(sim.world.y[order], last["y"].values)


def test_missing_duration_is_a_config_error(tmp_path):
    config = {k: v for k, v in TINY_SCRIPTED.items() if k != "scripted"}
    with pytest.raises(orogen.ConfigError, match=r"scripted\.duration"):
        orogen.run(config, out=tmp_path / "r", setup=build_box)
    assert not (tmp_path / "r").exists()  # refused before anything was written
    with pytest.raises(orogen.ConfigError, match=r"scripted\.duration"):
        orogen.Simulation(config)
    proc = subprocess.run([BINARY, "run", "--out", str(tmp_path / "cli"), "--set", "run.experiment=scripted"],
                          capture_output=True, text=True)
    assert proc.returncode == 2 and "scripted.duration" in proc.stderr


def test_discs_below_d_min_are_refused(tmp_path):
    def tiny_disc(world):
        world.add_disc(1.0, 1.0, 0.1)

    with pytest.raises(orogen.RunError) as e:
        orogen.run(TINY_SCRIPTED, out=tmp_path / "r", setup=tiny_disc)
    assert e.value.code == 2
    assert not (tmp_path / "r" / "config.toml").exists()  # the folder is released, as after any failed set-up
    with pytest.raises(orogen.ConfigError, match=r"particles\.d_min.*0\.2"):
        orogen.Simulation(TINY_SCRIPTED, setup=tiny_disc)


def test_an_exception_in_setup_propagates_and_leaves_no_run(tmp_path):
    class Boom(Exception):
        pass

    def setup(world):
        build_box(world)
        raise Boom("from setup")

    with pytest.raises(Boom):
        orogen.run(TINY_SCRIPTED, out=tmp_path / "r", setup=setup)
    assert not (tmp_path / "r" / "config.toml").exists()
    assert orogen.run(TINY_SCRIPTED, out=tmp_path / "r", setup=build_box) == orogen.FINISHED  # the folder is free


def test_series_columns_are_documented(scripted_run):
    from test_output_docs import csv_columns, documented_columns
    header, meanings = csv_columns(str(scripted_run / "series.csv"))
    assert meanings == documented_columns("series.csv", "scripted") and header == list(meanings)


def test_branch_needs_a_checkpointed_output(scripted_run, tmp_path):
    # A replay to output 2 would need the setup function; the finished run's checkpoint holds output 5.
    with pytest.raises(orogen.RunError) as e:
        orogen.run(TINY_SCRIPTED, out=tmp_path / "b2", from_run=f"{scripted_run}:2")
    assert e.value.code == 2
    rougher = {**TINY_SCRIPTED, "contact": {"mu": 0.5}}  # a key a branch may change
    assert orogen.run(rougher, out=tmp_path / "b5", from_run=f"{scripted_run}:5") == orogen.FINISHED
    assert orogen.open_run(tmp_path / "b5").series["n_discs"].iloc[0] == 30  # the geometry came with it
