"""Titles of the chart files the chart scripts write, with the thesis figures they reproduce
(python/README.md; the scripts' docstrings)."""
import re

CHARTS = {
    "height_peak.png": ("Height and peak position against S, power-law fit", "Figs 4.6, 4.9, 4.11"),
    "tapers.png": ("Pro and retro tapers against S", "Figs 4.7, 4.12"),
    "fronts.png": ("Deformation and marker fronts against S", "Fig 5.14"),
    "topography.png": ("Upper surface through time with the fronts", "Fig 5.13"),
    "slip.png": ("Basal contacts at the Coulomb limit against S", ""),
    "spacetime_elevation.png": ("Elevation in space and time", "Figs 6.10, 6.11"),
    "spacetime_max_depth.png": ("Maximum depth of the surface disc in space and time", "Figs 6.12, 6.15"),
    "spacetime_cum_erosion.png": ("Cumulative erosion in space and time", "Fig 6.16"),
    "spacetime_surface_age.png": ("Surface age in space and time", "Figs 6.20, 6.21"),
    "max_depth_positions.png": ("Maximum depth at fixed positions", "Fig 6.13"),
    "age_positions.png": ("Surface age at fixed positions", "Fig 6.17"),
    "age_jump_stats.png": ("Surface age statistics and jumps across x", "Figs 6.18, 6.19"),
    "trajectories.png": ("Surface discs traced back in time", "Fig 6.9"),
    "horizon_frames.png": ("Horizons and erosion at a few outputs", "Figs 6.1-6.4"),
    "flux.png": ("Eroded flux against the incoming flux", ""),
    "pro_cycle.png": ("Pro fronts against the erosion, low erosion in grey", "Figs 6.6, 6.7"),
    "spacetime_deposits.png": ("Sediment in each column in space and time", ""),
    "basin_strata.png": ("Growth strata: the sediment by the S it was laid at", ""),
    "base_deflection.png": ("The deflecting base through time and its profile", ""),
    "fig5_14_fronts_members.png": ("Every member's fronts", "Fig 5.14"),
    "fig5_16_mean_fronts.png": ("Mean fronts with one standard deviation", "Fig 5.16"),
    "fig5_17_18_fits.png": ("Power-law fits of the fronts (log-log)", "Figs 5.17, 5.18"),
    "cycles.png": ("Thrust cycles: the saw-tooth with its step-outs", "sections 5.4.5-5.4.7"),
    "simple_model.png": ("Simple Model against the runs", ""),
}

# Animations by frames folder (orogen sections, orogen render --frames-dir): label, thesis figure.
ANIMATIONS = {
    "frames": ("Horizons (initial depth)", "Figs 4.5, 5.3"),
    "frames_faults": ("Faults (orogen sections: incremental shear strain; orogen render: relative displacement)",
                      "Fig 5.7"),
    "frames_vectors": ("Displacement over the last three outputs", "Fig 5.11"),
    "frames_rel_disp": ("Faults (relative displacement of neighbours)", "Fig 5.7"),
    "frames_max_depth": ("Maximum depth so far (orogen.charts.exhumation_frames)", ""),
    "frames_age": ("Closure-depth age (orogen.charts.exhumation_frames)", ""),
    "frames_cluster": ("Clusters", ""),
}


def chart(name):
    """(title, thesis figures) of a chart file; a per-member envelope chart by its pattern."""
    if name in CHARTS:
        return CHARTS[name]
    m = re.match(r"fig5_19_22_(.+)\.png$", name)
    if m:
        return ("%s against the mean trends, 1 and 2 standard-error envelopes" % m.group(1), "Figs 5.19-5.22")
    return (name.rsplit(".", 1)[0].replace("_", " "), "")


def animation(folder):
    if folder in ANIMATIONS:
        return ANIMATIONS[folder]
    return (folder.replace("frames_", "").replace("_", " "), "")
