#!/usr/bin/python3
"""The stress state inside the pro-wedge against the critical state of critical-taper theory
(issue 38, point 1).

Reads a wedge run made with `output.stress_grid = h` (the bulk Love-Weber stress on square cells
of side h, docs/output-files.md) and, for every output of the last third of S with a pro front,
takes the cells inside the pro-wedge: between one h0 behind the pro front and one h0 before the
crest (the highest column), at least 1.5 cells below the surface of their column and above the
lowest row of cells (which straddles the base), gathered into squares about h0 / 4 wide (a bulk
stress needs many discs: a single cell of a few discs is mostly fluctuation). For each square,
with compression positive:

- phi_mob: the mobilised friction angle, asin((s1 - s3) / (s1 + s3)); at failure it is the
  material's bulk friction angle, as critical-taper theory assumes everywhere in the wedge;
- psi: the angle of the greatest compression s1 to the base (degrees, positive when s1 dips
  toward the foreland). Dahlen's homogeneous critical wedge has one psi throughout, psi_b =
  (asin(sin phi_b / sin phi) - phi_b) / 2 on a flat base of friction angle phi_b.

Prints their medians and quartiles over all those squares, the theory's psi_b for the base's
mu_bp at the peak and residual friction angles given, and the late pro taper of the series.

    python3 -m orogen.analysis.stress RUN_DIR [--block D] [--phi 35.6,24.6]
"""
import argparse
import math

import h5py
import numpy as np
import pandas as pd

from .traction import late_outputs


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


def pro_wedge_cells(g, h0, dp, block):
    """(phi_mob, psi) in degrees of the pro-wedge's interior blocks of one output: the grid's
    cells (additive: a block's stress is the mean of its cells') gathered into squares about
    `block` d wide, so that each holds enough discs for a bulk stress."""
    grid = g["stress_grid"]
    h, x0, y0 = float(grid.attrs["cell"]), float(grid.attrs["x0"]), float(grid.attrs["y0"])
    pxx, pyy = -grid["xx"][()], -grid["yy"][()]
    pxy = -0.5 * (grid["xy"][()] + grid["yx"][()])
    rows, columns = pxx.shape
    x, y, r = g["x"][()], g["y"][()], g["radius"][()]
    surface = surface_of_columns(x, y + r, x0, h, columns)
    xc = x0 + (np.arange(columns) + 0.5) * h
    yc = y0 + (np.arange(rows) + 0.5) * h
    crest = xc[np.nanargmax(np.where(xc < 2 * h0, surface, -np.inf))]
    X, Y = np.meshgrid(xc, yc)
    inside = (X > dp * h0 + h0) & (X < crest - h0) & (Y - 0.5 * h > y0 + h) & (Y < surface[None, :] - 1.5 * h)
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
    return phi_mob, psi


def measure(run, block=None):
    series, h0, config, late = late_outputs(run)
    block = 0.25 * h0 if block is None else block
    cells = []
    with h5py.File(f"{run}/snapshots.h5", "r") as f:
        for k in late:
            g = f["output_%06d" % k]
            if "stress_grid" not in g:
                raise SystemExit(f"{run}: output {k} has no stress grid (run with --set output.stress_grid=2)")
            phi_mob, psi = pro_wedge_cells(g, h0, series["Dp"].iloc[k], block)
            cells += [{"output": k, "phi_mob": a, "psi": b} for a, b in zip(phi_mob, psi)]
    return config, series.iloc[late], pd.DataFrame(cells)


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("run", help="a wedge run folder made with output.stress_grid > 0")
    p.add_argument("--block", type=float, help="width of the squares the stress is averaged over [d] (default h0 / 4)")
    p.add_argument("--phi", default="35.6,24.6",
                   help="peak and residual bulk friction angles of the material [deg] (default: the clusters')")
    args = p.parse_args()
    config, late, cells = measure(args.run, args.block)
    mu_bp = config["wedge"]["mu_bp"]
    if cells.empty:
        raise SystemExit(f"{args.run}: no interior cells in the pro-wedge (is the wedge thicker than a few cells?)")
    print(f"{args.run}: {len(late)} outputs, {len(cells)} interior pro-wedge squares, mu_bp {mu_bp}")
    for name in ("phi_mob", "psi"):
        q = cells[name].quantile([0.25, 0.5, 0.75])
        print(f"  {name}: median {q[0.5]:.1f} deg, quartiles {q[0.25]:.1f}-{q[0.75]:.1f}")
    for phi in (float(v) for v in args.phi.split(",")):
        print(f"  critical wedge of phi {phi:.1f} deg on mu_bp {mu_bp}: phi_mob {phi:.1f}, psi_b {psi_base(phi, mu_bp):.1f} deg")
    print(f"  late pro taper alpha {late['alpha'].mean():.2f} deg, H {late['H'].mean():.2f} h0")


if __name__ == "__main__":
    main()
