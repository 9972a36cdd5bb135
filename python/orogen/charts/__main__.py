"""`python3 -m orogen.charts PATH [--out DIR]`, what `orogen charts PATH` runs: the charts that
fit the folder, chosen by what it holds.

    an ensemble (ensemble.toml)             orogen.charts.ensemble      DIR/aggregate/charts
    a wedge run                             orogen.charts.wedge         RUN/charts
      ... analysed by `orogen analyze`      orogen.charts.exhumation    RUN/charts/exhumation
    a repose, singly-vergent or biaxial     orogen.charts.granular      RUN/charts
      run, or a sweep of them

--out replaces the folder of the wedge and granular charts. Each module runs on its own too,
with more options (python3 -m orogen.charts.wedge --help). Exit 0 drawn, 2 bad input.
"""

import argparse
import os
import sys

from .. import folders
from . import ensemble, exhumation, granular, wedge

GRANULAR = {"repose": "repose", "singly_vergent": "singly", "biaxial": "biaxial"}


def experiment_of(path):
    """The experiment of a run folder or of the runs of a sweep, or None."""
    try:
        runs = folders.collect_runs([path])
    except folders.RunError:
        return None
    kinds = {r.experiment for r in runs}
    return kinds.pop() if len(kinds) == 1 else None


def main(argv=None):
    p = argparse.ArgumentParser(prog="orogen charts", description="The charts of a run, sweep or ensemble folder, "
                                "chosen by what it holds (docs/python.md).")
    p.add_argument("path", metavar="DIR", help="a run, sweep or ensemble folder")
    p.add_argument("--out", metavar="OUTDIR", help="folder for the charts (default: DIR/charts)")
    try:
        a = p.parse_args(argv)
    except SystemExit as e:
        return 0 if e.code == 0 else 2
    if not os.path.isdir(a.path):
        print("error: %s: no such folder (give a run, sweep or ensemble folder)" % a.path, file=sys.stderr)
        return 2
    out = a.out or os.path.join(a.path, "charts")
    if os.path.isfile(os.path.join(a.path, "ensemble.toml")):
        return ensemble.main([a.path])
    kind = experiment_of(a.path)
    if kind == "wedge":
        status = wedge.main([a.path, "--out", out])
        if status == 0 and os.path.isfile(os.path.join(a.path, "analysis.h5")):
            status = exhumation.main([a.path, "--out", os.path.join(out, "exhumation")])
        return status
    if kind in GRANULAR:
        return granular.main([GRANULAR[kind], a.path, "--out", out])
    print("error: %s holds no wedge, repose, singly-vergent or biaxial run, sweep of them, or ensemble "
          "(its experiment: %s); the charts of other runs are drawn by the scripts that made them"
          % (a.path, kind or "none found"), file=sys.stderr)
    return 2


if __name__ == "__main__":
    sys.exit(main())
