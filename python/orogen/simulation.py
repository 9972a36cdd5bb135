"""An experiment stepped from Python, in memory (no files): the CLI's set-up and steps, bit for bit.

    sim = orogen.Simulation({"run": {"experiment": "wedge"}, "wedge": {"s_end": 1}})
    sim.step(100)
    sim.advance_to(S=0.5)
    x = sim.world.x            # a numpy view, no copy
    with sim.edit() as w:      # writable views; the world is told on leaving
        w.array("vx", writable=True)[:] = 0
    sim = orogen.Simulation({"run": {"experiment": "scripted"}, "scripted": {"duration": 20}},
                            setup=build_column)   # setup(world) before the first step
"""

import contextlib

from ._engine import _orogen
from .config import load_config


class Simulation:
    def __init__(self, config=None, set=None, setup=None):
        """`setup(world)`, if given, builds on the experiment's set-up before the first step, as
        orogen.run's does: the geometry of a scripted experiment. ConfigError if its discs are
        too small for the configured time step (particles.d_min)."""
        self.config = load_config(config, set)
        self._sim = _orogen.Simulation(self.config)
        if setup is not None:
            setup(self.world)  # as orogen.run calls it, so the two stay bit for bit alike
            self._sim.check_setup()

    @property
    def world(self):
        """The world (orogen World): numpy views, walls, pin/release, add/remove, friction."""
        return self._sim.world

    def set_surface_law(self, law):
        """Gives a wedge a surface law of the user's: law(h, dx, x_lo, dt) returns the new heights
        of the surface columns (h: numpy array, columns dx wide from x_lo, over time dt), run at
        each surface update after the [surface] keys' laws; what it lowers is eroded and logged
        "eroded_script", what it raises is deposited as the keys' laws' is (docs/surface.md)."""
        self._sim.set_surface_law(law)

    @property
    def done(self):
        return self._sim.done

    def step(self, n=1, hook=None, every=1):
        """Takes up to n steps (fewer once the experiment ends); with `hook`, calls hook(world)
        after each step whose number is a multiple of `every`, as orogen.run does."""
        if hook is None:
            return self._sim.step(n)
        taken = 0
        while taken < n and not self.done:
            chunk = min(every - self.world.step % every, n - taken)  # steps to the next call
            k = self._sim.step(chunk)
            taken += k
            if k < chunk:
                break
            if self.world.step % every == 0:
                hook(self.world)
        return taken

    def advance_to(self, **target):
        """Steps until a scalar of the experiment (S of a wedge) or `time` reaches the value:
        advance_to(S=2.0). False if the experiment ended first."""
        if len(target) != 1:
            raise TypeError("advance_to takes one keyword, e.g. advance_to(S=2.0) or advance_to(time=5)")
        ((key, value),) = target.items()
        return self._sim.advance_to(key, float(value))

    @contextlib.contextmanager
    def edit(self):
        """Write into the arrays (world.array(name, writable=True)); on leaving, the world
        places member discs on their bodies and rebuilds its neighbour list."""
        try:
            yield self.world
        finally:
            self.world.changed()

    def save(self, path):
        """The world and the experiment's state (a checkpoint archive)."""
        self._sim.save(str(path))

    def load(self, path):
        """Continues from a save() of a simulation of the same configuration, bit for bit."""
        self._sim.load(str(path))
