"""Makes the tests use the package of this source tree (python/orogen), not an installed one:
python/ goes first on this interpreter's path and on the PYTHONPATH of every program a test
starts (`python3 -m orogen.charts.wedge`, `orogen ensemble` running `python3 -m orogen.stats`).

    sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
    from source_tree import REPO, module_command
"""

import os
import sys

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
PYTHON_DIR = os.path.join(REPO, "python")

sys.path.insert(0, PYTHON_DIR)
os.environ["PYTHONPATH"] = os.pathsep.join(p for p in (PYTHON_DIR, os.environ.get("PYTHONPATH", "")) if p)


def module_command(module, *args):
    """The command line that runs a module of the package, as `orogen charts` runs it."""
    return ["/usr/bin/python3", "-m", module, *args]
