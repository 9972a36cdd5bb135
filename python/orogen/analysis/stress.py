#!/usr/bin/python3
"""The stress state inside the pro-wedge (or the retro-wedge) against the critical state of
critical-taper theory (issue 38, point 1).

Reads a wedge run made with `output.stress_grid = h` (the bulk Love-Weber stress on square cells
of side h, docs/output-files.md) and, for every output of the last third of S with a pro front,
takes the cells inside the pro-wedge: between one h0 behind the pro front and one h0 before the
crest (the highest column), at least 1.5 cells below the surface of their column and above the
lowest row of cells (which straddles the base), gathered into squares about h0 / 4 wide (a bulk
stress needs many discs: a single cell of a few discs is mostly fluctuation). With --side retro,
the retro-wedge's cells the same way: between one h0 retro-ward of the crest and one h0 before
the retro front, the layer ahead of it beyond that front, psi mirrored (positive when s1 dips
toward the retro foreland) and the theory on the retro base's mu_br. A singly-vergent
run is read the same way over its late outputs (orogen.analysis.traction), its wedge from one h0
behind its front to one h0 before its backstop. For each square, with compression positive:

- phi_mob: the mobilised friction angle, asin((s1 - s3) / (s1 + s3)); at failure it is the
  material's bulk friction angle, as critical-taper theory assumes everywhere in the wedge;
- psi: the angle of the greatest compression s1 to the base (degrees, positive when s1 dips
  toward the foreland). Dahlen's homogeneous critical wedge has one psi throughout, psi_b =
  (asin(sin phi_b / sin phi) - phi_b) / 2 on a flat base of friction angle phi_b.

Also the solid fraction inside the pro-wedge and in the layer one to three h0 ahead of its
front (the material after accretion against the incoming layer). Prints the medians and
quartiles of phi_mob and psi over all those squares, the solid fractions, the theory's psi_b
for the base's mu_bp at the peak and residual friction angles given with the critical taper
they give, and the late pro taper of the series.

    python3 -m orogen.analysis.stress RUN_DIR [--block D] [--phi 35.6,24.6] [--side retro]
"""
import argparse
import math

import h5py
import numpy as np
import pandas as pd

from .surface import critical_taper_deg
from .traction import base_friction, is_singly, late_outputs, pro_span


def psi_base(phi_deg, mu_b):
    """Dahlen's angle of s1 to a flat base of friction coefficient mu_b [deg]."""
    phi, phi_b = math.radians(phi_deg), math.atan(mu_b)
    return math.degrees(0.5 * (math.asin(math.sin(phi_b) / math.sin(phi)) - phi_b))


def surface_of_columns(x, top, x0, h, columns):
    """Highest disc top per column of the grid (NaN where a column holds no disc centre)."""
    surface = np.full(columns, np.nan)
    col = np.floor((x - x0) / h).astype(int)
    keep = (col >= 0) & (col < columns)
    np.fmax.at(surface, col[keep], top[keep])
    return surface


def blocks(a, b):
    """Means of the b x b blocks of a 2-D array (its trailing rows and columns cut off)."""
    rows, columns = a.shape[0] // b * b, a.shape[1] // b * b
    return a[:rows, :columns].reshape(rows // b, b, columns // b, b).mean(axis=(1, 3))


def regions(g, h0, span, side="pro"):
    """The stress grid's cells (boolean arrays of its shape) inside the pro-wedge, and in the
    layer ahead of it (from three to one h0 before the front), both above the lowest row and
    1.5 cells below the surface of their column; the grid's (cell, x0, y0). `span` is (front,
    back) in h0, the back None for the crest near the S-point. With side "retro", `span` is
    (None, the retro front) and the cells are the retro-wedge's, from one h0 retro-ward of the
    crest (the last of the highest columns beyond -2 h0) to one h0 before the retro front, the
    layer ahead one to three h0 beyond it."""
    grid = g["stress_grid"]
    h, x0, y0 = float(grid.attrs["cell"]), float(grid.attrs["x0"]), float(grid.attrs["y0"])
    rows, columns = grid["xx"].shape
    x, y, r = g["x"][()], g["y"][()], g["radius"][()]
    surface = surface_of_columns(x, y + r, x0, h, columns)
    xc = x0 + (np.arange(columns) + 0.5) * h
    yc = y0 + (np.arange(rows) + 0.5) * h
    X, Y = np.meshgrid(xc, yc)
    deep = (Y - 0.5 * h > y0 + h) & (Y < surface[None, :] - 1.5 * h)
    front, back = span
    if side == "retro":
        heights = np.where(xc > -2 * h0, surface, -np.inf)
        crest = xc[len(xc) - 1 - np.nanargmax(heights[::-1])]
        inside = (X > crest + h0) & (X < back * h0 - h0) & deep
        ahead = (X > back * h0 + h0) & (X < back * h0 + 3 * h0) & deep
        return inside, ahead, (h, x0, y0)
    back = xc[np.nanargmax(np.where(xc < 2 * h0, surface, -np.inf))] if back is None else back * h0
    inside = (X > front * h0 + h0) & (X < back - h0) & deep
    ahead = (X > front * h0 - 3 * h0) & (X < front * h0 - h0) & deep
    return inside, ahead, (h, x0, y0)


def wedge_cells(g, region, block, mirror=False):
    """(phi_mob, psi) in degrees of the wedge's interior blocks of one output (`region`:
    regions()): the grid's cells (additive: a block's stress is the mean of its cells') gathered
    into squares about `block` d wide, so that each holds enough discs for a bulk stress.
    `mirror` (the retro-wedge): psi measured as if the wedge were turned over, positive when s1
    dips toward its own foreland (+x)."""
    grid = g["stress_grid"]
    pxx, pyy = -grid["xx"][()], -grid["yy"][()]
    pxy = -0.5 * (grid["xy"][()] + grid["yx"][()])
    inside, _, (h, _, _) = region
    b = max(1, int(round(block / h)))
    full = blocks(inside.astype(float), b) == 1.0
    pxx, pyy, pxy = blocks(pxx, b)[full], blocks(pyy, b)[full], blocks(pxy, b)[full]
    centre = 0.5 * (pxx + pyy)
    radius = np.hypot(0.5 * (pxx - pyy), pxy)
    pressed = centre > 0
    phi_mob = np.degrees(np.arcsin(np.clip(radius[pressed] / centre[pressed], 0, 1)))
    # s1 from +x, anticlockwise: positive when s1 rises toward the hinterland (+x), that is,
    # dips toward the foreland, as a base dragging the wedge toward the S-point tilts it
    # (forethrusts shallower than backthrusts)
    psi = 0.5 * np.degrees(np.arctan2(2 * pxy[pressed], pxx[pressed] - pyy[pressed]))
    return phi_mob, -psi if mirror else psi


def solid_fractions(g, region):
    """(inside the pro-wedge, in the layer ahead of it; `region`: regions()): the area of the
    discs whose centres lie in the region's cells over the cells' area (NaN for a region of no
    cells): how much the material has dilated or compacted since it was the incoming layer."""
    inside, ahead, (h, x0, y0) = region
    x, y, r = g["x"][()], g["y"][()], g["radius"][()]
    row, col = np.floor((y - y0) / h).astype(int), np.floor((x - x0) / h).astype(int)
    on_grid = (row >= 0) & (row < inside.shape[0]) & (col >= 0) & (col < inside.shape[1])
    area = np.pi * r[on_grid] ** 2
    row, col = row[on_grid], col[on_grid]

    def fraction(mask):
        return area[mask[row, col]].sum() / (mask.sum() * h * h) if mask.any() else np.nan

    return fraction(inside), fraction(ahead)


def measure(run, block=None, side="pro"):
    """(configuration, the late outputs' series rows with their solid fractions `solid_wedge`
    and `solid_ahead`, the interior squares' phi_mob and psi), of the pro-wedge or, with side
    "retro", the retro-wedge of a doubly-vergent run."""
    series, h0, config, late = late_outputs(run)
    if side == "retro" and is_singly(config):
        raise SystemExit(f"{run}: a singly-vergent wedge has no retro side")
    block = 0.25 * h0 if block is None else block
    cells, fractions = [], []
    with h5py.File(f"{run}/snapshots.h5", "r") as f:
        for k in late:
            g = f["output_%06d" % k]
            if "stress_grid" not in g:
                raise SystemExit(f"{run}: output {k} has no stress grid (run with --set output.stress_grid=2)")
            if side == "retro":
                span = (None, series["Dr"].iloc[k])
            else:
                front, back = pro_span(series, config, k)
                span = (front, back if is_singly(config) else None)
            region = regions(g, h0, span, side)
            phi_mob, psi = wedge_cells(g, region, block, mirror=side == "retro")
            cells += [{"output": k, "phi_mob": a, "psi": b} for a, b in zip(phi_mob, psi)]
            fractions.append(solid_fractions(g, region))
    late_rows = series.iloc[late].copy()
    late_rows["solid_wedge"], late_rows["solid_ahead"] = zip(*fractions)
    return config, late_rows, pd.DataFrame(cells)


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("run", help="a wedge run folder made with output.stress_grid > 0")
    p.add_argument("--block", type=float, help="width of the squares the stress is averaged over [d] (default h0 / 4)")
    p.add_argument("--phi", default="35.6,24.6",
                   help="peak and residual bulk friction angles of the material [deg] (default: the clusters')")
    p.add_argument("--side", choices=("pro", "retro"), default="pro",
                   help="the pro-wedge (default) or the retro-wedge of a doubly-vergent run")
    args = p.parse_args()
    config, late, cells = measure(args.run, args.block, args.side)
    retro = args.side == "retro"
    mu_b = config["wedge"]["mu_br"] if retro else base_friction(config)
    if cells.empty:
        raise SystemExit(f"{args.run}: no interior cells in the {args.side}-wedge (is the wedge thicker than a few cells?)")
    print(f"{args.run}: {len(late)} outputs, {len(cells)} interior {args.side}-wedge squares, "
          f"{'mu_br' if retro else 'mu_bp'} {mu_b}")
    for name in ("phi_mob", "psi"):
        q = cells[name].quantile([0.25, 0.5, 0.75])
        print(f"  {name}: median {q[0.5]:.1f} deg, quartiles {q[0.25]:.1f}-{q[0.75]:.1f}")
    print(f"  solid fraction: inside the {args.side}-wedge {late['solid_wedge'].mean():.3f}, in the layer 1-3 h0 "
          f"ahead of its front {late['solid_ahead'].mean():.3f}")
    for phi in (float(v) for v in args.phi.split(",")):
        print(f"  critical wedge of phi {phi:.1f} deg on mu_b {mu_b}: phi_mob {phi:.1f}, psi_b {psi_base(phi, mu_b):.1f} deg, "
              f"taper {critical_taper_deg(phi, mu_b):.1f} deg")
    if is_singly(config):
        print(f"  late taper {late['taper'].mean():.2f} deg, height {late['height'].mean():.2f} h0")
    elif retro:
        print(f"  late retro taper beta {late['beta'].mean():.2f} deg, H {late['H'].mean():.2f} h0")
    else:
        print(f"  late pro taper alpha {late['alpha'].mean():.2f} deg, H {late['H'].mean():.2f} h0")


if __name__ == "__main__":
    main()
