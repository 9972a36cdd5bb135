"""orogen.analysis.traction (issue 38): what a wedge's bases transmit, read from the contact
forces of a short main-job wedge. The transmitted friction can never exceed the Coulomb limit
of its base, and the contacts it counts as at the limit carry exactly mu fn. The pro plate is
a Coulomb belt (wedge.traction_law = "spring"): the contacts below the limit stick to it, those
at the limit are held back by the wedge, and the base under the wedge transmits nearly mu_bp
(eq. 4.1's drag transmitted 0.11 of 0.2 late in the main job). A singly-vergent wedge is read
the same way: its floor stands still, and under the wedge the discs slide over it at its limit.

The binary is $OROGEN_BINARY (CTest sets it), else build/release/orogen."""
import os
import shutil
import subprocess
import sys
import tempfile
import unittest

import h5py
import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import source_tree  # noqa: E402,F401  (the package of this source tree)
from orogen.analysis import traction as basal_traction  # noqa: E402

BINARY = os.environ.get("OROGEN_BINARY", os.path.join(ROOT, "build", "release", "orogen"))


class RunOnce(unittest.TestCase):
    """A class whose tests read one run made once, with its contact forces, in a temporary folder."""
    ARGS = []

    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.mkdtemp()
        cls.folder = os.path.join(cls.tmp, "run")
        r = subprocess.run([BINARY, "run", *cls.ARGS, "--out", cls.folder, "--set", "output.contacts=true", "--set",
                            "output.progress=never", "--set", "output.vtp=false", "--threads", "1"],
                           capture_output=True, text=True)
        assert r.returncode == 0, r.stderr

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.tmp)


class BasalTraction(RunOnce):
    ARGS = ["--set", "wedge.s_end=1.5", "--set", "wedge.outputs=6"]

    def test_the_bases_transmit_at_most_their_coulomb_limit(self):
        config, late, _, table, slip, retro = basal_traction.measure(self.folder)
        self.assertGreaterEqual(len(late), 2)  # outputs of the last third with a pro front
        mu_bp, mu_br = config["wedge"]["mu_bp"], config["wedge"]["mu_br"]
        # fx, fy hold mu to about 1e-8: the pro base starts at x = -1e7, so its contact normals tilt by rounding
        self.assertTrue(((table["mu_pro"] > 0) & (table["mu_pro"] <= mu_bp * (1 + 1e-6))).all(), table["mu_pro"])
        self.assertTrue((table["mu_retro"].dropna() <= mu_br * (1 + 1e-6)).all(), table["mu_retro"])
        self.assertTrue(((table["at_limit_pro"] >= 0) & (table["at_limit_pro"] <= 1)).all())
        self.assertGreaterEqual(table["mu_pro"].mean(), 0.7 * mu_bp, table["mu_pro"])
        below, at = slip[slip.at_limit == 0].slip, slip[slip.at_limit == 1].slip
        self.assertLess(abs(below.median()), 0.02)  # stuck to the plate (an elastic stick)
        self.assertLess(at.median(), -0.1)  # the wedge holds them back: slower than the plate
        # The retro base stands still: what it holds sits on it, what slides is pushed retro-ward.
        self.assertGreater(len(retro), 0)
        self.assertTrue(((retro.u > 0) & (retro.u < 1)).all())  # from the S-point (0) to the retro front (1)
        held, sliding = retro[retro.at_limit == 0], retro[retro.at_limit == 1]
        self.assertLess(abs(held.slip.median()), 0.02)
        if len(sliding):
            np.testing.assert_allclose(sliding.fx / sliding.fy, mu_br, rtol=1e-6)  # -fx: it holds the wedge back
            self.assertGreater(sliding.slip.median(), 0)  # moving retro-ward (+x) over the base

    def test_a_contact_at_the_limit_carries_mu_fn(self):
        with h5py.File(os.path.join(self.folder, "snapshots.h5"), "r") as f:
            g = f["output_%06d" % (int(f.attrs["n_outputs"]) - 1)]
            pro, _ = basal_traction.base_rows(g["walls"][()])
            c = g["contacts"]
            on_pro = (c["is_wall"][()] == 1) & np.isin(c["id_a"][()], pro) & (c["at_limit"][()] == 1)
            ft, fn = c["ft"][()][on_pro], c["fn"][()][on_pro]
            fx, fy = c["fx"][()][on_pro], c["fy"][()][on_pro]
        self.assertGreater(on_pro.sum(), 0)
        np.testing.assert_allclose(np.abs(ft) / fn, 0.2, rtol=1e-12)
        np.testing.assert_allclose(np.abs(fx) / fy, 0.2, rtol=1e-6)  # the base is flat: t along x, n along y


class SinglyVergentFloor(RunOnce):
    """A short singly-vergent wedge on a floor of mu_b = 0.2 (about 10 s)."""
    ARGS = [os.path.join(ROOT, "examples", "singly_vergent.toml"), "--set", "singly.mu_b=0.2", "--set",
            "layer.length=60", "--set", "singly.shortening=1.5", "--set", "singly.outputs=6"]

    def test_the_floor_under_the_wedge_transmits_at_most_mu_b(self):
        config, late, series, table, slip, retro = basal_traction.measure(self.folder)
        self.assertEqual(basal_traction.base_friction(config), 0.2)
        # the outputs after singly.steady_from (0.5) of the shortening that have a wedge
        self.assertTrue((series["shortening"].iloc[late] >= 0.75 - 1e-9).all())
        self.assertGreaterEqual(len(late), 2)
        self.assertTrue(((table["mu_pro"] > 0) & (table["mu_pro"] <= 0.2 * (1 + 1e-6))).all(), table["mu_pro"])
        self.assertTrue(table["mu_retro"].isna().all())  # no retro base
        self.assertEqual(len(retro), 0)
        below, at = slip[slip.at_limit == 0].slip, slip[slip.at_limit == 1].slip
        self.assertLess(abs(below.median()), 0.05)  # stuck to the floor
        self.assertLess(at.median(), -0.3)  # sliding towards the foreland with the wedge
        self.assertTrue(((slip.u >= 0) & (slip.u <= 1)).all())  # from the front (0) to the backstop (1)
        at_limit = slip[slip.at_limit == 1]
        np.testing.assert_allclose(at_limit.fx / at_limit.fy, 0.2, rtol=1e-6)  # the flat floor: mu_b fn along x


if __name__ == "__main__":
    unittest.main()
