#!/usr/bin/python3
"""How rigidly a pushed singly-vergent wedge moved (Buiter et al. 2016 experiment 1, a stable
wedge: it must slide without deforming inside; docs/cohesion-evidence.md): between the first and
the last output, the share of the wedge's discs that moved with the backstop (within 10% of its
displacement), the shear strain of the wedge's discs (median, 95th percentile;
orogen.analysis.strain), and the surface slope over the wedge before and after.

    scripts/rigid_slide.py RUN
"""

import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "python"))
from orogen.analysis.strain import shear_strain  # noqa: E402
from orogen.frames import Snapshots  # noqa: E402


def slope(x, y, r, x_back, length):
    """Least-squares slope [deg] of the highest disc tops in columns 1 d wide over the `length`
    d next to the backstop."""
    tops = []
    for c in np.arange(x_back - length, x_back - 1, 1.0):
        inside = (x >= c) & (x < c + 1)
        if inside.any():
            tops.append((c + 0.5, float((y + r)[inside].max())))
    t = np.array(tops)
    return math.degrees(math.atan(np.polyfit(t[:, 0], t[:, 1], 1)[0]))


def main(run):
    with Snapshots(os.path.join(run, "snapshots.h5")) as s:
        h0 = float(s.attrs["h0"])
        first, last = s.frame(0), s.frame(len(s) - 1)
    back0, back1 = first["walls"][:, 0].max(), last["walls"][:, 0].max()  # the backstop: the rightmost wall
    shift = back1 - back0
    order = np.argsort(first["id"])
    pos = np.searchsorted(first["id"], last["id"], sorter=order)
    pos = np.clip(pos, 0, len(order) - 1)
    prev = order[pos]
    known = first["id"][prev] == last["id"]
    dx = last["x"][known] - first["x"][prev[known]]
    rigid = np.abs(dx - shift) <= 0.1 * abs(shift)
    strain = shear_strain({"x": first["x"] / h0, "y": first["y"] / h0, "id": first["id"], "h0": h0},
                          {"x": last["x"] / h0, "y": last["y"] / h0, "id": last["id"], "h0": h0})
    inner = np.isfinite(strain)
    wedge_length = h0 / math.tan(math.radians(20))
    print("backstop moved %.2f d (%.2f h0); %d of %d discs (%.1f%%) moved with it within 10%%"
          % (-shift, -shift / h0, rigid.sum(), rigid.size, 100 * rigid.mean()))
    print("shear strain first to last output: median %.4f, 95th percentile %.4f, largest %.3f"
          % (np.median(strain[inner]), np.percentile(strain[inner], 95), strain[inner].max()))
    print("surface slope next to the backstop: %.1f deg before, %.1f deg after"
          % (slope(first["x"], first["y"], first["radius"], back0, 0.8 * wedge_length),
             slope(last["x"], last["y"], last["radius"], back1, 0.8 * wedge_length)))


if __name__ == "__main__":
    main(sys.argv[1])
