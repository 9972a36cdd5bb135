"""Shared pieces of the pytest files of the Python package (test_py_*.py): a tiny wedge and its
CLI run. CTest runs each file with PYTHONPATH=python and OROGEN_BUILD=the build folder."""

import os
import subprocess
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parents[2]
BINARY = os.environ.get("OROGEN_BINARY", str(REPO / "build" / "release" / "orogen"))

# A wedge of a few hundred discs and a few hundred steps: seconds on one core.
TINY_WEDGE = {
    "run": {"experiment": "wedge", "threads": 1},
    "output": {"progress": "never"},
    "layer": {"thickness": 4.0},
    "wedge": {"tile_length": 4.0, "retro_length": 4.0, "initial_active": 4.0, "s_end": 0.1, "outputs": 4,
              "erosion_height": 0.9},
}


def cli_sets(settings, prefix=""):
    """--set arguments of a nested dict (as orogen.config.overrides does, for the CLI)."""
    import orogen.config
    return [a for o in orogen.config.overrides(settings) for a in ("--set", o)]


def run_cli(out, settings=TINY_WEDGE, extra=()):
    subprocess.run([BINARY, "run", "--out", str(out), "--threads", "1", *cli_sets(settings), *extra],
                   check=True, capture_output=True, text=True)
    return out


@pytest.fixture(scope="session")
def cli_wedge(tmp_path_factory):
    """The tiny wedge run by the CLI, once per test process."""
    return run_cli(tmp_path_factory.mktemp("cli") / "wedge")
