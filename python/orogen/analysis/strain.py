"""The incremental shear strain of a granular packing between two outputs, per disc: the local
deformation gradient F of each disc from its neighbours within STRAIN_NEIGHBOURS_H0 (at least
STRAIN_NEIGHBOURS_MIN_D d: the second shell of discs), by least squares over the neighbour
pairs (F = W V^-1, V = sum d0 d0^T, W = sum d1 d0^T), and from the Green-Lagrange strain
E = (F^T F - I) / 2 its maximum shear strain, the radius of its Mohr circle,
sqrt(((E_xx - E_yy) / 2)^2 + E_xy^2). Used by the fault frames (orogen.charts.sections) and
the fault picker (orogen.analysis.faults).
"""

import numpy as np

STRAIN_NEIGHBOURS_H0 = 0.2   # neighbours for the local deformation gradient: within 0.2 h0,
STRAIN_NEIGHBOURS_MIN_D = 1.5  # and at least 1.5 d (the second shell of discs)


def matched(before, after):
    """For each disc of `after`, its index in `before` (by id) and whether it was there."""
    order = np.argsort(before["id"])
    pos = np.clip(np.searchsorted(before["id"], after["id"], sorter=order), 0, len(order) - 1)
    prev = order[pos]
    return prev, before["id"][prev] == after["id"]


def shear_strain(before, after, radius=None):
    """The incremental maximum shear strain of each disc of `after` since `before` (outputs as
    dicts of x, y, id in h0 and h0 in d; module docstring); NaN for discs not in `before` or
    with fewer than two neighbours."""
    from scipy.spatial import cKDTree

    if radius is None:  # in h0, as the positions
        radius = max(STRAIN_NEIGHBOURS_H0, STRAIN_NEIGHBOURS_MIN_D / after["h0"])
    n = len(after["x"])
    strain = np.full(n, np.nan)
    prev, known = matched(before, after)
    idx = np.flatnonzero(known)
    if idx.size < 3:
        return strain
    X = np.column_stack([before["x"][prev[idx]], before["y"][prev[idx]]])
    x = np.column_stack([after["x"][idx], after["y"][idx]])
    pairs = cKDTree(X).query_pairs(radius, output_type="ndarray")
    if len(pairs) == 0:
        return strain
    i, j = pairs[:, 0], pairs[:, 1]
    d0 = X[j] - X[i]
    d1 = x[j] - x[i]
    m = len(idx)

    def summed(a, b):  # sum over each disc's pairs of a b^T (the pair counts for both discs)
        out = np.zeros((m, 2, 2))
        for r in range(2):
            for c in range(2):
                w = a[:, r] * b[:, c]
                out[:, r, c] = np.bincount(i, w, m) + np.bincount(j, w, m)
        return out

    V = summed(d0, d0)
    W = summed(d1, d0)
    count = np.bincount(i, minlength=m) + np.bincount(j, minlength=m)
    det = V[:, 0, 0] * V[:, 1, 1] - V[:, 0, 1] * V[:, 1, 0]
    ok = (count >= 2) & (det > 1e-12 * np.maximum(V[:, 0, 0] * V[:, 1, 1], 1e-300))
    Vinv = np.zeros_like(V)
    Vinv[ok, 0, 0] = V[ok, 1, 1] / det[ok]
    Vinv[ok, 1, 1] = V[ok, 0, 0] / det[ok]
    Vinv[ok, 0, 1] = -V[ok, 0, 1] / det[ok]
    Vinv[ok, 1, 0] = -V[ok, 1, 0] / det[ok]
    F = W @ Vinv
    C = np.transpose(F, (0, 2, 1)) @ F
    exx, eyy, exy = (C[:, 0, 0] - 1) / 2, (C[:, 1, 1] - 1) / 2, C[:, 0, 1] / 2
    eta = np.sqrt(((exx - eyy) / 2) ** 2 + exy ** 2)
    strain[idx[ok]] = eta[ok]
    return strain
