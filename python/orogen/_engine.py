"""Finds and imports the compiled engine `_orogen` (built by CMake into build/<preset>/python).

Looked for, in order: the folder named by $OROGEN_BUILD (a build folder or its python/), inside
the package (where scripts/install-python.sh installs it), the interpreter's own path
(PYTHONPATH), then the build/release and build/debug of the source tree this package sits in.
So from a source tree `import orogen` needs only python/ on the path.
"""

import importlib
import os
import sys
from pathlib import Path

_REPO = Path(__file__).resolve().parents[2]


def _candidates():
    for preset in ("release", "debug"):
        yield _REPO / "build" / preset / "python"


def _load():
    env = os.environ.get("OROGEN_BUILD")
    for folder in ([Path(env) / "python", Path(env)] if env else []):
        if any(folder.glob("_orogen*.so")):
            sys.path.insert(0, str(folder))
            return importlib.import_module("_orogen")
    for name in (f"{__package__}._orogen", "_orogen"):
        try:
            return importlib.import_module(name)
        except ImportError:
            pass
    for folder in _candidates():
        if any(folder.glob("_orogen*.so")):
            sys.path.insert(0, str(folder))
            return importlib.import_module("_orogen")
    raise ImportError(
        "the compiled module _orogen was not found: build it (cmake --preset release && "
        "ninja -C build/release _orogen) or set OROGEN_BUILD to the build folder")


_orogen = _load()
InstabilityError = _orogen.InstabilityError
World = _orogen.World
version = _orogen.version

# Each per-disc array as a read-only numpy view: world.x, world.radius, world.cluster_id, ...
for _name in ("x", "y", "vx", "vy", "theta", "omega", "radius", "mass", "id", "cluster_id", "motion",
              "x0", "y0", "depth0"):
    setattr(_orogen.World, _name, property(lambda self, n=_name: self.array(n), doc=f"per-disc `{_name}` (a view)"))
