"""Tests of orogen.analysis.faults (docs/materials.md, Fault picking): on a synthetic strain
field with a forethrust and a backthrust of known dips in a weak background, the picker finds
those two, of the right kind, dip and place along the base, and nothing else; spacing along the
base; a rigid thrust's slip from its walls, beyond a wide zone too; bad input named.

Run from the repository root:  /usr/bin/python3 -m unittest tests/python/test_faults.py
"""

import math
import os
import subprocess
import sys
import tempfile
import unittest

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from source_tree import module_command  # noqa: E402
from orogen.analysis import faults  # noqa: E402


def wedge_lattice(d=0.1):
    """Disc centres (h0) of a layer 1 h0 thick from x = -7 to 5 with a wedge 1.6 h0 high between
    x = -3.5 and 1, on a triangular lattice of spacing d."""
    xs, ys = [], []
    for row in range(int(1.7 / (d * math.sqrt(3) / 2))):
        y = row * d * math.sqrt(3) / 2 + d / 2
        for x in np.arange(-7 + (row % 2) * d / 2, 5, d):
            if y <= 1.0 or (-3.5 <= x <= 1.0 and y <= 1.6):
                xs.append(x)
                ys.append(y)
    return np.array(xs), np.array(ys)


def band_strain(x, y, x_base, dip_deg, deepens_to_plus_x, top, width=0.12, value=1.0):
    """Strain `value` within `width` of the line through (x_base, 0) at the dip, up to height `top`."""
    slope = math.tan(math.radians(dip_deg)) * (-1 if deepens_to_plus_x else 1)
    # the line: y = slope (x - x_base); distance of each disc from it
    dist = np.abs(slope * (x - x_base) - y) / math.hypot(slope, 1)
    return np.where((dist <= width) & (y <= top), value, 0.0)


class Picker(unittest.TestCase):
    def setUp(self):
        self.x, self.y = wedge_lattice()
        rng = np.random.default_rng(5)
        self.background = rng.exponential(0.02, self.x.size)  # weak, diffuse

    def test_finds_a_forethrust_and_a_backthrust_and_nothing_else(self):
        x, y = self.x, self.y
        strain = self.background + band_strain(x, y, -1.5, 30, True, 1.3) + band_strain(x, y, -1.0, 60, False, 1.3)
        picked = faults.pick_faults(x, y, strain, d_h0=0.1, seed=1)
        self.assertEqual(len(picked), 2, [(f["kind"], f["dip_deg"], f["x_base"]) for f in picked])
        by_kind = {f["kind"]: f for f in picked}
        self.assertEqual(set(by_kind), {"forethrust", "backthrust"})
        fore, back = by_kind["forethrust"], by_kind["backthrust"]
        self.assertEqual(fore["side"], "pro")
        self.assertAlmostEqual(fore["dip_deg"], 30, delta=3)
        self.assertAlmostEqual(fore["x_base"], -1.5, delta=0.15)
        self.assertAlmostEqual(back["dip_deg"], 60, delta=3)
        self.assertAlmostEqual(back["x_base"], -1.0, delta=0.15)
        self.assertGreater(fore["length"], 1.5)

    def test_a_weak_background_alone_has_no_faults(self):
        # Its 99.5th percentile sets the level: a quarter of it still leaves scattered discs,
        # but no line of them.
        picked = faults.pick_faults(self.x, self.y, self.background, d_h0=0.1, seed=1)
        self.assertEqual(picked, [])

    def test_retro_side_vergence_and_spacing(self):
        x, y = self.x, self.y
        # Two retro forethrusts (deepening towards the S-point, -x), 0.8 h0 apart along the base.
        strain = self.background + band_strain(x, y, 0.2, 35, False, 1.2) + band_strain(x, y, 1.0, 35, False, 1.0)
        picked = faults.pick_faults(x, y, strain, d_h0=0.1, seed=2, min_length=0.4)
        self.assertEqual(len(picked), 2)
        self.assertTrue(all(f["side"] == "retro" and f["kind"] == "forethrust" for f in picked))
        gaps = faults.spacings(picked)
        inner = min(range(2), key=lambda k: picked[k]["x_base"])
        self.assertAlmostEqual(gaps[inner], 0.8, delta=0.15)  # to the next one out (+x)
        self.assertTrue(math.isnan(gaps[1 - inner]))

    def test_a_singly_vergent_wedge_has_its_core_at_the_backstop(self):
        """A fault right of x = 0 deepening towards +x: a retro backthrust about a doubly-vergent
        wedge's S-point, a forethrust of a singly-vergent wedge whose backstop stands at +x."""
        x, y = self.x, self.y
        strain = self.background + band_strain(x, y, 2.5, 30, True, 1.0)
        (doubly,) = faults.pick_faults(x, y, strain, d_h0=0.1, seed=1)
        self.assertEqual((doubly["side"], doubly["kind"]), ("retro", "backthrust"))
        walls = np.array([[-8.0, 0.0, 8.0, 0.0], [-7.0, 0.0, -7.0, 3.0], [5.2, 0.0, 5.2, 3.0]])
        (singly,) = faults.pick_faults(x, y, strain, d_h0=0.1, seed=1, core_x=faults.backstop_x(walls))
        self.assertEqual((singly["side"], singly["kind"]), ("pro", "forethrust"))


def thrust(x, y, x_base, dip_deg, deepens_to_plus_x, slip):
    """The lattice after a rigid thrust: the discs above the line through (x_base, 0) at the dip
    moved `slip` up-dip along it. Returns the new x, y and the line's up-dip unit vector."""
    sign = -1 if deepens_to_plus_x else 1  # slope of the line
    slope = sign * math.tan(math.radians(dip_deg))
    up = np.array([sign * math.cos(math.radians(dip_deg)), math.sin(math.radians(dip_deg))])
    above = y > slope * (x - x_base)
    return x + above * slip * up[0], y + above * slip * up[1], up


class Offsets(unittest.TestCase):
    """A rigid thrust of known slip through a lattice: the slip of its walls (the hanging wall's
    up-dip motion less the footwall's) in the thrust sense; walls beyond a wide sheared zone."""

    def setUp(self):
        self.x, self.y = wedge_lattice()
        self.ids = np.arange(self.x.size)

    def check(self, x_base, dip, deepens_to_plus_x, amount):
        x1, y1, _ = thrust(self.x, self.y, x_base, dip, deepens_to_plus_x, amount)
        strain = band_strain(x1, y1, x_base, dip, deepens_to_plus_x, 1.3)
        (f,) = faults.pick_faults(x1, y1, strain, d_h0=0.1, seed=1)
        wall = faults.walls(f, x1, y1, 0.1, strain, f["level"])
        before, after = {"x": self.x, "y": self.y, "id": self.ids}, {"x": x1, "y": y1, "id": self.ids}
        return f, faults.slip(wall, before, after)

    def test_a_forethrust_of_known_slip(self):
        f, slip = self.check(-2.0, 30, True, 0.4)
        self.assertEqual(f["kind"], "forethrust")
        self.assertAlmostEqual(slip, 0.4, delta=0.02)  # rigid walls: their medians move exactly

    def test_a_backthrust_and_its_sense(self):
        f, slip = self.check(-1.0, 55, False, 0.3)
        self.assertEqual(f["kind"], "backthrust")
        self.assertAlmostEqual(slip, 0.3, delta=0.02)
        _, slip = self.check(-1.0, 55, False, -0.3)  # the hanging wall down: a normal fault's sense
        self.assertAlmostEqual(slip, -0.3, delta=0.02)

    def test_the_walls_stand_beyond_a_wide_sheared_zone(self):
        # The thrust's 0.4 h0 taken up across a zone: the hanging wall's share of it rises as
        # tanh(distance / 0.25 h0), and the strain is its gradient, sheared (a quarter of the
        # peak) within 3.3 discs of the line. Walls right beside the picked band see part of the
        # slip; walls beyond the zone, as the strain field shows it, nearly all of it.
        slope = -math.tan(math.radians(30))
        up = np.array([-math.cos(math.radians(30)), math.sin(math.radians(30))])
        across = (self.y - slope * (self.x + 2.0)) * math.cos(math.radians(30))  # distance above the line
        share = 0.5 * (1 + np.tanh(across / 0.25))
        x1, y1 = self.x + 0.4 * share * up[0], self.y + 0.4 * share * up[1]
        strain = np.cosh(across / 0.25) ** -2
        (f,) = faults.pick_faults(x1, y1, strain, d_h0=0.1, seed=1)  # one zone, one fault
        self.assertAlmostEqual(f["dip_deg"], 30, delta=5)  # a line inside a wide zone may lean
        before, after = {"x": self.x, "y": self.y, "id": self.ids}, {"x": x1, "y": y1, "id": self.ids}
        self.assertLess(faults.slip(faults.walls(f, x1, y1, 0.1), before, after), 0.34)
        wall = faults.walls(f, x1, y1, 0.1, strain, f["level"])
        self.assertAlmostEqual(faults.slip(wall, before, after), 0.4, delta=0.03)

    def test_walls_that_were_not_there_have_no_slip(self):
        # Discs that came later (the inflow of a doubly-vergent wedge): nothing to compare with.
        x1, y1, _ = thrust(self.x, self.y, -2.0, 30, True, 0.4)
        (f,) = faults.pick_faults(x1, y1, band_strain(x1, y1, -2.0, 30, True, 1.3), d_h0=0.1, seed=1)
        wall = faults.walls(f, x1, y1, 0.1)
        moved = (x1 != self.x) | (y1 != self.y)
        before = {"x": self.x[~moved], "y": self.y[~moved], "id": self.ids[~moved]}  # no hanging wall yet
        self.assertTrue(math.isnan(faults.slip(wall, before, {"x": x1, "y": y1, "id": self.ids})))


class Command(unittest.TestCase):
    def test_bad_input_is_named(self):
        with tempfile.TemporaryDirectory() as d:
            for args, expect in (([d], "snapshots.h5 not found"), ([d, "--window", "0"], "--window 0"),
                                 ([d, "--threshold", "2"], "--threshold 2")):
                r = subprocess.run(module_command("orogen.analysis.faults", *args), capture_output=True, text=True)
                self.assertEqual(r.returncode, 2, r.stderr)
                self.assertIn(expect, r.stderr)


if __name__ == "__main__":
    unittest.main()
