"""orogen.run is `orogen run`: the same files with the same bits, hooks at the right steps,
a stop by the hook and a resume that end bit for bit as the uninterrupted CLI run."""

import subprocess

import h5py
import numpy as np

import orogen
from conftest import BINARY, TINY_WEDGE, run_cli


def datasets(run_dir):
    """{file/dataset: array} of every output file, and the series as text."""
    out = {}
    for path in sorted((run_dir / "snapshots").glob("output_*.h5")):
        with h5py.File(path, "r") as f:
            f.visititems(lambda name, obj: out.__setitem__(f"{path.name}/{name}", obj[()])
                         if isinstance(obj, h5py.Dataset) else None)
    return out


def assert_same_bits(a, b):
    da, db = datasets(a), datasets(b)
    assert da.keys() == db.keys() and da
    for k in da:
        assert da[k].dtype == db[k].dtype and da[k].tobytes() == db[k].tobytes(), k
    assert (a / "series.csv").read_text() == (b / "series.csv").read_text()
    assert (a / "removals.csv").read_text() == (b / "removals.csv").read_text()


def test_python_run_equals_cli_bitwise(cli_wedge, tmp_path):
    calls = []
    assert orogen.run(TINY_WEDGE, out=tmp_path / "py", hook=lambda w: calls.append(w.step), every=1) == orogen.FINISHED
    assert_same_bits(cli_wedge, tmp_path / "py")
    assert calls == list(range(1, calls[-1] + 1))  # every step, before the last one's end


def test_hook_called_at_multiples_of_every(tmp_path):
    seen = []

    def hook(world):
        seen.append((world.step, world.scalars()["S"]))

    orogen.run(TINY_WEDGE, out=tmp_path / "r", hook=hook, every=50)
    steps = [s for s, _ in seen]
    assert steps and all(s % 50 == 0 for s in steps) and steps == sorted(set(steps))
    assert steps[0] == 50 and seen[-1][1] > seen[0][1]  # S grows


def test_hook_stop_and_resume_equal_the_cli(cli_wedge, tmp_path):
    out = tmp_path / "r"
    assert orogen.run(TINY_WEDGE, out=out, hook=lambda w: w.step == 120, every=10) == orogen.STOPPED
    assert orogen.resume(out) == orogen.FINISHED
    assert_same_bits(cli_wedge, out)


def test_hook_exception_propagates_with_a_checkpoint(tmp_path):
    class Boom(Exception):
        pass

    def hook(world):
        raise Boom("from the hook")

    out = tmp_path / "r"
    try:
        orogen.run(TINY_WEDGE, out=out, hook=hook, every=30)
        raise AssertionError("no exception")
    except Boom:
        pass
    assert (out / "checkpoint.bin").exists()
    assert orogen.resume(out) == orogen.FINISHED


def test_simulation_steps_as_the_cli(cli_wedge):
    last = orogen.open_run(cli_wedge).output(-1).sortby("particle")
    sim = orogen.Simulation(TINY_WEDGE)
    sim.step(int(last.attrs["step"]))
    w = sim.world
    order = np.argsort(w.id)
    assert np.array_equal(w.id[order], last.particle.values)
    assert w.x[order].tobytes() == last.x.values.tobytes()
    assert w.vy[order].tobytes() == last.vy.values.tobytes()


def test_cli_tools_read_a_python_run(tmp_path):
    out = tmp_path / "py"
    orogen.run(TINY_WEDGE, out=out)
    subprocess.run([BINARY, "analyze", str(out)], check=True, capture_output=True)
    subprocess.run([BINARY, "render", str(out)], check=True, capture_output=True)
    assert len(list((out / "frames").glob("*.png"))) == 5
    subprocess.run([BINARY, "export", str(out), "--format", "csv", "--to", str(tmp_path / "o.csv")], check=True,
                   capture_output=True)
    assert orogen.open_run(out).analysis is not None


def test_a_changing_hook_resumes_bit_for_bit(tmp_path):
    """A rule that changes the world (a wall's velocity, by step number): stopped and resumed
    with the same hook, the run ends with the bits of the run that went through."""
    def pulses(world):
        world.set_wall_velocity("retro_end", 0.0 if (world.step // 2000) % 2 else 0.01, 0.0)

    def stop_at(step):
        def hook(world):
            pulses(world)
            return world.step == step
        return hook

    whole, parts = tmp_path / "whole", tmp_path / "parts"
    assert orogen.run(TINY_WEDGE, out=whole, hook=pulses, every=50) == orogen.FINISHED
    assert orogen.run(TINY_WEDGE, out=parts, hook=stop_at(4000), every=50) == orogen.STOPPED
    assert orogen.resume(parts, hook=pulses, every=50) == orogen.FINISHED
    assert_same_bits(whole, parts)
    walls = orogen.open_run(whole).snapshots["walls"].values
    assert not np.array_equal(walls[0], walls[-1])  # the hook did move the wall


def test_two_threads_same_bits(cli_wedge, tmp_path):
    """threads= reaches the engine; a tiny wedge stays below the parallel loops (2048 discs)."""
    orogen.run(TINY_WEDGE, out=tmp_path / "t2", threads=2, hook=lambda w: None, every=100)
    assert_same_bits(cli_wedge, tmp_path / "t2")


def test_bad_openmp_variables_raise_config_error_before_anything_is_written(tmp_path, monkeypatch):
    """The CLI's check of the OpenMP variables (exit 2 there) is a ConfigError here (issue 35)."""
    import pytest
    for name, value in (("OMP_NUM_THREADS", "100000"), ("OMP_PROC_BIND", "sideways")):
        with monkeypatch.context() as m:
            m.setenv(name, value)
            with pytest.raises(orogen.ConfigError, match=name):
                orogen.run(TINY_WEDGE, out=tmp_path / "r")
            with pytest.raises(orogen.ConfigError, match=name):
                orogen.Simulation(TINY_WEDGE)
    assert not (tmp_path / "r").exists()


def test_a_run_into_a_folder_that_holds_one_names_the_python_call_that_continues_it(tmp_path):
    """Issue 36: the refusal said "see run.log" (which does not mention it) and named the CLI's --resume."""
    import pytest
    out = tmp_path / "r"
    assert orogen.run(TINY_WEDGE, out=out) == orogen.FINISHED
    before = sorted(p.name for p in out.iterdir())
    with pytest.raises(orogen.RunError) as refused:
        orogen.run(TINY_WEDGE, out=out)
    assert refused.value.code == 2
    assert f"orogen.resume({str(out)!r})" in str(refused.value) and "run.log" not in str(refused.value)
    assert sorted(p.name for p in out.iterdir()) == before


PACKING = {"run": {"experiment": "packing", "threads": 1}, "particles": {"packing": "random_discs"},
           "layer": {"length": 10.0, "thickness": 3.0}, "contact": {"kn": 1000.0},
           "settle": {"relax_time": 1.0, "ke_threshold": 1e-3}, "output": {"interval": 2.0, "progress": "never"}}


def test_a_stop_between_a_removal_and_the_next_output_resumes(tmp_path):
    """The packing trims 9 discs at step 2200, between outputs 4 (step 1836) and 5 (2295): a stop
    at step 2250 checkpoints them, and removals.csv must agree with that checkpoint (the long run
    E(V) could not be resumed when the file lagged it)."""
    whole, parts = tmp_path / "whole", tmp_path / "parts"
    assert orogen.run(PACKING, out=whole) == orogen.FINISHED
    assert orogen.run(PACKING, out=parts, hook=lambda w: w.step == 2250, every=10) == orogen.STOPPED
    assert "2200," in (parts / "removals.csv").read_text()  # written with the checkpoint
    assert orogen.resume(parts) == orogen.FINISHED
    assert (parts / "removals.csv").read_text() == (whole / "removals.csv").read_text()
    assert (parts / "series.csv").read_text() == (whole / "series.csv").read_text()


def test_a_removals_file_that_lags_the_checkpoint_is_accepted(tmp_path):
    """A folder left by a build that wrote removals.csv only at outputs: the file ends before the
    stop's removals, and the resume writes them."""
    whole, parts = tmp_path / "whole", tmp_path / "parts"
    assert orogen.run(PACKING, out=whole) == orogen.FINISHED
    assert orogen.run(PACKING, out=parts, hook=lambda w: w.step == 2250, every=10) == orogen.STOPPED
    header = [line for line in (parts / "removals.csv").read_text().splitlines(keepends=True)
              if not line[0].isdigit()]
    (parts / "removals.csv").write_text("".join(header).replace("through_step: 2250", "through_step: 1836"))
    assert orogen.resume(parts) == orogen.FINISHED
    assert (parts / "removals.csv").read_text() == (whole / "removals.csv").read_text()
