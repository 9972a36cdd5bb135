"""A synthetic ensemble folder (what `orogen ensemble` leaves) for the statistics and chart
tests: members whose fronts are a power law with an offset plus a saw-tooth of step-outs."""

import os

import numpy as np


def sawtooth_front(s, step_every, step_size, retreat, start):
    """Outward distance: jumps of step_size at start, start + step_every, ...; retreat per S between."""
    p = np.zeros_like(s)
    level, last = 0.0, s[0]
    steps = []
    for i, x in enumerate(s):
        if x >= start + len(steps) * step_every:
            level += step_size
            steps.append(i)
        p[i] = level + retreat * (x - s[0])
    return p, steps


def write_member(folder, name, s, cols):
    os.makedirs(os.path.join(folder, "members", name), exist_ok=True)
    names = ["step", "time", "S"] + list(cols)
    with open(os.path.join(folder, "members", name, "series.csv"), "w") as f:
        f.write("# synthetic\n" + ",".join(names) + "\n")
        for i in range(len(s)):
            row = [str(i), repr(float(s[i]) / 0.5), repr(float(s[i]))] + [repr(float(cols[c][i])) for c in cols]
            f.write(",".join(row) + "\n")


def make_ensemble(folder, n_members=4, n_outputs=200, s_end=21.0, seed=1):
    rng = np.random.default_rng(seed)
    s = np.linspace(0.0, s_end, n_outputs + 1)[1:]
    names = [f"seed{k + 1}" for k in range(n_members)]
    for k, name in enumerate(names):
        noise = lambda: rng.normal(0.0, 0.02, s.size)  # noqa: E731
        cols = {
            "H": 0.4 * s ** 0.5 + noise(),
            "Dp": -(1.0 + 2.0 * s ** 0.5) + noise(),
            "Mp": -(0.5 + 1.5 * s ** 0.5) + noise(),
            "Dr": 0.8 + 1.0 * s ** 0.5 + noise(),
            "Mr": 0.4 + 0.8 * s ** 0.5 + noise(),
            "T": -0.2 + noise(),
            "alpha": np.full(s.size, 8.0) + noise(),
            "beta": np.full(s.size, 30.0) + noise(),
        }
        write_member(folder, name, s, cols)
    with open(os.path.join(folder, "ensemble.toml"), "w") as f:
        f.write('[ensemble]\nfile = "synthetic.toml"\ntitle = "synthetic"\n\n[stats]\ns_min = 2.0\nstep_min = 0.5\n'
                'sheet_reference = 5.0\n\n[stats.offset]\nDp = "auto"\nMp = "auto"\nDr = "auto"\nMr = "auto"\n'
                'H = "none"\nT = "auto"\n')
        for k, name in enumerate(names):
            f.write(f'\n[[member]]\nname = "{name}"\ngroup = ""\nseed = {k + 1}\npreset = "x.toml"\noverrides = []\n')
    with open(os.path.join(folder, "members.csv"), "w") as f:
        f.write("# synthetic\nname,group,seed,exit_status,error\n")
        for k, name in enumerate(names):
            f.write(f"{name},,{k + 1},0,\n")
    return names
