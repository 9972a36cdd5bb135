"""Finds the run, sweep and ensemble folders under a root (docs/output-files.md says what
marks each)."""
import os

# Subfolders of a run that hold no runs: not walked (a run folder may hold thousands of files).
_SKIP = {"snapshots", "vtp", "charts", "logs", "aggregate", "node_modules"}


def is_run(names):
    return "config.toml" in names and ("series.csv" in names or "snapshots.h5" in names)


def is_sweep(names):
    return "results.csv" in names and "runs" in names and ("sweep.log" in names or "sweep.lock" in names)


def is_ensemble(names):
    return "ensemble.toml" in names and "members" in names


def find(root, site):
    """(runs, groups): runs [(abs path, rel path, group rel path or '')], groups [(abs, rel, kind)]
    with kind 'sweep' or 'ensemble'; in sorted order; the site folder itself skipped. Symbolic
    links to folders are followed (a folder of linked runs), each real folder once."""
    root = os.path.abspath(root)
    site = os.path.abspath(site)
    runs, groups, group_of_parent = [], [], {}
    seen = set()  # real paths walked: symbolic links are followed, each folder once (no cycles)
    for here, dirs, files in os.walk(root, followlinks=True):
        real = os.path.realpath(here)
        if real in seen:
            dirs[:] = []
            continue
        seen.add(real)
        names = set(dirs) | set(files)
        if os.path.abspath(here) == site or {"manifest.json", "index.html", "assets"} <= names:
            dirs[:] = []  # an atlas (this one or another): its copies of run files are not runs
            continue
        rel = os.path.relpath(here, root)
        rel = "" if rel == "." else rel
        if is_sweep(names) or is_ensemble(names):
            kind = "sweep" if is_sweep(names) else "ensemble"
            groups.append((here, rel or os.path.basename(root), kind))
            group_of_parent[os.path.join(here, "runs" if kind == "sweep" else "members")] = rel or os.path.basename(root)
        if is_run(names):
            runs.append((here, rel or os.path.basename(root), group_of_parent.get(os.path.dirname(here), "")))
            dirs[:] = []  # a run holds no runs
            continue
        dirs[:] = sorted(d for d in dirs if d not in _SKIP and not d.startswith(".") and not d.startswith("frames"))
    runs.sort(key=lambda r: r[1])
    groups.sort(key=lambda g: g[1])
    return runs, groups


def slug(rel):
    """A file name for a folder's pages: its path with the separators spelt out."""
    out = []
    for ch in rel:
        out.append(ch if ch.isalnum() or ch in "-_." else "~")
    return "".join(out).replace("~", "--") or "root"
