#!/usr/bin/env python3
"""A granular column collapse whose geometry is written in Python (run.experiment = "scripted").

The setup function builds everything: a box of walls (floor, left wall, far right wall) and a
column of discs against the left wall, held by a gate; the discs sit on an offset (hexagonal)
grid with radii drawn by a seeded numpy generator, so the run is the same every time. A hook
opens the gate once the column has settled a little (a rule of the model time alone, so a
stopped run resumes bit for bit); the column slumps into a heap along the floor. The run reports
the runout and the mean slope of the deposit.

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


def column_setup(width, height, box_length, seed):
    """The setup function: walls and a column `width` x `height` [d] of discs of diameters in
    [D_MIN, 1] on an offset grid of spacing 1 (neighbours never overlap)."""

    def setup(world):
        top = 2.0 * height
        # Walls are segments touched from either side; they overlap at the corners (as the C++
        # box of src/packing does), so no disc slips out between two ends.
        world.add_wall("floor", -1.0, 0.0, box_length + 1.0, 0.0, friction="rough", mu=0.5)
        world.add_wall("left", 0.0, -1.0, 0.0, top)
        world.add_wall("right", box_length, -1.0, box_length, top)
        world.add_wall("gate", width, 0.0, width, top)
        rng = np.random.default_rng(seed)
        row_height = math.sqrt(3.0) / 2.0
        for row in range(int((height - 1.0) / row_height) + 1):
            shift = 0.5 * (row % 2)
            y = 0.5 + row * row_height
            for col in range(int(width - shift)):
                world.add_disc(0.5 + shift + col, y, 0.5 * rng.uniform(D_MIN, 1.0))

    return setup


def open_gate_at(time):
    """The hook: switches the gate off at the first call after model time `time`."""

    def hook(world):
        if world.time >= time and any(w["name"] == "gate" and w["enabled"] for w in world.walls):
            world.enable_wall("gate", False)

    return hook


def deposit(run, width):
    """(runout beyond the column's foot, height at the wall, mean slope in degrees) of the last output."""
    last = run.series.iloc[-1]
    runout = float(last["x_max"]) - width
    height = float(last["y_max"])
    return runout, height, math.degrees(math.atan2(height, float(last["x_max"])))


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
    runout, h, slope = deposit(r, width)
    aspect = height / width
    print(f"{args.out}: column {width:g} x {height:g} d (aspect {aspect:.3g}), {int(r.series['n_discs'].iloc[0])} "
          f"discs: runout {runout:.3g} d beyond the column ({runout / width:.3g} column widths), deposit "
          f"{h:.3g} d high at the wall, mean slope {slope:.3g} deg")


if __name__ == "__main__":
    main()
