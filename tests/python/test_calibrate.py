"""Tests of orogen.calibrate (docs/materials.md, Calibration): the envelope fit recovers a known
Mohr-Coulomb envelope from synthetic stress states within their scatter, and `orogen calibrate`
on a small bonded sample runs its biaxial tests and writes the envelopes, the table and the
figure, with bad input named (exit 2).

Run from the repository root:  /usr/bin/python3 -m unittest tests/python/test_calibrate.py
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

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from source_tree import module_command  # noqa: E402
from orogen import calibrate  # noqa: E402


class EnvelopeFit(unittest.TestCase):
    def test_a_known_envelope_is_recovered_within_its_scatter(self):
        phi, c = math.radians(28.0), 1.5
        n = (1 + math.sin(phi)) / (1 - math.sin(phi))
        rng = np.random.default_rng(3)
        sigma3 = np.repeat([1.0, 2.0, 5.0, 10.0, 20.0], 4)
        sigma1 = 2 * c * math.sqrt(n) + n * sigma3 + rng.normal(0, 0.3, sigma3.size)
        e = calibrate.fit_envelope(sigma3, sigma1)
        self.assertLess(abs(e["phi_deg"] - 28.0), 3 * e["phi_stderr_deg"])
        self.assertLess(abs(e["cohesion"] - c), 3 * e["cohesion_stderr"])
        self.assertLess(e["phi_stderr_deg"], 1.0)
        # Exact states give the envelope exactly.
        exact = calibrate.fit_envelope([1, 4, 9], [2 * c * math.sqrt(n) + n * s for s in (1, 4, 9)])
        self.assertAlmostEqual(exact["phi_deg"], 28.0, places=9)
        self.assertAlmostEqual(exact["cohesion"], c, places=9)
        self.assertAlmostEqual(exact["ucs"], 2 * c * math.sqrt(n), places=9)

    def test_fewer_than_three_confining_stresses_are_refused(self):
        with self.assertRaises(calibrate.CalibrationError):
            calibrate.fit_envelope([1, 1, 2], [3, 3.1, 5])


CONFIG = """
[run]
experiment = "biaxial"
[particles]
packing = "random_discs"
[biaxial]
width = 10.0
height = 20.0
strain_rate = 0.0005
strain_end = 0.04
outputs = 8
[materials.sand]
friction = 0.3
[materials.rock]
friction = 0.5
bond_tensile_strength = 5.0
"""


class CalibrateCommand(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.dir = tempfile.mkdtemp(prefix="orogen_calibrate_")
        cls.config = os.path.join(cls.dir, "rock.toml")
        with open(cls.config, "w") as f:
            f.write(CONFIG)
        cls.out = os.path.join(cls.dir, "cal")
        cls.r = subprocess.run(module_command("orogen.calibrate", cls.config, "--out", cls.out, "--material", "rock",
                                              "--sigma3", "2,5,10"), capture_output=True, text=True)

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.dir, ignore_errors=True)

    def test_the_tests_run_and_the_envelopes_are_written(self):
        self.assertEqual(self.r.returncode, 0, self.r.stderr)
        for name in ("calibration.json", "calibration.csv", "calibration.png", "calibration.pdf"):
            self.assertTrue(os.path.isfile(os.path.join(self.out, name)), name)
        with open(os.path.join(self.out, "calibration.json")) as f:
            result = json.load(f)
        for state in ("peak", "residual"):
            e = result[state]
            self.assertTrue(5 < e["phi_deg"] < 60, e)
            self.assertTrue(math.isfinite(e["cohesion"]), e)
        # Each test is a biaxial run of the named material.
        for s in ("2", "5", "10"):
            with open(os.path.join(self.out, "sigma3_" + s, "config.toml")) as f:
                text = f.read()
            self.assertIn('material = "rock"', text)
            self.assertIn("sigma3 = %s.0" % s, text)
        self.assertIn("peak: phi =", self.r.stdout)
        # The Brazilian test: a bonded material's tensile strength, positive and below its bonds'.
        t = result["tensile_strength"]
        self.assertTrue(0 < t["sigma_t_rho_g_d"] < 5, t)
        self.assertAlmostEqual(t["sigma_t"] * math.pi / 4, t["sigma_t_rho_g_d"])
        with open(os.path.join(self.out, "brazilian", "config.toml")) as f:
            text = f.read()
        self.assertIn('test = "brazilian"', text)
        self.assertIn("tension (Brazilian): sigma_t =", self.r.stdout)

    def test_bad_input_is_named(self):
        cases = [(["--sigma3", "2,5"], "three or more"),
                 (["--sigma3", "2,x,5"], "--sigma3 2,x,5"),
                 (["--material", "granite"], "biaxial.material"),
                 (["--tension-sigma3", "-1"], "--tension-sigma3")]
        for args, expect in cases:
            out = os.path.join(self.dir, "bad")
            r = subprocess.run(module_command("orogen.calibrate", self.config, "--out", out, *args),
                               capture_output=True, text=True)
            self.assertEqual(r.returncode, 2, (args, r.stderr))
            self.assertIn(expect, r.stderr, args)
        r = subprocess.run(module_command("orogen.calibrate", os.path.join(self.dir, "none.toml"), "--out", self.out),
                           capture_output=True, text=True)
        self.assertEqual(r.returncode, 2)
        self.assertIn("none.toml", r.stderr)


if __name__ == "__main__":
    unittest.main()
