#!/usr/bin/python3
"""A run's deflected base against the analytic deflection of its own load (docs/isostasy-evidence.md):
at an output, the load of the discs over each base node's column beyond the reference layer (the
layer's weight per length at output 0, as the run measures it), and the deflection that load gives
an infinite elastic plate (the sum of Hetenyi's line-load solutions) or Airy's balance (the load
averaged over the nodes within h0 of each, as the run does); printed beside the base's nodes as the run placed them (the snapshot's
walls), with the largest difference. The run's base lags its load by up to isostasy.every steps.

    scripts/isostasy_check.py RUN [OUTPUT]        (OUTPUT: default the last)
"""

import math
import os
import sys
import tomllib

import h5py
import numpy as np


def main(run, output=None):
    with open(os.path.join(run, "config.toml"), "rb") as f:
        config = tomllib.load(f)
    h0 = config["layer"]["thickness"]
    iso = config["isostasy"]
    k, D = iso["mantle_density"], iso["rigidity"] * h0 ** 4
    dx = iso["segment_length"] * h0
    x_end = config["wedge"]["retro_length"] * h0
    files = sorted(f for f in os.listdir(os.path.join(run, "snapshots")) if f.endswith(".h5"))
    first = h5py.File(os.path.join(run, "snapshots", files[0]), "r")
    last = h5py.File(os.path.join(run, "snapshots", files[-1 if output is None else int(output)]), "r")
    # The reference: the built layer's weight per length away from its ends.
    x0, r0 = first["x"][()], first["radius"][()]
    lo, hi = x0.min() + h0, x_end - h0
    inside = (x0 >= lo) & (x0 < hi)
    reference = np.sum(math.pi * r0[inside] ** 2) / (hi - lo)
    # The base's nodes as placed: the segments' start points and the last end point.
    walls = last["walls"][()]
    segments = walls[(walls[:, 0] != walls[:, 2]) & (np.abs(walls[:, 0]) < 1e6)]
    segments = segments[np.argsort(segments[:, 0])]
    nodes = np.append(segments[:, 0], segments[-1, 2])
    placed = np.append(segments[:, 1], segments[-1, 3])
    nodes, placed = nodes[:-1], placed[:-1]  # the last segment reaches past the end wall
    # The load per node column, beyond the reference, where the column is inside the model.
    x, r = last["x"][()], last["radius"][()]
    column = np.round((x - nodes[0]) / dx).astype(int)
    ok = (column >= 0) & (column < nodes.size)
    load = np.bincount(column[ok], weights=math.pi * r[ok] ** 2, minlength=nodes.size) / dx - reference
    covered = (nodes - 0.5 * dx >= x.min()) & (nodes + 0.5 * dx <= x_end)
    load[~covered] = 0.0
    if iso["model"] == "flexure":
        alpha = (4 * D / k) ** 0.25
        s = np.abs(nodes[:, None] - nodes[None, :]) / alpha
        green = alpha ** 3 / (8 * D) * np.exp(-s) * (np.cos(s) + np.sin(s))
        expected = -(green @ (load * dx))
        label = "elastic plate, alpha = %.3g h0" % (alpha / h0)
    else:
        half = int(0.5 * 2 * h0 / dx)
        mean = np.array([load[max(0, j - half):j + half + 1].mean() for j in range(load.size)])
        expected = -mean / k
        label = "Airy over %d nodes" % (2 * half + 1)
    diff = placed - expected
    deepest = np.argmin(expected)
    print(f"{run}: S = {last.attrs['S']:.2f}, {label}; deepest {-expected[deepest] / h0:.4f} h0 expected, "
          f"{-placed[deepest] / h0:.4f} h0 placed at x = {nodes[deepest] / h0:.2f} h0; largest difference "
          f"{np.abs(diff).max() / h0:.4f} h0 ({np.abs(diff).max() / max(1e-12, -expected.min()):.1%} of the deepest)")


if __name__ == "__main__":
    main(*sys.argv[1:])
