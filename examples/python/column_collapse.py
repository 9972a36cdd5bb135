#!/usr/bin/env python3
"""A granular column collapse whose geometry is written in Python (run.experiment = "scripted").

The setup function builds everything: a box of walls (floor, left wall, far right wall), a
bumpy base of pinned discs along the floor (discs roll without resistance, so on a flat floor
they would roll to the far wall), and a column of discs against the left wall, held by a gate;
the discs sit on an offset (hexagonal) grid with radii drawn by a seeded numpy generator, so the
run is the same every time. A hook opens the gate once the column has settled a little (a rule
of the model time alone, so a stopped run resumes bit for bit); the column slumps into a heap
along the base. The run reports the runout and the mean slope of the deposit.

The C++ side is the plain `scripted` experiment: an empty world at the start, World::advance()
steps until scripted.duration, outputs and checkpoints as every run. A resume does not call the
setup function: the checkpoint holds the geometry.

    /usr/bin/python3 examples/python/column_collapse.py --out runs/collapse
    /usr/bin/python3 examples/python/column_collapse.py --out /tmp/cc --tiny   # seconds
"""

import argparse
import math

import numpy as np

import orogen

D_MIN = 0.8  # smallest disc diameter made here; particles.d_min, so the time step suits it [d]


BASE = 1.0  # top of the bumpy base [d]


def column_setup(width, height, box_length, seed):
    """The setup function: walls, the pinned base, and a column `width` x `height` [d] (above
    the base) of discs of diameters in [D_MIN, 1] on an offset grid of spacing 1 (neighbours
    never overlap)."""

    def setup(world):
        top = BASE + 2.0 * height
        # Walls are segments touched from either side; they overlap at the corners (as the C++
        # box of src/packing does), so no disc slips out between two ends.
        world.add_wall("floor", -1.0, 0.0, box_length + 1.0, 0.0, friction="rough", mu=0.5)
        world.add_wall("left", 0.0, -1.0, 0.0, top)
        world.add_wall("right", box_length, -1.0, box_length, top)
        world.add_wall("gate", width, 0.0, width, top)
        base = [world.add_disc(0.5 + i, 0.5 * BASE, 0.5 * BASE) for i in range(int(box_length))]
        world.pin(base)  # kinematic at rest: a rough floor that stops rolling discs
        rng = np.random.default_rng(seed)
        row_height = math.sqrt(3.0) / 2.0
        for row in range(int((height - 1.0) / row_height) + 1):
            shift = 0.5 * (row % 2)
            y = BASE + 0.5 + row * row_height
            for col in range(int(width - shift)):
                world.add_disc(0.5 + shift + col, y, 0.5 * rng.uniform(D_MIN, 1.0))

    return setup


def open_gate_at(time):
    """The hook: switches the gate off at the first call after model time `time`."""

    def hook(world):
        if world.time >= time and any(w["name"] == "gate" and w["enabled"] for w in world.walls):
            world.enable_wall("gate", False)

    return hook


def deposit(run, width, gap=0.5):
    """(discs in the column, runout beyond the column's foot, discs that rolled away, deposit
    height, mean slope in degrees) of the last output's free discs (the base is pinned). The
    deposit's front is where, from the wall, the discs first leave a gap wider than `gap` [d]:
    single discs rolling ahead do not count."""
    last = run.output(-1)
    free = last["motion"].values == 0
    x, y, r = (last[k].values[free] for k in ("x", "y", "radius"))
    order = np.argsort(x)
    front, kept = 0.0, 0
    for i in order:
        if x[i] - r[i] > front + gap:
            break
        front, kept = max(front, x[i] + r[i]), kept + 1
    height = float(np.max(y + r)) - BASE
    return int(free.sum()), front - width, int(free.sum()) - kept, height, math.degrees(math.atan2(height, front))


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--out", required=True)
    p.add_argument("--tiny", action="store_true", help="a column of about a hundred discs (a test)")
    p.add_argument("--seed", type=int, default=1)
    args = p.parse_args(argv)
    width, height, duration, settle = (20.0, 40.0, 60.0, 2.0) if not args.tiny else (6.0, 12.0, 12.0, 1.0)
    box_length = width + 3.0 * height
    config = {"run": {"experiment": "scripted"}, "particles": {"d_min": D_MIN},
              "scripted": {"duration": duration, "outputs": 30 if not args.tiny else 6}}
    if args.tiny:
        config["run"]["threads"] = 1
        config["output"] = {"progress": "never"}
    orogen.run(config, out=args.out, setup=column_setup(width, height, box_length, args.seed),
               hook=open_gate_at(settle), every=50)
    r = orogen.open_run(args.out)
    n, runout, strays, h, slope = deposit(r, width)
    print(f"{args.out}: column {width:g} x {height:g} d (aspect {height / width:.3g}), {n} discs: runout "
          f"{runout:.3g} d beyond the column ({runout / width:.3g} column widths; {strays} discs rolled further), "
          f"deposit {h:.3g} d high, mean slope {slope:.3g} deg")


if __name__ == "__main__":
    main()
