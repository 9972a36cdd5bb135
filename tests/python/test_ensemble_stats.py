"""Tests of the ensemble statistics (orogen.analysis.powerlaw, orogen.analysis.cycles,
orogen.stats, orogen.charts.ensemble) on synthetic data: docs/ensembles.md."""

import csv
import filecmp
import os
import shutil
import subprocess
import sys
import tempfile
import time
import unittest

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, HERE)
import ensemble_fixture  # noqa: E402
from source_tree import module_command  # noqa: E402
from orogen.analysis import cycles as thrust_cycles, powerlaw  # noqa: E402


class PowerLawTest(unittest.TestCase):
    def test_fit_recovers_a_and_b_within_their_standard_errors(self):
        # Several noise draws: the truth within 2 standard errors every time, and the errors
        # honest (the spread of b over draws is about its standard error).
        s = np.linspace(0.1, 21.0, 200)
        bs, ses = [], []
        for seed in range(20):
            rng = np.random.default_rng(seed)
            x = 1.7 * s ** 0.5 * np.exp(rng.normal(0.0, 0.05, s.size))
            fit = powerlaw.power_law_fit(s, x, s_min=2.0)
            self.assertLess(abs(fit["b"] - 0.5), 2.5 * fit["b_se"])
            self.assertLess(abs(fit["log_a"] - np.log(1.7)), 2.5 * fit["log_a_se"])
            self.assertLess(abs(fit["a"] - 1.7), 2.5 * fit["a_se"])
            self.assertAlmostEqual(fit["residual_se"], 0.05, delta=0.01)
            bs.append(fit["b"])
            ses.append(fit["b_se"])
        self.assertLess(np.std(bs), 2.0 * np.mean(ses))
        self.assertGreater(np.std(bs), 0.5 * np.mean(ses))

    def test_offset_removal_is_exact_on_a_shifted_power_law(self):
        s = np.linspace(0.1, 21.0, 200)
        for x0, a, b in ((2.5, 1.7, 0.5), (-3.0, 1.7, 0.5), (10.0, 0.3, 0.8), (1.0, 0.1, 1.5)):
            found = powerlaw.auto_offset(s, x0 + a * s ** b, s_min=0.0)
            self.assertAlmostEqual(found, x0, delta=1e-6 * (a * 21.0 ** b), msg=(x0, a, b))
            fit = powerlaw.power_law_fit(s, x0 + a * s ** b - found, s_min=2.0)
            self.assertAlmostEqual(fit["b"], b, places=5)

    def test_a_logarithm_has_no_offset_to_find(self):
        # ln S is the limit of (S^b - 1) / b as b -> 0: the best offset runs off to -infinity.
        s = np.linspace(0.1, 21.0, 200)
        self.assertTrue(np.isnan(powerlaw.auto_offset(s, 5.0 + np.log(s))))


class StepOutTest(unittest.TestCase):
    def test_finds_the_steps_of_a_saw_tooth_and_nothing_else(self):
        s = np.linspace(0.1, 21.0, 210)
        p, steps = ensemble_fixture.sawtooth_front(s, step_every=4.0, step_size=2.0, retreat=-0.3, start=2.0)
        p += np.random.default_rng(3).normal(0.0, 0.05, s.size)
        events, summary = thrust_cycles.cycles(s, s / 0.5, -p, "pro", step_min=0.5)
        self.assertEqual([e["first"] for e in events], steps)
        for e in events:
            self.assertAlmostEqual(e["size"], 2.0 - 0.3 * 0.1, delta=0.25)
        self.assertAlmostEqual(summary["mean_spacing"], 4.0, delta=0.11)
        self.assertAlmostEqual(summary["speed"], 0.5, places=9)
        self.assertAlmostEqual(summary["mean_time_scale"], summary["mean_size"] / 0.5, places=9)
        self.assertAlmostEqual(summary["retreat_rate"], -0.3, delta=0.05)

    def test_a_jump_over_two_outputs_is_one_step_and_growth_is_none(self):
        s = np.linspace(0.1, 10.0, 100)
        smooth = 2.0 * s ** 0.5
        self.assertEqual(thrust_cycles.step_outs(s, smooth, 0.5), [])
        p = smooth.copy()
        p[50:] += 0.6
        p[51:] += 0.6
        events = thrust_cycles.step_outs(s, p, 0.5)
        self.assertEqual(len(events), 1)
        self.assertEqual((events[0]["first"], events[0]["last"]), (50, 51))
        # Missing fronts (no front yet) are never steps.
        q = p.copy()
        q[:30] = np.nan
        self.assertEqual(len(thrust_cycles.step_outs(s, q, 0.5)), 1)


class AggregateTest(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.mkdtemp()

    def tearDown(self):
        shutil.rmtree(self.tmp)

    def run_stats(self, folder):
        return subprocess.run(module_command("orogen.stats", folder),
                              capture_output=True, text=True)

    def test_four_members_of_200_outputs_in_seconds_and_the_same_bytes_twice(self):
        a, b = os.path.join(self.tmp, "a"), os.path.join(self.tmp, "b")
        ensemble_fixture.make_ensemble(a)
        ensemble_fixture.make_ensemble(b)
        start = time.monotonic()
        r = self.run_stats(a)
        elapsed = time.monotonic() - start
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertLess(elapsed, 10.0)
        self.assertEqual(self.run_stats(b).returncode, 0)
        files = sorted(os.listdir(os.path.join(a, "aggregate")))
        self.assertIn("fits.md", files)
        match, mismatch, errors = filecmp.cmpfiles(os.path.join(a, "aggregate"), os.path.join(b, "aggregate"),
                                                   files, shallow=False)
        self.assertEqual((mismatch, errors), ([], []))
        self.assertTrue(filecmp.cmp(os.path.join(a, "results.csv"), os.path.join(b, "results.csv"), shallow=False))
        # The fits find the synthetic laws: Dp = -(1 + 2 S^0.5) with its offset.
        with open(os.path.join(a, "aggregate", "fits.csv"), newline="") as f:
            fits = {row["series"]: row for row in csv.DictReader(line for line in f if not line.startswith("#"))}
        self.assertAlmostEqual(float(fits["Dp"]["b"]), 0.5, delta=0.03)
        self.assertAlmostEqual(float(fits["Dp"]["offset"]), -1.0, delta=0.15)
        self.assertEqual(fits["H"]["offset_how"], "none")
        # The Simple Model table: ratio is the mean H over the model's H, row by row.
        with open(os.path.join(a, "aggregate", "simple_model.csv"), newline="") as f:
            rows = [r for r in csv.DictReader(line for line in f if not line.startswith("#"))
                    if float(r["H_simple"]) > 0]
        self.assertTrue(rows)
        for r in rows:
            self.assertAlmostEqual(float(r["ratio"]), float(r["H_mean"]) / float(r["H_simple"]), places=12)
        # Charts: one command, every figure.
        r = subprocess.run(module_command("orogen.charts.ensemble", a),
                           capture_output=True, text=True)
        self.assertEqual(r.returncode, 0, r.stderr)
        charts = os.listdir(os.path.join(a, "aggregate", "charts"))
        for name in ("fig5_14_fronts_members.png", "fig5_16_mean_fronts.png", "fig5_17_18_fits.png",
                     "fig5_19_22_seed1.png", "cycles.png", "simple_model.png"):
            self.assertIn(name, charts)

    def test_not_an_ensemble_folder_is_exit_2(self):
        r = self.run_stats(self.tmp)
        self.assertEqual(r.returncode, 2)
        self.assertIn("ensemble.toml", r.stderr)


if __name__ == "__main__":
    unittest.main()
