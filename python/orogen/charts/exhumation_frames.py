#!/usr/bin/python3
"""Animations of an eroding run's exhumation: every output's discs coloured by their maximum
depth so far and by their closure-depth age (thesis chapter 6), from `orogen analyze`.

Usage:
    build/release/orogen analyze RUN_DIR
    python3 -m orogen.charts.exhumation_frames RUN_DIR [--closure 0.5] [--every 1] [--width 1000] [--fps 12]

Writes RUN_DIR/frames_max_depth/frame_NNNNNN.png and RUN_DIR/frames_age/frame_NNNNNN.png (NNNNNN
the output, as `orogen render` names its frames, each file atomically) and, where ffmpeg is
installed, RUN_DIR/animation_frames_max_depth.{mp4,gif} and animation_frames_age.{mp4,gif}.
`orogen report` shows them on the run's page beside the horizons and faults. Colour scales
are fixed over the run (0 to the 99th percentile of the last output), so frames compare.
"""

import argparse
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from ..analysis import exhumation as orogen_analysis  # noqa: E402
from ..atomic import save_figure  # noqa: E402
from .animation import animate  # noqa: E402


def frames(ds, values, label, what, cmap, folder, every, width_px):
    """One PNG per kept output: discs at their positions, coloured by values[time, particle]."""
    os.makedirs(folder, exist_ok=True)
    x, y = ds.x.values, ds.y.values
    x_lo, x_hi = np.nanmin(x), np.nanmax(x)
    y_hi = max(np.nanmax(y), 1.0) * 1.1
    last = values[-1][np.isfinite(values[-1])]
    v_hi = float(np.percentile(last, 99)) if last.size else 1.0
    dpi = 100
    width_in = width_px / dpi
    height_in = max(2.0, width_in * (y_hi + 0.3) / (x_hi - x_lo + 0.6) + 1.0)
    # Marker size: a disc's diameter (about one d, d/h0 in h0) in points on these axes.
    d_h0 = 1.0 / float(ds.attrs["h0"])
    stride = int(ds.attrs.get("particle_stride", 1))
    for k in range(0, ds.sizes["time"], every):
        fig, ax = plt.subplots(figsize=(width_in, height_in), dpi=dpi, layout="constrained")
        ax.set_xlim(x_lo - 0.3, x_hi + 0.3)
        ax.set_ylim(0, y_hi)
        ax.set_aspect("equal")
        norm = matplotlib.colors.Normalize(0, v_hi)
        fig.colorbar(matplotlib.cm.ScalarMappable(norm, cmap), ax=ax, label=label, shrink=0.8)
        fig.canvas.draw()  # the axes' final size, for the marker size
        points_per_h0 = ax.get_window_extent().width * 72 / dpi / (x_hi - x_lo + 0.6)
        ok = np.isfinite(x[k])
        ax.scatter(x[k][ok], y[k][ok], c=values[k][ok], s=(d_h0 * points_per_h0) ** 2, cmap=cmap, norm=norm,
                   linewidths=0)
        ax.set_xlabel("x from the S-point [h0]")
        ax.set_ylabel("y [h0]")
        ax.set_title("S = %.2f: %s%s" % (float(ds.S[k]), what, "" if stride == 1 else " (every %d-th disc)" % stride),
                     fontsize=9)
        save_figure(fig, os.path.join(folder, "frame_%06d.png" % k))


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("run", help="run folder holding analysis.h5 (orogen analyze)")
    p.add_argument("--closure", type=float, default=0.5, help="closure depth [h0] of the age frames (nearest)")
    p.add_argument("--every", type=int, default=1, help="draw every n-th output")
    p.add_argument("--width", type=int, default=1000, help="frame width in pixels")
    p.add_argument("--fps", type=int, default=12, help="animation frames per second")
    a = p.parse_args(argv)
    if not orogen_analysis.found(a.run):
        return 2
    if a.every < 1 or a.width < 200 or a.fps < 1:
        print("error: --every and --fps must be at least 1, --width at least 200", file=sys.stderr)
        return 2
    ds = orogen_analysis.load(a.run)
    ci = int(np.argmin(np.abs(ds.closure.values - a.closure)))
    frames(ds, ds.max_depth.values, "depth [h0]", "maximum depth so far", "magma_r",
           os.path.join(a.run, "frames_max_depth"), a.every, a.width)
    frames(ds, ds.age.isel(closure=ci).values, "age [sqrt(d/g)]", "age at closure depth %.2f h0" % float(ds.closure[ci]),
           "viridis", os.path.join(a.run, "frames_age"), a.every, a.width)
    made = all(animate(a.run, name, a.fps) for name in ("frames_max_depth", "frames_age"))
    print("exhumation frames of %d outputs in %s/frames_max_depth, frames_age%s" %
          (len(range(0, ds.sizes["time"], a.every)), a.run, " and their animations" if made else ""))
    return 0


if __name__ == "__main__":
    sys.exit(main())
