"""Tests of orogen.analysis.exhumation and orogen.charts.exhumation on a tiny eroding wedge
run analysed by `orogen analyze` (OROGEN_BINARY, set by CTest; skipped without it).

Run from the repository root:
    OROGEN_BINARY=build/release/orogen /usr/bin/python3 -m unittest tests/python/test_exhumation_charts.py
"""

import os
import shutil
import subprocess
import sys
import tempfile
import unittest

import h5py
import numpy as np
import xarray as xr

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import source_tree  # noqa: E402,F401  (the package of this source tree)
from orogen.analysis import basins, exhumation as orogen_analysis, exhumation_summary  # noqa: E402
from orogen.charts import exhumation as exhumation_charts  # noqa: E402

BINARY = os.environ.get("OROGEN_BINARY", "")
SMALL = ("layer.thickness=5 wedge.tile_length=4 wedge.retro_length=4 wedge.initial_active=4 wedge.window=3 "
         "wedge.s_end=0.3 wedge.outputs=6 wedge.erosion_height=0.9 output.progress=never output.vtp=false").split()


class ProCycle(unittest.TestCase):
    """orogen_analysis.pro_cycle on a synthetic series and analysis with known answers."""

    def test_fronts_steps_and_low_erosion(self):
        tmp = tempfile.mkdtemp(prefix="orogen_pro_cycle_")
        self.addCleanup(shutil.rmtree, tmp)
        # Seven rows of series: the analysis has reached six outputs only (a running run).
        dp = [0, -0.2, -1.0, -1.1, -1.1, -2.0, -2.1]
        mp = [0, 0, -0.5, -0.5, -0.6, -0.6, -0.6]
        with open(os.path.join(tmp, "series.csv"), "w") as f:
            f.write("# S: convergence [-]\n# Dp: pro front [h0]\n# Mp: pro marker front [h0]\nS,Dp,Mp\n")
            for k in range(7):
                f.write(f"{0.1 * k},{dp[k]},{mp[k]}\n")
        cum = np.array([[0, 0], [0, 0], [1, 0], [1, 1], [2, 1], [2, 2]], dtype=float)
        ds = xr.Dataset({"flux_out": ("time", [0, 0, 1.0, 0.4, 0.2, 1.9]),
                         "cum_eroded_area": (("time", "column"), cum)}, attrs={"flux_in": 2.0})
        cycle = orogen_analysis.pro_cycle(tmp, ds)
        self.assertEqual(len(cycle), 6)
        # Outward steps of Dp: 0.2, 0.8, 0.1, 0, 0.9; above 0.5 h0 at outputs 2 and 5.
        self.assertEqual(list(cycle.step_out), [False, False, True, False, False, True])
        np.testing.assert_allclose(cycle.front_gap, [0, 0.2, 0.5, 0.6, 0.5, 1.4])
        np.testing.assert_allclose(cycle.flux, [0, 0, 0.5, 0.2, 0.1, 0.95])
        np.testing.assert_allclose(cycle.eroded_area, [0, 0, 1, 2, 3, 4])
        # Low erosion counts only once erosion has begun (output 2): outputs 3 and 4.
        self.assertEqual(list(cycle.low), [False, False, False, True, True, False])

        # With the steady state at output 4: before is outputs 2-3 (from the first erosion),
        # after 4-5. The step-out at 2 has no low output in 0-2; the one at 5 has 3 and 4.
        phases = exhumation_summary.phases_of_cycle(cycle, 4)
        before, after = phases["before"], phases["after"]
        self.assertEqual((before["outputs"], after["outputs"]), ([2, 3], [4, 5]))
        self.assertEqual((before["step_outs"], before["step_outs_after_low"]), (1, 0))
        self.assertEqual((after["step_outs"], after["step_outs_after_low"]), (1, 1))
        # Windows of three ending at 2, 3 (one of two holds a low output); at 4, 5 (both).
        self.assertEqual((before["window_chance"], after["window_chance"]), (0.5, 1.0))
        self.assertEqual((before["low_outputs"], after["low_outputs"]), (1, 1))
        self.assertAlmostEqual(before["flux_at_steps"], 0.5)
        self.assertAlmostEqual(before["flux_otherwise"], 0.2)
        self.assertAlmostEqual(after["flux_at_steps"], 0.95)
        self.assertAlmostEqual(after["flux_otherwise"], 0.1)
        # No steady state: every output from the first erosion is "before".
        phases = exhumation_summary.phases_of_cycle(cycle, None)
        self.assertEqual((phases["before"]["outputs"], phases["after"]["outputs"]), ([2, 5], None))
        self.assertEqual(phases["before"]["step_outs"], 2)


class AgeSettling(unittest.TestCase):
    """exhumation_summary.age_settling on a synthetic surface with known answers."""

    def test_first_reset_and_means_of_the_halves(self):
        s = np.arange(6) * 0.5
        # Two columns, one closure depth. Column 0: un-reset ageing until output 2, then
        # reset ages 10, 20, NaN (empty), 30. Column 1: never reset.
        age = np.array([[[0.0, 0]], [[1, 1]], [[10, 2]], [[20, 3]], [[np.nan, 4]], [[30, 5]]])
        unreset = np.array([[[1, 1]], [[1, 1]], [[0, 1]], [[0, 1]], [[0, 1]], [[0, 1]]], dtype=np.uint8)
        cum = np.array([[0, 0]] * 5 + [[4.0, 1.0]])
        ds = xr.Dataset({"S": ("time", s),
                         "surface_age": (("time", "closure", "column"), age),
                         "surface_unreset": (("time", "closure", "column"), unreset),
                         "cum_eroded_area": (("time", "column"), cum)},
                        coords={"column": [-1.0, 1.0], "closure": [0.3]})
        self.assertEqual(exhumation_summary.eroding_positions(ds, 2), [-1.0, 1.0])
        self.assertEqual(exhumation_summary.eroding_positions(ds.isel(time=slice(0, 5)), 2), [])
        rows = exhumation_summary.age_settling(ds, [-1.0, 1.0])
        first, never = rows
        self.assertEqual((first["x"], first["closure"], first["S_reset"]), (-1.0, 0.3, 1.0))
        # From output 2 on, the finite ages 10, 20, 30: mean 20; halves (10) and (20, 30).
        self.assertAlmostEqual(first["mean"], 20.0)
        self.assertAlmostEqual(first["first_half"], 10.0)
        self.assertAlmostEqual(first["second_half"], 25.0)
        self.assertIsNone(never["S_reset"])
        self.assertTrue(np.isnan(never["mean"]))


@unittest.skipUnless(BINARY and os.path.exists(BINARY), "OROGEN_BINARY not set")
class ExhumationCharts(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.mkdtemp(prefix="orogen_exhumation_charts_")
        cls.run_dir = os.path.join(cls.tmp, "run")
        args = [BINARY, "run", "--out", cls.run_dir, "--threads", "1"]
        for kv in SMALL:
            args += ["--set", kv]
        subprocess.run(args, check=True, capture_output=True)
        subprocess.run([BINARY, "analyze", cls.run_dir], check=True, capture_output=True)

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.tmp)

    def test_summary_row_of_indicators(self):
        row = exhumation_summary.indicators(self.run_dir)
        ds = orogen_analysis.load(self.run_dir)
        self.assertEqual(row["outputs"], ds.sizes["time"])
        self.assertEqual(row["steady_output"], orogen_analysis.steady_output(ds))
        # The column eroded most is one of the columns the analysis has, and the erosion is there.
        cum = ds.cum_eroded_area.isel(time=-1)
        self.assertEqual(float(cum.sel(column=row["x_max_erosion"])), float(cum.max()))
        self.assertLessEqual(row["low_erosion_near_step"], row["low_erosion_outputs"])
        table = exhumation_summary.markdown([row])
        self.assertEqual(len(table.strip().splitlines()), 3)
        self.assertEqual(exhumation_summary.main([os.path.join(self.tmp, "missing")]), 2)
        self.assertEqual(exhumation_summary.main([self.run_dir, "--ages", "0"]), 2)
        self.assertEqual(exhumation_summary.main([self.run_dir, "--flux-table", "-1"]), 2)

    def test_flux_table_holds_the_ratio_per_stretch(self):
        # A window of 2 outputs, so that this short run has a flux ratio from its third output.
        run = os.path.join(self.tmp, "run_window2")
        shutil.copytree(self.run_dir, run, ignore=shutil.ignore_patterns("analysis*"))
        subprocess.run([BINARY, "analyze", run, "--flux-window", "2"], check=True, capture_output=True)
        ds = orogen_analysis.load(run)
        s, ratio = ds.S.values, ds.flux_ratio.values
        width = float(s[-1] - s[0]) / 2
        rows = exhumation_summary.flux_stretches(run, width)
        self.assertGreaterEqual(len(rows), 1)
        # Every stretch's numbers are those of flux_ratio over its outputs.
        for start, _, mean, lo, hi in rows:
            r = ratio[(s >= start) & (s < start + width) & np.isfinite(ratio)]
            self.assertAlmostEqual(mean, float(r.mean()))
            self.assertEqual((lo, hi), (float(r.min()), float(r.max())))
        table = exhumation_summary.flux_table(run, width)
        self.assertEqual(len(table.strip().splitlines()), 3)
        # The ages table: a header, a rule, a row per position.
        self.assertEqual(len(exhumation_summary.ages_table(run, 3).strip().splitlines()), 5)
        # The cycle table: a header, a rule, a row per phase.
        self.assertEqual(len(exhumation_summary.cycle_table(run).strip().splitlines()), 4)

    def test_loader_gives_labelled_dataset(self):
        ds = orogen_analysis.load(self.run_dir)
        self.assertEqual(ds.sizes["time"], 7)
        self.assertEqual(ds.sizes["closure"], 5)
        self.assertEqual(ds.elevation.dims, ("time", "column"))
        self.assertEqual(ds.age.dims, ("time", "closure", "particle"))
        for name, var in ds.variables.items():
            self.assertIn("units", var.attrs, name)
            self.assertIn("description", var.attrs, name)
        # The disc at the surface has depth = its radius: the smallest depths, all positive.
        depth = ds.depth.values
        self.assertTrue(np.nanmin(depth) > 0)
        # Cumulative erosion never falls, and sums to the eroded discs.
        cum = ds.cum_eroded_count.values
        self.assertTrue((np.diff(cum, axis=0) >= 0).all())
        self.assertEqual(int(cum[-1].sum()), int((ds.removal_column.values >= 0).sum()))
        self.assertEqual(int(ds.eroded_count.sum()), ds.sizes["removal"])
        ages = orogen_analysis.at_positions(ds.surface_age.isel(closure=0), [0.0])
        self.assertEqual(ages.dims, ("time", "column"))

    def test_all_figures_in_one_command(self):
        out = os.path.join(self.tmp, "charts")
        self.assertEqual(exhumation_charts.main([self.run_dir, "--out", out]), 0)
        for name in exhumation_charts.FIGURES:
            path = os.path.join(out, name)
            self.assertTrue(os.path.getsize(path) > 1000, name)
        self.assertEqual([f for f in os.listdir(out) if f.startswith(".")], [])

    def test_refuses_a_folder_without_analysis(self):
        self.assertEqual(exhumation_charts.main([self.tmp]), 2)
        self.assertEqual(exhumation_charts.main([self.run_dir, "--positions", "a,b", "--out", self.tmp]), 2)


@unittest.skipUnless(BINARY, "OROGEN_BINARY not set")
class BasinsAndBase(unittest.TestCase):
    """A small wedge with a river, deposition and a plate under it (docs/surface.md,
    docs/isostasy.md): the charts of its sediment and its base."""

    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.mkdtemp(prefix="orogen_basins_")
        cls.run_dir = os.path.join(cls.tmp, "run")
        keys = SMALL + ("wedge.s_end=0.6 surface.every=100 surface.diffusivity=0.2 surface.erodibility=0.02 "
                        "surface.deposition=true surface.base_level=1.02 isostasy.model=flexure "
                        "isostasy.rigidity=5 isostasy.every=100").split()
        subprocess.run([BINARY, "run", "--out", cls.run_dir, "--threads", "1"] + [a for k in keys for a in ("--set", k)],
                       check=True, capture_output=True)
        subprocess.run([BINARY, "analyze", cls.run_dir], check=True, capture_output=True)

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.tmp)

    def test_sediment_and_base_charts(self):
        out = os.path.join(self.tmp, "charts")
        self.assertEqual(exhumation_charts.main([self.run_dir, "--out", out]), 0)
        for name in exhumation_charts.FIGURES + exhumation_charts.BASIN_FIGURES + exhumation_charts.BASE_FIGURES:
            self.assertTrue(os.path.getsize(os.path.join(out, name)) > 1000, name)
        ds = orogen_analysis.load(self.run_dir)
        laid = np.isfinite(ds.deposition_time.values)
        self.assertTrue(laid.any())
        # The sediment per column is the area of the deposits there (the last snapshot's) over
        # the column width, in h0.
        with h5py.File(os.path.join(self.run_dir, "snapshots.h5"), "r") as f:
            g = f[sorted(k for k in f if k.startswith("output_"))[-1]]
            x, r, t = g["x"][()], g["radius"][()], g["deposition_time"][()]
            h0 = float(f.attrs["h0"])
        width = float(ds.column[1] - ds.column[0]) * h0
        lo = float(ds.column[0]) * h0 - width / 2
        column = np.floor((x - lo) / width).astype(int)
        ok = np.isfinite(t) & (column >= 0) & (column < ds.sizes["column"])
        expected = np.bincount(column[ok], weights=np.pi * r[ok] ** 2, minlength=ds.sizes["column"]) / width / h0
        np.testing.assert_allclose(ds.deposit_thickness.values[-1], expected, rtol=1e-9, atol=1e-12)
        self.assertGreater(expected.sum(), 0)

    def test_parcels_followed_through_their_basin(self):
        tracks = basins.deposit_tracks(self.run_dir)
        self.assertGreater(tracks["id"].nunique(), 0)
        # Every deposit counted once, on one side; a side is where it was first seen.
        table = basins.record(tracks)
        self.assertEqual(table["laid"].sum(), tracks["id"].nunique())
        first = tracks.groupby("id").first()
        self.assertTrue(((first["x"] < 0) == (first["side"] == "pro")).all())
        # The base under a parcel is the snapshot's base line there; on the plate it has moved.
        with h5py.File(os.path.join(self.run_dir, "snapshots.h5"), "r") as f:
            k = int(tracks["output"].max())
            g, h0 = f["output_%06d" % k], float(f.attrs["h0"])
            walls = g["walls"][()]
        at = tracks[tracks["output"] == k]
        np.testing.assert_allclose(at["base"], basins.base_under(walls, at["x"].values * h0) / h0, rtol=0, atol=1e-12)
        self.assertGreater(np.abs(at["base"]).max(), 0.0)
        # Histories start where each parcel was first seen and stop when it leaves its basin.
        history = basins.subsidence(tracks)
        start = history.groupby("id").first()
        self.assertTrue((start[["age", "sunk", "subsided"]] == 0).all().all())
        self.assertTrue(tracks.loc[tracks["in_basin"], "id"].isin(history["id"]).all())
        summary = basins.subsidence_summary(history, span=0.2)
        self.assertEqual(list(summary["side"]), ["pro", "retro"])
        out = os.path.join(self.tmp, "subsidence.png")
        basins.main([self.run_dir, "--figure", out])
        self.assertGreater(os.path.getsize(out), 1000)

    def test_base_under_is_the_line_through_the_segments(self):
        # Two sloping segments and a vertical end wall: the line through their ends.
        walls = np.array([[-2.0, 0.0, 0.0, -1.0], [0.0, -1.0, 2.0, 0.0], [2.0, 0.0, 2.0, 5.0]])
        np.testing.assert_allclose(basins.base_under(walls, np.array([-1.0, 0.0, 1.5])), [-0.5, -1.0, -0.25])


if __name__ == "__main__":
    unittest.main()
