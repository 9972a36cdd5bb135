"""The surface of a set of discs as the model measures it (MODEL section 8: columns 2.3 mean
radii wide, the top of the highest disc in each; src/analysis/surface.cpp), the least-squares
line and quadratic of a profile (numpy.polyfit, as src/analysis/profile_fit.cpp) and the
critical taper of a dry Coulomb wedge (src/analysis/critical_taper.cpp; Dahlen 1984, MODEL
section 9)."""

import math

import numpy as np

COLUMN_WIDTH_RADII = 2.3  # surface columns 2.3 mean radii wide (MODEL section 8)


def surface_columns(x, y, r, x_lo, x_hi, width=None):
    """Columns [x_lo + k w, x_lo + (k+1) w), w = 2.3 mean radii unless given, up to x_hi:
    returns (centres, heights) with the top y + r of the highest disc, NaN for empty columns."""
    x, y, r = (np.asarray(a, dtype=float) for a in (x, y, r))
    if width is None:
        width = COLUMN_WIDTH_RADII * (float(np.mean(r)) if r.size else 0.5)
    n = max(1, int(math.ceil((x_hi - x_lo) / width)))
    height = np.full(n, -np.inf)
    ok = np.isfinite(x) & np.isfinite(y) & np.isfinite(r) & (x >= x_lo) & (x < x_lo + n * width)
    k = np.clip(np.floor((x[ok] - x_lo) / width).astype(np.int64), 0, n - 1)
    np.maximum.at(height, k, y[ok] + r[ok])
    height[~np.isfinite(height)] = np.nan
    return x_lo + (np.arange(n) + 0.5) * width, height


def fit_line(x, y):
    """Least-squares line through (x, y) as profile_fit.cpp fits it: a dict with n, slope,
    intercept, r2, rms, concavity [rad] (descent angle of a quadratic's tangent at the upper end
    minus at the lower end), x_lo, x_hi; None with fewer than 3 points."""
    x = np.asarray(x, dtype=float)
    y = np.asarray(y, dtype=float)
    n = x.size
    if n < 3 or np.ptp(x) <= 0:
        return None
    slope, intercept = (float(c) for c in np.polyfit(x, y, 1))
    ss_res = float(np.sum((y - (intercept + slope * x)) ** 2))
    syy = float(np.sum((y - y.mean()) ** 2))
    x_lo, x_hi = float(x.min()), float(x.max())
    mx, half = x.mean(), max(0.5 * (x_hi - x_lo), 1e-12)
    q2, q1, _ = np.polyfit((x - mx) / half, y, 2)
    slope_lo = (q1 + 2 * q2 * (x_lo - mx) / half) / half
    slope_hi = (q1 + 2 * q2 * (x_hi - mx) / half) / half
    sign = -1.0 if slope <= 0 else 1.0
    upper, lower = (slope_lo, slope_hi) if slope <= 0 else (slope_hi, slope_lo)
    return dict(n=n, slope=slope, intercept=intercept, r2=1.0 - ss_res / syy if syy > 0 else 1.0,
                rms=math.sqrt(ss_res / n), concavity=math.atan(sign * upper) - math.atan(sign * lower),
                x_lo=x_lo, x_hi=x_hi)


# --------------------------------------------------------------------------------------------
# Critical taper (as src/analysis/critical_taper.cpp)


def critical_taper(phi, phi_b, beta=0.0):
    """Critical surface slope [rad] of a dry, non-cohesive Coulomb wedge of bulk friction angle
    phi on a base of friction angle phi_b dipping at beta (all radians; Dahlen 1984, MODEL
    section 9): solves alpha + beta = psi_b - psi_0 by bisection on (-phi, phi). Raises
    ValueError when phi is not in (0, 90 deg), phi_b not in [0, phi), or no root exists."""
    if not (0 < phi < math.pi / 2):
        raise ValueError("internal friction angle %.4g deg must be in (0, 90) deg" % math.degrees(phi))
    if not (0 <= phi_b < phi):
        raise ValueError("basal friction angle %.4g deg must be at least 0 and below the internal friction "
                         "angle %.4g deg" % (math.degrees(phi_b), math.degrees(phi)))
    psi_b = 0.5 * (math.asin(math.sin(phi_b) / math.sin(phi)) - phi_b)

    def residual(alpha):
        s = max(-1.0, min(1.0, math.sin(alpha) / math.sin(phi)))
        return alpha + beta - psi_b + 0.5 * (math.asin(s) - alpha)

    lo, hi = -phi * (1 - 1e-12), phi * (1 - 1e-12)
    if residual(lo) > 0 or residual(hi) < 0:
        raise ValueError("no critical taper for phi = %.4g deg, phi_b = %.4g deg, basal dip %.4g deg"
                         % (math.degrees(phi), math.degrees(phi_b), math.degrees(beta)))
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if residual(mid) > 0:
            hi = mid
        else:
            lo = mid
    return 0.5 * (lo + hi)


def critical_taper_deg(phi_deg, mu_b):
    """Critical taper [deg] on a flat base for bulk friction angle phi_deg and basal friction
    coefficient mu_b; NaN where there is none (phi_b = atan(mu_b) >= phi, or phi not finite),
    as the biaxial summary's taper_mub*_deg columns."""
    try:
        phi_deg, mu_b = float(phi_deg), float(mu_b)
        if not (math.isfinite(phi_deg) and math.isfinite(mu_b)):
            return float("nan")
        return math.degrees(critical_taper(math.radians(phi_deg), math.atan(mu_b)))
    except (TypeError, ValueError):
        return float("nan")
