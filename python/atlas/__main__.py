"""Entry point: `/usr/bin/python3 python/atlas DIR --out SITE` (what `orogen report` runs) or
`python3 -m atlas` with python/ on the path."""
import os
import sys

if __package__ in (None, ""):  # run as a folder or a file: make `atlas` importable
    here = os.path.dirname(os.path.abspath(__file__))
    sys.path[:] = [p for p in sys.path if os.path.abspath(p or ".") != here]  # its modules only as atlas.*
    sys.path.insert(0, os.path.dirname(here))

from atlas.cli import main  # noqa: E402

sys.exit(main())
