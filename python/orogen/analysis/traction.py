#!/usr/bin/python3
"""What the bases of a wedge run transmit (issue 38, "is the base at its Coulomb limit?").

Reads a wedge run made with `output.contacts = true` and, for every output of the last third of
S (the late wedge), sums the disc-wall contact forces of the pro base between the pro
deformation front and the S-point, and of the retro base between the S-point and the retro
front. A singly-vergent run (`run.experiment = "singly_vergent"`) is read the same way: its
outputs after `singly.steady_from` of the shortening (those its steady taper averages), its
floor between the front and the backstop as the pro base (`singly.mu_b`), no retro base:

- mu_pro, mu_retro: the friction the base transmits, sum(fx) / sum(fy) over those contacts
  (for the retro base -sum(fx) / sum(fy): it holds the wedge back), to set beside
  wedge.mu_bp and wedge.mu_br;
- at_limit_pro, at_limit_retro: the share of those contacts whose tangential force sits on the
  Coulomb limit mu fn;
- with --bins N, the same along the pro base in N equal parts from the front to the S-point (or
  the backstop), and along the retro base from the S-point to the retro front, all late outputs
  together: where under the wedge the base is at its limit;
- slip_pro: the median slip of the pro contacts against the plate, (v_contact - v) / v, with
  v_contact = vx + omega r at the disc's lowest point, for the contacts below and at the limit
  (the singly-vergent floor stands still: v_contact / v with v the backstop's speed, -1 for a
  disc that moves with the backstop, 0 for one stuck to the floor);
- slip_retro: the same for the retro base, which stands still (v_contact / v: 0 for a disc held
  by it, above 0 for one pushed over it towards the retro front).

Prints the mean, standard deviation and range over the outputs.

    python3 -m orogen.analysis.traction RUN_DIR
"""
import argparse
import tomllib

import h5py
import numpy as np
import pandas as pd


def is_singly(config):
    return config.get("run", {}).get("experiment") == "singly_vergent"


def base_friction(config):
    """The friction coefficient of the (pro) base: wedge.mu_bp, or a singly-vergent run's mu_b."""
    return config["singly"]["mu_b"] if is_singly(config) else config["wedge"]["mu_bp"]


def late_outputs(run):
    """(series, h0, configuration, indices of the late outputs with a wedge): the doubly-vergent
    wedge's outputs in the last third of S with a pro front (Dp < -0.5 h0); the singly-vergent
    wedge's after singly.steady_from of its shortening with a wedge (width > 0.5 h0)."""
    series = pd.read_csv(f"{run}/series.csv", comment="#")
    with h5py.File(f"{run}/snapshots.h5", "r") as f:
        h0 = float(f.attrs["h0"])
        text = f.attrs["config_toml"]
    config = tomllib.loads(text.decode() if isinstance(text, bytes) else text)
    if is_singly(config):
        s = config["singly"]
        late = [k for k in range(len(series))
                if series["shortening"].iloc[k] >= s["steady_from"] * s["shortening"] and series["width"].iloc[k] > 0.5]
    else:
        s_end = config["wedge"]["s_end"]
        late = [k for k in range(len(series)) if series["S"].iloc[k] >= s_end * 2 / 3 and series["Dp"].iloc[k] < -0.5]
    if not late:
        raise SystemExit(f"{run}: no late output has a wedge (a pro front, or a singly-vergent wedge wider than "
                         "0.5 h0): nothing to measure; run the wedge further")
    return series, h0, config, late


def pro_span(series, config, k):
    """(x from, x to) [h0] of the pro base under the wedge at output k: from the pro front to
    the S-point, or a singly-vergent wedge's from its front to its backstop."""
    if is_singly(config):
        return series["front"].iloc[k], series["backstop"].iloc[k]
    return series["Dp"].iloc[k], 0.0


def base_rows(walls, singly=False):
    """Rows of the pro and retro bases in an output's `walls`: every wall that is not vertical
    (the retro end wall is), the pro base's ending at or before the S-point (a singly-vergent
    run's floor is all pro base). A rigid base is one
    wall each side on y = 0; a deflecting one (docs/isostasy.md) is segments, nearly level, whose
    x and y forces this analysis takes as the base's shear and normal ones."""
    base = [i for i, w in enumerate(walls) if w[0] != w[2]]
    pro = base if singly else [i for i in base if max(walls[i][0], walls[i][2]) <= 0]
    return pro, [i for i in base if i not in pro]


def contact_speed(g, disc):
    """x velocity of each disc's lowest point in output group g: vx + omega r."""
    return g["vx"][()][disc] + g["omega"][()][disc] * g["radius"][()][disc]


def measure(run):
    series, h0, config, late = late_outputs(run)
    singly = is_singly(config)
    v = config["singly" if singly else "wedge"]["speed"]
    v_base = 0.0 if singly else v  # the floor under a singly-vergent wedge stands still
    rows, slips, retro_slips = [], [], []
    with h5py.File(f"{run}/snapshots.h5", "r") as f:
        for k in late:
            g = f["output_%06d" % k]
            if "contacts" not in g:
                raise SystemExit(f"{run}: output {k} has no contacts (run with --set output.contacts=true)")
            pro, retro = base_rows(g["walls"][()], singly)
            x_from, x_to = pro_span(series, config, k)
            c = g["contacts"]
            wall, wall_row = c["is_wall"][()] == 1, c["id_a"][()]
            x, fx, fy, limit = c["x"][()] / h0, c["fx"][()], c["fy"][()], c["at_limit"][()]
            on_pro = wall & np.isin(wall_row, pro) & (x > x_from) & (x < x_to)
            on_retro = wall & np.isin(wall_row, retro) & (x > 0)
            if retro:
                on_retro &= x < series["Dr"].iloc[k]
            rows.append({"mu_pro": fx[on_pro].sum() / fy[on_pro].sum(), "at_limit_pro": limit[on_pro].mean(),
                         "mu_retro": -fx[on_retro].sum() / fy[on_retro].sum() if on_retro.any() else np.nan,
                         "at_limit_retro": limit[on_retro].mean() if on_retro.any() else np.nan})
            disc = c["index_b"][()][on_pro]
            slip = (contact_speed(g, disc) - v_base) / v
            u = (x[on_pro] - x_from) / (x_to - x_from)  # 0 at the front, 1 at the S-point or backstop
            slips += list(zip(limit[on_pro], slip, u, fx[on_pro], fy[on_pro]))
            if not singly and on_retro.any():
                disc = c["index_b"][()][on_retro]
                slip = contact_speed(g, disc) / v
                u = x[on_retro] / series["Dr"].iloc[k]  # 0 at the S-point, 1 at the retro front
                retro_slips += list(zip(limit[on_retro], slip, u, -fx[on_retro], fy[on_retro]))
    table = pd.DataFrame(rows)
    columns = ["at_limit", "slip", "u", "fx", "fy"]
    slip, retro_slip = pd.DataFrame(slips, columns=columns), pd.DataFrame(retro_slips, columns=columns)
    return config, late, series, table, slip, retro_slip


def print_bins(name, contacts, bins, ends):
    """The base's transmitted friction and share at the limit in `bins` equal parts of u."""
    part = np.minimum((contacts.u * bins).astype(int), bins - 1)
    for b, group in contacts.groupby(part):
        print(f"  {name} {b / bins:.2f}-{(b + 1) / bins:.2f} of the way {ends}: transmits "
              f"{group.fx.sum() / group.fy.sum():.3f}, {group.at_limit.mean():.0%} of {len(group)} contacts at the limit, "
              f"median slip {group.slip.median():.2f} v")


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("run", help="a wedge run folder made with output.contacts = true")
    p.add_argument("--bins", type=int, default=0, help="also along each base, in this many parts")
    args = p.parse_args()
    config, late, series, table, slip, retro_slip = measure(args.run)
    if is_singly(config):
        print(f"{args.run}: singly-vergent, mu_b {config['singly']['mu_b']}, {len(late)} outputs, shortening "
              f"{series['shortening'].iloc[late[0]]:.2f}-{series['shortening'].iloc[late[-1]]:.2f} h0")
        table = table.drop(columns=["mu_retro", "at_limit_retro"])
    else:
        w = config["wedge"]
        law = w.get("traction_law", "drag")  # a run before the key dragged the layer by eq. 4.1
        base = f"traction_law {law}" + (f", gamma_b {w['gamma_b']}" if law == "drag" else "")
        print(f"{args.run}: {w['basal']}, mu_bp {w['mu_bp']}, mu_br {w['mu_br']}, {base}, "
              f"{len(late)} outputs, S {series['S'].iloc[late[0]]:.2f}-{series['S'].iloc[late[-1]]:.2f}")
    for name in table.columns:
        col = table[name]
        print(f"  {name}: mean {col.mean():.3f}, sd {col.std():.3f}, range {col.min():.3f}-{col.max():.3f}")
    for name, contacts in (("slip_pro", slip), ("slip_retro", retro_slip)):
        for at_limit, group in contacts.groupby("at_limit"):
            print(f"  {name} of the contacts {'at' if at_limit else 'below'} the limit: median {group.slip.median():.2f} v "
                  f"({len(group)} contacts)")
    if args.bins > 0:
        print_bins("pro base", slip, args.bins, "from the front")
        if len(retro_slip):
            print_bins("retro base", retro_slip, args.bins, "from the S-point")
    tapers = series.iloc[late]
    if is_singly(config):
        print(f"  late taper {tapers['taper'].mean():.2f} deg (front half {tapers['taper_front'].mean():.2f}, back half "
              f"{tapers['taper_back'].mean():.2f}), height {tapers['height'].mean():.2f} h0")
    else:
        print(f"  late pro taper alpha {tapers['alpha'].mean():.2f} deg, retro beta {tapers['beta'].mean():.2f} deg, "
              f"H {tapers['H'].mean():.2f} h0")


if __name__ == "__main__":
    main()
