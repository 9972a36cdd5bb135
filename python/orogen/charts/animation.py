"""Animations from a folder of numbered PNG frames (ffmpeg), as `orogen render` assembles its own.

    animate(run, "frames_faults", fps)   # RUN/animation_frames_faults.mp4 and .gif
    animate(run, "frames", fps, stem="animation")   # RUN/animation.mp4 and .gif

Each file is written under a temporary name and renamed when ffmpeg succeeds. Without ffmpeg
nothing is written and False is returned; a failing ffmpeg is a warning on stderr.
"""

import os
import shutil
import subprocess
import sys

from ..atomic import temporary_path

# MP4: even width and height, as yuv420p requires; GIF: one palette fitted to the whole clip.
_ENCODINGS = (
    ("mp4", ["-vf", "pad=ceil(iw/2)*2:ceil(ih/2)*2", "-c:v", "libx264", "-pix_fmt", "yuv420p",
             "-movflags", "+faststart"]),
    ("gif", ["-vf", "scale='min(800,iw)':-1:flags=lanczos,split[a][b];[a]palettegen[p];[b][p]paletteuse"]),
)


def animate(run, name, fps, stem=None):
    """RUN/<stem>.mp4 and .gif from RUN/NAME/frame_*.png (stem: animation_NAME by default)."""
    ffmpeg = shutil.which("ffmpeg")
    if not ffmpeg:
        return False
    pattern = os.path.join(run, name, "frame_*.png")
    stem = stem or "animation_%s" % name
    for ext, extra in _ENCODINGS:
        out = os.path.join(run, "%s.%s" % (stem, ext))
        try:
            with temporary_path(out, suffix="." + ext) as tmp:
                r = subprocess.run([ffmpeg, "-nostdin", "-y", "-loglevel", "error", "-framerate", str(fps),
                                    "-pattern_type", "glob", "-i", pattern, *extra, "-f", ext, tmp],
                                   capture_output=True, stdin=subprocess.DEVNULL)
                if r.returncode != 0:
                    raise RuntimeError(r.stderr.decode(errors="replace")[-300:])
        except RuntimeError as e:
            print("warning: ffmpeg failed on %s: %s" % (out, e), file=sys.stderr)
            return False
    return True
