"""docs/output-files.md matches the files (issue 18): a small wedge run and a small packing run,
then their HDF5 datasets (names, units, descriptions, types) and CSV columns (names, the
`# name: meaning [unit]` lines) are compared with the doc's tables, both ways; every dataset has
a non-empty `units` and `description`, every file the resolved configuration, and every file in
the run folders is named in the doc's run-folder table.

Run from the repository root, with OROGEN_BINARY naming the orogen program:
    OROGEN_BINARY=build/release/orogen /usr/bin/python3 -m unittest tests/python/test_output_docs.py
"""

import csv
import glob
import os
import re
import shutil
import subprocess
import tempfile
import unittest

import h5py
import numpy as np

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
DOC = os.path.join(REPO, "docs", "output-files.md")
BINARY = os.environ.get("OROGEN_BINARY", os.path.join(REPO, "build", "release", "orogen"))
COMMON = ["--set", "output.progress=never", "--threads", "1"]
RUNS = {
    "wedge": ["--set", "run.experiment=wedge", "--set", "layer.thickness=5", "--set", "wedge.tile_length=4",
              "--set", "wedge.retro_length=4", "--set", "wedge.initial_active=4", "--set", "wedge.s_end=0.2",
              "--set", "wedge.outputs=4", "--set", "wedge.erosion_height=0.9",
              "--set", "output.contacts=true", "--set", "output.stress=true", "--set", "output.stress_grid=2",
              "--set", "analysis.in_run=true"],
    # A wedge with surface laws, an outside supply and deposits (docs/surface.md): its series
    # gains the area ledger and the supply's books, its outputs the deposition time.
    "surface": ["--set", "run.experiment=wedge", "--set", "layer.thickness=5", "--set", "wedge.tile_length=4",
                "--set", "wedge.retro_length=4", "--set", "wedge.initial_active=4", "--set", "wedge.s_end=0.2",
                "--set", "wedge.outputs=4", "--set", "surface.every=100", "--set", "surface.diffusivity=0.5",
                "--set", "surface.deposition=true", "--set", "surface.sediment_supply=0.1"],
    # A singly-vergent wedge with surface laws, a supply and deposits: the same ledger and field.
    "singly_surface": ["--set", "run.experiment=singly_vergent", "--set", "particles.packing=random_discs",
                       "--set", "layer.length=40", "--set", "layer.thickness=5", "--set", "contact.kn=2000",
                       "--set", "singly.speed=0.05", "--set", "singly.shortening=0.5", "--set", "singly.outputs=3",
                       "--set", "surface.every=100", "--set", "surface.diffusivity=0.3",
                       "--set", "surface.deposition=true", "--set", "surface.sediment_supply=0.1"],
    # A wedge on a deflecting base (docs/isostasy.md): its series gains the base's columns.
    "isostasy": ["--set", "run.experiment=wedge", "--set", "layer.thickness=5", "--set", "wedge.tile_length=4",
                 "--set", "wedge.retro_length=4", "--set", "wedge.initial_active=4", "--set", "wedge.s_end=0.2",
                 "--set", "wedge.outputs=4", "--set", "isostasy.model=airy", "--set", "isostasy.every=100"],
    "packing": ["--set", "run.experiment=packing", "--set", "particles.packing=random_discs",
                "--set", "layer.length=10", "--set", "layer.thickness=3", "--set", "contact.kn=1000",
                "--set", "settle.relax_time=1", "--set", "settle.ke_threshold=1e-3", "--set", "output.interval=2"],
}


def read_text(path):
    with open(path, encoding="utf-8") as f:
        return f.read()


def cells(line):
    return [c.strip() for c in line.strip().strip("|").split("|")]


def unquote(cell):
    return cell.strip().strip("`")


def doc_tables():
    """[(heading, header cells, rows of cells)] of every Markdown table, with the heading above it."""
    tables, heading, rows, header = [], "", None, None
    for line in read_text(DOC).splitlines(keepends=True):
        if line.startswith("#"):
            heading = line.strip("# \n")
        if line.startswith("|"):
            if header is None:
                header, rows = cells(line), []
            elif not set(line.strip()) <= set("|-: "):
                rows.append(cells(line))
        elif header is not None:
            tables.append((heading, header, rows))
            header = None
    if header is not None:
        tables.append((heading, header, rows))
    return tables


# Runs named after what they add to an experiment: the experiment they are, and the tag of the
# doc's rows and tables only they write.
VARIANTS = {"surface": ("wedge", "with [surface]"), "singly_surface": ("singly_vergent", "with [surface]"),
            "isostasy": ("wedge", "wedge with [isostasy]")}


def documented_columns(csv_name, experiment):
    """{column: meaning} of the doc's table for `csv_name` of `experiment`, in order (a variant:
    its experiment's, then its own table's if it has one)."""
    if experiment in VARIANTS:
        base, tag = VARIANTS[experiment]
        out = documented_columns(csv_name, base)
        for heading, header, rows in doc_tables():
            if heading == "`%s` columns, %s" % (csv_name, tag) and header[:2] == ["column", "meaning"]:
                out = {**out, **{unquote(r[0]): r[1] for r in rows}}
        return out
    for heading, header, rows in doc_tables():
        m = re.match(r"`([a-z_]+\.csv)` columns, (\w+) experiment", heading)
        if m and header[:2] == ["column", "meaning"] and m.group(1) == csv_name and m.group(2) in (experiment, "every"):
            return {unquote(r[0]): r[1] for r in rows}
    return None


def documented_datasets(experiment):
    """{dataset: (type, units, description)} the doc says `experiment` (or a variant) writes."""
    writers = {"every experiment"}
    writers.update(VARIANTS.get(experiment, (experiment,)))
    for heading, header, rows in doc_tables():
        if header == ["dataset", "type", "units", "written by", "description"]:
            return {unquote(r[0]): (r[1], r[2], r[4]) for r in rows
                    if writers & {w.strip() for w in r[3].split(",")} or r[3] in writers}
    raise AssertionError("docs/output-files.md has no table of datasets")


GROUPS_HEADING = "Contacts, stress and cluster poses"


def documented_groups():
    """{group: {dataset names}} of the optional output groups (`contacts/`, `stress/`, ...): the
    backquoted names in each group's paragraph (and table) of the doc's section on them."""
    text = read_text(DOC)
    section = text[text.index("### " + GROUPS_HEADING):]
    section = section[:section.index("\n#", 1)]
    groups, current = {}, None
    for line in section.splitlines():
        m = re.match(r"`([a-z_]+)/`", line)
        if m:
            current = groups.setdefault(m.group(1), set())
        if current is not None:
            current.update(re.findall(r"`([a-z_]+)`", line))
    return groups


def documented_group_table():
    """{dataset: (type with its dimension letters, units)} of the contacts table."""
    for heading, header, rows in doc_tables():
        if heading.startswith(GROUPS_HEADING) and header == ["dataset", "type", "units", "meaning"]:
            return {name: (r[1], r[2]) for r in rows for name in re.findall(r"`([a-z_]+)`", r[0])}
    raise AssertionError("docs/output-files.md has no table of contact datasets")


def documented_run_files():
    """Regular expressions of the file names in the doc's run-folder table."""
    for heading, header, rows in doc_tables():
        if heading == "The run folder":
            names = [n for r in rows for n in re.findall(r"`([^`]+)`", r[0])]
            return [re.compile(re.escape(n).replace("NNNNNN", r"\d{6}").replace(r"\*", r"[^/]*") + "$") for n in names]
    raise AssertionError("docs/output-files.md has no run-folder table")


def csv_columns(path):
    """(header names, {name: meaning} of the `# name: meaning` lines) of an Orogen CSV file."""
    comments, header = [], None
    with open(path, encoding="utf-8") as f:
        for line in f:
            if line.startswith("#"):
                comments.append(line[2:].rstrip("\n"))
            else:
                header = next(csv.reader([line]))
                break
    meanings = {}
    for c in comments:
        name, sep, meaning = c.partition(": ")
        if sep and name in header:
            meanings[name] = meaning
    return header, meanings


def h5_type(ds):
    dims = "[n]" if ds.ndim == 1 else ("[n, 2]" if ds.shape[1] == 2 else "[n_walls, 4]") if ds.ndim == 2 else "?"
    return "%s %s" % (ds.dtype.name, dims)


class OutputFilesMatchTheirDoc(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.mkdtemp(prefix="orogen_output_docs_")
        cls.dirs = {}
        for name, args in RUNS.items():
            out = os.path.join(cls.tmp, name)
            subprocess.run([BINARY, "run", "--out", out] + args + COMMON, check=True, capture_output=True)
            cls.dirs[name] = out

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.tmp, ignore_errors=True)

    def check_group(self, group, experiment, where):
        documented = documented_datasets(experiment)
        written = {k: group[k] for k in group.keys() if isinstance(group[k], h5py.Dataset)}
        self.assertEqual(sorted(written), sorted(documented), "%s: written vs documented" % where)
        for name in group.keys():
            if isinstance(group[name], h5py.Group):
                self.check_subgroup(group[name], name, "%s/%s" % (where, name))
        for name, ds in written.items():
            units, description = ds.attrs.get("units"), ds.attrs.get("description")
            self.assertTrue(units and description, "%s/%s has no units or description" % (where, name))
            if name in documented:
                self.assertEqual((h5_type(ds), units, description), documented[name], "%s/%s" % (where, name))

    def check_subgroup(self, group, name, where):
        groups = documented_groups()
        self.assertIn(name, groups, where + " is not a documented group")
        self.assertTrue(group.attrs.get("description"), where + " has no description")
        table = documented_group_table() if name == "contacts" else {}
        for key in group.keys():
            ds = group[key]
            self.assertIn(key, groups[name], "%s/%s is not in the doc" % (where, key))
            self.assertTrue(ds.attrs.get("units") and ds.attrs.get("description"),
                            "%s/%s has no units or description" % (where, key))
            if key in table:
                self.assertEqual((ds.dtype.name, ds.attrs["units"]), (table[key][0].split()[0], table[key][1]),
                                 "%s/%s" % (where, key))
        if table:
            self.assertEqual(sorted(group.keys()), sorted(table), where + ": written vs documented")

    def test_snapshot_datasets_match_the_doc(self):
        seen_groups = set()
        for experiment, run in self.dirs.items():
            files = sorted(glob.glob(os.path.join(run, "snapshots", "output_*.h5")))
            self.assertGreaterEqual(len(files), 2)
            config = read_text(os.path.join(run, "config.toml"))
            for path in files:
                with h5py.File(path, "r") as f:
                    self.check_group(f, experiment, path)
                    seen_groups.update(k for k in f.keys() if isinstance(f[k], h5py.Group))
                    self.assertEqual(f.attrs["config_toml"], config, path)
            with h5py.File(os.path.join(run, "snapshots.h5"), "r") as index:
                self.assertEqual(index.attrs["config_toml"], config)
                # The links, and the sidecar's vertex cells (as many as the largest output's discs).
                self.assertEqual(len(index.keys()), int(index.attrs["n_outputs"]) + 1)
                self.check_disc_index(index, max(index[k]["x"].shape[0] for k in index if k.startswith("output_")))
                self.check_group(index["output_000000"], experiment, "snapshots.h5/output_000000")
        self.assertEqual(seen_groups, set(documented_groups()), "groups written vs documented")

    def check_disc_index(self, f, n):
        ds = f["disc_index"]
        np.testing.assert_array_equal(ds[()], np.arange(n, dtype=np.int32))
        self.assertEqual((ds.attrs.get("units"), ds.dtype.name), ("-", "int32"))
        self.assertIn("snapshots.xmf", ds.attrs.get("description"))

    def test_packing_file_matches_the_doc(self):
        run = self.dirs["packing"]
        with h5py.File(os.path.join(run, "packing.h5"), "r") as f:
            self.assertEqual(list(f.keys()), ["disc_index", "output_000000"])
            self.check_disc_index(f, f["output_000000"]["x"].shape[0])
            self.check_group(f["output_000000"], "packing", "packing.h5")
            self.assertEqual(f.attrs["config_toml"], read_text(os.path.join(run, "config.toml")))

    def test_csv_columns_match_the_doc(self):
        for experiment, run in self.dirs.items():
            for name in ("series.csv", "summary.csv", "removals.csv"):
                with self.subTest(experiment=experiment, file=name):
                    documented = documented_columns(name, experiment)
                    self.assertIsNotNone(documented, "no table of %s for %s" % (name, experiment))
                    header, meanings = csv_columns(os.path.join(run, name))
                    self.assertEqual(header, list(documented))
                    self.assertEqual(meanings, documented)
                    for column, meaning in meanings.items():
                        self.assertRegex(meaning, r" \[[^\]]+\]$", "%s: %s states no unit" % (name, column))

    def test_every_file_of_a_run_is_documented(self):
        patterns = documented_run_files()
        for run in self.dirs.values():
            for root, _, files in os.walk(run):
                for f in files:
                    rel = os.path.relpath(os.path.join(root, f), run)
                    self.assertTrue(any(p.match(rel) for p in patterns), rel + " is not in the run-folder table")


if __name__ == "__main__":
    unittest.main()
