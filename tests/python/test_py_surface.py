"""A surface law from Python (docs/surface.md) plugs into the wedge's surface updates: the
linear hillslope law written in Python, operation for operation as src/surface/profile_laws.cpp
solves it, moves the same particles at the same steps as surface.diffusivity in C++, bit for bit;
only the name its removals are logged with differs."""

import numpy as np
import pytest

import orogen

KAPPA = 0.3
WEDGE = {
    "run": {"experiment": "wedge", "threads": 1},
    "output": {"progress": "never"},
    "layer": {"thickness": 5.0},
    "wedge": {"tile_length": 4.0, "retro_length": 4.0, "initial_active": 4.0, "window": 3.0, "s_end": 0.3,
              "outputs": 4},
    "surface": {"every": 100, "deposition": True},
}


def diffuse_linear(h, dx, x_lo, dt):
    """Backward Euler, closed ends, Thomas's algorithm: diffuse_linear's operations in its order."""
    n, r = len(h), KAPPA * dt / (dx * dx)
    diag, rhs, upper = [1 + 2 * r] * n, [float(v) for v in h], [0.0] * n
    diag[0] -= r
    diag[-1] -= r
    for j in range(n):
        pivot = diag[j] - (-r * upper[j - 1] if j > 0 else 0.0)
        upper[j] = -r / pivot
        rhs[j] = (rhs[j] - (-r * rhs[j - 1] if j > 0 else 0.0)) / pivot
    for j in range(n - 2, -1, -1):
        rhs[j] -= upper[j] * rhs[j + 1]
    return np.array(rhs)


def stepped(config, law=None, steps=3000):
    sim = orogen.Simulation(config)
    if law is not None:
        sim.set_surface_law(law)
    sim.step(steps)
    return sim.world


def test_a_python_law_equals_the_same_law_in_cpp():
    in_cpp = {**WEDGE, "surface": {**WEDGE["surface"], "diffusivity": KAPPA}}
    calls = []

    def law(h, dx, x_lo, dt):
        calls.append(len(h))
        return diffuse_linear(h, dx, x_lo, dt)

    a, b = stepped(in_cpp), stepped(WEDGE, law)
    assert len(calls) == 30 and min(calls) > 20  # every 100 steps, over the whole profile
    for name in ("x", "y", "vx", "vy", "radius"):
        assert a.array(name).tobytes() == b.array(name).tobytes(), name
    assert np.array_equal(a.array("id"), b.array("id"))
    assert len(a) != 0


def test_orogen_run_takes_a_surface_law_too(tmp_path):
    """The run driver (files, checkpoints) with the Python law: the same discs at every output as
    the run with surface.diffusivity, the removals the same but for the law they name."""
    config = {**WEDGE, "wedge": {**WEDGE["wedge"], "s_end": 0.2}}
    in_cpp = {**config, "surface": {**config["surface"], "diffusivity": KAPPA}}
    assert orogen.run(in_cpp, out=tmp_path / "cpp") == orogen.FINISHED
    assert orogen.run(config, out=tmp_path / "py", surface_law=diffuse_linear) == orogen.FINISHED
    a, b = orogen.open_run(tmp_path / "cpp"), orogen.open_run(tmp_path / "py")
    for k in (0, -1):
        for name in ("x", "y", "particle"):
            assert a.output(k)[name].values.tobytes() == b.output(k)[name].values.tobytes(), (k, name)
    ra, rb = a.removals, b.removals
    assert len(ra) > 0 and list(ra["id"]) == list(rb["id"])
    assert set(ra["reason"]) == {"eroded_hillslope"} and set(rb["reason"]) == {"eroded_script"}


def test_a_law_returning_the_wrong_length_is_refused():
    sim = orogen.Simulation(WEDGE)
    sim.set_surface_law(lambda h, dx, x_lo, dt: h[:-1])
    with pytest.raises(ValueError, match="one height per column"):
        sim.step(200)


def test_an_experiment_without_a_surface_refuses_a_law():
    sim = orogen.Simulation({"run": {"experiment": "repose"}, "repose": {"size": 10.0, "min_time": 0.5, "max_time": 1.0}})
    with pytest.raises(ValueError, match="no surface processes"):
        sim.set_surface_law(lambda h, dx, x_lo, dt: h)
