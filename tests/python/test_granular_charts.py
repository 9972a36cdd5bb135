"""Tests of orogen.charts.granular and orogen.folders on small synthetic run and sweep folders.

Run from the repository root:  /usr/bin/python3 -m unittest -v tests/python/test_granular_charts.py
"""

import csv
import math
import os
import shutil
import subprocess
import sys
import tempfile
import unittest

import numpy as np

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from source_tree import module_command  # noqa: E402
from orogen import folders, tables  # noqa: E402
from orogen.results import RunFolder  # noqa: E402
from orogen.analysis import surface  # noqa: E402
from orogen.charts import granular as gc  # noqa: E402

try:
    import h5py
except ImportError:
    h5py = None

PNG = b"\x89PNG\r\n\x1a\n"


# --------------------------------------------------------------------------------------------
# Synthetic files in the layouts orogen writes


def fmt(v):
    return repr(v) if isinstance(v, float) else str(v)  # repr: 'nan' for NaN, as orogen writes


def write_series(path, columns, rows, title="series"):
    """series.csv / summary.csv: '# name: meaning' lines, header row, rows."""
    lines = ["# Orogen test %s" % title] + ["# %s: column %s" % (c, c) for c in columns]
    lines.append(",".join(columns))
    lines += [",".join(fmt(v) for v in row) for row in rows]
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")


def write_summary(path, values, descriptions=None):
    descriptions = descriptions or {}
    lines = ["# Orogen test summary"] + ["# %s: %s" % (k, descriptions.get(k, "value " + k)) for k in values]
    lines.append(",".join(values))
    lines.append(",".join(fmt(v) for v in values.values()))
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")


def write_config(path, experiment, packing, mu, extra=None):
    """A config.toml with the keys the charts read (the real one has every key)."""
    tables = {"run": {"experiment": experiment, "seed": 1},
              "particles": {"packing": packing, "d_min": 0.7, "d_max": 1.0},
              "layer": {"length": 100.0, "thickness": 10.0, "column_width_factor": 2.3},
              "contact": {"mu": mu},
              "settle": {"mu": 0.0}}
    for key, value in (extra or {}).items():
        table, name = key.split(".")
        tables.setdefault(table, {})[name] = value
    lines = ["# Orogen configuration, fully resolved"]
    for table, values in tables.items():
        lines.append("\n[%s]" % table)
        for k, v in values.items():
            lines.append("# %s\n%s = %s" % (k, k, '"%s"' % v if isinstance(v, str) else repr(v)))
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")


def write_snapshots(path, frames, h0, experiment, incomplete=True):
    """snapshots.h5 as src/io/snapshot_writer.cpp lays it out; frames: list of dicts x, y,
    radius, walls (n x 4), attrs. With `incomplete`, one more group with no 'y' beyond
    n_outputs (left by a killed run), which readers must ignore."""
    with h5py.File(path, "w") as f:
        f.attrs["format"] = "orogen-snapshots"
        f.attrs["version"] = np.int64(1)
        f.attrs["h0"] = float(h0)
        f.attrs["x_split"] = float("nan")
        f.attrs["experiment"] = experiment
        f.attrs["n_outputs"] = np.int64(len(frames))
        groups = list(frames) + ([frames[-1]] if incomplete else [])
        for k, fr in enumerate(groups):
            g = f.create_group("output_%06d" % k)
            g.attrs["step"] = np.int64(100 * k)
            g.attrs["time"] = float(k)
            for a, v in fr.get("attrs", {}).items():
                g.attrs[a] = float(v)
            x, y, r = (np.asarray(fr[n], dtype=float) for n in ("x", "y", "radius"))
            n = x.size
            for name, v in (("x", x), ("y", y), ("radius", r), ("theta", np.zeros(n)), ("vx", np.zeros(n)),
                            ("vy", np.zeros(n)), ("omega", np.zeros(n)), ("x0", x), ("y0", y),
                            ("depth0", np.max(y) - y if n else y), ("max_rel_disp", np.zeros(n)),
                            ("disp3_x", np.full(n, np.nan)), ("disp3_y", np.full(n, np.nan))):
                g.create_dataset(name, data=np.asarray(v, dtype=np.float64))
            g.create_dataset("id", data=np.arange(n, dtype=np.int64))
            g.create_dataset("cluster_id", data=np.full(n, -1, dtype=np.int64))
            motion = np.zeros(n, dtype=np.uint8)
            motion[y < 1.0] = 1  # the held bottom row
            g.create_dataset("motion", data=motion)
            g.create_dataset("walls", data=np.asarray(fr["walls"], dtype=float).reshape(-1, 4))
            if k == len(frames):
                del g["y"]


def write_results(path, swept, rows, summary_columns):
    """A sweep's results.csv: name, swept keys, exit_status, render_status, summary columns."""
    header = ["name"] + swept + ["exit_status", "render_status"] + summary_columns
    lines = ["# Orogen test sweep results: one row per run of test.toml (base base.toml)",
             "# name: the run's folder under runs/ (index, then the swept values)"]
    lines += ["# %s: swept configuration key" % k for k in swept]
    lines += ["# exit_status: of `orogen run`", "# render_status: of `orogen render`"]
    lines += ["# %s: column %s" % (c, c) for c in summary_columns]
    with open(path, "w", newline="") as f:
        f.write("\n".join(lines) + "\n")
        w = csv.writer(f, lineterminator="\n")
        w.writerow(header)
        for row in rows:
            w.writerow([fmt(row.get(c, "")) for c in header])


def block(width, height, radius=0.5):
    """Discs on a square grid filling [0, width] x [0, height]."""
    xs, ys = np.meshgrid(np.arange(radius, width, 2 * radius), np.arange(radius, height, 2 * radius))
    return xs.ravel(), ys.ravel(), np.full(xs.size, radius)


def slope_discs(size, top, angle_deg, radius=0.5):
    """Columns of discs whose tops lie under y = top - tan(angle) x (at least one disc each)."""
    xs, ys = [], []
    for x in np.arange(radius, size, 2 * radius):
        h = max(top - math.tan(math.radians(angle_deg)) * x, 2 * radius)
        for y in np.arange(radius, h - radius + 1e-9, 2 * radius):
            xs.append(x)
            ys.append(y)
    return np.array(xs), np.array(ys), np.full(len(xs), radius)


# --------------------------------------------------------------------------------------------
# Run folders


def make_repose_run(folder, packing, mu, angle, variant="slump", with_profile=True, with_h5=True, size=20.0):
    os.makedirs(folder)
    write_config(os.path.join(folder, "config.toml"), "repose", packing, mu,
                 {"repose.variant": variant, "repose.size": size, "repose.fixed_height": 1.0,
                  "repose.ledge_fraction": 0.2})
    write_summary(os.path.join(folder, "summary.csv"),
                  {"angle_deg": float(angle), "angle_r2": 0.95, "angle_rms": 0.4, "concavity_deg": -3.5,
                   "slope_length": 15.0, "removed_fraction": 0.4, "at_rest": 1, "time_to_rest": 50.0})
    write_series(os.path.join(folder, "series.csv"), ["step", "time", "angle"], [[0, 0.0, float("nan")],
                                                                                 [100, 5.0, float(angle)]])
    if with_profile:
        x = np.arange(0.575, size, 1.15)
        h = 18.0 - math.tan(math.radians(angle)) * x
        fitted = (h > 2.0) & (h < 18.5)
        text = "# Surface profile at rest\n# fitted: 1 where fitted\nx,height,fitted,line\n"
        text += "".join("%r,%r,%d,%r\n" % (float(a), float(b), c, float(b)) for a, b, c in zip(x, h, fitted))
        with open(os.path.join(folder, "profile.csv"), "w") as f:
            f.write(text)
    if with_h5 and h5py is not None:
        walls = [[-1.0, 0.0, size + 1, 0.0], [0.0, -1.0, 0.0, 4 * size]]
        x0, y0, r0 = block(size, size)
        x1, y1, r1 = slope_discs(size, 18.0, angle)
        write_snapshots(os.path.join(folder, "snapshots.h5"),
                        [dict(x=x0, y=y0, radius=r0, walls=walls), dict(x=x1, y=y1, radius=r1, walls=walls)],
                        h0=size, experiment="repose")


def make_singly_run(folder, packing, mu, mu_b, steady, with_h5=False, h0=10.0, wedge_angle=10.0, extra=None):
    os.makedirs(folder)
    write_config(os.path.join(folder, "config.toml"), "singly_vergent", packing, mu,
                 {"singly.mu_b": mu_b, "singly.shortening": 2.0, **(extra or {})})
    n = 21
    s = np.linspace(0, 2.0, n)
    taper = np.where(s < 0.4, np.nan, steady + 2.0 * np.sin(7 * s))
    backstop_x = 100.0 - s * h0
    front_x = backstop_x - 4.0 * h0  # the wedge four h0 wide
    rows = []
    for i in range(n):
        wedge = np.isfinite(taper[i])
        rows.append([100 * i, 4.0 * i, s[i], backstop_x[i] / h0, front_x[i] / h0 if wedge else float("nan"),
                     4.0 if wedge else float("nan"), 0.5 if wedge else float("nan"), taper[i], taper[i] + 1,
                     taper[i] - 1, taper[i], 0.5, 1000])
    write_series(os.path.join(folder, "series.csv"),
                 ["step", "time", "shortening", "backstop", "front", "width", "height", "taper", "taper_front",
                  "taper_back", "taper_mean", "slip_base", "n_discs"], rows)
    write_summary(os.path.join(folder, "summary.csv"),
                  {"taper_steady_deg": float(steady), "taper_steady_sd_deg": 1.25, "taper_final_deg": steady + 0.5,
                   "taper_front_final_deg": steady + 1.5, "taper_back_final_deg": steady - 1.5, "width_final": 4.0,
                   "height_final": 0.5, "shortening": 2.0})
    if with_h5 and h5py is not None:
        # The final layer: h0 thick, rising at wedge_angle from the front to the backstop.
        b, fr = backstop_x[-1], front_x[-1]
        xs, ys = [], []
        for x in np.arange(0.5, b, 1.0):
            top = h0 + (math.tan(math.radians(wedge_angle)) * (x - fr) if x > fr else 0.0)
            for y in np.arange(0.5, top - 0.5 + 1e-9, 1.0):
                xs.append(x)
                ys.append(y)
        walls = [[-1.0, 0.0, 101.0, 0.0], [0.0, -1.0, 0.0, 80.0], [b, 0.0, b, 80.0]]
        write_snapshots(os.path.join(folder, "snapshots.h5"),
                        [dict(x=xs, y=ys, radius=np.full(len(xs), 0.5), walls=walls, attrs={"S": 2.0})],
                        h0=h0, experiment="singly_vergent")


BIAXIAL_SUMMARY = ("phi_peak_deg", "axial_strain_peak", "phi_residual_deg", "mu_bulk_peak", "mu_bulk_residual",
                   "psi_peak_deg", "vol_strain_end", "sigma3_max_dev", "inertial_number")


def biaxial_summary(phi_peak, phi_res, tapers=True):
    v = {"phi_peak_deg": phi_peak, "axial_strain_peak": 0.03, "phi_residual_deg": phi_res,
         "mu_bulk_peak": math.tan(math.radians(phi_peak)), "mu_bulk_residual": math.tan(math.radians(phi_res)),
         "psi_peak_deg": 10.0, "vol_strain_end": 0.02, "sigma3_max_dev": 0.01, "inertial_number": 3e-4}
    if tapers:
        for mb in (0.1, 0.2, 0.3):
            for which, phi in (("residual", phi_res), ("peak", phi_peak)):
                v["taper_mub%g_%s_deg" % (mb, which)] = surface.critical_taper_deg(phi, mb)
    return v


def make_biaxial_run(folder, packing, mu, phi_peak, phi_res, tapers=True, extra=None):
    os.makedirs(folder)
    write_config(os.path.join(folder, "config.toml"), "biaxial", packing, mu,
                 {"biaxial.strain_end": 0.2, **(extra or {})})
    rows = [[0, 0.0, 0, 0.0, 0.0, 5.0, 5.0, float("nan")], [10, 1.0, 0, 0.0, 0.0, 5.0, 5.0, 0.0]]
    for i, e in enumerate(np.linspace(0.0, 0.2, 21)):
        phi = phi_peak * min(1.0, e / 0.03) if e <= 0.03 else phi_res + (phi_peak - phi_res) * math.exp(-(e - 0.03) / 0.03)
        rows.append([20 + 10 * i, 2.0 + i, 1 if i < 20 else 2, float(e), 0.1 * e, 5.0, 5.0, float(phi)])
    write_series(os.path.join(folder, "series.csv"),
                 ["step", "time", "phase", "axial_strain", "vol_strain", "sigma3", "sigma1", "phi_deg"], rows)
    write_summary(os.path.join(folder, "summary.csv"), biaxial_summary(phi_peak, phi_res, tapers),
                  {"phi_residual_deg": "mean mobilised friction angle beyond axial strain 0.1333 (residual state) [deg]"})


def make_sweep(folder, experiment_runs, swept):
    """experiment_runs: list of (name, values dict, summary dict or None, maker) ; maker(run_dir)
    builds the run folder (None: a run not finished, exit_status empty)."""
    os.makedirs(os.path.join(folder, "runs"))
    rows, columns = [], []
    for name, values, summary, maker in experiment_runs:
        row = dict(name=name, **values)
        if maker is not None:
            maker(os.path.join(folder, "runs", name))
            row["exit_status"] = 0
            for k, v in (summary or {}).items():
                row[k] = v
                if k not in columns:
                    columns.append(k)
        rows.append(row)
    write_results(os.path.join(folder, "results.csv"), swept, rows, columns)


def read_csv_table(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


# --------------------------------------------------------------------------------------------
# Tests


class CriticalTaperTest(unittest.TestCase):
    def test_thesis_check_value(self):
        alpha = surface.critical_taper(math.radians(30.0), math.radians(10.0))
        self.assertAlmostEqual(math.degrees(alpha), 3.44, delta=0.005)
        self.assertAlmostEqual(surface.critical_taper_deg(30.0, math.tan(math.radians(10.0))), 3.4365, delta=1e-3)

    def test_no_taper_when_base_not_weaker(self):
        with self.assertRaises(ValueError):
            surface.critical_taper(math.radians(15.0), math.radians(16.0))
        self.assertTrue(math.isnan(surface.critical_taper_deg(15.0, 0.3)))  # atan(0.3) = 16.7 deg
        self.assertTrue(math.isnan(surface.critical_taper_deg(float("nan"), 0.1)))

    def test_weaker_wedge_steeper(self):
        self.assertGreater(surface.critical_taper_deg(20.0, 0.1), surface.critical_taper_deg(30.0, 0.1))
        self.assertGreater(surface.critical_taper_deg(30.0, 0.3), surface.critical_taper_deg(30.0, 0.1))


class ReadersTest(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.mkdtemp(prefix="granular_io_test_")

    def tearDown(self):
        shutil.rmtree(self.tmp, ignore_errors=True)

    def test_results_and_sweep_runs(self):
        sweep = os.path.join(self.tmp, "sweep")
        make_sweep(sweep, [
            ("000_packing=hexagonal_mu=0.3", {"particles.packing": "hexagonal", "contact.mu": 0.3},
             {"angle_deg": 40.0, "note": "a, \"quoted\" text"},
             lambda d: make_repose_run(d, "hexagonal", 0.3, 40.0, with_h5=False)),
            ("001_packing=hexagonal_mu=0.1", {"particles.packing": "hexagonal", "contact.mu": 0.1}, None, None),
        ], ["particles.packing", "contact.mu"])
        rows, header, desc = tables.read_results(os.path.join(sweep, "results.csv"))
        self.assertEqual(header[:4], ["name", "particles.packing", "contact.mu", "exit_status"])
        self.assertEqual(rows[0]["note"], "a, \"quoted\" text")
        self.assertEqual(desc["contact.mu"], "swept configuration key")
        runs = folders.collect_runs([sweep], "repose")  # the unfinished run is left out
        self.assertEqual([r.name for r in runs], ["000_packing=hexagonal_mu=0.3"])
        self.assertAlmostEqual(runs[0].value("contact.mu"), 0.3)
        self.assertAlmostEqual(runs[0].summary["angle_deg"], 40.0)
        # results.csv alone (no run folders): values from the table, swept keys not in the summary.
        shutil.rmtree(os.path.join(sweep, "runs"))
        runs = folders.collect_runs([os.path.join(sweep, "results.csv")], "repose")
        self.assertEqual(runs[0].value("particles.packing"), "hexagonal")
        self.assertAlmostEqual(runs[0].summary["angle_deg"], 40.0)
        self.assertNotIn("contact.mu", runs[0].summary)

    def test_wrong_experiment_is_an_error(self):
        run = os.path.join(self.tmp, "bx")
        make_biaxial_run(run, "random_discs", 0.3, 25.0, 20.0)
        with self.assertRaises(folders.RunError):
            folders.collect_runs([run], "repose")
        with self.assertRaises(folders.RunError):
            folders.collect_runs([self.tmp], "repose")  # a folder of runs, none of them repose

    def test_surface_and_last_frame(self):
        if h5py is None:
            self.skipTest("h5py not installed")
        run = os.path.join(self.tmp, "r")
        make_repose_run(run, "random_discs", 0.3, 30.0)
        path = os.path.join(run, "snapshots.h5")
        frame = folders.read_last_frame(path)
        self.assertEqual(frame["output"], 1)  # the incomplete third group is ignored
        self.assertEqual(frame["file_attrs"]["experiment"], "repose")
        first = folders.read_frame(path, 0)
        x, h = surface.surface_columns(first["x"], first["y"], first["radius"], 0.0, 20.0)
        self.assertAlmostEqual(x[1] - x[0], 1.15)
        self.assertEqual(len(h), 18)  # ceil(20 / 1.15)
        self.assertTrue(np.allclose(h[:-1], 20.0))
        self.assertTrue(np.isnan(h[-1]))  # [19.55, 20.7) holds no disc centre

    def test_fit_line(self):
        x = np.linspace(0, 10, 11)
        fit = surface.fit_line(x, 5.0 - 0.5 * x)
        self.assertAlmostEqual(fit["slope"], -0.5)
        self.assertAlmostEqual(fit["r2"], 1.0)
        self.assertAlmostEqual(fit["concavity"], 0.0, places=9)
        fit = surface.fit_line(x, 10.0 - np.sqrt(x + 1) * 3)  # steep top, flatter foot: concave
        self.assertGreater(fit["concavity"], 0.0)
        self.assertIsNone(surface.fit_line([1, 2], [1, 2]))


class ReposeChartsTest(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.mkdtemp(prefix="granular_repose_test_")
        self.out = os.path.join(self.tmp, "charts")
        self.sweep = os.path.join(self.tmp, "sweep")
        self.angles = {("hexagonal", 0.3): 45.0, ("hexagonal", 0.1): 40.0,
                       ("random_discs", 0.3): 22.0, ("random_discs", 0.1): 18.0}
        runs = []
        for i, ((p, mu), a) in enumerate(sorted(self.angles.items())):
            name = "%03d_packing=%s_mu=%g" % (i, p, mu)
            runs.append((name, {"particles.packing": p, "contact.mu": mu}, {"angle_deg": a},
                         lambda d, p=p, mu=mu, a=a: make_repose_run(d, p, mu, a, with_h5=(p == "hexagonal"))))
        make_sweep(self.sweep, runs, ["particles.packing", "contact.mu"])
        # A lone run folder without profile.csv: the profile is computed from snapshots.h5.
        self.lone = os.path.join(self.tmp, "lone")
        make_repose_run(self.lone, "random_clusters", 0.2, 25.0, with_profile=False)

    def tearDown(self):
        shutil.rmtree(self.tmp, ignore_errors=True)

    def test_files_and_table(self):
        result = gc.make_repose([self.sweep, self.lone], self.out)
        names = ["repose_grid.png", "repose_angle_vs_mu.png"] + [
            "repose_profile_%s.png" % gc.safe_name(it["name"]) for it in result["items"]]
        for name in names:
            with open(os.path.join(self.out, name), "rb") as f:
                self.assertEqual(f.read(8), PNG, name)
        self.assertFalse([n for n in os.listdir(self.out) if n.startswith(".tmp-")])
        rows = read_csv_table(os.path.join(self.out, "repose_table.csv"))
        self.assertEqual(len(rows), 5)
        for row in rows:
            if row["run"] == "lone":
                self.assertEqual(row["packing"], "random_clusters")
                self.assertAlmostEqual(float(row["angle_deg"]), 25.0)
                self.assertEqual(row["profile"], "computed from snapshots.h5" if h5py else "none")
                continue
            self.assertAlmostEqual(float(row["angle_deg"]), self.angles[(row["packing"], float(row["mu"]))])
            self.assertAlmostEqual(float(row["removed_fraction"]), 0.4)
            self.assertEqual(row["profile"], "profile.csv")
        with open(os.path.join(self.out, "repose_table.md")) as f:
            md = f.read()
        self.assertIn("| 003_packing=random_discs_mu=0.3 | random discs | slump | 0.3 | 22.00 |", md)
        # The profile.csv line of a run reproduces its angle.
        item = [it for it in result["items"] if it["packing"] == "hexagonal" and it["mu"] == 0.3][0]
        self.assertAlmostEqual(gc.fit_angle(item["profile"]["fit"]), 45.0, places=6)

    def test_profile_computed_from_snapshots(self):
        if h5py is None:
            self.skipTest("h5py not installed")
        prof = gc.repose_profile(RunFolder(self.lone))
        self.assertEqual(prof["source"], "computed from snapshots.h5")
        self.assertAlmostEqual(gc.fit_angle(prof["fit"]), 25.0, delta=2.0)
        self.assertTrue(np.all(prof["height"][prof["fitted"]] > 2.0))  # above fixed_height + d_max
        self.assertTrue(np.all(prof["height"][prof["fitted"]] < 18.5))  # below top - 1.5 d_max


class SinglyChartsTest(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.mkdtemp(prefix="granular_singly_test_")
        self.out = os.path.join(self.tmp, "charts")
        self.sweep = os.path.join(self.tmp, "sv")
        runs, i = [], 0
        self.steady = {}
        for p in ("random_discs", "random_clusters"):
            for mu in (0.2, 0.3):
                for mb in (0.1, 0.3):
                    name = "%03d_packing=%s_mu=%g_mu_b=%g" % (i, p, mu, mb)
                    self.steady[name] = 3.0 + 10 * mb + 5 * mu + i * 0.01
                    runs.append((name, {"particles.packing": p, "contact.mu": mu, "singly.mu_b": mb},
                                 {"taper_steady_deg": self.steady[name]},
                                 lambda d, p=p, mu=mu, mb=mb, s=self.steady[name], h5=(i == 7):
                                 make_singly_run(d, p, mu, mb, s, with_h5=h5)))
                    i += 1
        make_sweep(self.sweep, runs, ["particles.packing", "contact.mu", "singly.mu_b"])
        # The bulk: a biaxial sweep; clusters with the summary's taper columns (one made up, to
        # see that the column is used), discs without them (computed here).
        self.bulk = os.path.join(self.tmp, "bx")
        brows = []
        for j, (p, mu, pk, res, tapers) in enumerate((("random_clusters", 0.3, 28.0, 24.0, True),
                                                      ("random_discs", 0.3, 24.0, 19.0, False),
                                                      ("random_discs", 0.2, 21.0, 16.0, False))):
            summ = biaxial_summary(pk, res, tapers)
            if tapers:
                summ["taper_mub0.3_peak_deg"] = 7.777
            brows.append(("%03d" % j, {"particles.packing": p, "contact.mu": mu}, summ,
                          lambda d, p=p, mu=mu, pk=pk, res=res, tapers=tapers, summ=summ:
                          (make_biaxial_run(d, p, mu, pk, res, tapers),
                           write_summary(os.path.join(d, "summary.csv"), summ))))
        make_sweep(self.bulk, brows, ["particles.packing", "contact.mu"])

    def tearDown(self):
        shutil.rmtree(self.tmp, ignore_errors=True)

    def test_files_and_table(self):
        result = gc.make_singly([self.sweep], self.out, [os.path.join(self.bulk, "results.csv")])
        for name in ("singly_taper.png", "singly_profiles.png"):
            with open(os.path.join(self.out, name), "rb") as f:
                self.assertEqual(f.read(8), PNG, name)
        self.assertFalse([n for n in os.listdir(self.out) if n.startswith(".tmp-")])
        rows = {r["run"]: r for r in read_csv_table(os.path.join(self.out, "singly_table.csv"))}
        self.assertEqual(len(rows), 8)
        for name, r in rows.items():
            self.assertAlmostEqual(float(r["taper_steady_deg"]), self.steady[name])
            self.assertAlmostEqual(float(r["taper_steady_sd_deg"]), 1.25)
            self.assertAlmostEqual(float(r["taper_final_deg"]), self.steady[name] + 0.5)
            self.assertAlmostEqual(float(r["taper_back_final_deg"]), self.steady[name] - 1.5)
        key = lambda p, mu, mb: [r for r in rows.values() if r["packing"] == p and float(r["mu"]) == mu
                                 and float(r["mu_b"]) == mb][0]
        c = key("random_clusters", 0.3, 0.3)
        self.assertAlmostEqual(float(c["thesis_appendix_a_deg"]), 11.75)
        self.assertAlmostEqual(float(c["phi_peak_deg"]), 28.0)
        self.assertAlmostEqual(float(c["phi_residual_deg"]), 24.0)
        self.assertAlmostEqual(float(c["critical_taper_peak_deg"]), 7.777)  # the summary's column
        self.assertAlmostEqual(float(c["critical_taper_residual_deg"]), surface.critical_taper_deg(24.0, 0.3))
        d = key("random_discs", 0.3, 0.1)  # no taper columns: computed from phi and mu_b
        self.assertAlmostEqual(float(d["critical_taper_peak_deg"]), surface.critical_taper_deg(24.0, 0.1))
        self.assertAlmostEqual(float(d["critical_taper_residual_deg"]), surface.critical_taper_deg(19.0, 0.1))
        self.assertTrue(math.isnan(float(d["thesis_appendix_a_deg"])))
        self.assertTrue(math.isnan(float(key("random_clusters", 0.2, 0.1)["phi_peak_deg"])))  # no bulk run
        self.assertTrue(math.isnan(float(key("random_discs", 0.2, 0.3)["critical_taper_residual_deg"])))  # 16 < 16.7
        with open(os.path.join(self.out, "singly_table.md")) as f:
            md = f.read()
        self.assertIn("| 11.75 |", md)
        self.assertIn("%.2f ± 1.25" % self.steady[c["run"]], md)

    def test_critical_taper_from_the_biaxial_test_of_the_same_preparation(self):
        # A wedge of a rained layer (settle.mu 0.3) beside biaxial tests of the default
        # preparation and of the rain: its critical taper comes from the rain's bulk friction.
        rain = {"particles.placement": "rain", "settle.mu": 0.3}
        wedge, default, rained = (os.path.join(self.tmp, n) for n in ("wedge_rain", "bx_default", "bx_rain"))
        make_singly_run(wedge, "random_clusters", 0.3, 0.2, 5.0, extra=rain)
        make_biaxial_run(default, "random_clusters", 0.3, 35.6, 24.6, tapers=False)
        make_biaxial_run(rained, "random_clusters", 0.3, 29.4, 25.8, tapers=False, extra=rain)
        out = os.path.join(self.tmp, "prep_charts")
        gc.make_singly([wedge], out, [default, rained])
        row = read_csv_table(os.path.join(out, "singly_table.csv"))[0]
        self.assertAlmostEqual(float(row["phi_peak_deg"]), 29.4)
        self.assertAlmostEqual(float(row["critical_taper_residual_deg"]), surface.critical_taper_deg(25.8, 0.2))
        gc.make_singly([wedge], out, [default])  # no biaxial test of its preparation: none
        row = read_csv_table(os.path.join(out, "singly_table.csv"))[0]
        self.assertTrue(math.isnan(float(row["phi_peak_deg"])))

    def test_without_bulk(self):
        gc.make_singly([self.sweep], self.out)
        rows = read_csv_table(os.path.join(self.out, "singly_table.csv"))
        self.assertTrue(all(math.isnan(float(r["critical_taper_peak_deg"])) for r in rows))
        self.assertTrue(os.path.isfile(os.path.join(self.out, "singly_taper.png")))

    def test_final_surface_taper(self):
        if h5py is None:
            self.skipTest("h5py not installed")
        run = os.path.join(self.tmp, "one")
        make_singly_run(run, "random_clusters", 0.3, 0.3, 10.0, with_h5=True, wedge_angle=10.0)
        surf = gc.final_surface(gc.load_singly(RunFolder(run)))
        self.assertAlmostEqual(surf["backstop"], 80.0)
        self.assertAlmostEqual(surf["front"], -4.0)
        self.assertAlmostEqual(math.degrees(math.atan(surf["fit"]["slope"])), 10.0, delta=1.5)


class BiaxialChartsTest(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.mkdtemp(prefix="granular_biaxial_test_")
        self.out = os.path.join(self.tmp, "charts")
        self.runs = []
        for p, mu, pk, res in (("random_discs", 0.1, 18.0, 14.0), ("random_discs", 0.3, 24.0, 19.0),
                               ("random_clusters", 0.3, 28.0, 24.0)):
            d = os.path.join(self.tmp, "%s_%g" % (p, mu))
            make_biaxial_run(d, p, mu, pk, res)
            self.runs.append(d)

    def tearDown(self):
        shutil.rmtree(self.tmp, ignore_errors=True)

    def test_files_and_table(self):
        result = gc.make_biaxial(self.runs, self.out)
        for name in ("biaxial_stress_strain.png", "biaxial_friction_vs_mu.png"):
            with open(os.path.join(self.out, name), "rb") as f:
                self.assertEqual(f.read(8), PNG, name)
        self.assertAlmostEqual(result["items"][0]["residual_from"], 0.1333)  # from the description
        rows = {r["run"]: r for r in read_csv_table(os.path.join(self.out, "biaxial_table.csv"))}
        self.assertEqual(set(rows), {"random_discs_0.1", "random_discs_0.3", "random_clusters_0.3"})
        r = rows["random_clusters_0.3"]
        self.assertAlmostEqual(float(r["phi_peak_deg"]), 28.0)
        self.assertAlmostEqual(float(r["phi_residual_deg"]), 24.0)
        self.assertAlmostEqual(float(r["critical_taper_mub0.2_peak_deg"]), surface.critical_taper_deg(28.0, 0.2))
        self.assertTrue(math.isnan(float(rows["random_discs_0.1"]["critical_taper_mub0.3_residual_deg"])))
        with open(os.path.join(self.out, "biaxial_table.md")) as f:
            md = f.read()
        self.assertIn("| random_clusters_0.3 | random clusters | 0.3 | 28.00 |", md)


class CommandLineTest(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.mkdtemp(prefix="granular_cli_test_")
        self.run_dir = os.path.join(self.tmp, "r1")
        make_repose_run(self.run_dir, "random_discs", 0.3, 21.0, with_h5=False)

    def tearDown(self):
        shutil.rmtree(self.tmp, ignore_errors=True)

    def run_script(self, *args):
        return subprocess.run(module_command("orogen.charts.granular", *args), stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                              universal_newlines=True)

    def test_cli(self):
        out = os.path.join(self.tmp, "out")
        proc = self.run_script("repose", self.run_dir, "--out", out)
        self.assertEqual(proc.returncode, 0, proc.stderr)
        self.assertIn("angle 21.00 deg", proc.stdout)
        self.assertTrue(os.path.isfile(os.path.join(out, "repose_profile_r1.png")))
        bad = self.run_script("singly", self.run_dir, "--out", out)
        self.assertEqual(bad.returncode, 2)
        self.assertIn("not a 'singly_vergent' run", bad.stderr)
        missing = self.run_script("biaxial", os.path.join(self.tmp, "nope"), "--out", out)
        self.assertEqual(missing.returncode, 2)


if __name__ == "__main__":
    unittest.main()
