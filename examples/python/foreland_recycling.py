#!/usr/bin/env python3
"""Erosion and foreland deposition written in Python (thesis 6.2 and 7.1.4: material eroded
from the wedge is recycled into the foreland basin and carried back into the wedge).

Every `--every` steps the hook removes what stands above the erosion height (as wedge.erosion_height
does in C++; the removals are logged as `eroded` in removals.csv) and drops the same area of
new discs onto the pro-side foreland, a few h0 ahead of the pro-side deformation front, where
the incoming plate carries them back into the wedge. The engine runs in C++ between calls.

The area not yet deposited (less than one disc) is carried in Python from call to call; a
resumed run starts it at zero, so unlike sandbox_backstop.py this rule is not bit-for-bit
resumable (keep such state in the world, or derive it from the step number, where that matters).

    /usr/bin/python3 examples/python/foreland_recycling.py --out runs/recycling
    /usr/bin/python3 examples/python/foreland_recycling.py --out /tmp/fr --tiny   # seconds
"""

import argparse
import math

import numpy as np

import orogen


class ForelandRecycling:
    """The hook: erosion above `height` (h0), deposition of discs of radius `radius` (d) spread
    over [x_lo, x_hi] (h0 from the S-point), dropped just above the surface there. The world's
    coordinates are in d: the hook scales by the run's h0 (world.h0)."""

    def __init__(self, height, x_lo, x_hi, radius):
        self.height_h0, self.x_lo_h0, self.x_hi_h0, self.radius = height, x_lo, x_hi, radius
        self.pending = 0.0  # eroded area not yet deposited [d^2]
        self.slot = 0       # next deposition column, cycling over the foreland
        self.eroded = self.deposited = 0.0

    def __call__(self, world):
        self.height, self.x_lo, self.x_hi = (v * world.h0 for v in (self.height_h0, self.x_lo_h0, self.x_hi_h0))
        area = lambda: float(np.sum(np.pi * world.radius ** 2))
        before = area()
        if world.remove_above(self.height, "eroded"):
            lost = before - area()
            self.pending += lost
            self.eroded += lost
        disc = math.pi * self.radius ** 2
        columns = max(1, int((self.x_hi - self.x_lo) / (2 * self.radius)))
        while self.pending >= disc:
            x = self.x_lo + (self.slot % columns + 0.5) * (self.x_hi - self.x_lo) / columns
            self.slot += 1
            near = np.abs(world.x - x) < 2 * self.radius + world.radius
            top = float(np.max(world.y[near] + world.radius[near])) if near.any() else 0.0
            world.add_disc(x, top + 1.05 * self.radius, self.radius)
            self.pending -= disc
            self.deposited += disc


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--out", required=True)
    p.add_argument("--tiny", action="store_true", help="a wedge of a few hundred discs (a test)")
    p.add_argument("--every", type=int, default=100, help="steps between calls of the hook")
    p.add_argument("--erosion", type=float, default=1.5, help="erosion height [h0]")
    args = p.parse_args(argv)
    config = {"run": {"experiment": "wedge"}, "wedge": {"s_end": 4.0, "outputs": 50, "erosion_height": 0.0}}
    if args.tiny:
        config = {"run": {"experiment": "wedge", "threads": 1}, "output": {"progress": "never"},
                  "particles": {"packing": "random_discs"}, "layer": {"thickness": 4.0},
                  "wedge": {"tile_length": 4.0, "retro_length": 4.0, "initial_active": 4.0, "s_end": 0.3,
                            "outputs": 3, "erosion_height": 0.0}}
        args.erosion = min(args.erosion, 0.9)  # the tiny wedge barely rises
    orogen.load_config(config)  # checked before anything runs
    rule = ForelandRecycling(height=args.erosion, x_lo=-4.0, x_hi=-2.0, radius=0.5)
    orogen.run(config, out=args.out, hook=rule, every=args.every)
    r = orogen.open_run(args.out)
    print(f"{args.out}: eroded {rule.eroded:.4g} d^2, deposited {rule.deposited:.4g} d^2 in the foreland; "
          f"{int((r.removals['reason'] == 'eroded').sum())} discs eroded, {int(r.series['n_discs'].iloc[-1])} discs "
          f"at the end, H = {r.series['H'].iloc[-1]:.3g} h0")


if __name__ == "__main__":
    main()
