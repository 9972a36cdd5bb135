"""`orogen run CONFIG --from RUN[:OUTPUT] --out DIR` (docs/output-files.md, "Branches"): a
branch starts from exactly the stored state, an unchanged branch continues its source bit for
bit, a changed one runs on, a branch resumes bit for bit, and a bad --from is refused with
exit code 2 naming it.

The binary is $OROGEN_BINARY (CTest sets it), else build/release/orogen."""

import filecmp
import os
import shutil
import subprocess
import tempfile
import unittest

import h5py
import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
BINARY = os.environ.get("OROGEN_BINARY", os.path.join(ROOT, "build", "release", "orogen"))
PRESET = os.path.join(ROOT, "examples", "wedge_main_modest.toml")
TINY = ["layer.thickness=5", "wedge.tile_length=4", "wedge.retro_length=4", "wedge.initial_active=4",
        "wedge.s_end=0.3", "wedge.outputs=6", "output.vtp=false", "run.threads=1"]
STATE = ("x", "y", "theta", "vx", "vy", "omega", "radius", "id", "cluster_id", "depth0")


def orogen(*args):
    return subprocess.run([BINARY, *args], capture_output=True, text=True)


def run(out, *extra, sets=()):
    args = ["run", PRESET, "--out", out]
    for s in list(TINY) + list(sets):
        args += ["--set", s]
    return orogen(*args, *extra)


def output(folder, k):
    with h5py.File(os.path.join(folder, "snapshots.h5"), "r") as f:
        g = f["output_%06d" % k]
        arrays = {name: g[name][()] for name in g if name != "walls" and isinstance(g[name], h5py.Dataset)}
        return arrays | {"step": g.attrs["step"]}


def n_outputs(folder):
    with h5py.File(os.path.join(folder, "snapshots.h5"), "r") as f:
        return int(f.attrs["n_outputs"])


class BranchTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.mkdtemp()
        cls.source = os.path.join(cls.tmp, "source")
        r = run(cls.source)
        assert r.returncode == 0, r.stderr

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.tmp)

    def path(self, name):
        return os.path.join(self.tmp, name)

    def assert_same_state(self, a, b):
        for name in STATE:
            self.assertTrue(np.array_equal(a[name], b[name]), name)
        self.assertEqual(a["step"], b["step"])

    def test_branch_starts_from_the_stored_state_and_continues_its_source(self):
        out = self.path("b2")
        r = run(out, "--from", self.source + ":2")
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assert_same_state(output(out, 0), output(self.source, 2))
        # Unchanged, it is the source's run from there on, bit for bit (contact histories included).
        count = n_outputs(self.source)
        self.assertEqual(n_outputs(out), count - 2)
        for k in range(1, count - 2):
            a, b = output(out, k), output(self.source, k + 2)
            self.assert_same_state(a, b)
            self.assertTrue(np.array_equal(a["max_rel_disp"], b["max_rel_disp"], equal_nan=True))
        # Where it came from: config.toml, run.log, the snapshots' metadata.
        with open(os.path.join(out, "config.toml")) as f:
            self.assertEqual(f.readline().strip(), "# branch of %s:2 (orogen run --from)" % self.source)
        with open(os.path.join(out, "run.log")) as f:
            self.assertIn("branch of %s at output 2" % self.source, f.read())
        with h5py.File(os.path.join(out, "snapshots.h5"), "r") as f:
            self.assertEqual(f.attrs["branch_from"], "%s:2" % self.source)

    def test_default_is_the_last_output_and_a_changed_branch_runs_on(self):
        out = self.path("changed")
        r = run(out, "--from", self.source,
                sets=["contact.mu=0.6", "wedge.erosion_height=1.2", "wedge.s_end=0.4", "wedge.outputs=8"])
        self.assertEqual(r.returncode, 0, r.stderr)
        last = n_outputs(self.source) - 1
        self.assert_same_state(output(out, 0), output(self.source, last))
        self.assertEqual(n_outputs(out), 3)  # outputs at S = 0.35 and 0.4
        end = output(out, 2)
        self.assertGreater(end["step"], output(out, 0)["step"])
        self.assertTrue(np.all(np.isfinite(end["x"])))

    def test_basal_friction_changes_in_a_branch(self):
        same, rougher = self.path("mu_same"), self.path("mu_rougher")
        self.assertEqual(run(same, "--from", self.source + ":1").returncode, 0)
        r = run(rougher, "--from", self.source + ":1", sets=["wedge.mu_bp=0.6", "wedge.mu_br=0.9"])
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assert_same_state(output(rougher, 0), output(same, 0))
        last = n_outputs(same) - 1
        self.assertEqual(n_outputs(rougher), n_outputs(same))
        # The walls carry the branch's friction from its first step on, so the runs part.
        self.assertFalse(np.array_equal(output(rougher, last)["x"], output(same, last)["x"]))
        with open(os.path.join(rougher, "config.toml")) as f:
            self.assertIn("mu_bp = 0.6", f.read())

    def test_a_branch_resumes_bit_for_bit(self):
        whole, killed = self.path("whole"), self.path("killed")
        self.assertEqual(run(whole, "--from", self.source + ":1").returncode, 0)
        r = run(killed, "--from", self.source + ":1", "--abort-after-outputs", "3")
        self.assertEqual(r.returncode, 137, r.stderr)
        r = orogen("run", "--resume", killed)
        self.assertEqual(r.returncode, 0, r.stderr)
        for f in ("series.csv", "checkpoint.bin"):
            self.assertTrue(filecmp.cmp(os.path.join(whole, f), os.path.join(killed, f), shallow=False), f)
        # Extended, it still names its source.
        r = orogen("run", "--resume", killed, "--set", "wedge.s_end=0.35", "--set", "wedge.outputs=7")
        self.assertEqual(r.returncode, 0, r.stderr)
        with open(os.path.join(killed, "config.toml")) as f:
            self.assertTrue(f.readline().startswith("# branch of %s:1" % self.source))

    def test_a_branch_without_a_configuration_takes_its_sources(self):
        # Issue 36: without CONFIG the branch is the one with the source's configuration (not the
        # built-in default's), the same files bit for bit.
        given, taken = self.path("given"), self.path("taken")
        self.assertEqual(run(given, "--from", self.source + ":2", sets=["wedge.mu_bp=0.3"]).returncode, 0)
        r = orogen("run", "--from", self.source + ":2", "--out", taken, "--set", "wedge.mu_bp=0.3")
        self.assertEqual(r.returncode, 0, r.stderr)
        for f in ("config.toml", "series.csv", "checkpoint.bin", "removals.csv"):
            self.assertTrue(filecmp.cmp(os.path.join(given, f), os.path.join(taken, f), shallow=False), f)
        self.assertEqual(n_outputs(taken), n_outputs(self.source) - 2)

    def test_bad_from_exit_2_naming_it(self):
        empty = self.path("empty")
        os.makedirs(empty, exist_ok=True)
        cases = [
            (["--from", self.path("missing")], [], "no such folder"),
            (["--from", self.source + ":99"], [], "output 99 is out of range"),
            (["--from", empty], [], "is not a run folder"),
            (["--from", self.source], ["run.experiment=repose"], "experiment 'wedge'"),
            (["--from", self.source], ["layer.thickness=6"], "layer.thickness"),
            (["--from", self.source], ["wedge.gamma_b=0.3"], "wedge.gamma_b"),
        ]
        for i, (extra, sets, named) in enumerate(cases):
            out = self.path("bad%d" % i)
            r = run(out, *extra, sets=sets)
            self.assertEqual(r.returncode, 2, (extra, sets, r.stderr))
            self.assertIn(named, r.stderr, (extra, sets))
            self.assertFalse(os.path.exists(os.path.join(out, "config.toml")), (extra, sets))
        r = orogen("run", "--resume", self.source, "--from", self.source)
        self.assertEqual(r.returncode, 2, r.stderr)
        self.assertIn("--from", r.stderr)


if __name__ == "__main__":
    unittest.main()
