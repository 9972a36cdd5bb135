"""The package installs as a package (python/pyproject.toml): every module and the atlas's
assets end up in the installed copy, which runs from any folder without the source tree; and
the commands that run it say how to install it where it is missing."""

import os
import shutil
import subprocess
import sys
from pathlib import Path

from conftest import BINARY, REPO

MODULES = ["orogen.tables", "orogen.results", "orogen.folders", "orogen.atomic", "orogen.stats",
           "orogen.charts.wedge", "orogen.charts.granular", "orogen.charts.ensemble", "orogen.charts.exhumation",
           "orogen.charts.exhumation_frames", "orogen.analysis.surface", "orogen.analysis.exhumation_summary",
           "orogen.analysis.traction", "orogen.analysis.stress", "orogen.atlas.build"]


def test_pip_installs_every_module_and_the_atlas_assets(tmp_path):
    # From a copy, as scripts/install-python.sh does: setuptools builds inside the project folder.
    project = tmp_path / "project"
    shutil.copytree(REPO / "python" / "orogen", project / "orogen", ignore=shutil.ignore_patterns("__pycache__"))
    shutil.copy(REPO / "python" / "pyproject.toml", project)
    target = tmp_path / "site"
    pip = subprocess.run(["/usr/bin/python3", "-m", "pip", "install", "--quiet", "--no-deps", "--no-build-isolation",
                          "--no-index", "--target", str(target), str(project)],
                         capture_output=True, text=True, cwd=tmp_path)
    assert pip.returncode == 0, pip.stderr
    env = {**os.environ, "PYTHONPATH": str(target)}
    code = "import importlib, orogen; [importlib.import_module(m) for m in %r]; print(orogen.__file__)" % MODULES
    found = subprocess.run(["/usr/bin/python3", "-c", code], capture_output=True, text=True, cwd=tmp_path, env=env)
    assert found.returncode == 0, found.stderr
    assert Path(found.stdout.strip()).is_relative_to(target)  # the installed copy, not the source tree
    source = REPO / "python" / "orogen" / "atlas"
    for folder in ("assets", "vendor"):
        for f in (source / folder).iterdir():
            assert (target / "orogen" / "atlas" / folder / f.name).read_bytes() == f.read_bytes(), f.name
    help_text = subprocess.run(["/usr/bin/python3", "-m", "orogen.charts.wedge", "--help"], capture_output=True,
                               text=True, cwd=tmp_path, env=env)
    assert help_text.returncode == 0 and "--out" in help_text.stdout


def test_a_command_without_the_package_says_how_to_install_it(tmp_path):
    """`orogen charts` where the interpreter finds a package orogen without the charts (an old
    or foreign one): exit 1, naming the module and the script that installs the package."""
    fake = tmp_path / "fake" / "orogen"
    fake.mkdir(parents=True)
    (fake / "__init__.py").write_text("")
    env = {**os.environ, "PYTHONPATH": str(tmp_path / "fake")}
    r = subprocess.run([BINARY, "charts", str(tmp_path)], capture_output=True, text=True, env=env)
    assert r.returncode == 1, r.stderr
    assert "orogen.charts" in r.stderr and "scripts/install-python.sh" in r.stderr


def test_charts_of_a_folder_are_picked_by_what_it_holds(tmp_path):
    """`python3 -m orogen.charts DIR` (what `orogen charts` runs): an ensemble gets the ensemble
    charts, a biaxial run the granular ones; a folder of neither is refused with exit 2."""
    sys.path.insert(0, str(REPO / "tests" / "python"))
    import ensemble_fixture
    import test_granular_charts as granular_fixtures

    ensemble = tmp_path / "ensemble"
    ensemble_fixture.make_ensemble(str(ensemble))
    stats = subprocess.run(["/usr/bin/python3", "-m", "orogen.stats", str(ensemble)], capture_output=True, text=True)
    assert stats.returncode == 0, stats.stderr
    charts = subprocess.run(["/usr/bin/python3", "-m", "orogen.charts", str(ensemble)], capture_output=True, text=True)
    assert charts.returncode == 0, charts.stderr
    assert (ensemble / "aggregate" / "charts" / "fig5_16_mean_fronts.png").is_file()

    biaxial = tmp_path / "biaxial"
    granular_fixtures.make_biaxial_run(str(biaxial), "random_clusters", 0.3, 35.0, 25.0)
    charts = subprocess.run(["/usr/bin/python3", "-m", "orogen.charts", str(biaxial)], capture_output=True, text=True)
    assert charts.returncode == 0, charts.stderr
    assert (biaxial / "charts" / "biaxial_stress_strain.png").is_file()

    empty = tmp_path / "empty"
    empty.mkdir()
    refused = subprocess.run(["/usr/bin/python3", "-m", "orogen.charts", str(empty)], capture_output=True, text=True)
    assert refused.returncode == 2 and "holds no wedge" in refused.stderr
