#!/usr/bin/env python3
"""A sandbox wedge (thesis chapter 3, singly-vergent) whose backstop moves by a rule written in
Python: convergence in pulses, fast then slow, with the same mean speed as singly.speed.

The C++ experiment builds the box and measures the wedge; the hook, called every `--every` steps,
only sets the backstop's velocity through the World API. Its velocity depends on the step
number alone, so a stopped run resumes bit for bit (`orogen.resume(OUT, hook=..., every=...)`).

    /usr/bin/python3 examples/python/sandbox_backstop.py --out runs/sandbox_pulses
    /usr/bin/python3 examples/python/sandbox_backstop.py --out /tmp/sb --tiny   # seconds
"""

import argparse

import orogen

BACKSTOP = "right"  # the box's right wall is the backstop of the singly-vergent experiment


def pulsed_backstop(speed, period_steps, ratio=3.0):
    """A hook: the backstop moves at `ratio`/(1+ratio)*2*speed for half a period, then at the
    rest of twice the mean; the mean over a period is `speed`."""
    fast, slow = 2 * speed * ratio / (1 + ratio), 2 * speed / (1 + ratio)

    def hook(world):
        v = fast if (world.step // period_steps) % 2 == 0 else slow
        world.set_wall_velocity(BACKSTOP, -v, 0.0)  # towards -x, as the experiment moves it

    return hook


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--out", required=True)
    p.add_argument("--tiny", action="store_true", help="a box of a few hundred discs (a test)")
    p.add_argument("--every", type=int, default=100, help="steps between calls of the hook")
    args = p.parse_args(argv)
    config = {"run": {"experiment": "singly_vergent"}, "singly": {"speed": 0.025, "shortening": 1.0, "outputs": 20},
              "layer": {"length": 120.0, "thickness": 10.0}}
    if args.tiny:
        config = {"run": {"experiment": "singly_vergent", "threads": 1}, "output": {"progress": "never"},
                  "particles": {"packing": "random_discs"}, "layer": {"length": 30.0, "thickness": 4.0},
                  "singly": {"speed": 0.05, "shortening": 0.3, "outputs": 3, "speed_bound": "off"}}
    speed = config["singly"]["speed"]
    orogen.run(config, out=args.out, hook=pulsed_backstop(speed, period_steps=20 * args.every), every=args.every)
    r = orogen.open_run(args.out)
    last = r.series.iloc[-1]
    print(f"{args.out}: shortening {last['shortening']:.3g} h0, wedge height {last['height']:.3g} h0, "
          f"taper {last['taper']:.3g} deg after {int(last['step'])} steps")


if __name__ == "__main__":
    main()
