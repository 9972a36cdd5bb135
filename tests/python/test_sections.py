"""Tests of orogen.charts.sections: the strain measure against known deformations, the horizon
colours, and the figures of a short main-job wedge (OROGEN_BINARY, set by CTest) read as a reader
relies on them: bands of the stated thickness, a crop that holds the whole wedge, one fault
scale for every frame, vector stills.

Run from the repository root:  /usr/bin/python3 -m unittest tests/python/test_sections.py
"""

import json
import os
import shutil
import subprocess
import sys
import tempfile
import unittest

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from source_tree import module_command  # noqa: E402
from orogen.charts import sections  # noqa: E402

BINARY = os.environ.get("OROGEN_BINARY")


def lattice(n=20, spacing=1.0):
    """A triangular lattice of n x n discs as one output (h0 = 1, ids 0..)."""
    i, j = np.meshgrid(np.arange(n), np.arange(n))
    x = (i + 0.5 * (j % 2)).ravel() * spacing
    y = (j * np.sqrt(3) / 2).ravel() * spacing
    return {"x": x, "y": y, "id": np.arange(x.size), "h0": 1.0}


def moved(o, F, shift=(0.0, 0.0), ids=None):
    p = np.column_stack([o["x"], o["y"]]) @ np.asarray(F).T + np.asarray(shift)
    return {"x": p[:, 0], "y": p[:, 1], "id": o["id"] if ids is None else ids, "h0": 1.0}


class StrainMeasure(unittest.TestCase):
    def test_simple_shear_gives_its_mohr_radius_everywhere(self):
        g = 0.1
        before = lattice()
        strain = sections.shear_strain(before, moved(before, [[1, g], [0, 1]]), radius=1.5)
        # E = (F^T F - I)/2 for simple shear: exx 0, eyy g^2/2, exy g/2.
        expected = np.hypot(g * g / 4, g / 2)
        np.testing.assert_allclose(strain, expected, rtol=1e-9)

    def test_rigid_motion_has_no_strain(self):
        c, s = np.cos(0.3), np.sin(0.3)
        before = lattice()
        strain = sections.shear_strain(before, moved(before, [[c, -s], [s, c]], shift=(5.0, -2.0)), radius=1.5)
        self.assertLess(np.nanmax(strain), 1e-12)

    def test_a_fault_lights_up_and_nothing_else(self):
        before = lattice(30)
        after = moved(before, np.eye(2))
        hanging = before["y"] > before["y"].mean()  # the upper half slides 1 d to the right
        after["x"] = after["x"] + np.where(hanging, 1.0, 0.0)
        strain = sections.shear_strain(before, after, radius=1.5)
        distance = np.abs(before["y"] - before["y"].mean())
        self.assertGreater(np.min(strain[distance < 0.5]), 0.1)
        self.assertLess(np.max(strain[distance > 2.0]), 1e-12)

    def test_new_discs_and_reordered_ids(self):
        before = lattice(10)
        after = moved(before, np.eye(2))
        order = np.random.default_rng(1).permutation(after["x"].size)
        after = {k: (v[order] if isinstance(v, np.ndarray) else v) for k, v in after.items()}
        after["id"] = after["id"].copy()
        after["id"][0] = 10_000  # a disc that entered since
        strain = sections.shear_strain(before, after, radius=1.5)
        self.assertTrue(np.isnan(strain[0]))
        self.assertLess(np.nanmax(strain), 1e-12)
        self.assertEqual(np.isnan(strain).sum(), 1)


class HorizonColours(unittest.TestCase):
    def test_bands_alternate_sides_differ_and_the_marker_bed_is_red(self):
        band = 0.2
        depth = (np.arange(5) + 0.5) * band
        pro = sections.horizon_colours(depth, -np.ones(5), band)
        retro = sections.horizon_colours(depth, np.ones(5), band)
        red = np.array(sections.matplotlib.colors.to_rgba(sections.MARKER_COLOUR))
        np.testing.assert_array_equal(pro[2], red)
        np.testing.assert_array_equal(retro[2], red)
        self.assertFalse(np.array_equal(pro[0], pro[1]))  # light, dark
        np.testing.assert_array_equal(pro[1], pro[3])
        self.assertFalse(np.array_equal(pro[0], retro[0]))  # blue against brown
        # Lightness contrast between neighbouring bands (luma of sRGB): at least 0.3.
        luma = lambda c: 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2]  # noqa: E731
        for colours in (pro, retro):
            self.assertGreater(abs(luma(colours[0]) - luma(colours[1])), 0.3)

    def test_materials_have_hues_of_their_own_in_the_same_bands(self):
        band = 0.2
        depth = np.tile((np.arange(5) + 0.5) * band, 2)
        material = np.repeat([0, 1], 5)
        colours = sections.material_colours(depth, material, band)
        red = np.array(sections.matplotlib.colors.to_rgba(sections.MARKER_COLOUR))
        np.testing.assert_array_equal(colours[2], red)  # the marker bed in either material
        np.testing.assert_array_equal(colours[7], red)
        self.assertFalse(np.array_equal(colours[0], colours[1]))  # light, dark
        self.assertFalse(np.array_equal(colours[0], colours[5]))  # material 0 against 1
        np.testing.assert_array_equal(colours[0], sections.matplotlib.colors.to_rgba(sections.MATERIAL_COLOURS[0][0]))
        np.testing.assert_array_equal(colours[6], sections.matplotlib.colors.to_rgba(sections.MATERIAL_COLOURS[1][1]))

    def test_round_up(self):
        self.assertEqual([sections.round_up(v) for v in (0.13, 0.2, 0.51, 7.0)], [0.2, 0.2, 1.0, 10.0])


@unittest.skipUnless(BINARY and os.path.exists(BINARY), "OROGEN_BINARY not set")
class MainJobSections(unittest.TestCase):
    """A short main-job wedge (S = 1.2, 6 outputs), drawn as a user's main job is."""

    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.mkdtemp(prefix="orogen_sections_")
        cls.folder = os.path.join(cls.tmp, "run")
        r = subprocess.run([BINARY, "run", "--out", cls.folder, "--set", "wedge.s_end=1.2", "--set", "wedge.outputs=6",
                            "--set", "output.progress=never", "--threads", "1"], capture_output=True, text=True)
        assert r.returncode == 0, r.stderr
        r = subprocess.run(module_command("orogen.charts.sections", cls.folder, "--kinds", "horizons,faults,vectors",
                                          "--formats", "png,pdf,svg", "--stills", "0,-1", "--jobs", "2"),
                           capture_output=True, text=True)
        assert r.returncode == 0, r.stderr
        with open(os.path.join(cls.folder, "sections", "sections.json")) as f:
            cls.summary = json.load(f)
        cls.outputs = sections.read_outputs(cls.folder)

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.tmp, ignore_errors=True)

    def test_every_frame_still_and_animation_is_written(self):
        n = len(self.outputs)
        for folder in ("frames", "frames_faults", "frames_vectors"):
            names = sorted(os.listdir(os.path.join(self.folder, folder)))
            self.assertEqual(names, ["frame_%06d.png" % k for k in range(n)])
        for kind in sections.KINDS:
            for fmt in ("png", "pdf", "svg"):
                for k in (0, n - 1):
                    path = os.path.join(self.folder, "sections", "%s_%06d.%s" % (kind, k, fmt))
                    self.assertGreater(os.path.getsize(path), 1000, path)
        with open(os.path.join(self.folder, "sections", "horizons_%06d.svg" % (n - 1))) as f:
            self.assertIn("<svg", f.read(2000))
        if shutil.which("ffmpeg"):
            for stem in ("animation", "animation_frames_faults", "animation_frames_vectors"):
                self.assertGreater(os.path.getsize(os.path.join(self.folder, stem + ".mp4")), 1000)

    def test_the_crop_holds_every_disc_of_the_wedge_and_the_base(self):
        v = self.summary["view_h0"]
        self.assertLessEqual(v["y_min"], 0.0)
        for o in self.outputs:
            wedge = o["y"] - o["radius"] > 1.0 + sections.CROP_RISE
            self.assertTrue(np.all(o["x"][wedge] >= v["x_min"]) and np.all(o["x"][wedge] <= v["x_max"]))
            in_view = (o["x"] >= v["x_min"]) & (o["x"] <= v["x_max"])
            self.assertTrue(np.all(o["y"][in_view] + o["radius"][in_view] <= v["y_max"]))
        # Cropped: much narrower than the model's layer, and at least a fifth as tall as wide.
        last = self.outputs[-1]
        self.assertLess(v["x_max"] - v["x_min"], 0.8 * (last["x"].max() - last["x"].min()))
        ve = self.summary["vertical_exaggeration"]
        self.assertGreaterEqual((v["y_max"] - v["y_min"]) * ve / (v["x_max"] - v["x_min"]), 0.2 - 1e-9)

    def test_bands_of_the_stated_thickness_are_in_the_picture(self):
        from matplotlib.image import imread

        band = self.summary["band_thickness_h0"]
        self.assertAlmostEqual(band, 0.2)
        # Each band of the layer holds discs, so each band's colour is in the last frame.
        depth0 = self.outputs[-1]["depth0"]
        counts = np.bincount(np.floor(depth0[np.isfinite(depth0)] / band).astype(int))
        self.assertTrue(np.all(counts[:5] > 20), counts)
        image = imread(os.path.join(self.folder, "frames", "frame_%06d.png" % (len(self.outputs) - 1)))[..., :3]
        pixels = image.reshape(-1, 3)
        for colour in sections.PRO_COLOURS + sections.RETRO_COLOURS + (sections.MARKER_COLOUR,):
            rgb = np.array(sections.matplotlib.colors.to_rgb(colour))
            share = np.mean(np.all(np.abs(pixels - rgb) < 0.02, axis=1))
            self.assertGreater(share, 0.002, colour)

    def test_one_fault_scale_for_every_frame(self):
        top = self.summary["scales"]["faults_shear_strain_max"]
        self.assertGreater(top, 0)
        strains = sections.run_strains(self.outputs)
        self.assertEqual(top, sections.fixed_scale(strains[1:], sections.STRAIN_PERCENTILE))
        # The colour bar is the same picture in every frame: compare its column of pixels.
        from matplotlib.image import imread

        bars = []
        for k in range(1, len(self.outputs)):
            image = imread(os.path.join(self.folder, "frames_faults", "frame_%06d.png" % k))
            bars.append(image[:, -100:, :3])
        for bar in bars[1:]:
            np.testing.assert_array_equal(bar, bars[0])

    def test_the_same_run_draws_the_same_bytes(self):
        out = os.path.join(self.tmp, "again")
        shutil.copytree(self.folder, out, ignore=shutil.ignore_patterns("frames*", "sections", "animation*"))
        r = subprocess.run(module_command("orogen.charts.sections", out, "--kinds", "horizons", "--formats", "pdf,svg",
                                          "--no-animation", "--jobs", "1"), capture_output=True, text=True)
        self.assertEqual(r.returncode, 0, r.stderr)
        n = len(self.outputs)
        for name in ("frames/frame_%06d.png" % (n - 1), "sections/horizons_%06d.pdf" % (n - 1),
                     "sections/horizons_%06d.svg" % (n - 1)):
            with open(os.path.join(self.folder, name), "rb") as a, open(os.path.join(out, name), "rb") as b:
                self.assertEqual(a.read(), b.read(), name)

    def test_runs_drawn_together_share_one_view_and_scale(self):
        other = os.path.join(self.tmp, "seed2")
        r = subprocess.run([BINARY, "run", "--out", other, "--set", "wedge.s_end=1.2", "--set", "wedge.outputs=6",
                            "--set", "output.progress=never", "--set", "run.seed=2", "--threads", "1"],
                           capture_output=True, text=True)
        self.assertEqual(r.returncode, 0, r.stderr)
        mine = os.path.join(self.tmp, "seed1")
        shutil.copytree(self.folder, mine, ignore=shutil.ignore_patterns("frames*", "sections", "animation*"))
        r = subprocess.run(module_command("orogen.charts.sections", mine, other, "--no-animation", "--formats", "png"),
                           capture_output=True, text=True)
        self.assertEqual(r.returncode, 0, r.stderr)
        shared = []
        for run in (mine, other):
            with open(os.path.join(run, "sections", "sections.json")) as f:
                shared.append(json.load(f))
        for key in ("view_h0", "vertical_exaggeration", "scales", "runs_sharing_view_and_scales"):
            self.assertEqual(shared[0][key], shared[1][key], key)
        both = sections.read_outputs(mine) + sections.read_outputs(other)
        self.assertEqual(shared[0]["view_h0"], {k: v for k, v in sections.run_view(both).items() if k != "exaggeration"})
        # Frames of the same size, so that they line up on the atlas's compare page.
        from matplotlib.image import imread
        last = "frames_faults/frame_%06d.png" % (len(self.outputs) - 1)
        self.assertEqual(imread(os.path.join(mine, last)).shape, imread(os.path.join(other, last)).shape)

    def test_bad_input_is_named(self):
        import h5py

        packing = os.path.join(self.tmp, "packing")
        os.makedirs(packing)
        with h5py.File(os.path.join(packing, "snapshots.h5"), "w") as f:
            f.attrs["experiment"], f.attrs["h0"], f.attrs["n_outputs"] = "packing", 10.0, 0
        damaged = os.path.join(self.tmp, "damaged")
        os.makedirs(damaged)
        with open(os.path.join(self.folder, "snapshots.h5"), "rb") as f, \
                open(os.path.join(damaged, "snapshots.h5"), "wb") as g:
            g.write(f.read(3000))  # truncated
        cases = ((["packing_dir"], "a run of experiment 'packing'"),
                 ([damaged], "is not a readable orogen snapshot file"),
                 ([self.folder, "--kinds", "horizons,folds"], "--kinds 'horizons,folds'"),
                 ([self.folder, "--exaggeration", "0.5"], "--exaggeration '0.5'"),
                 ([self.folder, "--width", "100"], "--width 100"),
                 ([os.path.join(self.tmp, "nothing")], "no such folder"))
        for args, text in cases:
            args = [packing if a == "packing_dir" else a for a in args]
            r = subprocess.run(module_command("orogen.charts.sections", *args), capture_output=True, text=True)
            self.assertEqual(r.returncode, 2, args)
            self.assertIn(text, r.stderr)


@unittest.skipUnless(BINARY and os.path.exists(BINARY), "OROGEN_BINARY not set")
class SinglyVergentSections(unittest.TestCase):
    """A singly-vergent wedge draws too: x from its far wall, no S-point, the shortening in the
    title; its faults are picked with the backstop as the core."""

    def test_a_singly_vergent_run_is_drawn(self):
        with tempfile.TemporaryDirectory() as tmp:
            run = os.path.join(tmp, "singly")
            r = subprocess.run([BINARY, "run", "--out", run, "--set", "run.experiment=singly_vergent",
                                "--set", "layer.length=40", "--set", "layer.thickness=6", "--set", "singly.shortening=0.5",
                                "--set", "singly.outputs=4", "--set", "output.progress=never", "--threads", "1"],
                               capture_output=True, text=True)
            self.assertEqual(r.returncode, 0, r.stderr)
            outputs = sections.read_outputs(run)
            self.assertTrue(all(o["singly"] for o in outputs))
            r = subprocess.run(module_command("orogen.charts.sections", run, "--formats", "png", "--no-animation"),
                               capture_output=True, text=True)
            self.assertEqual(r.returncode, 0, r.stderr)
            self.assertTrue(os.path.isfile(os.path.join(run, "sections", "horizons_000004.png")))


if __name__ == "__main__":
    unittest.main()
