"""The faults of a wedge at each output, picked from the shear strain field (docs/materials.md,
Fault picking): forethrusts and backthrusts, their dips, where they meet the base and their
spacing along it, and which are active. The numbers the cohesion studies and the community
benchmark (Buiter et al. 2016) compare codes by.

    python3 -m orogen.analysis.faults RUN [--window 3] [--threshold 0.25]

writes RUN/faults.csv: one row per fault per output.

How: the shear strain of each disc over the last `window` outputs (orogen.analysis.strain);
the discs above `threshold` times the field's 99.5th percentile are the sheared ones. Lines
are taken out of them one at a time (sequential RANSAC, seeded: the same faults every time):
among lines through two sheared discs, the one whose contiguous run of sheared discs within a
band of BAND_D disc diameters about it carries the most strain, the run holding at least
MIN_FILL of all the discs in that stretch of band (a line of sheared discs, not one through
scattered ones); the refitted run must hold more sheared discs than the region's share of them
would put in its band by chance with probability SIGNIFICANCE (binomial); its discs are fitted again by a
strain-weighted principal axis and removed, until the best run is shorter than `min_length`
h0. A fault dips towards where its plane deepens: one that deepens towards the wedge's core
(the S-point of a doubly-vergent wedge: x = 0; the backstop of a singly-vergent one, whose
faults are all of its "pro" side) is a forethrust of its side (its hanging wall moves out,
towards the foreland), one that deepens away from it a backthrust. It is active
when its discs' mean strain over the last output alone is at least the threshold of that
increment. Lines flatter than MIN_DIP_DEG (bedding-parallel shear) are not reported, and only
discs within WEDGE_MARGIN of the wedge (where the surface stands WEDGE_RISE above the layer)
are looked at. The spacing of a fault is the distance along the base (where its line meets y = 0)
to the next fault of its side and kind towards the foreland (NaN for the outermost).

How far a fault has moved, from its walls: the discs just beyond its sheared zone (WALL_D thick,
along the picked segment), the hanging wall above it and the footwall below. Its slip over the
window is how much further up-dip the hanging wall's discs moved than the footwall's (medians;
positive in the sense of a thrust); its offset, the same since the run's first output, is all
the slip the zone between the two walls has carried (of the wall discs that were there then:
NaN where fewer were, as for faults in the inflow of a doubly-vergent wedge). Read from the
walls' motion rather than from their horizons: on the wedges measured (docs/materials.md) the
horizons' separation along a fault was too noisy to use.
"""

import argparse
import math
import os
import sys

import numpy as np
from scipy import stats

from ..atomic import write_text
from .strain import matched, shear_strain

PERCENTILE = 99.5
MIN_DIP_DEG = 10.0    # flatter lines are bedding-parallel shear, not thrusts: not reported
WEDGE_RISE = 0.25     # discs higher than this above the layer's top [h0] make the wedge ...
WEDGE_MARGIN = 3.0    # ... and faults are picked within this of it on either side [h0]
BAND_D = 1.2          # half width of a fault's band of discs [d]
LINK_D = 2.5          # largest gap between neighbouring discs along one fault [d]
TRIALS = 400          # candidate lines per fault
MAX_FAULTS = 24
MIN_FILL = 0.6        # a fault's band is mostly sheared discs: at least this share of the discs in it
SIGNIFICANCE = 1e-6   # and so many that sheared discs scattered at random would line up so less often
WALL_D = 3.0          # a fault's walls: the discs up to this beyond its sheared zone on either side [d]
MIN_WALL_DISCS = 3    # a slip needs at least this many discs in each wall
MAX_ZONE_D = 12       # a fault's sheared zone is looked for up to this far out on either side [d]


class FaultError(Exception):
    """Bad input: the message names the run or option; exit code 2."""


def sheared(strain, threshold):
    """Indices of the discs whose strain reaches `threshold` times the field's 99.5th percentile,
    and that strain level (0 where the field has no finite value)."""
    finite = np.isfinite(strain)
    if not finite.any():
        return np.zeros(0, dtype=np.int64), 0.0
    level = threshold * float(np.percentile(strain[finite], PERCENTILE))
    return np.flatnonzero(finite & (strain >= level) & (strain > 0)), level


def _run_along(t, link):
    """The longest stretch of the sorted projections `t` with no gap above `link`: (start, end)
    indices into the sorted order."""
    gaps = np.flatnonzero(np.diff(t) > link)
    starts = np.concatenate([[0], gaps + 1])
    ends = np.concatenate([gaps + 1, [len(t)]])
    k = int(np.argmax(ends - starts))
    return starts[k], ends[k]


def _segment(px, py, w, link, idx):
    """The contiguous run of discs `idx` about their strain-weighted principal axis: (centre,
    direction, members, t_min, t_max)."""
    cx, cy = np.average(px[idx], weights=w[idx]), np.average(py[idx], weights=w[idx])
    dx, dy = px[idx] - cx, py[idx] - cy
    cov = np.cov(np.vstack([dx, dy]), aweights=w[idx]) if len(idx) > 2 else np.eye(2)
    vals, vecs = np.linalg.eigh(cov)
    u = vecs[:, 1]
    t = dx * u[0] + dy * u[1]
    order = np.argsort(t)
    a, b = _run_along(t[order], link)
    members = idx[order[a:b]]
    return (cx, cy), u, members, float(t[order[a]]), float(t[order[b - 1]])


def pick_faults(x, y, strain, d_h0, threshold=0.25, min_length=0.5, core_x=0.0, seed=1):
    """Faults of one strain field: x, y in h0, strain per disc, d_h0 the disc diameter in h0.
    Returns a list of dicts (side, kind, dip_deg, x_base, ends, length, strain, members)."""
    x, y, strain = (np.asarray(v, float) for v in (x, y, strain))
    pool, level = sheared(strain, threshold)
    raised = y > 1.0 + WEDGE_RISE
    region = np.arange(len(x))
    if raised.any():  # the wedge and its surroundings only: not the far slab's window edges
        lo, hi = x[raised].min() - WEDGE_MARGIN, x[raised].max() + WEDGE_MARGIN
        pool = pool[(x[pool] >= lo) & (x[pool] <= hi)]
        region = region[(x >= lo) & (x <= hi)]
    rx, ry = x[region], y[region]
    share = len(pool) / max(1, len(region))  # of the discs there, the sheared
    band, link = BAND_D * d_h0, LINK_D * d_h0
    rng = np.random.default_rng(seed)
    faults = []
    w = np.where(np.isfinite(strain), strain, 0.0)
    while len(pool) >= 4 and len(faults) < MAX_FAULTS:
        best = None
        for _ in range(TRIALS):
            i, j = rng.choice(pool, 2, replace=False)
            ex, ey = x[j] - x[i], y[j] - y[i]
            norm = math.hypot(ex, ey)
            if norm < 3 * d_h0:
                continue
            ex, ey = ex / norm, ey / norm
            off = np.abs((x[pool] - x[i]) * ey - (y[pool] - y[i]) * ex)
            near = pool[off <= band]
            if len(near) < 4:
                continue
            t = (x[near] - x[i]) * ex + (y[near] - y[i]) * ey
            order = np.argsort(t)
            a, b = _run_along(t[order], link)
            # Mostly sheared discs along it, not a line through scattered ones.
            t_lo, t_hi = t[order[a]], t[order[b - 1]]
            rt = (rx - x[i]) * ex + (ry - y[i]) * ey
            in_band = (np.abs((rx - x[i]) * ey - (ry - y[i]) * ex) <= band) & (rt >= t_lo) & (rt <= t_hi)
            if b - a < MIN_FILL * np.count_nonzero(in_band):
                continue
            score = float(w[near[order[a:b]]].sum())
            if best is None or score > best[0]:
                best = (score, near[order[a:b]])
        if best is None:
            break
        centre, u, members, t0, t1 = _segment(x, y, w, link, best[1])
        length = t1 - t0
        if length < min_length or len(members) < 4:
            break
        # As many sheared discs in its band as scattered ones would give by chance? Then not a fault.
        rt = (rx - centre[0]) * u[0] + (ry - centre[1]) * u[1]
        n_band = np.count_nonzero((np.abs((rx - centre[0]) * u[1] - (ry - centre[1]) * u[0]) <= band) &
                                  (rt >= t0) & (rt <= t1))
        if stats.binom.sf(len(members) - 1, max(n_band, len(members)), share) >= SIGNIFICANCE:
            pool = np.setdiff1d(pool, members)
            continue
        if u[0] < 0 or (u[0] == 0 and u[1] < 0):  # direction towards +x
            u = -u
            t0, t1 = -t1, -t0
        slope = u[1] / u[0] if u[0] != 0 else math.copysign(math.inf, u[1])
        dip = math.degrees(math.atan(abs(slope)))
        if not math.isfinite(slope):  # vertical
            x_base = centre[0]
        elif slope == 0:  # parallel to the base (not reported: flatter than MIN_DIP_DEG)
            x_base = math.nan
        else:
            x_base = centre[0] - centre[1] / slope
        side = "pro" if centre[0] < core_x else "retro"
        deepens_to_plus_x = slope < 0
        towards_core = deepens_to_plus_x if side == "pro" else not deepens_to_plus_x
        ends = ((centre[0] + t0 * u[0], centre[1] + t0 * u[1]), (centre[0] + t1 * u[0], centre[1] + t1 * u[1]))
        # Its whole sheared zone is this fault's: lines through the rest of it are not other faults.
        zone = walls({"ends": ends}, x, y, d_h0, w, level)
        inside = zone["along"] & (zone["s"] <= zone["zone"][0]) & (zone["s"] >= -zone["zone"][1])
        pool = np.setdiff1d(pool, np.union1d(members, np.flatnonzero(inside)))
        if dip < MIN_DIP_DEG:
            continue
        faults.append({"side": side, "kind": "forethrust" if towards_core else "backthrust", "dip_deg": dip,
                       "x_base": x_base, "ends": ends, "length": length,
                       "strain": float(np.mean(strain[members])), "members": members, "level": level})
    return faults


def walls(fault, x, y, d_h0, strain=None, level=0.0):
    """The discs beside a fault, as a dict: hanging and foot (indices of the hanging wall, above
    the fault's line, and of the footwall), t and s (every disc's distance up-dip along the fault
    from its lower end and across it, upwards) [h0], u (the up-dip unit vector), length, along
    (the discs beside the segment) and zone (how far the sheared zone reaches above and below
    the line) [h0]. Each wall is WALL_D thick. Without a strain field it starts at the band's
    edge (BAND_D); with one, where the sheared zone about the fault ends on that side: the first
    slice of one disc across, going out, whose discs' median `strain` is below `level` (at most
    MAX_ZONE_D out). A granular fault is a zone several discs wide, and walls inside it would
    see only part of its slip."""
    (xa, ya), (xb, yb) = sorted(fault["ends"], key=lambda e: e[1])  # lower end first
    length = math.hypot(xb - xa, yb - ya)
    u = np.array([xb - xa, yb - ya]) / length
    n = np.array([-u[1], u[0]]) if u[0] >= 0 else np.array([u[1], -u[0]])  # the normal pointing up
    x, y = np.asarray(x, float), np.asarray(y, float)
    t = (x - xa) * u[0] + (y - ya) * u[1]
    s = (x - xa) * n[0] + (y - ya) * n[1]
    along = (t >= 0) & (t <= length)
    out = {"t": t, "s": s, "u": u, "length": length, "along": along, "zone": []}
    for name, side in (("hanging", 1.0), ("foot", -1.0)):
        inner = BAND_D
        if strain is not None:
            while inner < MAX_ZONE_D:
                here = along & (side * s >= inner * d_h0) & (side * s < (inner + 1) * d_h0)
                if not here.any() or np.nanmedian(strain[here]) < level:
                    break
                inner += 1
        out[name] = np.flatnonzero(along & (side * s > inner * d_h0) & (side * s <= (inner + WALL_D) * d_h0))
        out["zone"].append(inner * d_h0)
    return out


def slip(wall, before, after):
    """How much further up-dip the hanging wall (`walls` of `after`) moved than the footwall from
    `before` to `after` (outputs: x, y, id in h0) [h0]; positive in the sense of a thrust, NaN with
    too few discs."""
    prev, known = matched(before, after)
    u = wall["u"]
    up = ((after["x"] - before["x"][prev]) * u[0] + (after["y"] - before["y"][prev]) * u[1])
    hanging, foot = wall["hanging"][known[wall["hanging"]]], wall["foot"][known[wall["foot"]]]
    if min(len(hanging), len(foot)) < MIN_WALL_DISCS:
        return math.nan
    return float(np.median(up[hanging]) - np.median(up[foot]))


def spacings(faults):
    """Each fault's distance along the base to the next fault of its side and kind towards the
    foreland (pro: -x, retro: +x); NaN for the outermost."""
    out = [math.nan] * len(faults)
    for side in ("pro", "retro"):
        for kind in ("forethrust", "backthrust"):
            ks = [k for k, f in enumerate(faults) if f["side"] == side and f["kind"] == kind
                  and math.isfinite(f["x_base"])]
            ks.sort(key=lambda k: faults[k]["x_base"], reverse=(side == "retro"))
            for a, b in zip(ks[1:], ks[:-1]):  # b is the next one out from a
                out[a] = abs(faults[a]["x_base"] - faults[b]["x_base"])
    return out


def late_faults(rows, s_end, side="pro", share=0.25):
    """The rows of a faults.csv (dicts of text, as orogen.tables.read_rows gives them) of one side
    over the last `share` of a run that ends at S (or shortening) `s_end`: the faults the cohesion
    and convergence tables read."""
    return [f for f in rows if float(f["S"]) >= (1 - share) * s_end and f["side"] == side]


COLUMNS = [("output", "output number [-]"), ("S", "convergence of the output [-]"),
           ("side", "pro or retro: the side of the S-point the fault's centre is on [-]"),
           ("kind", "forethrust (deepens towards the S-point) or backthrust [-]"),
           ("dip_deg", "dip of the fitted line [deg]"),
           ("x_base", "where the line meets the base, from the S-point [h0]"),
           ("x_top", "upper end of the picked segment [h0]"), ("y_top", "its height [h0]"),
           ("x_bottom", "lower end of the picked segment [h0]"), ("y_bottom", "its height [h0]"),
           ("length", "length of the picked segment [h0]"),
           ("strain", "mean shear strain of its discs over the window [-]"),
           ("active", "1 when its discs' mean strain over the last output reaches that increment's threshold [-]"),
           ("spacing", "distance along the base to the next fault of its side and kind towards the foreland [h0]"),
           ("n_discs", "discs of the fault [-]"),
           ("slip", "how much further up-dip its hanging wall moved than its footwall over the window "
                    "(positive: thrust sense) [h0]"),
           ("offset", "the same since the run's first output: all the slip its zone has carried (NaN where "
                      "fewer than three discs of a wall were there then) [h0]")]


def run_faults(outputs, window=3, threshold=0.25, min_length=0.5):
    """Rows of faults.csv for every output from `window` on (outputs as orogen.charts.sections
    reads them: x, y, id in h0 from the S-point, h0 in d)."""
    rows = []
    for k in range(window, len(outputs)):
        now, then, last = outputs[k], outputs[k - window], outputs[k - 1]
        d_h0 = 1.0 / now["h0"]
        total = shear_strain(then, now)
        recent = shear_strain(last, now)
        faults = pick_faults(now["x"], now["y"], total, d_h0, threshold, min_length, core_x=now["core_x"], seed=k)
        _, recent_level = sheared(recent, threshold)
        for f, spacing in zip(faults, spacings(faults)):
            top, bottom = sorted(f["ends"], key=lambda e: -e[1])
            active = recent_level > 0 and float(np.nanmean(recent[f["members"]])) >= recent_level
            wall = walls(f, now["x"], now["y"], d_h0, total, f["level"])
            rows.append([now["output"], now["S"], f["side"], f["kind"], f["dip_deg"], f["x_base"], top[0], top[1],
                         bottom[0], bottom[1], f["length"], f["strain"], int(active), spacing, len(f["members"]),
                         slip(wall, then, now), slip(wall, outputs[0], now)])
    return rows


def write_faults(run, rows):
    lines = ["# faults picked from the shear strain field, one row per fault per output (orogen.analysis.faults)"]
    lines += ["# %s: %s" % c for c in COLUMNS]
    lines.append(",".join(c[0] for c in COLUMNS))
    for r in rows:
        lines.append(",".join(v if isinstance(v, str) else repr(float(v)) if isinstance(v, float) else str(v)
                              for v in r))
    write_text(os.path.join(run, "faults.csv"), "\n".join(lines) + "\n")


def backstop_x(walls):
    """A singly-vergent wedge's core: its backstop, the vertical wall furthest along +x (the
    backstop pushes towards -x; the far wall stands at 0)."""
    vertical = walls[np.isclose(walls[:, 0], walls[:, 2])]
    return float(vertical[:, 0].max()) if len(vertical) else math.inf


def read_outputs(run):
    """Every complete output of a wedge run's snapshots.h5 (doubly- or singly-vergent): x, y
    (h0; x from the S-point in a doubly-vergent wedge), id, h0 (d), S (a singly-vergent wedge's
    shortening in h0), the core's x (core_x, h0) and the output number."""
    from ..frames import Snapshots

    path = os.path.join(run, "snapshots.h5")
    if not os.path.isfile(path):
        raise FaultError("%s not found: %s holds no run" % (path, run))
    try:
        with Snapshots(path) as snaps:
            h0 = float(snaps.attrs.get("h0", 0.0))
            experiment = snaps.attrs.get("experiment", "")
            if experiment not in ("wedge", "singly_vergent") or not h0 > 0:
                raise FaultError("%s: not a wedge run (faults are picked in doubly- and singly-vergent wedges)" % run)
            outputs = []
            for k in range(len(snaps)):
                f = snaps.frame(k, ("x", "y", "id"))
                singly = experiment == "singly_vergent"
                core_x = backstop_x(f["walls"]) / h0 if singly else 0.0
                outputs.append({"x": f["x"] / h0, "y": f["y"] / h0, "id": f["id"], "h0": h0, "core_x": core_x,
                                "S": float(f["attrs"].get("S", np.nan)), "output": f["output"]})
            return outputs
    except (OSError, KeyError, ValueError) as e:
        raise FaultError("%s is not a readable orogen snapshot file: %s" % (path, e)) from e


def main(argv=None):
    p = argparse.ArgumentParser(prog="python3 -m orogen.analysis.faults", description=__doc__.split("\n\n")[0])
    p.add_argument("run", help="a wedge run folder")
    p.add_argument("--window", type=int, default=3, help="outputs the strain is taken over (default 3)")
    p.add_argument("--threshold", type=float, default=0.25,
                   help="sheared: at least this times the 99.5th percentile of the strain (default 0.25)")
    p.add_argument("--min-length", type=float, default=0.5, help="shortest fault [h0] (default 0.5)")
    a = p.parse_args(argv)
    try:
        if not 1 <= a.window <= 100:
            raise FaultError("--window %d: 1 to 100 outputs" % a.window)
        if not 0 < a.threshold < 1:
            raise FaultError("--threshold %g: between 0 and 1" % a.threshold)
        if not 0 < a.min_length <= 10:
            raise FaultError("--min-length %g: above 0, at most 10 h0" % a.min_length)
        outputs = read_outputs(a.run)
        rows = run_faults(outputs, a.window, a.threshold, a.min_length)
        write_faults(a.run, rows)
    except FaultError as e:
        print("error: %s" % e, file=sys.stderr)
        return 2
    print("%d faults in %d outputs: %s" % (len(rows), max(0, len(outputs) - a.window),
                                            os.path.join(a.run, "faults.csv")))
    return 0


if __name__ == "__main__":
    sys.exit(main())
