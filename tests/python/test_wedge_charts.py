"""Tests of python/wedge_charts.py on a tiny synthetic run folder.

Run from the repository root:  /usr/bin/python3 -m unittest tests/python/test_wedge_charts.py
"""

import json
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
from orogen.charts import wedge as wc  # noqa: E402

try:
    import h5py
except ImportError:
    h5py = None

COLUMNS = ("step,time,S,H,Dp,Mp,Dr,Mr,T,alpha,beta,alpha_fit,beta_fit,slip_pro,slip_retro,n_active,"
           "n_discs,n_eroded,n_left,n_entered,window_pro,window_retro").split(",")
PNGS = ("height_peak.png", "tapers.png", "fronts.png", "topography.png", "slip.png")
SUMMARY_KEYS = {"label", "dir", "final_S", "final_H", "b", "b_se", "r2", "mean_alpha_late",
                "mean_beta_late", "retro_onset_step"}
H0 = 6.0  # layer thickness in world units (largest disc diameters)


def fmt(v):
    return repr(v) if isinstance(v, float) else str(v)  # repr: 'nan' for NaN, as orogen writes


def write_series(path, n=41, s_end=4.0, nan_row=None):
    """series.csv with H = 0.8 S^0.5; no fronts (exact 0) for S < 1, Dr passing +1 h0 at S = 3."""
    lines = ["# Orogen test series, experiment 'wedge': one row per output step",
             "# lengths in units of the largest disc diameter d, time in sqrt(d/g)"]
    lines += ["# %s: column %s" % (c, c) for c in COLUMNS]
    lines.append(",".join(COLUMNS))
    for i in range(n):
        s = s_end * i / (n - 1)
        h = 0.8 * math.sqrt(s)
        wedge = s >= 1.0
        row = dict(step=1000 * i, time=10.0 * i, S=s, H=h,
                   Dp=-0.5 * s if wedge else 0.0, Mp=-0.3 * s if wedge else 0.0,
                   Dr=(s - 2.0) if s > 2.0 else (0.1 if wedge else 0.0), Mr=0.0,
                   T=0.1 if wedge else 0.0,
                   alpha=20.0 if wedge else 0.0, beta=40.0 if wedge else 0.0,
                   alpha_fit=18.0 if wedge else 0.0, beta_fit=35.0 if wedge else 0.0,
                   slip_pro=0.9, slip_retro=0.5 if s > 3 else 0.0,
                   n_active=100, n_discs=200, n_eroded=0, n_left=0, n_entered=200,
                   window_pro=-12.0, window_retro=3.0)
        if i == nan_row:
            for k in ("Dp", "Dr", "alpha", "beta", "slip_pro", "slip_retro"):
                row[k] = float("nan")
        lines.append(",".join(fmt(row[c]) for c in COLUMNS))
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")


def write_snapshots(path, n_outputs=3, extra_incomplete=True):
    """A minimal snapshots.h5: a flat layer of discs that grows a bump at the S-point."""
    rng = np.random.default_rng(1)
    with h5py.File(path, "w") as f:
        f.attrs["format"] = "orogen-snapshots"
        f.attrs["version"] = np.int64(1)
        f.attrs["h0"] = H0
        f.attrs["x_split"] = 0.0
        f.attrs["n_outputs"] = np.int64(n_outputs)
        groups = n_outputs + (1 if extra_incomplete else 0)
        for k in range(groups):
            g = f.create_group("output_%06d" % k)
            g.attrs["step"] = np.int64(1000 * 20 * k)  # rows 0, 20, 40 of the series
            g.attrs["time"] = 200.0 * k
            g.attrs["S"] = 2.0 * k
            x = np.repeat(np.arange(-60.0, 30.0, 1.0), 6)
            y = np.tile(np.arange(6) + 0.5, x.size // 6)
            bump = k * 3.0 * np.exp(-(x / 6.0) ** 2)
            y = y + bump * (y / 6.0)
            r = 0.5 - 0.1 * rng.random(x.size)
            n = x.size
            for name, v in (("x", x), ("y", y), ("radius", r), ("theta", np.zeros(n)), ("vx", np.zeros(n)),
                            ("vy", np.zeros(n)), ("omega", np.zeros(n)), ("x0", x), ("y0", y),
                            ("depth0", 6.0 - y), ("max_rel_disp", np.zeros(n)),
                            ("disp3_x", np.full(n, np.nan)), ("disp3_y", np.full(n, np.nan))):
                g.create_dataset(name, data=np.asarray(v, dtype=np.float64))
            g.create_dataset("id", data=np.arange(n, dtype=np.int64))
            g.create_dataset("cluster_id", data=np.full(n, -1, dtype=np.int64))
            g.create_dataset("motion", data=np.zeros(n, dtype=np.uint8))
            g.create_dataset("walls", data=np.array([[-60.0, 0.0, 30.0, 0.0]]))
            if k == n_outputs:  # an incomplete group: must be ignored
                del g["y"]


class WedgeChartsTest(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.mkdtemp(prefix="wedge_charts_test_")
        self.run_dir = os.path.join(self.tmp, "run_a")
        os.makedirs(self.run_dir)
        write_series(os.path.join(self.run_dir, "series.csv"))
        if h5py is not None:
            write_snapshots(os.path.join(self.run_dir, "snapshots.h5"))
        self.out = os.path.join(self.tmp, "charts")

    def tearDown(self):
        shutil.rmtree(self.tmp, ignore_errors=True)

    def test_fit_exponent(self):
        series, _ = wc.read_series(os.path.join(self.run_dir, "series.csv"))
        fit = wc.power_law_fit(series["S"], series["H"])
        self.assertIsNotNone(fit)
        self.assertAlmostEqual(fit["b"], 0.5, delta=0.01)
        self.assertAlmostEqual(fit["a"], 0.8, delta=0.01)
        self.assertGreater(fit["r2"], 0.999)
        self.assertEqual(fit["n"], int(np.sum(series["S"] > 0.5)))

    def test_fit_too_few_points(self):
        self.assertIsNone(wc.power_law_fit([0.1, 0.2, 1.0], [0.1, 0.2, 0.3]))
        self.assertIsNone(wc.power_law_fit([], []))

    def test_simple_model(self):
        h = wc.simple_model_height(np.array([0.0, 2.0]), 45.0, 45.0)
        self.assertAlmostEqual(h[0], 0.0)
        self.assertAlmostEqual(h[1], math.sqrt(2.0), places=12)  # 2*1*1/(1+1) * 2
        self.assertIsNone(wc.simple_model_height([1.0], 0.0, 30.0))
        self.assertIsNone(wc.simple_model_height([1.0], float("nan"), 30.0))

    def test_charts_and_summary(self):
        summary = wc.make_charts([self.run_dir], self.out)
        for name in PNGS:
            path = os.path.join(self.out, name)
            self.assertTrue(os.path.isfile(path), name)
            with open(path, "rb") as f:
                self.assertEqual(f.read(8), b"\x89PNG\r\n\x1a\n", name)
        self.assertFalse([n for n in os.listdir(self.out) if n.startswith(".tmp-")])
        with open(os.path.join(self.out, "summary.json")) as f:
            data = json.load(f)
        self.assertEqual(data, json.loads(json.dumps(summary)))
        self.assertEqual(len(data["runs"]), 1)
        run = data["runs"][0]
        self.assertTrue(SUMMARY_KEYS <= set(run), SUMMARY_KEYS - set(run))
        self.assertAlmostEqual(run["b"], 0.5, delta=0.01)
        self.assertLess(run["b_se"], 1e-6)
        self.assertAlmostEqual(run["final_S"], 4.0)
        self.assertAlmostEqual(run["final_H"], 1.6)
        self.assertAlmostEqual(run["mean_alpha_late"], 20.0)
        self.assertAlmostEqual(run["mean_beta_late"], 40.0)
        # Dr = S - 2 first exceeds 1 at the first row with S > 3: row 31, step 31000.
        self.assertEqual(run["retro_onset_step"], 31000)
        self.assertEqual(run["retro_onset_output"], 31)

    def test_critical_tapers_of_the_calibrated_material(self):
        """A run of the default material finds the shipped calibration; its critical tapers are
        Dahlen's for the calibrated angles and the run's basal friction. A run of another
        contact friction finds none, and says why; an explicit calibration of it is used."""
        from orogen.analysis import calibrated_taper as ct, surface
        default = ct.load_calibration(ct.DEFAULT_CALIBRATION)
        from orogen.config import resolved_toml
        config_text = resolved_toml()  # the default configuration, as a run's config.toml holds it
        with open(os.path.join(self.run_dir, "config.toml"), "w") as f:
            f.write(config_text)
        run = wc.make_charts([self.run_dir], self.out)["runs"][0]["critical_taper"]
        self.assertEqual(run["calibration"], "calibrated default material")
        for side, mu_b in (("pro", 0.2), ("retro", 0.4)):
            for state in ("peak", "residual"):
                self.assertAlmostEqual(run[side][state], surface.critical_taper_deg(default[state]["phi_deg"], mu_b))
        self.assertTrue(0 < run["pro"]["peak"] < 20, run)
        with open(os.path.join(self.run_dir, "config.toml"), "w") as f:
            f.write(config_text.replace("\nmu = 0.3\n", "\nmu = 0.5\n", 1))
        run = wc.make_charts([self.run_dir], self.out)["runs"][0]["critical_taper"]
        self.assertIsNone(run["calibration"])
        self.assertIn("contact.mu", run["why"])
        other = dict(default, material_keys=dict(default["material_keys"],
                                                 contact=dict(default["material_keys"]["contact"], mu=0.5)))
        run = wc.make_charts([self.run_dir], self.out, calibration=other)["runs"][0]["critical_taper"]
        self.assertEqual(run["calibration"], "calibrated default material")
        # A key that came after the shipped calibration was recorded (rolling resistance): at its
        # default the calibration still fits, at another value it does not.
        with open(os.path.join(self.run_dir, "config.toml"), "w") as f:
            f.write(config_text.replace("\nrolling_friction = 0.0\n", "\nrolling_friction = 0.2\n", 1))
        run = wc.make_charts([self.run_dir], self.out)["runs"][0]["critical_taper"]
        self.assertIsNone(run["calibration"])
        self.assertIn("contact.rolling_friction", run["why"])

    def test_topography_reads_complete_outputs_only(self):
        if h5py is None:
            self.skipTest("h5py not installed")
        profiles = wc.read_topography(os.path.join(self.run_dir, "snapshots.h5"))
        self.assertEqual(len(profiles), 3)
        top = [np.nanmax(p["height"]) for p in profiles]
        self.assertAlmostEqual(top[0], 6.0 / H0, delta=0.1)  # flat layer, h0 thick
        self.assertTrue(top[0] < top[1] < top[2])
        self.assertAlmostEqual(top[2], (6.0 + 6.0) / H0, delta=0.1)

    def test_package_reads_groups_written_into_snapshots_h5(self):
        # The fixture's outputs are groups of snapshots.h5 itself, not links to snapshots/: the
        # package's lazy Dataset reads them too, the complete ones only, as read_frame does.
        if h5py is None:
            self.skipTest("h5py not installed")
        from orogen.snapshots import open_snapshots
        frame = wc.folders.read_frame(os.path.join(self.run_dir, "snapshots.h5"), -1)
        snaps = open_snapshots(self.run_dir)
        self.assertEqual(snaps.sizes["output"], 3)
        self.assertTrue(np.array_equal(snaps["y"].isel(output=2).values, frame["y"]))
        self.assertTrue(np.array_equal(snaps["walls"].isel(output=2).values, frame["walls"]))

    def test_nan_and_no_front(self):
        # NaN rows, no front ever, no snapshots: every chart still drawn, nulls in the summary.
        other = os.path.join(self.tmp, "run_b")
        os.makedirs(other)
        write_series(os.path.join(other, "series.csv"), n=8, s_end=0.7, nan_row=3)
        summary = wc.make_charts([self.run_dir, other], self.out, labels="a,b")
        for name in PNGS:
            self.assertTrue(os.path.isfile(os.path.join(self.out, name)), name)
        b = summary["runs"][1]
        self.assertEqual(b["label"], "b")
        self.assertIsNone(b["b"])  # only one point with S > 0.5
        self.assertIsNone(b["retro_onset_step"])
        self.assertIsNone(b["mean_alpha_late"])
        with open(os.path.join(self.out, "summary.json")) as f:
            json.load(f)  # strict JSON: no NaN

    def test_cli(self):
        proc = subprocess.run(module_command("orogen.charts.wedge") + [self.run_dir, self.run_dir, "--out", self.out,
                               "--labels", "x,y"], stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                              universal_newlines=True)
        self.assertEqual(proc.returncode, 0, proc.stderr)
        with open(os.path.join(self.out, "summary.json")) as f:
            self.assertEqual([r["label"] for r in json.load(f)["runs"]], ["x", "y"])
        bad = subprocess.run(module_command("orogen.charts.wedge") + [self.tmp, "--out", self.out],
                             stdout=subprocess.PIPE, stderr=subprocess.PIPE, universal_newlines=True)
        self.assertNotEqual(bad.returncode, 0)
        self.assertIn("series.csv", bad.stderr)


if __name__ == "__main__":
    unittest.main()
