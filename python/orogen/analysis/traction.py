#!/usr/bin/python3
"""What the bases of a wedge run transmit (issue 38, "is the base at its Coulomb limit?").

Reads a wedge run made with `output.contacts = true` and, for every output of the last third of
S (the late wedge), sums the disc-wall contact forces of the pro base between the pro
deformation front and the S-point, and of the retro base between the S-point and the retro
front:

- mu_pro, mu_retro: the friction the base transmits, sum(fx) / sum(fy) over those contacts
  (for the retro base -sum(fx) / sum(fy): it holds the wedge back), to set beside
  wedge.mu_bp and wedge.mu_br;
- at_limit_pro, at_limit_retro: the share of those contacts whose tangential force sits on the
  Coulomb limit mu fn;
- slip_pro: the median slip of the pro contacts against the plate, (v_contact - v) / v, with
  v_contact = vx + omega r at the disc's lowest point, for the contacts below and at the limit.

Prints the mean, standard deviation and range over the outputs.

    python3 -m orogen.analysis.traction RUN_DIR
"""
import argparse
import tomllib

import h5py
import numpy as np
import pandas as pd


def late_outputs(run):
    """(series, h0, configuration, indices of the outputs in the last third of S with a front)."""
    series = pd.read_csv(f"{run}/series.csv", comment="#")
    with h5py.File(f"{run}/snapshots.h5", "r") as f:
        h0 = float(f.attrs["h0"])
        text = f.attrs["config_toml"]
    config = tomllib.loads(text.decode() if isinstance(text, bytes) else text)
    s_end = config["wedge"]["s_end"]
    late = [k for k in range(len(series)) if series["S"].iloc[k] >= s_end * 2 / 3 and series["Dp"].iloc[k] < -0.5]
    if not late:
        raise SystemExit(f"{run}: no output in the last third of S has a pro front (Dp < -0.5 h0): "
                         "nothing to measure; run the wedge further")
    return series, h0, config, late


def base_rows(walls):
    """Rows of the pro and retro bases in an output's `walls`: every wall that is not vertical
    (the retro end wall is), the pro base's ending at or before the S-point. A rigid base is one
    wall each side on y = 0; a deflecting one (docs/isostasy.md) is segments, nearly level, whose
    x and y forces this analysis takes as the base's shear and normal ones."""
    base = [i for i, w in enumerate(walls) if w[0] != w[2]]
    pro = [i for i in base if max(walls[i][0], walls[i][2]) <= 0]
    return pro, [i for i in base if i not in pro]


def measure(run):
    series, h0, config, late = late_outputs(run)
    v = config["wedge"]["speed"]
    rows, slips = [], []
    with h5py.File(f"{run}/snapshots.h5", "r") as f:
        for k in late:
            g = f["output_%06d" % k]
            if "contacts" not in g:
                raise SystemExit(f"{run}: output {k} has no contacts (run with --set output.contacts=true)")
            pro, retro = base_rows(g["walls"][()])
            c = g["contacts"]
            wall, wall_row = c["is_wall"][()] == 1, c["id_a"][()]
            x, fx, fy, limit = c["x"][()] / h0, c["fx"][()], c["fy"][()], c["at_limit"][()]
            on_pro = wall & np.isin(wall_row, pro) & (x > series["Dp"].iloc[k]) & (x < 0)
            on_retro = wall & np.isin(wall_row, retro) & (x > 0) & (x < series["Dr"].iloc[k])
            rows.append({"mu_pro": fx[on_pro].sum() / fy[on_pro].sum(), "at_limit_pro": limit[on_pro].mean(),
                         "mu_retro": -fx[on_retro].sum() / fy[on_retro].sum() if on_retro.any() else np.nan,
                         "at_limit_retro": limit[on_retro].mean() if on_retro.any() else np.nan})
            disc = c["index_b"][()][on_pro]
            slip = (g["vx"][()][disc] + g["omega"][()][disc] * g["radius"][()][disc] - v) / v
            slips += list(zip(limit[on_pro], slip))
    table = pd.DataFrame(rows)
    slip = pd.DataFrame(slips, columns=["at_limit", "slip"])
    return config, late, series, table, slip


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("run", help="a wedge run folder made with output.contacts = true")
    args = p.parse_args()
    config, late, series, table, slip = measure(args.run)
    w = config["wedge"]
    law = w.get("traction_law", "drag")  # a run before the key dragged the layer by eq. 4.1
    base = f"traction_law {law}" + (f", gamma_b {w['gamma_b']}" if law == "drag" else "")
    print(f"{args.run}: {w['basal']}, mu_bp {w['mu_bp']}, mu_br {w['mu_br']}, {base}, "
          f"{len(late)} outputs, S {series['S'].iloc[late[0]]:.2f}-{series['S'].iloc[late[-1]]:.2f}")
    for name in table.columns:
        col = table[name]
        print(f"  {name}: mean {col.mean():.3f}, sd {col.std():.3f}, range {col.min():.3f}-{col.max():.3f}")
    for at_limit, group in slip.groupby("at_limit"):
        print(f"  slip_pro of the contacts {'at' if at_limit else 'below'} the limit: median {group.slip.median():.2f} v "
              f"({len(group)} contacts)")
    tapers = series.iloc[late]
    print(f"  late pro taper alpha {tapers['alpha'].mean():.2f} deg, retro beta {tapers['beta'].mean():.2f} deg, "
          f"H {tapers['H'].mean():.2f} h0")


if __name__ == "__main__":
    main()
