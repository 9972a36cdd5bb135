#!/usr/bin/python3
"""An ensemble's copy whose series carry the thesis's deformation fronts (wedge.fronts = discs),
measured again from every output's snapshot, so that `python3 -m orogen.stats` gives Table 5.1
under both rules from the same runs (docs/model.md "Measurements"; the rule moves no disc).

Usage (from the repository root):
    PYTHONPATH=python /usr/bin/python3 scripts/thesis_fronts.py ENSEMBLE_DIR COPY_DIR
    PYTHONPATH=python /usr/bin/python3 -m orogen.stats COPY_DIR

For each member: Dp and Dr are the extreme x of the discs centred above h0 + d_max (h0 from
the snapshots, d_max from the member's config.toml), T the x of the highest disc top (the
smaller x on a tie), all three 0 (the S-point) while no disc is that high, as the C++ measures
them (a run with wedge.fronts = discs gets its own series back, to round-off); every other
column is copied as it is. Prints, per member, how many outputs' fronts
differ between the rules and the largest difference.
"""

import os
import shutil
import sys
import tomllib

import numpy as np

from orogen.frames import Snapshots


def thesis_fronts(run):
    """[(Dp, Dr, T)] in h0 per output of RUN, by the thesis's rule."""
    with open(os.path.join(run, "config.toml"), "rb") as f:
        d_max = float(tomllib.load(f)["particles"]["d_max"])
    out = []
    with Snapshots(os.path.join(run, "snapshots.h5")) as snaps:
        h0 = float(snaps.attrs["h0"])
        for k in range(len(snaps)):
            f = snaps.frame(k, ("x", "y", "radius"))
            x, y, top = f["x"], f["y"], f["y"] + f["radius"]
            raised = y > h0 + d_max
            if not raised.any():
                out.append((0.0, 0.0, 0.0))
                continue
            peak = np.flatnonzero(top == top.max())
            out.append((x[raised].min() / h0, x[raised].max() / h0, x[peak].min() / h0))
    return out


def main(source, target):
    if os.path.exists(target):
        sys.exit("error: %s exists; give a new folder" % target)
    os.makedirs(os.path.join(target, "members"))
    for name in ("ensemble.toml", "members.csv"):
        shutil.copy2(os.path.join(source, name), target)
    for member in sorted(os.listdir(os.path.join(source, "members"))):
        run = os.path.join(source, "members", member)
        lines = open(os.path.join(run, "series.csv"), encoding="utf-8").read().splitlines(keepends=True)
        header_at = next(i for i, line in enumerate(lines) if not line.startswith("#"))
        columns = lines[header_at].strip().split(",")
        fronts = thesis_fronts(run)
        rows = lines[header_at + 1:]
        if len(rows) != len(fronts):
            sys.exit("error: %s: %d series rows, %d outputs" % (run, len(rows), len(fronts)))
        changed, largest = 0, 0.0
        for i, (dp, dr, t) in enumerate(fronts):
            cells = rows[i].rstrip("\n").split(",")
            for col, value in (("Dp", dp), ("Dr", dr), ("T", t)):
                j = columns.index(col)
                old = float(cells[j])
                if col != "T" and abs(old - value) > 1e-9:  # beyond round-off (1e-16 here)
                    changed += 1
                    largest = max(largest, abs(old - value))
                cells[j] = repr(float(value))
            rows[i] = ",".join(cells) + "\n"
        os.makedirs(os.path.join(target, "members", member))
        with open(os.path.join(target, "members", member, "series.csv"), "w", encoding="utf-8") as f:
            f.writelines(lines[:header_at + 1] + rows)
        print("%s: %d front values of %d outputs differ between the rules, the largest by %.3f h0" %
              (member, changed, len(fronts), largest))


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2])
