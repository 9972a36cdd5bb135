"""Thrust-sheet cycles from a front's position (Naylor 2004, sections 5.4.5-5.4.7).

A new pro thrust sheet shows as a sudden outward jump of the pro deformation front Dp,
followed by a slow retreat while the sheet is shortened and carried inward (the saw-tooth of
Fig. 5.23); the retro front steps out too, less often.

Detection rule (docs/ensembles.md): with p the front's outward distance from the S-point
(-Dp on the pro side, +Dr on the retro side, in h0), every output i whose rise
p[i] - p[i-1] exceeds `step_min` (default 0.5 h0) is part of a step-out; consecutive such
outputs are one step-out (a jump caught across two outputs). Its size is the rise over the
run of outputs, its S the S of its first output. Between outputs the steady growth of the
wedge moves a front by a few hundredths of h0 and the retreat moves it inward, so only a new
sheet (or a Stage 3 retro accretion) passes the threshold. Outputs where the front is
missing (no front yet) break a run and are never steps.
"""

import numpy as np


def outward(series_front, side):
    """The front's outward distance: -x on the pro side, +x on the retro side."""
    x = np.asarray(series_front, dtype=float)
    return -x if side == "pro" else x


def step_outs(s, p, step_min=0.5):
    """Step-outs of an outward distance p(s): a list of dicts with first, last (output
    indices: the jump runs from output first-1 to last), S (at `first`), size (the rise, h0)."""
    s = np.asarray(s, dtype=float)
    p = np.asarray(p, dtype=float)
    rise = np.full(p.size, np.nan)
    if p.size > 1:
        rise[1:] = p[1:] - p[:-1]
    jump = np.isfinite(rise) & (rise > step_min)
    events = []
    i = 0
    while i < p.size:
        if not jump[i]:
            i += 1
            continue
        first = i
        while i + 1 < p.size and jump[i + 1]:
            i += 1
        events.append(dict(first=int(first), last=int(i), S=float(s[first]), size=float(p[i] - p[first - 1])))
        i += 1
    return events


def convergence_speed(s, time):
    """dS/dt (h0 per model time unit), the median over the outputs; NaN if it cannot be told."""
    s = np.asarray(s, dtype=float)
    t = np.asarray(time, dtype=float)
    ds, dt = np.diff(s), np.diff(t)
    ok = np.isfinite(ds) & np.isfinite(dt) & (dt > 0)
    return float(np.median(ds[ok] / dt[ok])) if ok.any() else float("nan")


def retreat_rate(s, p, events):
    """Mean slope dp/dS between step-outs (negative: the front moves inward), least squares
    over the outputs that are not part of a jump, each stretch with its own intercept."""
    s = np.asarray(s, dtype=float)
    p = np.asarray(p, dtype=float)
    bounds = [0] + [e["first"] for e in events] + [p.size]
    starts = [0] + [e["last"] for e in events]
    stretches = []  # (s, p) of each stretch with at least 2 finite outputs
    for k, start in enumerate(starts):
        ss, pp = s[start:bounds[k + 1]], p[start:bounds[k + 1]]
        ok = np.isfinite(ss) & np.isfinite(pp)
        if ok.sum() >= 2:
            stretches.append((ss[ok], pp[ok]))
    if not stretches or all(np.ptp(ss) <= 0 for ss, _ in stretches):
        return float("nan")
    # One common slope, one intercept per stretch: columns s, then an indicator per stretch.
    sizes = [len(ss) for ss, _ in stretches]
    design = np.zeros((sum(sizes), 1 + len(stretches)))
    design[:, 0] = np.concatenate([ss for ss, _ in stretches])
    design[np.arange(sum(sizes)), 1 + np.repeat(np.arange(len(stretches)), sizes)] = 1.0
    coef = np.linalg.lstsq(design, np.concatenate([pp for _, pp in stretches]), rcond=None)[0]
    return float(coef[0])


def cycles(s, time, front, side, step_min=0.5):
    """Step-outs of one front with spacing in S, sheet length l (the step size) and the
    time-scale l/v; plus a summary dict."""
    p = outward(front, side)
    events = step_outs(s, p, step_min)
    v = convergence_speed(s, time)
    prev = None
    for e in events:
        e["spacing"] = e["S"] - prev if prev is not None else float("nan")
        e["time_scale"] = e["size"] / v if v > 0 else float("nan")
        prev = e["S"]
    spacing = np.array([e["spacing"] for e in events[1:]], dtype=float)
    sizes = np.array([e["size"] for e in events], dtype=float)
    summary = dict(
        n_steps=len(events),
        mean_spacing=float(spacing.mean()) if spacing.size else float("nan"),
        std_spacing=float(spacing.std(ddof=1)) if spacing.size > 1 else float("nan"),
        mean_size=float(sizes.mean()) if sizes.size else float("nan"),
        mean_time_scale=float(sizes.mean() / v) if sizes.size and v > 0 else float("nan"),
        speed=v,
        retreat_rate=retreat_rate(s, p, events),
    )
    return events, summary
