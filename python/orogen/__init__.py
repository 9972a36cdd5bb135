"""Orogen from Python: configure, run, step and extend the engine; read every result.

    import orogen
    orogen.run({"wedge": {"s_end": 2}}, out="runs/a")          # exactly `orogen run`
    sim = orogen.Simulation("examples/wedge.toml"); sim.step(100)
    r = orogen.open_run("runs/a"); r.series; r.snapshots

docs/python.md describes it all. The readers (open_run, read_csv) need only numpy, pandas,
xarray and h5py; the rest needs the compiled engine _orogen (python/bindings), imported on
first use, so results can be read where the engine was never built.
"""

from .results import RunFolder, open_run
from .tables import read_csv

_ENGINE = {
    "ConfigError": ("config", "ConfigError"), "load_config": ("config", "load_config"),
    "resolved_toml": ("config", "resolved_toml"), "run": ("running", "run"), "resume": ("running", "resume"),
    "RunError": ("running", "RunError"), "FINISHED": ("running", "FINISHED"), "STOPPED": ("running", "STOPPED"),
    "Simulation": ("simulation", "Simulation"), "InstabilityError": ("_engine", "InstabilityError"),
    "World": ("_engine", "World"), "__version__": ("_engine", "version"),
}


def __getattr__(name):  # PEP 562: the engine's names, imported when first asked for
    if name not in _ENGINE:
        raise AttributeError(f"module 'orogen' has no attribute {name!r}")
    import importlib
    module, attr = _ENGINE[name]
    value = getattr(importlib.import_module(f".{module}", __name__), attr)
    globals()[name] = value
    return value


__all__ = ["RunFolder", "open_run", "read_csv", *[n for n in _ENGINE if not n.startswith("_")]]
