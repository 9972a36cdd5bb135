"""The package installs as a package (python/pyproject.toml): every module and the atlas's
assets end up in the installed copy, which runs from any folder without the source tree; and
the commands that run it say how to install it where it is missing."""

import os
import shutil
import subprocess
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
