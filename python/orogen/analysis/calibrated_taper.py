"""The critical taper a wedge should stand at, from its material's calibration (issue 39.4).

`orogen calibrate` measures a material's bulk friction (peak and residual Mohr-Coulomb
envelopes, calibration.json) and records the keys that make the material (MATERIAL_KEYS and the
material's own [materials.NAME] entry). A run whose configuration has the same values is made
of that material: its critical taper is Dahlen's (surface.critical_taper_deg) for the
calibrated peak and residual friction angles and the run's basal friction. The package ships
the calibration of the default material (default_calibration.json: the default configuration's
biaxial sample, random clusters at contact mu 0.3), so a default wedge gets it without asking.

Cohesion is left out: a cohesive wedge tapers towards the cohesionless critical taper as it
grows (Dahlen 1990), which is the line drawn; near its toe it may stand steeper.

    calibration_for(config, explicit=None)   the calibration that fits a run's configuration
    critical_tapers(calibration, mu_b)        {"peak": deg, "residual": deg}
    material_keys(config, material)           the keys a calibration is matched on
"""

import json
import os

from .surface import critical_taper_deg

# The keys that make a material besides its [materials.NAME] entry: the contact law, the grains
# and how the packing settles (the seed, the walls and the time step do not).
MATERIAL_KEYS = {
    "contact": ("mu", "kn", "ks_ratio", "normal_force", "damping", "damping_rate", "restitution",
                "tangential_damping_ratio", "rolling_friction", "rolling_stiffness"),
    "particles": ("packing", "d_min", "d_max", "placement"),
    "settle": ("mu",),
}

# Keys that came after calibrations were first recorded, with their defaults: a calibration that
# does not record one was made at its default.
LATER_KEYS = {"contact": {"rolling_friction": 0.0, "rolling_stiffness": 1.0}, "material": {"rolling_friction": 0.0}}

DEFAULT_CALIBRATION = os.path.join(os.path.dirname(__file__), "default_calibration.json")


def material_keys(config, material=""):
    """The values a calibration is matched on, from a resolved configuration (a dict as
    tomllib reads config.toml): the MATERIAL_KEYS and, when `material` is named, its entry of
    [materials] (None when the configuration has no such material)."""
    out = {section: {k: config.get(section, {}).get(k) for k in keys} for section, keys in MATERIAL_KEYS.items()}
    materials = config.get("materials", {})
    name = material or (next(iter(materials)) if materials else "")
    out["material"] = dict(materials[name], name=name) if name in materials else None
    return out


def load_calibration(path):
    with open(path) as f:
        return json.load(f)


def calibration_for(config, explicit=None):
    """(calibration, why): the calibration that fits the run's configuration (a dict of its
    config.toml) - the explicit one (a path or a dict) when given, else the shipped default when
    the run is of the default material - or (None, the reason none fits)."""
    source = explicit if explicit is not None else DEFAULT_CALIBRATION
    if isinstance(source, (str, os.PathLike)):
        if not os.path.isfile(source):
            return None, "no calibration file %s" % source
        source = load_calibration(source)
    keys = source.get("material_keys")
    if keys is None:
        return None, "the calibration records no material keys (made before they were recorded)"
    material = (keys.get("material") or {}).get("name", "")
    mine = material_keys(config, material)
    if material and mine["material"] is None:
        return None, "the run has no material %r" % material
    recorded = {s: dict(LATER_KEYS.get(s, {}), **keys[s]) for s in MATERIAL_KEYS}
    differ = ["%s.%s" % (s, k) for s in MATERIAL_KEYS for k in MATERIAL_KEYS[s] if recorded[s].get(k) != mine[s].get(k)]
    recorded_material = dict(LATER_KEYS["material"], **keys["material"]) if keys.get("material") else None
    if recorded_material != mine["material"]:
        differ.append("materials.%s" % material if material else
                      "[materials] (the calibration is of the default material, the run names its own)")
    if differ:
        return None, "the run's material differs from the calibrated one in %s" % ", ".join(differ)
    return source, "calibrated %s" % (material or "default material")


def critical_tapers(calibration, mu_b):
    """Critical tapers [deg] on a flat base of friction coefficient mu_b for the calibrated peak
    and residual friction angles (NaN where the base is not weaker than the material)."""
    return {state: critical_taper_deg(calibration[state]["phi_deg"], mu_b) for state in ("peak", "residual")}


def describe(calibration):
    """One line for a legend: the calibrated angles."""
    return "phi %.1f / %.1f deg (peak / residual)" % (calibration["peak"]["phi_deg"],
                                                       calibration["residual"]["phi_deg"])
