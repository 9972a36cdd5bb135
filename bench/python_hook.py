#!/usr/bin/env python3
"""The cost of a Python hook: the main job (the default wedge) run by the CLI and by orogen.run
with a hook every N steps that reads the disc arrays, alternately, `--repeat` times each.

Times are the stepping times run.log reports ("finished ... in X s": set-up and start-up
excluded), so the difference is what the hook calls cost. The hook does what a typical rule
does: numpy reductions over views of x, y and radius (no copy), the experiment's scalars.

    PYTHONPATH=python /usr/bin/python3 bench/python_hook.py --s-end 1 --repeat 2 [--every 100] [--threads 1]

The main job itself is --s-end 8; a shorter one keeps the benchmark within minutes (the cost
per call does not depend on S, the stepping rate little). docs/performance.md has the figures.
"""

import argparse
import re
import shutil
import statistics
import subprocess
import tempfile
import time
from pathlib import Path

import numpy as np

import orogen

REPO = Path(__file__).resolve().parents[1]
FINISHED = re.compile(r"finished at step (\d+) .* in ([0-9.]+) s")


def stepping(run_dir):
    m = FINISHED.search((Path(run_dir) / "run.log").read_text())
    return int(m.group(1)), float(m.group(2))


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--s-end", type=float, default=1.0)
    p.add_argument("--every", type=int, default=100)
    p.add_argument("--repeat", type=int, default=2)
    p.add_argument("--threads", type=int, default=1)
    p.add_argument("--binary", default=str(REPO / "build" / "release" / "orogen"))
    args = p.parse_args()
    sets = {"wedge": {"s_end": args.s_end}, "output": {"progress": "never", "vtp": False}}
    calls, inside = [], [0.0]

    def hook(world):  # a typical rule's reads: views, reductions, the scalars
        t0 = time.perf_counter()
        calls.append(world.step)
        top = float(np.max(world.y + world.radius))
        world.scalars()
        inside[0] += time.perf_counter() - t0
        return top < 0  # never stops

    cli, py = [], []
    tmp = Path(tempfile.mkdtemp(prefix="orogen_bench_"))
    try:
        for k in range(args.repeat):
            a, b = tmp / f"cli{k}", tmp / f"py{k}"
            cmd = [args.binary, "run", "--out", str(a), "--threads", str(args.threads)]
            cmd += [x for o in orogen.config.overrides(sets) for x in ("--set", o)]
            subprocess.run(cmd, check=True, capture_output=True)
            cli.append(stepping(a))
            orogen.run(sets, out=b, hook=hook, every=args.every, threads=args.threads)
            py.append(stepping(b))
            assert (a / "series.csv").read_text() == (b / "series.csv").read_text()  # same bits
            print(f"repeat {k}: CLI {cli[-1][1]:.2f} s, Python hook every {args.every} steps {py[-1][1]:.2f} s "
                  f"({cli[-1][0]} steps)", flush=True)
    finally:
        shutil.rmtree(tmp)
    c, h = statistics.median(t for _, t in cli), statistics.median(t for _, t in py)
    print(f"median stepping time: CLI {c:.2f} s, with the hook {h:.2f} s: {100 * (h / c - 1):+.1f}% "
          f"({len(calls) // args.repeat} hook calls per run, threads {args.threads}); time inside the hook "
          f"{inside[0] / args.repeat:.3f} s per run ({1e6 * inside[0] / max(len(calls), 1):.0f} us per call)")


if __name__ == "__main__":
    main()
