"""Power-law trends of wedge growth (Naylor 2004, sections 5.2 and 5.4.6; MODEL.md section 9).

Shared by orogen.charts.wedge (one run's H(S)) and orogen.stats (an ensemble's mean fronts):

    power_law_fit(s, x, s_min)      least squares of log x = log a + b log s over s > s_min
    auto_offset(s, x, s_min)        the offset x0 for which x - x0 is most nearly a power law
    simple_model_height(s, a, b)    eq. 5.4, H/h0 from the tapers alpha, beta [deg]
    simple_model_coefficient(a, b)  the coefficient C of eq. 5.4

The fits are numpy's least squares (numpy.polyfit); the offset search is a golden-section
search on 1 - R^2 (a bracket widened by hand: scipy's minimisers need one to start from).
"""

import math

import numpy as np


def power_law_fit(s, h, s_min=0.5):
    """Least-squares fit of h = a s^b in log-log space over s > s_min, h > 0.

    Returns a dict with a, a_se, b, b_se, r2, n, s_min, residual_se (standard errors from the
    residual variance, a_se by the delta method from the standard error of log a;
    residual_se the residual standard error in natural-log units, i.e. a relative scatter),
    or None with fewer than 3 usable points."""
    s = np.asarray(s, dtype=float)
    h = np.asarray(h, dtype=float)
    ok = np.isfinite(s) & np.isfinite(h) & (s > s_min) & (h > 0)
    n = int(ok.sum())
    if n < 3:
        return None
    lx, ly = np.log(s[ok]), np.log(h[ok])
    if np.ptp(lx) <= 0:
        return None
    # Least squares by numpy; cov: the coefficients' covariance scaled by the residual variance
    # ss_res / (n - 2), so its diagonal holds the squared standard errors of b and log a.
    (b, c), cov = np.polyfit(lx, ly, 1, cov=True)
    b, c = float(b), float(c)
    ss_res = float(np.sum((ly - (c + b * lx)) ** 2))
    ss_tot = float(np.sum((ly - ly.mean()) ** 2))
    sigma2 = ss_res / (n - 2)
    b_se, c_se = math.sqrt(cov[0, 0]), math.sqrt(cov[1, 1])
    a = math.exp(c)
    r2 = 1.0 - ss_res / ss_tot if ss_tot > 0 else 1.0
    return dict(a=a, a_se=a * c_se, log_a=c, log_a_se=c_se, b=b, b_se=b_se, r2=r2, n=n, s_min=s_min,
                residual_se=math.sqrt(sigma2))


MAX_SPANS = 8.0


def _log_rss(s, x, x0):
    # 1 - R^2, not the residual sum: as x0 -> -inf, log(x - x0) flattens and its residuals
    # vanish, whereas R^2 tends to that of a straight line in log s, short of a power law's 1.
    fit = power_law_fit(s, x - x0, s_min=-math.inf)
    if fit is None:
        return math.inf
    return 1.0 - fit["r2"]


def auto_offset(s, x, s_min=0.0, iterations=200):
    """The offset x0 such that x - x0 = a s^b fits best (least squares in log-log space), over
    s > s_min where x is finite: the power law's own value at s = 0, i.e. the trend
    extrapolated back to S = 0 (thesis 5.4.6, step 2, which did this by eye).

    x must grow with s (the magnitude of a front, not its signed position). The search runs
    over x0 < min(x) (minimising 1 - R^2 of the log-log fit) by golden sections on a bracket
    that is widened until the minimum lies inside it; for an exact shifted power law it returns the shift to rounding. Returns 0.0
    with fewer than 4 usable points."""
    s = np.asarray(s, dtype=float)
    x = np.asarray(x, dtype=float)
    ok = np.isfinite(s) & np.isfinite(x) & (s > max(s_min, 0.0))
    s, x = s[ok], x[ok]
    if s.size < 4:
        return 0.0
    top = float(np.min(x))
    span = max(float(np.max(x) - top), 1e-12)
    hi = top - 1e-9 * span  # x - x0 must stay positive
    lo = top - span
    # Widen downward while the error still falls there, up to MAX_SPANS spans below the data:
    # farther, the series grows like ln S (the b -> 0 limit) and has no offset to find.
    while _log_rss(s, x, lo) <= _log_rss(s, x, lo + 0.1 * (hi - lo)):
        if top - lo >= MAX_SPANS * span:
            return float("nan")
        lo = max(hi - 2.0 * (hi - lo), top - MAX_SPANS * span)
    g = (math.sqrt(5.0) - 1.0) / 2.0
    a, b = lo, hi
    c, d = b - g * (b - a), a + g * (b - a)
    fc, fd = _log_rss(s, x, c), _log_rss(s, x, d)
    for _ in range(iterations):
        if fc < fd:
            b, d, fd = d, c, fc
            c = b - g * (b - a)
            fc = _log_rss(s, x, c)
        else:
            a, c, fc = c, d, fd
            d = a + g * (b - a)
            fd = _log_rss(s, x, d)
        if b - a <= 1e-14 * max(1.0, abs(a)):
            break
    return float(0.5 * (a + b))


def simple_model_coefficient(alpha_deg, beta_deg):
    """C(alpha, beta) = sqrt(2 tan a tan b / (tan a + tan b)) of eq. 5.4, or None."""
    if not (np.isfinite(alpha_deg) and np.isfinite(beta_deg)):
        return None
    ta, tb = math.tan(math.radians(alpha_deg)), math.tan(math.radians(beta_deg))
    if ta <= 0 or tb <= 0:
        return None
    return math.sqrt(2.0 * ta * tb / (ta + tb))


def simple_model_height(s, alpha_deg, beta_deg):
    """Simple Model (eq. 5.4, MODEL section 9): H/h0 = sqrt(2 tan a tan b / (tan a + tan b) S)."""
    c = simple_model_coefficient(alpha_deg, beta_deg)
    if c is None:
        return None
    return c * np.sqrt(np.clip(np.asarray(s, dtype=float), 0, None))
