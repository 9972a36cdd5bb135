"""The results atlas (`orogen report`, docs/atlas.md) end to end: tiny real runs (an ensemble of
three seeds, rendered and charted, a sweep of two, and an eroding run with its exhumation
analysis), the site built and updated, then opened in headless Chromium by
tests/browser/atlas_browser.mjs (puppeteer-core, installed by scripts/install-deps.sh with `npm ci`).

The browser half is skipped, saying so, where chromium or node is missing. Screenshots and the browser's report
stay in $ATLAS_ARTEFACTS (CTest: build/<preset>/atlas_test/).

    OROGEN_BINARY=build/release/orogen /usr/bin/python3 -m unittest -v tests/python/test_atlas.py
"""

import json
import os
import shutil
import subprocess
import sys
import tempfile
import unittest

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
BINARY = os.environ.get("OROGEN_BINARY", os.path.join(ROOT, "build", "release", "orogen"))
BROWSER = os.path.join(ROOT, "tests", "browser")
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from source_tree import module_command  # noqa: E402
CHROMIUM = shutil.which("chromium") or "/usr/bin/chromium"
NODE = shutil.which("node") or "/usr/bin/node"
ARTEFACTS = os.environ.get("ATLAS_ARTEFACTS") or tempfile.mkdtemp(prefix="atlas_artefacts_")
SMALL = {"layer.thickness": 5, "wedge.tile_length": 4, "wedge.retro_length": 4, "wedge.initial_active": 4,
         "wedge.s_end": 0.6, "wedge.outputs": 12, "output.vtp": "false"}
ENSEMBLE = "[ensemble]\npreset = \"%s\"\ntitle = \"tiny\"\nseeds = [1, 2, 3]\n\n[ensemble.set]\n%s\n" \
           "[ensemble.stats]\ns_min = 0.1\n" % (os.path.join(ROOT, "examples", "wedge_main_modest.toml"),
                                                 "".join('"%s" = %s\n' % kv for kv in SMALL.items()))


def sh(*args):
    r = subprocess.run(list(args), capture_output=True, text=True)
    if r.returncode != 0:
        raise AssertionError("%s: exit %d\n%s%s" % (" ".join(args), r.returncode, r.stdout, r.stderr))
    return r


def draw_run(run):
    """What a finished run usually has: frames and animations of horizons and faults, the charts."""
    sh(BINARY, "render", run, "--width", "480", "--fps", "6")
    sh(BINARY, "render", run, "--width", "480", "--fps", "6", "--color", "field:max_rel_disp",
       "--frames-dir", "frames_faults")
    sh(*module_command("orogen.charts.wedge", run, "--out", os.path.join(run, "charts")))


TMP = RUNS = SITE = FIRST = None


def setUpModule():
    """The runs and the site, once for both classes (about 20 s)."""
    global TMP, RUNS, SITE, FIRST
    TMP = tempfile.mkdtemp(prefix="orogen_atlas_")
    RUNS = os.path.join(TMP, "runs")
    os.makedirs(RUNS)
    plan = os.path.join(TMP, "tiny.toml")
    with open(plan, "w") as f:
        f.write(ENSEMBLE)
    sh(BINARY, "ensemble", plan, "--out", os.path.join(RUNS, "tiny_ensemble"), "--jobs", "2", "--threads", "1")
    sh(*module_command("orogen.charts.ensemble", os.path.join(RUNS, "tiny_ensemble")))
    for seed in ("seed1", "seed2", "seed3"):
        draw_run(os.path.join(RUNS, "tiny_ensemble", "members", seed))
    sweep = os.path.join(TMP, "tiny_sweep.toml")
    with open(sweep, "w") as f:
        f.write('[sweep]\nbase = "%s"\n\n[set]\n%s\n[matrix]\n"contact.mu" = [0.2, 0.4]\n'
                % (os.path.join(ROOT, "examples", "wedge_main_modest.toml"),
                   "".join('"%s" = %s\n' % kv for kv in SMALL.items())))
    sh(BINARY, "sweep", sweep, "--out", os.path.join(RUNS, "tiny_sweep"), "--jobs", "2")
    eroding = os.path.join(RUNS, "eroding")
    sets = [a for k, v in SMALL.items() for a in ("--set", "%s=%s" % (k, v))]
    sh(BINARY, "run", "--out", eroding, "--threads", "1", "--set", "wedge.erosion_height=0.9",
       "--set", "output.progress=never", *sets)
    sh(BINARY, "analyze", eroding)
    sh(*module_command("orogen.charts.exhumation", eroding))
    sh(*module_command("orogen.charts.exhumation_frames", eroding, "--width", "480", "--fps", "6"))
    draw_run(eroding)
    SITE = os.path.join(TMP, "site")
    FIRST = sh(BINARY, "report", RUNS, "--out", SITE)


def tearDownModule():
    if TMP:
        shutil.rmtree(TMP, ignore_errors=True)


class AtlasSite(unittest.TestCase):
    """The site's files, updates and errors: no browser needed."""

    def test_1_site_has_every_run_and_group(self):
        self.assertIn("6 runs (6 pages rebuilt), 2 sweeps/ensembles", FIRST.stdout)
        for f in ("index.html", "compare.html", "data/catalog.js", "assets/uPlot.iife.min.js", "assets/uPlot.LICENSE",
                  "groups/tiny_ensemble.html", "runs/eroding.html", "runs/eroding/charts/exhumation/flux.png",
                  "runs/eroding/frames_max_depth/frame_000012.png", "runs/eroding/animation_frames_age.gif"):
            self.assertTrue(os.path.isfile(os.path.join(SITE, f)), f)
        with open(os.path.join(SITE, "groups", "tiny_ensemble.html")) as f:
            group = f.read()
        self.assertIn("Table 5.1", group)
        self.assertIn("fig5_16_mean_fronts.png", group)
        with open(os.path.join(SITE, "groups", "tiny_sweep.html")) as f:
            sweep = f.read()
        self.assertEqual(sweep.count('href="../runs/tiny_sweep--runs--'), 2, sweep)

    def test_2_update_rebuilds_only_what_changed(self):
        self.assertIn("(0 pages rebuilt)", sh(BINARY, "report", RUNS, "--out", SITE).stdout)
        os.utime(os.path.join(RUNS, "eroding", "series.csv"))
        self.assertIn("(1 pages rebuilt)", sh(BINARY, "report", RUNS, "--out", SITE).stdout)

    def test_2b_a_run_just_started_is_listed_as_incomplete(self):
        more = os.path.join(TMP, "more")
        os.makedirs(os.path.join(more, "starting"))
        shutil.copy(os.path.join(RUNS, "eroding", "config.toml"), os.path.join(more, "starting"))
        open(os.path.join(more, "starting", "series.csv"), "w").close()  # no rows yet
        os.makedirs(os.path.join(more, "broken"))
        with open(os.path.join(more, "broken", "config.toml"), "w") as f:
            f.write("this is = not [toml\n")
        with open(os.path.join(more, "broken", "series.csv"), "w") as f:
            f.write("step,time\n0,0\n")
        out = sh(BINARY, "report", more, "--out", os.path.join(TMP, "more_site")).stdout
        self.assertIn("2 runs (2 pages rebuilt)", out)
        with open(os.path.join(TMP, "more_site", "index.html")) as f:
            index = f.read()
        self.assertIn('status incomplete">incomplete', index)

    def test_3_bad_input_is_named(self):
        for args, words in ((["report", os.path.join(TMP, "missing")], "no such folder"),
                            (["report", RUNS, "--out", os.path.join(TMP, "tiny.toml")], "a file is there"),
                            (["report", RUNS, "--out", RUNS], "holds no atlas")):
            r = subprocess.run([BINARY, *args], capture_output=True, text=True)
            self.assertEqual(r.returncode, 2, r.stderr)
            self.assertIn(words, r.stderr)



@unittest.skipUnless(os.path.exists(CHROMIUM) and os.path.exists(NODE), "chromium or node not found")
class AtlasInChromium(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        if not os.path.isdir(os.path.join(BROWSER, "node_modules", "puppeteer-core")):
            raise AssertionError("tests/browser/node_modules is missing: run scripts/install-deps.sh "
                                 "(npm ci in tests/browser)")

    def test_4_vendored_plot_library_is_the_npm_package(self):
        for name in ("uPlot.iife.min.js", "uPlot.min.css"):
            with open(os.path.join(ROOT, "python", "orogen", "atlas", "vendor", name), "rb") as a, \
                 open(os.path.join(BROWSER, "node_modules", "uplot", "dist", name), "rb") as b:
                self.assertEqual(a.read(), b.read(), name)

    def test_5_in_chromium(self):
        shots = os.path.join(ARTEFACTS, "screenshots")
        r = subprocess.run([NODE, os.path.join(BROWSER, "atlas_browser.mjs"), SITE, shots, CHROMIUM],
                           capture_output=True, text=True, timeout=240)
        sys.stdout.write(r.stdout[-4000:] + r.stderr[-2000:])
        self.assertEqual(r.returncode, 0, r.stdout[-3000:] + r.stderr[-2000:])
        with open(os.path.join(shots, "report.json")) as f:
            report = json.load(f)
        self.assertEqual(report["failures"], [])
        for name in ("index.png", "run.png", "compare.png", "index_dark.png", "phone_index.png"):
            self.assertTrue(os.path.isfile(os.path.join(shots, name)), name)


if __name__ == "__main__":
    unittest.main()
