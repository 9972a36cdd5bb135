#!/usr/bin/python3
"""The faults of one wedge run through time (docs/cohesion-evidence.md, Buiter et al. 2016
experiment 2): at every `--every`-th output, the forethrusts and backthrusts the picker found
(orogen.analysis.faults: run it first), how many are active, their mean dips, the forethrusts'
median spacing and offset, and the wedge's surface slope beside the critical taper of its
calibrated material.

    python3 -m orogen.analysis.faults RUN
    scripts/fault_history.py RUN [--every 4] [--calibration cal/calibration.json] [--mu-b 0.2867]

A Markdown table on standard output. The critical tapers need the calibration of the run's
material (orogen calibrate) and the basal friction (default: the run's singly.mu_b or
wedge.mu_bp).
"""

import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "python"))
from orogen.analysis import calibrated_taper  # noqa: E402
from orogen.results import open_run  # noqa: E402
from orogen.tables import read_rows, read_table  # noqa: E402


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("run")
    p.add_argument("--every", type=int, default=4, help="every this many outputs (default 4)")
    p.add_argument("--calibration", default=None, help="calibration.json of the run's material")
    p.add_argument("--mu-b", type=float, default=None, help="basal friction for the critical taper")
    a = p.parse_args(argv)
    cols, _ = read_table(os.path.join(a.run, "series.csv"))
    faults, _ = read_rows(os.path.join(a.run, "faults.csv"))
    config = open_run(a.run).config
    singly = "shortening" in cols
    s_col, taper_col = ("shortening", "taper") if singly else ("S", "alpha_fit")
    mu_b = a.mu_b if a.mu_b is not None else (config["singly"]["mu_b"] if singly else config["wedge"]["mu_bp"])
    critical = ""
    if a.calibration:
        cal = calibrated_taper.load_calibration(a.calibration)
        c = calibrated_taper.critical_tapers(cal, mu_b)
        critical = " (critical taper at mu_b %.3g: %.1f peak, %.1f residual)" % (mu_b, c["peak"], c["residual"])
    print("| output | shortening or S [h0] | forethrusts (active) | backthrusts (active) | forethrust dip [deg] "
          "| backthrust dip [deg] | forethrust spacing [h0] | forethrust offset [h0] | surface taper [deg]%s |"
          % critical)
    print("|---|---|---|---|---|---|---|---|---|")
    outputs = sorted({int(f["output"]) for f in faults})
    for k in outputs[::a.every] + ([outputs[-1]] if outputs and outputs[-1] not in outputs[::a.every] else []):
        here = [f for f in faults if int(f["output"]) == k]
        fore = [f for f in here if f["kind"] == "forethrust"]
        back = [f for f in here if f["kind"] == "backthrust"]

        def mean(rows, key):
            v = [float(r[key]) for r in rows]
            return "%.0f" % np.mean(v) if v else "-"
        spacing = [float(f["spacing"]) for f in fore if f["spacing"] not in ("", "nan")]
        spacing = [v for v in spacing if np.isfinite(v)]
        offsets = [float(f["offset"]) for f in fore if f.get("offset", "") not in ("", None)]
        offsets = [v for v in offsets if np.isfinite(v)]
        row = min(k, len(cols[s_col]) - 1)
        print("| %d | %.2f | %d (%d) | %d (%d) | %s | %s | %s | %s | %.1f |" % (
            k, float(here[0]["S"]), len(fore), sum(int(f["active"]) for f in fore), len(back),
            sum(int(f["active"]) for f in back), mean(fore, "dip_deg"), mean(back, "dip_deg"),
            "%.2f" % np.median(spacing) if spacing else "-", "%.2f" % np.median(offsets) if offsets else "-",
            cols[taper_col][row]))
    return 0


if __name__ == "__main__":
    sys.exit(main())
