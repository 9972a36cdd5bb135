#!/usr/bin/python3
"""Kill-at-random stress test: runs are killed (SIGKILL) at random moments, again and again
while they resume, and every one must end bit for bit equal to an uninterrupted run.

Each trial starts a small run that writes an output and a checkpoint every few hundred steps
(so that many kills land inside a write), kills it after a random delay, then resumes it with
`orogen run --resume`, killing the resumed process too with some probability, until a resume
finishes. The finished folder is compared with a reference run of the same configuration:
every file byte for byte (run.log and run.lock aside), HDF5 files by content (HDF5 stores
object time stamps, so their bytes differ between runs).

    /usr/bin/python3 tests/stress/kill_resume.py --binary build/release/orogen --trials 10
    /usr/bin/python3 tests/stress/kill_resume.py --binary build/release/orogen --trials 200 --seed 7  # before a release

Prints one line per failed trial and closes with 'N passed, M failed'; exit status 1 if any failed.
"""
import argparse
import os
import random
import shutil
import signal
import subprocess
import sys
import tempfile
import time

try:
    import h5py
    import numpy
except ImportError:  # pragma: no cover - Debian's python3-h5py is a dependency of the suite
    h5py = None

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))

# name -> the run's command-line arguments after `orogen run`
CASES = {
    "packing": [os.path.join(REPO, "examples", "packing_discs.toml"), "--set", "layer.length=20",
                "--set", "layer.thickness=6", "--set", "output.interval=0.5", "--set", "output.checkpoint_every=1"],
    "packing_sparse_checkpoints": [os.path.join(REPO, "examples", "packing_clusters.toml"), "--set", "layer.length=16",
                                   "--set", "layer.thickness=5", "--set", "output.interval=0.3",
                                   "--set", "output.checkpoint_every=4"],
    # With the contact and stress outputs on: a resumed run must store the same forces too.
    "wedge": ["--set", "wedge.s_end=0.12", "--set", "wedge.outputs=12", "--set", "output.checkpoint_every=2",
              "--set", "layer.length=60", "--set", "layer.thickness=6", "--set", "output.contacts=true",
              "--set", "output.stress=true", "--set", "output.stress_grid=2"],
    # Constant velocity: its pinning hook (after the forces of every step) is added again on
    # resume, and the pinned discs cross the checkpoint.
    "wedge_constant_velocity": ["--set", "wedge.basal=constant_velocity", "--set", "wedge.s_end=0.12",
                                "--set", "wedge.outputs=12", "--set", "output.checkpoint_every=1",
                                "--set", "layer.length=60", "--set", "layer.thickness=6"],
}

IGNORED = {"run.log", "run.lock"}


def run_files(folder):
    out = {}
    for root, _, files in os.walk(folder):
        for name in files:
            path = os.path.join(root, name)
            rel = os.path.relpath(path, folder)
            if rel not in IGNORED:
                out[rel] = path
    return out


def h5_content(path):
    """Everything a reader sees in an HDF5 file, following links, as a dict of bytes."""
    content = {}
    with h5py.File(path, "r") as f:
        def attrs(prefix, obj):
            for k, v in sorted(obj.attrs.items()):
                content[prefix + "@" + k] = repr(v).encode() if not isinstance(v, numpy.ndarray) else v.tobytes()

        def walk(prefix, group):
            # Output groups hold datasets and groups of their own (contacts, clusters, ...).
            for name in sorted(group.keys()):
                obj = group[name]
                if isinstance(obj, h5py.Dataset):
                    content[prefix + name] = obj[()].tobytes()
                    attrs(prefix + name + "@", obj)
                else:
                    attrs(prefix + name + "/", obj)
                    walk(prefix + name + "/", obj)

        attrs("/", f)
        walk("", f)
    return content


def differences(ref, got):
    a, b = run_files(ref), run_files(got)
    out = []
    for rel in sorted(set(a) | set(b)):
        if rel not in a or rel not in b:
            out.append("%s only in %s" % (rel, "the reference" if rel in a else "the killed run"))
            continue
        if rel.endswith(".h5"):
            if h5py is None:
                continue
            if h5_content(a[rel]) != h5_content(b[rel]):
                out.append(rel + " differs")
        else:
            with open(a[rel], "rb") as fa, open(b[rel], "rb") as fb:
                if fa.read() != fb.read():
                    out.append(rel + " differs")
    return out


def start(binary, args, env):
    return subprocess.Popen([binary, "run"] + args, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, env=env)


def run_to_end(binary, args, env, timeout):
    p = start(binary, args, env)
    _, err = p.communicate(timeout=timeout)
    return p.returncode, err.decode(errors="replace")


def trial(binary, case, folder, rng, ref_seconds, env, timeout):
    """Kills a run at random moments until a resume finishes; returns an error or None."""
    args = CASES[case] + ["--out", folder]
    kills = 0
    p = start(binary, args, env)
    while True:
        delay = rng.uniform(0.0, 1.1 * ref_seconds)
        try:
            _, err = p.communicate(timeout=delay)
            if p.returncode == 2 and b"has already finished" in err:
                return None  # the kill came after the run's last write
            if p.returncode != 0:
                return "exit %d after %d kill(s): %s" % (p.returncode, kills, err.decode(errors="replace").strip())
            return None
        except subprocess.TimeoutExpired:
            p.send_signal(signal.SIGKILL)
            p.communicate()
            kills += 1
        if not os.path.exists(os.path.join(folder, "config.toml")):
            p = start(binary, args, env)  # killed before it claimed the folder: start it again
            continue
        if kills >= 6:  # enough: let this resume finish
            code, err = run_to_end(binary, ["--resume", folder], env, timeout)
            return None if code == 0 or "has already finished" in err else "resume exit %d after %d kill(s): %s" % (code, kills, err.strip())
        p = start(binary, ["--resume", folder], env)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--binary", required=True)
    ap.add_argument("--trials", type=int, default=10, help="killed runs per case")
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--cases", default=",".join(CASES), help="comma-separated: " + ", ".join(CASES))
    ap.add_argument("--timeout", type=float, default=300, help="seconds a finishing resume may take")
    ap.add_argument("--keep-failures", help="copy failing run folders here")
    opt = ap.parse_args()
    if os.environ.get("OROGEN_TEST_SCALE") == "small":
        opt.trials = max(1, opt.trials // 3)

    env = dict(os.environ, OMP_NUM_THREADS="1", OMP_WAIT_POLICY="passive")
    rng = random.Random(opt.seed)
    passed = failed = 0
    root = tempfile.mkdtemp(prefix="orogen_kill_resume_")
    try:
        for case in opt.cases.split(","):
            ref = os.path.join(root, case + "_ref")
            t0 = time.monotonic()
            code, err = run_to_end(opt.binary, CASES[case] + ["--out", ref], env, opt.timeout)
            ref_seconds = time.monotonic() - t0
            if code != 0:
                print("FAIL %s: the reference run exited %d: %s" % (case, code, err.strip()))
                failed += 1
                continue
            for k in range(opt.trials):
                folder = os.path.join(root, "%s_%03d" % (case, k))
                why = trial(opt.binary, case, folder, rng, ref_seconds, env, opt.timeout)
                if why is None:
                    diff = differences(ref, folder)
                    why = "; ".join(diff[:5]) if diff else None
                if why is None:
                    passed += 1
                    shutil.rmtree(folder)
                else:
                    failed += 1
                    print("FAIL %s trial %d: %s" % (case, k, why))
                    if opt.keep_failures:
                        shutil.copytree(folder, os.path.join(opt.keep_failures, os.path.basename(folder)))
    finally:
        shutil.rmtree(root, ignore_errors=True)
    print("%d passed, %d failed" % (passed, failed))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
