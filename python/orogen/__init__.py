"""Orogen from Python: configure, run, step and extend the engine; read every result.

    import orogen
    orogen.run({"wedge": {"s_end": 2}}, out="runs/a")          # exactly `orogen run`
    sim = orogen.Simulation("examples/wedge.toml"); sim.step(100)
    r = orogen.open_run("runs/a"); r.series; r.snapshots

docs/python.md describes it all; the engine is the compiled module _orogen (python/bindings).
"""

from ._engine import _orogen
from .config import ConfigError, load_config, resolved_toml
from .results import RunFolder, open_run, read_csv
from .running import FINISHED, STOPPED, RunError, resume, run
from .simulation import Simulation

InstabilityError = _orogen.InstabilityError
World = _orogen.World
__version__ = _orogen.version

__all__ = ["ConfigError", "InstabilityError", "RunError", "RunFolder", "Simulation", "World", "FINISHED",
           "STOPPED", "load_config", "open_run", "read_csv", "resolved_toml", "resume", "run"]
