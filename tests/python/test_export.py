"""`orogen export` (docs/output-files.md, "Exports"): every format reads back to the snapshot's
values bit for bit, Debian's LAMMPS (`lmp`) reads the data file, and bad input is refused
with exit code 2 naming it.

The binary is $OROGEN_BINARY (CTest sets it), else build/release/orogen."""

import csv
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
        "wedge.s_end=0.1", "wedge.outputs=2", "output.vtp=false", "run.threads=1"]


def as_written(v):
    """A bound as the file writes it (17 significant digits), compared exactly after the round trip."""
    return float("%.17g" % v)


def orogen(*args):
    return subprocess.run([BINARY, *args], capture_output=True, text=True)


class ExportTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.mkdtemp()
        cls.run_dir = os.path.join(cls.tmp, "run")
        args = ["run", PRESET, "--out", cls.run_dir]
        for s in TINY:
            args += ["--set", s]
        r = orogen(*args)
        assert r.returncode == 0, r.stderr
        with h5py.File(os.path.join(cls.run_dir, "snapshots.h5"), "r") as f:
            cls.n_outputs = int(f.attrs["n_outputs"])
            g = f["output_000001"]
            cls.snap = {name: g[name][()] for name in g  # xy: a view of x and y for the sidecar
                        if name not in ("walls", "xy") and isinstance(g[name], h5py.Dataset)}
            cls.step = int(g.attrs["step"])

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.tmp)

    def export(self, fmt, *extra):
        path = os.path.join(self.tmp, "export." + fmt)
        r = orogen("export", self.run_dir, "--output", "1", "--format", fmt, "--to", path, *extra)
        self.assertEqual(r.returncode, 0, r.stderr)
        with open(path) as f:
            return f.read()

    def assert_equal(self, got, name):
        self.assertTrue(np.array_equal(np.asarray(got), self.snap[name]), name)

    def test_lammps_data_reads_back(self):
        lines = self.export("lammps-data").splitlines()
        n = int(lines[2].split()[0])
        self.assertEqual(n, len(self.snap["id"]))
        atoms = lines.index("Atoms # sphere") + 2
        rows = [l.split() for l in lines[atoms:atoms + n]]
        self.assert_equal([int(r[0]) - 1 for r in rows], "id")
        self.assert_equal([float(r[2]) / 2 for r in rows], "radius")
        self.assert_equal([float(r[4]) for r in rows], "x")
        self.assert_equal([float(r[5]) for r in rows], "y")
        vel = lines.index("Velocities") + 2
        rows = [l.split() for l in lines[vel:vel + n]]
        self.assert_equal([float(r[1]) for r in rows], "vx")
        self.assert_equal([float(r[2]) for r in rows], "vy")
        self.assert_equal([float(r[6]) for r in rows], "omega")

    def test_lammps_dump_reads_back(self):
        lines = self.export("lammps-dump").splitlines()
        self.assertEqual(int(lines[1]), self.step)
        n = int(lines[3])
        self.assertEqual(lines[8].split()[2:], ["id", "type", "x", "y", "z", "radius", "vx", "vy", "vz", "omegaz"])
        rows = [l.split() for l in lines[9:9 + n]]
        self.assertEqual(len(rows), len(self.snap["id"]))
        for col, name in ((2, "x"), (3, "y"), (5, "radius"), (6, "vx"), (7, "vy"), (9, "omega")):
            self.assert_equal([float(r[col]) for r in rows], name)

    def test_xyz_reads_back(self):
        lines = self.export("xyz").splitlines()
        n = int(lines[0])
        self.assertIn("Properties=species:S:1:pos:R:3:velo:R:3:radius:R:1:id:I:1:cluster_id:I:1", lines[1])
        rows = [l.split() for l in lines[2:2 + n]]
        for col, name in ((1, "x"), (2, "y"), (4, "vx"), (5, "vy"), (7, "radius")):
            self.assert_equal([float(r[col]) for r in rows], name)
        self.assert_equal([int(r[8]) for r in rows], "id")
        self.assert_equal([int(r[9]) for r in rows], "cluster_id")

    def test_csv_reads_back_every_field_with_units(self):
        text = self.export("csv")
        rows = list(csv.reader(l for l in text.splitlines() if not l.startswith("#")))
        header = [h.split(" [")[0] for h in rows[0]]
        self.assertIn("x [d]", rows[0])
        self.assertEqual(sorted(header), sorted(self.snap.keys()))
        for j, name in enumerate(header):
            values = [float(r[j]) for r in rows[1:]]
            self.assertTrue(np.array_equal(np.asarray(values, dtype=self.snap[name].dtype), self.snap[name],
                                           equal_nan=True), name)

    def test_default_is_the_last_output(self):
        path = os.path.join(self.tmp, "last.dump")
        r = orogen("export", self.run_dir, "--format", "lammps-dump", "--to", path)
        self.assertEqual(r.returncode, 0, r.stderr)
        with h5py.File(os.path.join(self.run_dir, "snapshots.h5"), "r") as f:
            last = int(f["output_%06d" % (self.n_outputs - 1)].attrs["step"])
        with open(path) as f:
            self.assertEqual(int(f.read().splitlines()[1]), last)

    def test_lammps_reads_the_data_file(self):
        lmp = shutil.which("lmp")
        if lmp is None:
            self.skipTest("lmp (Debian package lammps) is not installed: the LAMMPS read is not checked")
        data = os.path.join(self.tmp, "lmp.data")
        with open(data, "w") as f:
            f.write(self.export("lammps-data"))
        script = os.path.join(self.tmp, "in.read")
        with open(script, "w") as f:
            f.write("dimension 2\nboundary f f p\natom_style sphere\nread_data lmp.data\nrun 0\n")
        r = subprocess.run([lmp, "-in", script, "-log", "none"],
                           capture_output=True, text=True, cwd=self.tmp, timeout=120)
        self.assertEqual(r.returncode, 0, r.stdout + r.stderr)
        self.assertIn("%d atoms" % len(self.snap["id"]), r.stdout)
        self.assertIn("reading velocities", r.stdout)

    def test_lammps_runs_an_export_of_the_main_job_with_its_walls(self):
        # Issue 36: the box reached x = -10,000,001 (the pro base), so LAMMPS stopped ("Too many
        # atom sorting bins"), and the walls were not exported, so the discs had no floor.
        lmp = shutil.which("lmp")
        if lmp is None:
            self.skipTest("lmp (Debian package lammps) is not installed: the LAMMPS run is not checked")
        main = os.path.join(self.tmp, "main")
        r = orogen("run", "--out", main, "--set", "wedge.s_end=0.05", "--set", "wedge.outputs=1",
                   "--set", "output.progress=never", "--threads", "1")
        self.assertEqual(r.returncode, 0, r.stderr)
        data = os.path.join(self.tmp, "main.data")
        r = orogen("export", main, "--format", "lammps-data", "--to", data)
        self.assertEqual(r.returncode, 0, r.stderr)
        with h5py.File(os.path.join(main, "snapshots.h5"), "r") as f:
            g = f["output_000001"]
            x, y, radius = g["x"][()], g["y"][()], g["radius"][()]
        with open(data) as f:
            bounds = {line.split()[-1]: [float(v) for v in line.split()[:2]] for line in f if line.rstrip().endswith("hi")}
        self.assertEqual(bounds["xhi"], [as_written(np.min(x - radius) - 1), as_written(np.max(x + radius) + 1)])
        self.assertEqual(bounds["yhi"], [as_written(np.min(y - radius) - 1), as_written(np.max(y + radius) + 1)])
        with open(data + ".in") as f:
            script = f.read()
        self.assertIn("yplane 0 NULL", script)  # the bases: a floor under the discs
        r = subprocess.run([lmp, "-in", "main.data.in", "-var", "steps", "100", "-log", "none"],
                           capture_output=True, text=True, cwd=self.tmp, timeout=120)
        self.assertEqual(r.returncode, 0, r.stdout + r.stderr)
        self.assertNotIn("Lost atoms", r.stdout + r.stderr)
        self.assertIn("100 steps with %d atoms" % len(x), r.stdout)

    def test_bad_input_exit_2_naming_it(self):
        out = os.path.join(self.tmp, "x.csv")
        cases = [
            (["export", os.path.join(self.tmp, "nothing"), "--format", "csv", "--to", out], "nothing"),
            (["export", self.run_dir, "--output", "99", "--format", "csv", "--to", out], "--output 99"),
            (["export", self.run_dir, "--format", "pdb", "--to", out], "--format pdb"),
            (["export", self.run_dir, "--format", "csv"], "--to"),
        ]
        for args, named in cases:
            r = orogen(*args)
            self.assertEqual(r.returncode, 2, (args, r.stderr))
            self.assertIn(named, r.stderr, args)
            self.assertFalse(os.path.exists(out), args)


if __name__ == "__main__":
    unittest.main()
