"""orogen.analysis.stress (issue 38): the mobilised friction angle and the orientation of the
greatest compression inside the pro-wedge, read from the stress grid of a wedge run. On a
synthetic run whose grid holds one known stress state everywhere (s1 = 3, s3 = 1 in m g / d,
so sin phi_mob = 1/2, with s1 rising 6 degrees toward the hinterland), the script must find
exactly that state in every square it counts, and count only squares inside the pro-wedge (for
a singly-vergent run, inside its wedge from the front to the backstop)."""
import math
import os
import shutil
import sys
import tempfile
import unittest

import h5py
import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import source_tree  # noqa: E402,F401  (the package of this source tree)
from orogen.analysis import stress as wedge_stress  # noqa: E402

H0, CELL, PSI = 10.0, 1.0, 6.0


def write_run(folder, singly=False, mirror=False):
    """A wedge whose surface rises from y = 4 at x = -60 to 20 at the S-point (x = 0), with
    the late pro front at -5 h0, and a stress grid of one state. As a singly-vergent run: the
    same front, the backstop at x = 5 (0.5 h0), five outputs of which the last three are late.
    Mirrored (x to -x, the stress state with it): a retro-wedge falling to its front at 5 h0."""
    os.makedirs(folder)
    with open(os.path.join(folder, "series.csv"), "w") as f:
        if singly:
            f.write("# synthetic\nshortening,backstop,front,width,taper,height\n")
            for k in range(5):
                f.write("%g,0.5,-5,5.5,9.5,1\n" % (k * 1.0))
        else:
            f.write("# synthetic\nS,Dp,Dr,alpha,beta,H\n")
            for k in range(3):
                f.write("%g,-5,5,9.5,9.5,2\n" % (6 + k))
    xs = np.arange(-60.0, 10.0, 1.0) + 0.5
    x, y = [], []
    for xi in xs:
        top = 20.0 + 0.27 * min(xi, 0.0)
        for yj in np.arange(0.5, top, 1.0):
            x.append(xi)
            y.append(yj)
    x, y = np.array(x) * (-1 if mirror else 1), np.array(y)
    rows, columns = 24, 70
    c, r, t = 2.0, 1.0, math.radians(2 * PSI)
    config = ("[run]\nexperiment = \"singly_vergent\"\n[singly]\nmu_b = 0.2\nshortening = 4.0\nsteady_from = 0.5\n"
              if singly else "[wedge]\ns_end = 8.0\nmu_bp = 0.2\nmu_br = 0.4\n")
    with h5py.File(os.path.join(folder, "snapshots.h5"), "w") as f:
        f.attrs["h0"] = H0
        f.attrs["config_toml"] = config
        for k in range(5 if singly else 3):
            g = f.create_group("output_%06d" % k)
            g["x"], g["y"], g["radius"] = x, y, np.full(x.size, 0.5)
            grid = g.create_group("stress_grid")
            grid.attrs["cell"], grid.attrs["x0"], grid.attrs["y0"] = CELL, -10.0 if mirror else -60.0, 0.0
            grid["xx"] = np.full((rows, columns), -(c + r * math.cos(t)))  # tension positive
            grid["yy"] = np.full((rows, columns), -(c - r * math.cos(t)))
            grid["xy"] = grid["yx"] = np.full((rows, columns), (1 if mirror else -1) * r * math.sin(t))


class WedgeStress(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.mkdtemp()
        self.folder = os.path.join(self.tmp, "wedge")
        write_run(self.folder)

    def tearDown(self):
        shutil.rmtree(self.tmp)

    def test_finds_the_stress_state_it_was_given(self):
        config, late, cells = wedge_stress.measure(self.folder, block=2.0)
        self.assertEqual(len(late), 3)  # S 6, 7, 8: the last third of s_end = 8
        self.assertGreater(len(cells), 0)
        np.testing.assert_allclose(cells["phi_mob"], 30.0, atol=1e-9)
        np.testing.assert_allclose(cells["psi"], PSI, atol=1e-9)
        # one disc of radius 0.5 centred in each 1 d cell: the solid fraction pi / 4; no cell of
        # the grid (x > -60) lies one to three h0 ahead of the front at -50
        np.testing.assert_allclose(late["solid_wedge"], math.pi / 4, rtol=1e-12)
        self.assertTrue(late["solid_ahead"].isna().all())

    def test_counts_only_squares_inside_the_pro_wedge(self):
        _, _, cells = wedge_stress.measure(self.folder, block=2.0)
        # A 1 d cell is inside when its centre lies more than one h0 behind the front (x > -40),
        # more than one h0 before the crest (the first of the highest columns), above the lowest
        # row (y > 1.5) and 1.5 d below the top of its column's discs; a 2 d square counts when
        # its four cells do.
        def surface(xc):
            top = 20.0 + 0.27 * min(xc, 0.0)
            return max(y for y in np.arange(0.5, top, 1.0)) + 0.5

        columns = [-59.5 + i for i in range(70)]
        crest = min(xc for xc in columns if surface(xc) == max(map(surface, columns)))
        self.assertEqual(crest, -1.5)  # the discs' tops reach 20 from x = -1.5 on

        def inside(i, j):
            xc, yc = -59.5 + i, 0.5 + j
            return -40 < xc < crest - H0 and yc > 1.5 and yc < surface(xc) - 1.5

        expected = sum(all(inside(2 * I + a, 2 * J + b) for a in (0, 1) for b in (0, 1))
                       for I in range(35) for J in range(12))
        self.assertGreater(expected, 20)
        self.assertEqual(len(cells), 3 * expected)

    def test_a_singly_vergent_wedge_is_read_from_its_front_to_its_backstop(self):
        folder = os.path.join(self.tmp, "singly")
        write_run(folder, singly=True)
        config, late, cells = wedge_stress.measure(folder, block=2.0)
        self.assertEqual(list(late["shortening"]), [2.0, 3.0, 4.0])  # after steady_from 0.5 of 4 h0
        np.testing.assert_allclose(cells["phi_mob"], 30.0, atol=1e-9)

        def surface(xc):
            top = 20.0 + 0.27 * min(xc, 0.0)
            return max(y for y in np.arange(0.5, top, 1.0)) + 0.5

        def inside(i, j):  # one h0 behind the front (x = -50) and before the backstop (x = 5)
            xc, yc = -59.5 + i, 0.5 + j
            return -40 < xc < 5 - H0 and yc > 1.5 and yc < surface(xc) - 1.5

        expected = sum(all(inside(2 * I + a, 2 * J + b) for a in (0, 1) for b in (0, 1))
                       for I in range(35) for J in range(12))
        self.assertGreater(expected, 20)
        self.assertEqual(len(cells), 3 * expected)

    def test_a_retro_wedge_is_read_as_the_pro_wedge_turned_over(self):
        folder = os.path.join(self.tmp, "retro")
        write_run(folder, mirror=True)
        config, late, cells = wedge_stress.measure(folder, block=2.0, side="retro")
        np.testing.assert_allclose(cells["phi_mob"], 30.0, atol=1e-9)
        np.testing.assert_allclose(cells["psi"], PSI, atol=1e-9)  # s1 dipping toward the retro foreland
        _, _, pro = wedge_stress.measure(self.folder, block=2.0)
        self.assertEqual(len(cells), len(pro))  # the mirror image of the pro-wedge's squares
        with self.assertRaises(SystemExit):  # a singly-vergent wedge has no retro side
            singly = os.path.join(self.tmp, "singly")
            write_run(singly, singly=True)
            wedge_stress.measure(singly, block=2.0, side="retro")

    def test_the_theory_beside_it(self):
        self.assertAlmostEqual(wedge_stress.psi_base(30.0, 0.0), 0.0)
        phi, phi_b = math.radians(30.0), math.atan(0.2)
        self.assertAlmostEqual(math.radians(wedge_stress.psi_base(30.0, 0.2)),
                               0.5 * (math.asin(math.sin(phi_b) / math.sin(phi)) - phi_b))


if __name__ == "__main__":
    unittest.main()
