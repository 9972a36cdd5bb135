"""What the last build saw of each folder, so the next build redraws only what changed:
a signature of the names, sizes and modification times of a run's files (its frames and
charts folders counted by their listing), with the atlas's own code in it too."""
import hashlib
import json
import os

NAME = "manifest.json"


def _code_version():
    h = hashlib.sha1()
    here = os.path.dirname(os.path.abspath(__file__))
    for sub in ("", "assets"):
        for name in sorted(os.listdir(os.path.join(here, sub))):
            path = os.path.join(here, sub, name)
            if os.path.isfile(path) and name.endswith((".py", ".js", ".css")):
                with open(path, "rb") as f:
                    h.update(name.encode() + f.read())
    return h.hexdigest()


CODE = _code_version()


def signature(folder):
    """Changes when a file of the folder (not snapshots/ or vtp/, which series.csv follows) or of
    its frames and charts folders is added, removed, or rewritten."""
    h = hashlib.sha1(CODE.encode())
    for entry in sorted(os.scandir(folder), key=lambda e: e.name):
        if entry.name in ("run.lock", "snapshots", "vtp") or entry.name.startswith("."):
            continue
        st = entry.stat()
        h.update(("%s %d %d\n" % (entry.name, st.st_size, st.st_mtime_ns)).encode())
        if entry.is_dir() and (entry.name.startswith("frames") or entry.name in ("charts",)):
            for here, dirs, files in os.walk(entry.path):
                dirs.sort()
                for f in sorted(files):
                    st = os.stat(os.path.join(here, f))
                    h.update(("%s/%s %d %d\n" % (here, f, st.st_size, st.st_mtime_ns)).encode())
    return h.hexdigest()


def load(site):
    try:
        with open(os.path.join(site, NAME), encoding="utf-8") as f:
            data = json.load(f)
        return data if isinstance(data, dict) else {}
    except (OSError, ValueError):
        return {}
