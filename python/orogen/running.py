"""`orogen run` from Python: the CLI's driver writes the same files with the same bits, and a
Python hook may act between steps.

    orogen.run({"wedge": {"s_end": 2}}, out="runs/a")                   # as the CLI
    orogen.run("examples/wedge.toml", out="runs/b", hook=erode, every=100)
    orogen.resume("runs/b", hook=erode, every=100)                       # as --resume
    orogen.run({"run": {"experiment": "scripted"}, "scripted": {"duration": 50}}, out="runs/c",
               setup=build_box)                                         # geometry from Python

The hook is called as hook(world) after each step whose number is a multiple of `every`, before
that step's output (so outputs show what it did); between calls the engine runs in C++ without
the GIL. It changes the world through the World API; returning True stops the run with a
checkpoint (orogen.resume continues it). What the hook depends on must live in the world or be
derived from the step number, so that a resumed run calls it alike.

`setup` is called as setup(world) once, after the experiment's own set-up and before output 0:
it builds the geometry of a scripted experiment (run.experiment = "scripted" starts from an empty
world) or adds to any other. A resume does not call it: the checkpoint holds what it built.
"""

import signal
from pathlib import Path

from ._engine import _orogen
from .config import load_config, overrides, split


class RunError(RuntimeError):
    """`orogen run` ended with a non-zero exit code (docs/exit-codes.md); the message says why,
    or where the reason was printed."""

    def __init__(self, code, out, why=None):
        self.code = code
        reasons = {1: "an I/O failure", 2: "bad input (folder or configuration)", 3: "the simulation became unstable"}
        where = ("the reason is printed above (standard error)" if code == 2 else
                 f"the reason is printed above and in {Path(out) / 'run.log'}")
        super().__init__(why or f"orogen run in {out} ended with exit code {code} "
                                f"({reasons.get(code, 'see docs/exit-codes.md')}); {where}")


STOPPED = "stopped"    # the hook returned True: a checkpoint to resume from
FINISHED = "finished"


def _result(code, out):
    if code == 0:
        return FINISHED
    if code == _orogen.STOPPED_BY_HOOK:
        return STOPPED
    if code in (128 + signal.SIGINT, 128 + signal.SIGTERM):
        raise KeyboardInterrupt(f"run in {out} stopped by a signal, with a checkpoint: orogen.resume({str(out)!r})")
    raise RunError(code, out)


def run(config=None, out="out", set=None, hook=None, every=100, threads=None, from_run=None, setup=None,
        surface_law=None):
    """Runs any experiment as `orogen run CONFIG --out OUT --set ...` does (config a TOML path,
    a dict or None; set a dict of overrides; from_run "RUN[:OUTPUT]" as --from; setup(world)
    builds on the set-up before output 0; surface_law(h, dx, x_lo, dt) -> new heights, a wedge's
    own surface law, docs/surface.md). Returns "finished", or "stopped" when the hook asked.
    Raises ConfigError before anything is written, RunError on the CLI's failures, and what the
    hook or setup raised (a hook's run checkpointed there; a setup's folder is left empty)."""
    file, settings = split(config)
    # ConfigErrors here, as Python exceptions, before any file: the keys, then the experiment's
    # cross-key checks (a scripted run without scripted.duration). A branch without a
    # configuration continues its source's, as the CLI's does.
    load_config(_branch_source_config(from_run) if config is None and from_run else config, set).check_experiment()
    if (Path(out) / "config.toml").exists():
        raise RunError(2, out, f"{out} already holds a run: continue it with orogen.resume({str(out)!r}), "
                               "or give another out")
    args = overrides(settings) + overrides(set)
    code = _orogen.run(file, args, Path(out), -1 if threads is None else int(threads), False,
                       from_run or "", hook, int(every) if hook else 0, setup, surface_law)
    return _result(code, out)


def _branch_source_config(from_run):
    """The config.toml of the run that "RUN[:OUTPUT]" names (a folder may itself hold ':')."""
    text = str(from_run)
    head, colon, tail = text.rpartition(":")
    return Path(head if colon and tail.isdigit() else text) / "config.toml"


def resume(out, set=None, hook=None, every=100, threads=None, setup=None, surface_law=None):
    """Continues a run folder as `orogen run --resume OUT` (set: extension keys, and keys of
    speed and display for this resume alone). `setup` is called only when the run was stopped
    before its first checkpoint and starts again; a run given a surface_law needs it again."""
    load_config(Path(out) / "config.toml", set)
    code = _orogen.run(None, overrides(set), Path(out), -1 if threads is None else int(threads), True, "",
                       hook, int(every) if hook else 0, setup, surface_law)
    return _result(code, out)
