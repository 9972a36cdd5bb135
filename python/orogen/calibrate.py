"""Calibration of a material (docs/materials.md, Calibration): what PFC users do before every
study. Biaxial tests (run.experiment = "biaxial") of a sample of one material at three or more
confining stresses, and from their peak and residual stress states the Mohr-Coulomb envelopes:
friction angle, cohesion and unconfined compressive strength, with the stress-strain curves;
and a Brazilian test (biaxial.test = "brazilian") for the tensile strength.

    python3 -m orogen.calibrate CONFIG --out DIR [--material NAME] [--sigma3 2,5,10]
                                [--tension-sigma3 0.5] [--no-tension] [--jobs 2] [--set KEY=VALUE ...]
    orogen calibrate CONFIG --out DIR ...

CONFIG holds the material ([materials.NAME]) and the sample's keys (particles.*, contact.*,
biaxial.*); the tests run it as a biaxial test of that material (biaxial.material) at each
biaxial.sigma3. Writes into DIR:

    sigma3_X/            each test, an orogen run folder (a test already finished is kept)
    brazilian/           the Brazilian test: the sample (biaxial.height = biaxial.width) consolidated
                         at --tension-sigma3, cut to its inscribed disc, bonded, split between platens
    calibration.csv      one row per test: sigma3, the peak and residual stresses, strains
    calibration.json     the envelopes (peak, residual): phi, cohesion, UCS, their standard errors;
                         the tensile strength 2 F_peak / (pi D) (null with --no-tension)
    calibration.png/.pdf the stress-strain curves, the Mohr circles with the envelopes, the
                         Brazilian test's platen force

Stresses are the biaxial test's, in m g / d^2 (m = pi / 4, the mass of a disc of diameter 1: the
biaxial.sigma3 unit); the JSON gives cohesion and UCS also in rho g d, the unit of the bond
strengths (times pi / 4). The fit: sigma1 = UCS + N sigma3 by least squares (scipy), so
sin(phi) = (N - 1) / (N + 1) and c = UCS / (2 sqrt(N)). The tensile strength is measured, not
extrapolated from the envelope (a Mohr-Coulomb line overestimates it: bonded materials fail in
tension at a fraction of c / tan(phi)).
"""

import argparse
import json
import math
import os
import sys
import tomllib
from concurrent.futures import ProcessPoolExecutor
from pathlib import Path

import numpy as np
from scipy import stats

from .analysis.calibrated_taper import material_keys
from .atomic import save_figure, write_text
from .config import ConfigError, load_config
from .tables import read_table

UNIT_MASS = math.pi / 4  # m in the biaxial stresses' m g / d^2


class CalibrationError(Exception):
    """Bad input or a failed test: the message names it; exit code 2."""


def fit_envelope(sigma3, sigma1):
    """The Mohr-Coulomb envelope through the stress states (sigma3, sigma1): the least-squares
    line sigma1 = ucs + n sigma3, as phi [deg], cohesion and UCS with standard errors."""
    sigma3, sigma1 = np.asarray(sigma3, float), np.asarray(sigma1, float)
    if len(sigma3) < 3 or len(np.unique(sigma3)) < 3:
        raise CalibrationError("an envelope needs three or more distinct confining stresses, got %s"
                               % sorted(set(sigma3.tolist())))
    line = stats.linregress(sigma3, sigma1)
    n, ucs = float(line.slope), float(line.intercept)
    if not n > 1:
        raise CalibrationError("the peak stresses do not rise with confinement (slope %.3g): no friction "
                               "angle; are the tests quasi-static and the sample sheared to its peak?" % n)
    phi = math.degrees(math.asin((n - 1) / (n + 1)))
    cohesion = ucs / (2 * math.sqrt(n))
    # Standard errors by first-order propagation from the slope and the intercept.
    dphi_dn = math.degrees(1 / ((n + 1) * math.sqrt(n)))
    phi_err = abs(dphi_dn) * float(line.stderr)
    c_err = math.hypot(float(line.intercept_stderr) / (2 * math.sqrt(n)),
                       ucs * float(line.stderr) / (4 * n ** 1.5))
    return {"phi_deg": phi, "phi_stderr_deg": phi_err, "cohesion": cohesion, "cohesion_stderr": c_err,
            "ucs": ucs, "ucs_stderr": float(line.intercept_stderr), "slope_n": n, "r_squared": float(line.rvalue ** 2),
            "cohesion_rho_g_d": cohesion * UNIT_MASS, "ucs_rho_g_d": ucs * UNIT_MASS}


def _test(job):
    """One biaxial test into its folder (kept when it finished before)."""
    from .running import run  # the engine, in this worker process

    config, out, sets = job
    if (Path(out) / "summary.csv").exists():
        return out
    run(config, out=out, set=sets, threads=1)
    return out


def test_states(folder):
    """The stress-strain curve of one finished test, its peak (largest mobilised friction) and
    its residual state (the mean over the last third of the shearing)."""
    cols, _ = read_table(os.path.join(folder, "series.csv"))
    shear = cols["phase"] >= 1
    strain, s1, s3, phi = (cols[k][shear] for k in ("axial_strain", "sigma1", "sigma3", "phi_deg"))
    if len(strain) < 3:
        raise CalibrationError("%s: fewer than three outputs of shearing" % folder)
    peak = int(np.nanargmax(phi))
    late = strain >= 2.0 / 3.0 * strain[-1]
    return {"strain": strain, "sigma1": s1, "sigma3": s3,
            "peak": {"sigma1": float(s1[peak]), "sigma3": float(s3[peak]), "strain": float(strain[peak])},
            "residual": {"sigma1": float(np.mean(s1[late])), "sigma3": float(np.mean(s3[late]))}}


def tension_state(folder):
    """The Brazilian test of one finished folder: its summary and platen force against strain."""
    cols, _ = read_table(os.path.join(folder, "series.csv"))
    summary, _ = read_table(os.path.join(folder, "summary.csv"))
    loading = cols["phase"] >= 1
    return {"strain": cols["axial_strain"][loading],
            "force": cols["sigma1"][loading] * cols["width"][loading],
            "summary": {k: float(v[0]) for k, v in summary.items()}}


def calibrate(config, out, material="", sigma3=(2.0, 5.0, 10.0), jobs=2, sets=None, tension_sigma3=0.5):
    """Runs the tests (jobs at a time) and writes the tables and figure; returns the envelopes.
    tension_sigma3: the Brazilian test's consolidation stress (None: no Brazilian test)."""
    out = Path(out)
    out.mkdir(parents=True, exist_ok=True)
    jobs_list = []

    def add_job(name, extra):
        keys = dict(sets or {})
        keys.update({"run.experiment": "biaxial", "output.progress": "never"})
        keys.update(extra)
        if material:
            keys["biaxial.material"] = material
        # Bad keys named here, before any test starts (a worker's error would only break the pool).
        load_config(config, keys).check_experiment()
        jobs_list.append((str(config), str(out / name), keys))

    for s in sigma3:
        add_job("sigma3_%g" % s, {"biaxial.sigma3": float(s)})
    if tension_sigma3 is not None:
        width = tomllib.loads(load_config(config, dict(sets or {})).to_toml())["biaxial"]["width"]
        add_job("brazilian", {"biaxial.test": "brazilian", "biaxial.sigma3": float(tension_sigma3),
                              "biaxial.height": width, "biaxial.strain_end": 0.03,
                              "biaxial.outputs": 100})
    with ProcessPoolExecutor(max_workers=max(1, jobs)) as pool:
        folders = list(pool.map(_test, jobs_list))
    tests = [test_states(f) for f in folders[:len(sigma3)]]
    tension = tension_state(folders[-1]) if tension_sigma3 is not None else None
    result = {"material": material or "(the configuration's first)", "config": str(config),
              "sigma3_targets": [float(s) for s in sigma3],
              "peak": fit_envelope([t["peak"]["sigma3"] for t in tests], [t["peak"]["sigma1"] for t in tests]),
              "residual": fit_envelope([t["residual"]["sigma3"] for t in tests],
                                       [t["residual"]["sigma1"] for t in tests]),
              "units": "stresses in m g / d^2 (m = pi / 4), as biaxial.sigma3; *_rho_g_d in rho g d",
              "tensile_strength": None,
              # What makes the material, so that a wedge of it finds this calibration
              # (orogen.analysis.calibrated_taper).
              "material_keys": material_keys(tomllib.loads(load_config(config, jobs_list[0][2]).to_toml()),
                                             material)}
    if tension is not None:
        t = tension["summary"]
        result["tensile_strength"] = {
            "sigma_t": t["tensile_strength"], "sigma_t_rho_g_d": t["tensile_strength_rho_g_d"],
            "peak_force": t["peak_force"], "diameter": t["diameter"], "consolidation_sigma3": float(tension_sigma3),
            "bonds_broken": t["bonds_broken"], "test": "Brazilian: 2 F_peak / (pi D), unit thickness"}
    rows = ["# one biaxial test per row (orogen calibrate); stresses in m g / d^2, m = pi / 4",
            "sigma3_target,sigma3_peak,sigma1_peak,axial_strain_peak,sigma3_residual,sigma1_residual"]
    for s, t in zip(sigma3, tests):
        rows.append("%r,%r,%r,%r,%r,%r" % (float(s), t["peak"]["sigma3"], t["peak"]["sigma1"], t["peak"]["strain"],
                                           t["residual"]["sigma3"], t["residual"]["sigma1"]))
    write_text(out / "calibration.csv", "\n".join(rows) + "\n")
    write_text(out / "calibration.json", json.dumps(result, indent=2, sort_keys=True) + "\n")
    fig = figure(tests, sigma3, result, tension)
    for fmt in ("png", "pdf"):
        save_figure(fig, out / ("calibration." + fmt), fmt, 120, {"png": {"Software": None},
                                                                 "pdf": {"CreationDate": None, "Producer": None}}[fmt])
    return result


def figure(tests, sigma3, result, tension=None):
    """Stress-strain curves (left), Mohr circles with the envelopes (middle) and the Brazilian
    test's platen force (right, when there is one)."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(1, 3 if tension else 2, figsize=(16 if tension else 11, 4.2))
    a, b = axes[0], axes[1]
    colours = plt.cm.viridis(np.linspace(0.1, 0.85, len(tests)))
    for s, t, c in zip(sigma3, tests, colours):
        a.plot(t["strain"], t["sigma1"] - t["sigma3"], color=c, label="sigma3 = %g" % s)
        a.plot(t["peak"]["strain"], t["peak"]["sigma1"] - t["peak"]["sigma3"], "o", color=c)
        for state, style in (("peak", "-"), ("residual", "--")):
            s1, s3 = t[state]["sigma1"], t[state]["sigma3"]
            angle = np.linspace(0, np.pi, 90)
            b.plot(0.5 * (s1 + s3) + 0.5 * (s1 - s3) * np.cos(angle), 0.5 * (s1 - s3) * np.sin(angle), style,
                   color=c, lw=1)
    a.set_xlabel("axial strain [-]")
    a.set_ylabel("deviator stress sigma1 - sigma3 [m g / d^2]")
    a.legend(fontsize=8)
    a.set_title("stress-strain (dots: peak)")
    top = max(t["peak"]["sigma1"] for t in tests)
    sigma = np.linspace(0, top, 50)
    for state, style in (("peak", "-"), ("residual", "--")):
        e = result[state]
        b.plot(sigma, e["cohesion"] + sigma * math.tan(math.radians(e["phi_deg"])), style, color="k",
               label="%s: phi %.1f deg, c %.2g" % (state, e["phi_deg"], e["cohesion"]))
    b.set_xlabel("normal stress [m g / d^2]")
    b.set_ylabel("shear stress [m g / d^2]")
    b.set_aspect("equal")
    b.set_xlim(0, top * 1.02)
    b.set_ylim(0, None)
    b.legend(fontsize=8, loc="upper left")
    b.set_title("Mohr circles (solid: peak, dashed: residual)")
    if tension:
        c = axes[2]
        t = result["tensile_strength"]
        c.plot(tension["strain"], tension["force"], color="C3")
        c.axhline(t["peak_force"], color="k", lw=0.8, ls=":")
        c.set_xlabel("shortening of the diameter / D [-]")
        c.set_ylabel("platen force [m g]")
        c.set_title("Brazilian test: sigma_t = 2 F / (pi D) = %.3g m g / d^2" % t["sigma_t"])
    fig.tight_layout()
    return fig


def parse_sets(values):
    sets = {}
    for text in values or []:
        key, eq, value = text.partition("=")
        if not eq or not key.strip():
            raise CalibrationError("--set %s: expected KEY=VALUE" % text)
        sets[key.strip()] = _value(value.strip())
    return sets


def _value(text):
    """A --set value as orogen run reads it: a number, true or false, else a string."""
    if text in ("true", "false"):
        return text == "true"
    for kind in (int, float):
        try:
            return kind(text)
        except ValueError:
            pass
    return text.strip("\"'")


def main(argv=None):
    p = argparse.ArgumentParser(prog="orogen calibrate", description=__doc__.split("\n\n")[0])
    p.add_argument("config", help="a configuration holding the material and the sample's keys")
    p.add_argument("--out", required=True, help="folder for the tests and the calibration")
    p.add_argument("--material", default="", help="the material to test (default: the first of [materials])")
    p.add_argument("--sigma3", default="2,5,10", help="confining stresses, three or more [m g / d^2] (default 2,5,10)")
    p.add_argument("--tension-sigma3", type=float, default=0.5,
                   help="consolidation stress of the Brazilian test's sample before the cut [m g / d^2] (default 0.5)")
    p.add_argument("--no-tension", action="store_true", help="no Brazilian test")
    p.add_argument("--jobs", type=int, default=2, help="tests at a time (default 2)")
    p.add_argument("--set", action="append", dest="sets", help="KEY=VALUE for every test, as orogen run --set")
    a = p.parse_args(argv)
    try:
        if not os.path.isfile(a.config):
            raise CalibrationError("%s: no such configuration file" % a.config)
        try:
            sigma3 = [float(v) for v in a.sigma3.split(",")]
        except ValueError:
            raise CalibrationError("--sigma3 %s: expected numbers separated by commas" % a.sigma3) from None
        if len(set(sigma3)) < 3 or not all(s > 0 and math.isfinite(s) for s in sigma3):
            raise CalibrationError("--sigma3 %s: three or more distinct confining stresses > 0" % a.sigma3)
        if not 1 <= a.jobs <= 64:
            raise CalibrationError("--jobs %d: 1 to 64" % a.jobs)
        if not (a.tension_sigma3 > 0 and math.isfinite(a.tension_sigma3)):
            raise CalibrationError("--tension-sigma3 %s: a stress > 0" % a.tension_sigma3)
        result = calibrate(a.config, a.out, a.material, sigma3, a.jobs, parse_sets(a.sets),
                           None if a.no_tension else a.tension_sigma3)
    except CalibrationError as e:
        print("error: %s" % e, file=sys.stderr)
        return 2
    except ConfigError as e:
        print("error: %s" % e, file=sys.stderr)
        return 2
    except Exception as e:  # a test that failed: the engine's words
        print("error: %s: %s" % (type(e).__name__, e), file=sys.stderr)
        return 1
    for state in ("peak", "residual"):
        e = result[state]
        print("%s: phi = %.2f +- %.2f deg, cohesion = %.3g +- %.2g, UCS = %.3g m g / d^2 (R^2 %.3f)"
              % (state, e["phi_deg"], e["phi_stderr_deg"], e["cohesion"], e["cohesion_stderr"], e["ucs"],
                 e["r_squared"]))
    if result["tensile_strength"]:
        t = result["tensile_strength"]
        print("tension (Brazilian): sigma_t = %.3g m g / d^2 (%.3g rho g d), %d bonds broken"
              % (t["sigma_t"], t["sigma_t_rho_g_d"], t["bonds_broken"]))
    print("written: %s" % os.path.join(a.out, "calibration.json"))
    return 0


if __name__ == "__main__":
    sys.exit(main())
