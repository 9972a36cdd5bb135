"""The world from Python: views without copies, changes through the World API that hold."""

import numpy as np
import pytest

import orogen
from conftest import TINY_WEDGE

# Free discs (the default wedge is all rigid 3-disc clusters, which move as bodies).
DISCS = {**TINY_WEDGE, "particles": {"packing": "random_discs"}}


@pytest.fixture(scope="module")
def sim():
    s = orogen.Simulation(DISCS)
    s.step(20)
    return s


def free_dynamic(world):
    return int(np.flatnonzero((world.cluster_id < 0) & (world.motion == 0))[0])


def test_views_share_memory_and_are_read_only(sim):
    w = sim.world
    assert np.shares_memory(w.x, w.array("x")) and not w.x.flags.writeable
    assert w.x.dtype == np.float64 and w.id.dtype == np.int64 and w.motion.dtype == np.uint8
    assert len(w.x) == len(w) and set(w.array_names) >= {"x", "vx", "omega", "radius", "cluster_id", "motion"}
    with pytest.raises(ValueError):
        w.x[0] = 1.0


def test_a_moved_disc_is_where_it_was_put(sim):
    w = sim.world
    i = free_dynamic(w)
    ident = int(w.id[i])
    top = float(np.max(w.y)) + 20.0  # above everything: nothing touches it there
    w.move([i], [1.5], [top])
    w.set_velocity([i], 0.0, 0.0)
    sim.step(1)
    j = int(np.flatnonzero(w.id == ident)[0])  # the list may have re-ordered the discs
    dt, g = w.dt, 1.0
    assert w.x[j] == pytest.approx(1.5, abs=1e-12)
    assert w.y[j] == pytest.approx(top - g * dt * dt, rel=0, abs=1e-9)  # one step of free fall


def test_writable_views_through_edit(sim):
    w = sim.world
    i = free_dynamic(w)
    ident = int(w.id[i])
    with sim.edit():
        w.array("vx", writable=True)[i] = 0.25
        w.array("vy", writable=True)[i] = 0.0
    j = int(np.flatnonzero(w.id == ident)[0])
    assert w.vx[j] == 0.25


def test_pin_release_add_remove(sim):
    w = sim.world
    i = free_dynamic(w)
    ident = int(w.id[i])
    w.pin([i], vx=0.1)
    sim.step(3)
    j = int(np.flatnonzero(w.id == ident)[0])
    assert w.motion[j] == 1 and w.vx[j] == 0.1 and w.vy[j] == 0.0
    w.release([j])
    assert w.motion[j] == 0
    n = len(w)
    k = w.add_disc(0.0, float(np.max(w.y)) + 10, 0.5)
    assert len(w) == n + 1 and w.radius[k] == 0.5
    removed = w.remove([k], "other")
    assert removed == 1 and len(w) == n
    sim.step(2)


def test_walls(sim):
    w = sim.world
    names = [wall["name"] for wall in w.walls]
    assert names
    w.add_wall("lid", -100.0, 60.0, 100.0, 60.0, friction="rough", mu=0.5)
    assert w.walls[-1]["name"] == "lid" and w.walls[-1]["friction"] == "rough"
    w.set_wall_velocity("lid", 0.0, -0.01)
    w.enable_wall("lid", False)
    sim.step(2)
    assert w.walls[-1]["enabled"] is False
    with pytest.raises(ValueError, match="lid"):
        w.add_wall("lid", 0, 0, 1, 1)
    with pytest.raises(Exception, match="nowall"):
        w.set_wall_velocity("nowall", 0, 0)
    touching, at_limit = w.wall_contacts(names[0])
    assert at_limit <= touching == len(w.touching(names[0]))


def test_member_disc_refused_but_its_cluster_pinned():
    s = orogen.Simulation(TINY_WEDGE)  # rigid 3-disc clusters
    w = s.world
    m = int(np.flatnonzero((w.cluster_id >= 0) & (w.motion == 0))[0])
    with pytest.raises(ValueError, match="cluster"):
        w.move([m], [0.0], [0.0])
    cluster = w.cluster_id[m]
    w.pin([m], vx=0.05)
    assert np.all(w.motion[w.cluster_id == cluster] == 1)
    s.step(2)
    assert np.all(w.vx[w.cluster_id == cluster] == 0.05)


def test_advance_to_and_save_load_bitwise(tmp_path):
    a = orogen.Simulation(TINY_WEDGE)
    assert a.advance_to(S=0.02)
    assert a.world.scalars()["S"] >= 0.02
    a.save(tmp_path / "state.bin")
    a.step(40)
    b = orogen.Simulation(TINY_WEDGE)
    b.load(tmp_path / "state.bin")
    b.step(40)
    assert a.world.step == b.world.step
    assert a.world.x.tobytes() == b.world.x.tobytes() and a.world.omega.tobytes() == b.world.omega.tobytes()


def test_stale_hook_world_raises(tmp_path):
    kept = []
    orogen.run(TINY_WEDGE, out=tmp_path / "r", hook=kept.append, every=100)
    with pytest.raises(RuntimeError, match="no longer valid"):
        len(kept[0])


def test_simulation_hook_every(tmp_path):
    s = orogen.Simulation(TINY_WEDGE)
    seen = []
    s.step(25, hook=lambda w: seen.append(w.step), every=10)
    assert seen == [10, 20] and s.world.step == 25


def test_hooks_and_simulations_read_h0_and_the_resolved_configuration(tmp_path):
    # Issue 36: a hook had no way to the run's h0 or configuration (the examples hard-coded h0).
    seen = []
    orogen.run(TINY_WEDGE, out=tmp_path / "r", every=100,
               hook=lambda w: seen.append((w.h0, w.config["wedge"]["s_end"], w.config["layer"]["thickness"])))
    thickness = TINY_WEDGE["layer"]["thickness"]
    assert seen and seen[0] == (thickness, TINY_WEDGE["wedge"]["s_end"], thickness)
    assert orogen.open_run(tmp_path / "r").config["layer"]["thickness"] == thickness
    s = orogen.Simulation(TINY_WEDGE)
    assert s.world.h0 == thickness and s.world.config["run"]["experiment"] == "wedge"
    assert s.world.config["contact"]["kn"] == 10000.0  # every key, resolved: the defaults too
