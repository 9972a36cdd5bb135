"""Command line: DIR [--out SITE]. Exit codes as orogen's: 0 built, 2 bad input, 1 I/O."""
import argparse
import os
import sys

from . import build, manifest


def check(root, site):
    """An error message for bad input, or ''."""
    if not os.path.exists(root):
        return "%s: no such folder (give the folder that holds the runs, sweeps and ensembles)" % root
    if not os.path.isdir(root):
        return "%s: not a folder (give the folder that holds the runs, sweeps and ensembles)" % root
    if os.path.exists(site) and not os.path.isdir(site):
        return "--out %s: a file is there, not a folder" % site
    if os.path.isdir(site) and os.listdir(site) and not os.path.isfile(os.path.join(site, manifest.NAME)):
        return "--out %s: a folder that is not empty and holds no atlas (no %s): pick a new or empty one" % (
            site, manifest.NAME)
    return ""


def main(argv=None):
    p = argparse.ArgumentParser(prog="orogen report", description="Build or update the results atlas: a static "
                                "web site of every run, sweep and ensemble under DIR (docs/atlas.md).")
    p.add_argument("dir", help="folder holding runs, sweeps and ensembles (searched at any depth)")
    p.add_argument("--out", help="site folder (default DIR/atlas); open SITE/index.html")
    try:
        a = p.parse_args(argv)
    except SystemExit as e:
        return 0 if e.code == 0 else 2
    site = a.out or os.path.join(a.dir, "atlas")
    error = check(a.dir, site)
    if error:
        print("error: " + error, file=sys.stderr)
        return 2
    try:
        return build.build(a.dir, site)
    except OSError as e:
        print("error: %s" % e, file=sys.stderr)
        return 1
