#!/usr/bin/python3
"""Fuzz test of the `orogen` command line (standard library only).

From a fixed seed, generates mutated configurations (the TOML files in examples/ and the
default `orogen config`) and odd command lines (run, render, sweep, config, unknown ones), runs
the binary on each in its own temporary folder, and checks that it:

  - ends with exit code 0, 2 or 3 (1 only where the case expects an I/O failure or a sweep
    member's failure) and never by a signal of its own;
  - never prints "terminate called", "Sanitizer" or "runtime error";
  - names a configuration key (section.key), a file path or a command-line argument in every
    exit-2 refusal.

Every case is kept short: tiny sizes and ends are forced with --set (except for the key under
test), and a case still running after --timeout seconds is killed by the harness and counted
as "ran" (a timeout never hides a signal the program got by itself: only our kill is excused).

Case i depends only on (seed, i), so a failure is reproduced by the same --seed alone, whatever
--jobs or --count. Prints one line per failure and closes with "N passed, M failed".
See docs/testing.md.
"""

import argparse
import concurrent.futures
import os
import random
import re
import resource
import shlex
import shutil
import signal
import subprocess
import sys
import tempfile

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
EXAMPLES = os.path.join(REPO, "examples")
BAD_OUTPUT = ("terminate called", "Sanitizer", "runtime error")
OUTPUT_CAP = 64 * 1024  # bytes of each stream kept for the checks

# Forced onto every run so it ends within a second or two; the mutated key keeps its value.
TINY = {
    "run.threads": "1",
    "layer.length": "10",
    "layer.thickness": "3",
    "contact.kn": "1000",
    "settle.relax_time": "1",
    "settle.ke_threshold": "1e-3",
    "settle.max_time": "60",
    "wedge.s_end": "0.02",
    "wedge.outputs": "2",
    "repose.size": "8",
    "repose.min_time": "0",
    "repose.max_time": "5",
    "singly.shortening": "0.05",
    "singly.outputs": "1",
    "biaxial.width": "6",
    "biaxial.height": "6",
    "biaxial.strain_end": "0.002",
    "biaxial.outputs": "6",
    "output.interval": "5",
    "output.vtp": "false",
    "output.progress": "never",
}

HUGE = "x" * 100000
EXTREMES = [
    "0", "-1", "1e-300", "1e300", "-1e300", "nan", "inf", "-inf", "+inf", "-0.0",
    str(2**31), str(2**31 - 1), str(-2**31), str(2**32), str(2**63 - 1), str(-2**63), str(2**63), str(2**64),
    "1e19", "-1e19", "4.9e-324", "0.5", "3", "true", "false", '""', '"x"', '"' + HUGE + '"', "[]", "[1, 2]",
    "{}", "{ a = 1 }", "1979-05-27T07:32:00Z", "'literal'", '"\\u0000"', '"random_discs"', '"wedge"', "0x7fffffff",
    "0b1", "1_000", "1.", ".5", "++1", "1e", '"\xff"',
]

# Characters dropped into a file to break its syntax.
SYNTAX_JUNK = ["[", "]", "=", '"', "'", "{", "}", ",", "\n", "\x00", "\\", "#", "[[", "]]", "\xff", "\t=", "."]


def words(text):
    return text.split()


class Case:
    """One generated case: files to write, an argv after the binary, what exit 1 means here."""

    def __init__(self, index, kind):
        self.index = index
        self.kind = kind
        self.files = {}        # relative path -> bytes
        self.argv = []
        self.allow_exit1 = False
        self.setup = None      # callable(case_dir) for cases needing a real run folder
        self.env = {}          # extra environment variables of the case
        self.expect = None     # the exit status the case must end with, where it is known
        self.after = None      # callable(case_dir) -> failure text or None, checked after the run
        self.note = ""

    def command_line(self, binary):
        return " ".join(shlex.quote(a) for a in [binary] + self.argv)


# ---------------------------------------------------------------- configuration mutations

KEY_LINE = re.compile(r"^\s*([A-Za-z0-9_\"'.-]+)\s*=\s*(.*)$")
SECTION_LINE = re.compile(r"^\s*\[([^\]]*)\]\s*$")


def parse_keys(text):
    """(line index, section.key) of every `key = value` line of a simple TOML file."""
    section, keys = "", []
    for i, line in enumerate(text.split("\n")):
        m = SECTION_LINE.match(line)
        if m:
            section = m.group(1).strip()
            continue
        m = KEY_LINE.match(line)
        if m and not line.lstrip().startswith("#"):
            keys.append((i, (section + "." if section else "") + m.group(1)))
    return keys


def mutate_config(rng, text, default_keys):
    """Mutates a TOML text; returns (new text, the keys the mutation touched)."""
    lines = text.split("\n")
    touched = []
    for _ in range(rng.choice([1, 1, 1, 2, 3])):
        lines = "\n".join(lines).split("\n")  # earlier steps may have cut or joined lines
        keys = parse_keys("\n".join(lines))
        # Mostly values that parse, so that the checks behind the parser are reached too.
        op = rng.choices(["extreme", "add_key", "drop", "duplicate", "unknown_key", "unknown_section", "syntax",
                          "nesting", "truncate", "wrong_section", "binary"],
                         weights=[30, 20, 5, 3, 4, 3, 4, 3, 3, 2, 2])[0]
        if op in ("extreme", "drop", "duplicate") and keys:
            i, key = rng.choice(keys)
            touched.append(key)
            if op == "extreme":
                name = lines[i].split("=", 1)[0]
                lines[i] = name + "= " + rng.choice(EXTREMES)
            elif op == "drop":
                lines[i] = ""
            else:
                lines.insert(i + 1, lines[i])
        elif op == "add_key":
            # A known key (perhaps of another section) with an extreme value, appended in its table.
            key = rng.choice(default_keys)
            touched.append(key)
            section, name = key.split(".", 1)
            line = name + " = " + rng.choice(EXTREMES)
            header = next((j for j, l in enumerate(lines) if l.strip() == "[" + section + "]"), None)
            if header is None:
                lines += ["", "[" + section + "]", line]
            else:
                # In its table, the key's own line (if any) replaced: a second one would be a syntax error.
                own = [j for j, k in parse_keys("\n".join(lines)) if k == key]
                if own:
                    lines[own[0]] = line
                else:
                    lines.insert(header + 1, line)
        elif op == "unknown_key":
            section = rng.choice(["run", "layer", "contact", "wedge", "output", "nosuch"])
            lines += ["[" + section + "]", rng.choice(["mu", "speeed", "x", "threads2", "a.b", '"q.r"']) + " = 1"]
        elif op == "unknown_section":
            lines += ["[" + rng.choice(["nosuch", "run.sub", "wedge.deep.er", "", " ", "a b"]) + "]", "k = 1"]
        elif op == "wrong_section":
            lines.insert(rng.randrange(len(lines) + 1), rng.choice(["[[run]]", "[run]\n[run]", "[contact]\n[contact]"]))
        elif op == "syntax":
            at = rng.randrange(len(lines))
            col = rng.randrange(len(lines[at]) + 1)
            lines[at] = lines[at][:col] + rng.choice(SYNTAX_JUNK) + lines[at][col:]
        elif op == "nesting":
            depth = rng.choice([10, 100, 1000, 100000])
            form = rng.choice(["array", "table", "header"])
            if form == "array":
                lines.append("deep = " + "[" * depth + "1" + "]" * depth)
            elif form == "table":
                lines.append("deep = " + "{a = " * depth + "1" + "}" * depth)
            else:
                lines.append("[" + ".".join(["a"] * min(depth, 20000)) + "]")
        elif op == "truncate":
            joined = "\n".join(lines)
            lines = joined[: rng.randrange(len(joined) + 1)].split("\n")
        elif op == "binary":
            lines.insert(rng.randrange(len(lines) + 1), "".join(chr(rng.randrange(256)) for _ in range(40)))
    return "\n".join(lines), touched


def tiny_overrides(rng, skip):
    """--set arguments that keep a run short, minus the keys under test."""
    argv = []
    for key, value in TINY.items():
        if key in skip:
            continue
        argv += ["--set", key + "=" + value]
    return argv


def config_case(rng, case, sources, default_keys):
    name, text = rng.choice(sources)
    mutated, touched = mutate_config(rng, text, default_keys)
    case.files["case.toml"] = mutated.encode("utf-8", "surrogateescape")
    case.argv = ["run", "case.toml"] + tiny_overrides(rng, set(touched)) + ["--threads", "1", "--out", "out"]
    case.note = "mutated " + name + (" (" + ", ".join(touched) + ")" if touched else "")


def set_case(rng, case, default_keys):
    """Extreme values through --set instead of a file, and malformed --set arguments."""
    key = rng.choice(default_keys)
    form = rng.choice(["value", "value", "value", "no_equals", "empty_key", "empty_value", "unknown", "section_only",
                       "spaces", "dup"])
    value = rng.choice(EXTREMES)
    if form == "value":
        arg = key + "=" + value
    elif form == "no_equals":
        arg = key
    elif form == "empty_key":
        arg = "=" + value
    elif form == "empty_value":
        arg = key + "="
    elif form == "unknown":
        arg = key + "x=" + value
    elif form == "section_only":
        arg = key.split(".")[0] + "=" + value
    elif form == "spaces":
        arg = " " + key + " = " + value + " "
    else:
        arg = key + "=" + value
    argv = ["run"]
    if rng.random() < 0.5:
        name = rng.choice(sorted(f for f in os.listdir(EXAMPLES) if f.endswith(".toml")))
        argv.append(os.path.join(EXAMPLES, name))
    argv += tiny_overrides(rng, {key}) + ["--set", arg]
    if form == "dup":
        argv += ["--set", key + "=" + rng.choice(EXTREMES)]
    case.argv = argv + ["--threads", "1", "--out", "out"]
    case.note = "--set " + arg[:60]


def file_case(rng, case):
    """Config files that are not TOML text: missing, a folder, empty, binary, /dev/zero-like."""
    form = rng.choice(["missing", "folder", "empty", "binary", "devnull", "devzero", "huge_line", "bom"])
    path = "case.toml"
    if form == "missing":
        path = "nosuch.toml"
    elif form == "folder":
        case.files["adir/x"] = b""
        path = "adir"
    elif form == "empty":
        case.files[path] = b""
    elif form == "binary":
        case.files[path] = bytes(rng.randrange(256) for _ in range(rng.choice([1, 100, 5000])))
    elif form == "devnull":
        path = "/dev/null"
    elif form == "devzero":
        path = "/dev/zero"  # endless: must be refused, not read until memory runs out
    elif form == "huge_line":
        case.files[path] = b"[run]\nexperiment = \"" + b"w" * 1000000 + b"\"\n"
    else:
        case.files[path] = b"\xef\xbb\xbf[run]\nexperiment = \"packing\"\n"
    case.argv = ["run", path] + tiny_overrides(rng, set()) + ["--threads", "1", "--out", "out"]
    case.note = "config file " + form


# ---------------------------------------------------------------- command-line mutations

ODD_NUMBERS = ["0", "-1", "1", "2", "3", "64", "1000000", "2147483647", "2147483648", "4294967296",
               "9223372036854775808", "-2147483649", "1.5", "abc", "", " ", "nan", "inf", "0x10", "1e3", "--"]


def cli_case(rng, case):
    form = rng.choice(["threads", "threads", "unknown_sub", "unknown_opt", "no_sub", "out_odd", "resume_odd",
                       "version", "help", "garbage"])
    base = ["run"] + tiny_overrides(rng, set()) + ["--set", "run.experiment=packing"]
    if form == "threads":
        case.argv = base + ["--threads", rng.choice(ODD_NUMBERS), "--out", "out"]
    elif form == "unknown_sub":
        case.argv = [rng.choice(["runn", "Run", "render2", "sweeps", "", "-", "help", "configs"])]
    elif form == "unknown_opt":
        sub = rng.choice(["run", "render", "sweep", "config"])
        case.argv = [sub, rng.choice(["--nosuch", "-x", "--out=", "--set", "--threads", "---", "--color"])]
    elif form == "no_sub":
        case.argv = []
    elif form == "out_odd":
        # An output folder that cannot be made: an existing file in the way is an I/O failure.
        case.files["afile"] = b"x"
        out = rng.choice(["afile", "afile/sub", "", "/proc/orogen_fuzz_out"])
        case.argv = base + ["--threads", "1", "--out", out]
        case.allow_exit1 = True
    elif form == "resume_odd":
        case.files["empty/.keep"] = b""
        case.argv = ["run", "--resume", rng.choice(["nosuch", "empty", "", "/"]), "--threads", "1"]
        case.allow_exit1 = True
    elif form == "version":
        case.argv = ["--version"]
    elif form == "help":
        case.argv = [rng.choice(["run", "render", "sweep", "config"]), "--help"]
    else:
        case.argv = ["".join(chr(rng.randrange(33, 127)) for _ in range(rng.randrange(1, 30)))
                     for _ in range(rng.randrange(1, 5))]
    case.note = "command line " + form


def config_command_case(rng, case):
    case.argv = ["config"] + rng.choice([[], ["--markdown"], ["--markdown", "--markdown"], ["extra"], ["--json"],
                                         ["--markdown=1"]])
    case.note = "config subcommand"


def render_case(rng, case, base_run):
    """`orogen render` on a copy of a real run, with odd options or a damaged snapshot file."""
    opts = []
    for _ in range(rng.randrange(0, 3)):
        opt = rng.choice(["--width", "--fps", "--every", "--vector-stride", "--vector-scale", "--color", "--frames-dir"])
        if opt == "--color":
            value = rng.choice(["horizons", "cluster", "field:NOPE", "field:", "bogus", "", "field:x", "field:radius"])
        elif opt == "--frames-dir":
            value = rng.choice(["f2", "", "..", "../up", "/tmp/orogen_fuzz_frames", "a/b", ".", "snapshots.h5"])
        elif opt == "--vector-scale":
            value = rng.choice(["1", "0", "-1", "1e300", "nan", "inf", "1e-300", "2"])
        else:
            value = rng.choice(ODD_NUMBERS + ["200", "400", "16384", "16385"])
        opts += [opt, value]
    if rng.random() < 0.2:
        opts.append("--vectors")
    damage = rng.choice(["none", "none", "none", "truncate", "flip", "empty", "text", "missing", "no_dir", "file"])
    target = "run"

    def setup(case_dir):
        run = os.path.join(case_dir, "run")
        shutil.copytree(base_run, run)
        h5 = os.path.join(run, "snapshots.h5")
        data = open(h5, "rb").read()
        if damage == "truncate":
            data = data[: rng.randrange(len(data))]
        elif damage == "flip":
            data = bytearray(data)
            at = rng.randrange(len(data))
            for k in range(at, min(len(data), at + rng.choice([1, 8, 64]))):
                data[k] ^= 0xFF
            data = bytes(data)
        elif damage == "empty":
            data = b""
        elif damage == "text":
            data = b"[run]\nexperiment = \"wedge\"\n"
        if damage == "missing":
            os.remove(h5)
        else:
            with open(h5, "wb") as f:
                f.write(data)

    case.setup = setup
    case.allow_exit1 = damage in ("truncate", "flip", "empty", "text")  # a damaged file is I/O: exit 1
    if damage == "no_dir":
        target = "nosuch"
    elif damage == "file":
        case.files["afile"] = b"x"
        target = "afile"
    case.argv = ["render", target, "--no-animation"] + opts
    case.note = "render (" + damage + ") " + " ".join(opts)


def folder_digest(folder):
    """Every file under `folder` with its bytes: what a refusal must leave as it was."""
    out = {}
    for top, _, files in os.walk(folder):
        for name in files:
            path = os.path.join(top, name)
            with open(path, "rb") as f:
                out[os.path.relpath(path, folder)] = f.read()
    return out


def unchanged_after(case, folder_name):
    """Records the folder's files at set-up (after `prepare`) and checks them after the run."""
    before = {}

    def record(case_dir):
        before.update(folder_digest(os.path.join(case_dir, folder_name)))

    def check_after(case_dir):
        after = folder_digest(os.path.join(case_dir, folder_name))
        changed = sorted(set(before) ^ set(after) | {k for k in before if k in after and before[k] != after[k]})
        return "the refusal changed %s: %s" % (folder_name, ", ".join(changed[:5])) if changed else None

    case.after = check_after
    return record


def mixed_case(rng, case, bases):
    """A stopped run with one file of another run (another seed) copied in: --resume must refuse
    it (exit 2, naming the file) and change nothing."""
    # The stopped run's checkpoint keeps outputs 0 and 1 (output 2 came after it and is written again).
    foreign = rng.choice(["snapshots/output_000000.h5", "snapshots/output_000001.h5", "series.csv", "removals.csv",
                          "vtp/output_000001.vtp"])
    record = unchanged_after(case, "run")

    def setup(case_dir):
        run = os.path.join(case_dir, "run")
        shutil.copytree(bases["stopped"], run)
        source = os.path.join(bases["other"], foreign)
        if foreign == "removals.csv":
            # The other run's removals, dated before the checkpoint: rows this run never wrote.
            rows = [l for l in open(source).read().split("\n") if l and not l.startswith("#")]
            body = [",".join(["1"] + r.split(",")[1:]) for r in rows[1:]] or ["1,0.001,0,-1,0.5,0.5,other"]
            with open(os.path.join(run, foreign), "w") as f:
                f.write("# foreign\n" + rows[0] + "\n" + "\n".join(body) + "\n")
        else:
            shutil.copyfile(source, os.path.join(run, foreign))
        record(case_dir)

    case.setup = setup
    case.argv = ["run", "--resume", "run"] + rng.choice([[], ["--set", "output.progress=never"], ["--threads", "1"]])
    case.expect = 2
    case.note = "resume with a foreign " + foreign


def export_into_case(rng, case, bases):
    """`orogen export` (or render, report) with a target among a run's own files: refused (exit 2)
    and the run left as it was."""
    record = unchanged_after(case, "run")
    case.setup = lambda case_dir: (shutil.copytree(bases["finished"], os.path.join(case_dir, "run")),
                                   record(case_dir))
    target = rng.choice(["run/snapshots.h5", "run/checkpoint.bin", "run/snapshots/output_000001.h5", "run/series.csv",
                         "run/config.toml", "run/removals.csv", "run/run.lock", "run/vtp/output_000000.vtp",
                         "run/analysis.h5", "run", "run/./series.csv", "run/snapshots/../series.csv"])
    form = rng.choice(["export", "export", "export", "render", "report"])
    if form == "export":
        case.argv = ["export", "run", "--format", rng.choice(["csv", "xyz", "lammps-data", "lammps-dump"]),
                     "--to", target]
    elif form == "render":
        case.argv = ["render", "run", "--no-animation", "--frames-dir",
                     rng.choice(["snapshots", "vtp", "series.csv", "config.toml", "analysis.h5"])]
    else:
        case.argv = ["report", ".", "--out", target]
    case.expect = 2
    case.note = " ".join(case.argv)


def omp_case(rng, case):
    """A tiny run under odd OpenMP settings: a bad one is refused (exit 2) before anything is
    written, a good one runs; neither may end by a signal of libgomp's."""
    name = rng.choice(["OMP_NUM_THREADS", "OMP_NUM_THREADS", "OMP_NUM_THREADS", "OMP_PROC_BIND", "OMP_WAIT_POLICY",
                       "OMP_DYNAMIC", "OMP_STACKSIZE", "OMP_THREAD_LIMIT", "GOMP_SPINCOUNT"])
    good = {"OMP_NUM_THREADS": ["1", "2", "2,1", " 2 "], "OMP_PROC_BIND": ["true", "close", "spread,close"],
            "OMP_WAIT_POLICY": ["passive", "ACTIVE"], "OMP_DYNAMIC": ["false", "TRUE"],
            "OMP_STACKSIZE": ["8M", "512k", "1048576"], "OMP_THREAD_LIMIT": ["4"], "GOMP_SPINCOUNT": ["0", "10k", "infinite"]}
    bad = {"OMP_NUM_THREADS": ["100000", "60000", "1025", "20000", "abc", "0", "-1", "1e3", "1.5", "", "2,,1", "2,0"],
           "OMP_PROC_BIND": ["sideways", "x", "", "1"], "OMP_WAIT_POLICY": ["lazy", "", "1"],
           "OMP_DYNAMIC": ["x", "-1", "", "yes"], "OMP_STACKSIZE": ["big", "-1", "", "1.5M", "8X"],
           "OMP_THREAD_LIMIT": ["0", "-1", "abc", ""], "GOMP_SPINCOUNT": ["abc", "-1", "", "1.5"]}
    value = rng.choice(good[name] + bad[name])
    case.env = {name: value}
    if value in bad[name]:
        case.expect = 2
    case.argv = ["run", "--set", "run.experiment=packing"] + [a for k, v in TINY.items() if k != "run.threads"
                                                              for a in ("--set", k + "=" + v)] + ["--out", "out"]
    case.note = "%s=%r" % (name, value)


def sweep_case(rng, case, base_toml, default_keys):
    """`orogen sweep` of up to three tiny runs, with odd matrices and arguments."""
    key = rng.choice(["contact.mu", "contact.mu", "settle.mu", "run.seed", "contact.kn", "nosuch.key", "layer"]
                     + default_keys)
    # Mostly values a run takes, so that members run (and some fail: kn = 3 is unstable).
    values = rng.sample(["0.1", "0.2", "0.3", "1", "2", "3"], rng.choice([1, 2, 3]))
    if rng.random() < 0.4:
        values[rng.randrange(len(values))] = rng.choice(EXTREMES[:20])
    form = rng.choice(["matrix", "matrix", "set", "bad_base", "junk", "empty"])
    case.files["base.toml"] = base_toml.encode()
    if form == "matrix":
        text = '[sweep]\nbase = "base.toml"\n[matrix]\n"%s" = [%s]\n' % (key, ", ".join(values))
    elif form == "set":
        text = '[sweep]\nbase = "base.toml"\n[set]\n"%s" = %s\n' % (key, values[0])
    elif form == "bad_base":
        text = '[sweep]\nbase = "%s"\n' % rng.choice(["nosuch.toml", "", "/dev/null", ".", "s.toml"])
    elif form == "junk":
        text, _ = mutate_config(rng, '[sweep]\nbase = "base.toml"\n[matrix]\n"contact.mu" = [0.1, 0.3]\n', default_keys)
    else:
        text = ""
    case.files["s.toml"] = text.encode("utf-8", "surrogateescape")
    extra = rng.choice([[], ["--jobs", rng.choice(ODD_NUMBERS)], ["--threads", rng.choice(ODD_NUMBERS)], ["--dry-run"]])
    case.argv = ["sweep", "s.toml", "--out", rng.choice(["sw", "sw", "", "s.toml"])] + extra
    case.allow_exit1 = True  # a member that failed, or an --out that is a file
    case.note = "sweep " + form + " " + key


def ensemble_case(rng, case, base_toml, default_keys):
    """`orogen ensemble` of up to three tiny members, with odd seeds, overrides and members."""
    key = rng.choice(["contact.mu", "settle.mu", "contact.kn", "run.seed", "nosuch.key", "layer"] + default_keys)
    seeds = rng.sample(["1", "2", "3", "4"], rng.choice([1, 2, 3]))
    if rng.random() < 0.3:
        seeds[rng.randrange(len(seeds))] = rng.choice(EXTREMES[:20])
    form = rng.choice(["seeds", "seeds", "set", "members", "duplicate", "bad_preset", "junk", "empty"])
    case.files["base.toml"] = base_toml.encode()
    head = '[ensemble]\npreset = "base.toml"\n'
    if form == "seeds":
        text = head + "seeds = [%s]\n" % ", ".join(seeds)
    elif form == "set":
        text = head + 'seeds = [1, 2]\n[ensemble.set]\n"%s" = %s\n' % (key, rng.choice(["0.2", "3"] + EXTREMES[:20]))
    elif form == "members":
        text = head + '[[member]]\nname = "a"\n[[member]]\nname = "b"\nset = { "%s" = %s }\n' % (
            key, rng.choice(["0.2", "1"] + EXTREMES[:20]))
    elif form == "duplicate":
        text = head + '[[member]]\nname = "a"\n[[member]]\nname = "a"\n'
    elif form == "bad_preset":
        text = '[ensemble]\npreset = "%s"\nseeds = [1]\n' % rng.choice(["nosuch.toml", "", "/dev/null", ".", "e.toml"])
    elif form == "junk":
        text, _ = mutate_config(rng, head + "seeds = [1, 2]\n", default_keys)
    else:
        text = ""
    case.files["e.toml"] = text.encode("utf-8", "surrogateescape")
    extra = rng.choice([[], ["--jobs", rng.choice(ODD_NUMBERS)], ["--threads", rng.choice(ODD_NUMBERS)],
                        ["--dry-run"], ["--dry-run"]])
    case.argv = ["ensemble", "e.toml", "--out", rng.choice(["en", "en", "", "e.toml"])] + extra
    case.allow_exit1 = True  # a member that failed, or an --out that is a file
    case.note = "ensemble " + form + " " + key


def sweep_base_toml():
    lines = ["[run]", 'experiment = "packing"', "threads = 1"]
    section = None
    for key, value in TINY.items():
        sec, name = key.split(".", 1)
        if sec in ("run", "wedge", "repose", "singly", "biaxial"):
            continue
        if sec != section:
            lines.append("[" + sec + "]")
            section = sec
        lines.append(name + " = " + (value if value in ("true", "false") or value[0].isdigit() else '"%s"' % value))
    return "\n".join(lines) + "\n"


def generate(seed, index, sources, default_keys, bases, base_toml):
    rng = random.Random("%d:%d" % (seed, index))
    kind = rng.choices(["config", "set", "file", "cli", "configcmd", "render", "sweep", "ensemble", "mixed", "export",
                        "omp"],
                       weights=[40, 18, 5, 10, 2, 15, 10, 6, 6, 4, 5])[0]
    case = Case(index, kind)
    if kind == "config":
        config_case(rng, case, sources, default_keys)
    elif kind == "set":
        set_case(rng, case, default_keys)
    elif kind == "file":
        file_case(rng, case)
    elif kind == "cli":
        cli_case(rng, case)
    elif kind == "configcmd":
        config_command_case(rng, case)
    elif kind == "render":
        render_case(rng, case, bases["finished"])
    elif kind == "mixed":
        mixed_case(rng, case, bases)
    elif kind == "export":
        export_into_case(rng, case, bases)
    elif kind == "omp":
        omp_case(rng, case)
    elif kind == "ensemble":
        ensemble_case(rng, case, base_toml, default_keys)
    else:
        sweep_case(rng, case, base_toml, default_keys)
    return case


# ---------------------------------------------------------------- running and checking

NAMES_KEY = re.compile(r"\b[a-z_][a-z0-9_]*\.[a-z_][a-z0-9_]*\b")


def names_something(err, case, case_dir):
    """Whether an exit-2 message names a key, a file path or a command-line argument."""
    if NAMES_KEY.search(err) or "/" in err or any(name in err for name in case.env):
        return True
    if re.search(r"^(--?[\w-]+|\w+) is required", err, re.M):
        return True  # CLI11 naming a missing option or positional argument ("file is required")
    for path in list(case.files) + [case_dir]:
        if path.split("/")[0] and path.split("/")[0] in err:
            return True
    for arg in case.argv:
        token = arg.split("=", 1)[0].strip()
        if (len(token) >= 2 and token in err) or (len(arg) >= 2 and arg in err) or ("'%s'" % arg) in err:
            return True
    return False


def read_capped(path):
    with open(path, "rb") as f:
        data = f.read(OUTPUT_CAP)
        f.seek(0, os.SEEK_END)
        size = f.tell()
        if size > 2 * OUTPUT_CAP:
            f.seek(size - OUTPUT_CAP)
            data += b"\n...\n" + f.read()
        elif size > OUTPUT_CAP:
            f.seek(OUTPUT_CAP)
            data += f.read()
    return data.decode("utf-8", "replace")


def sanitized(binary):
    """Whether the binary was built with AddressSanitizer (which needs terabytes of address space)."""
    with open(binary, "rb") as f:
        data = f.read()
    return b"__asan_init" in data or b"AddressSanitizer" in data  # libasan linked dynamically, or static


def run_case(case, binary, root, timeout, memory_mb):
    """Runs one case; returns (case, failure text or None, timed out)."""
    case_dir = os.path.join(root, "case_%06d" % case.index)
    os.makedirs(case_dir)
    for rel, data in case.files.items():
        path = os.path.join(case_dir, rel)
        os.makedirs(os.path.dirname(path), exist_ok=True)
        with open(path, "wb") as f:
            f.write(data)
    if case.setup:
        case.setup(case_dir)
    env = dict(os.environ, OMP_NUM_THREADS="1", OMP_WAIT_POLICY="passive")
    env.update(case.env)
    out_path, err_path = os.path.join(root, "out_%06d" % case.index), os.path.join(root, "err_%06d" % case.index)
    timed_out = False
    with open(out_path, "wb") as out, open(err_path, "wb") as err:
        # A session of its own, so a timeout kills the whole group (a sweep's runs, ffmpeg).
        proc = subprocess.Popen([binary] + case.argv, cwd=case_dir, stdin=subprocess.DEVNULL, stdout=out, stderr=err,
                                env=env, start_new_session=True)
        if memory_mb:
            # An input that makes orogen allocate without end (/dev/zero as config) must fail inside
            # it, visibly, not take the machine's memory during the timeout.
            limit = memory_mb << 20
            try:
                resource.prlimit(proc.pid, resource.RLIMIT_AS, (limit, limit))
            except (ProcessLookupError, PermissionError):
                pass
        try:
            status = proc.wait(timeout=timeout)
        except subprocess.TimeoutExpired:
            timed_out = True
            try:
                os.killpg(proc.pid, signal.SIGKILL)
            except ProcessLookupError:
                pass
            status = proc.wait()
    stdout, stderr = read_capped(out_path), read_capped(err_path)
    os.remove(out_path)
    os.remove(err_path)
    failure = check(case, case_dir, status, stdout, stderr, timed_out)
    if failure is None and case.after and not timed_out:
        failure = case.after(case_dir)
    return case, failure, timed_out, stderr, status


def check(case, case_dir, status, stdout, stderr, timed_out):
    both = stdout + stderr
    for bad in BAD_OUTPUT:
        if bad in both:
            line = next((l for l in both.split("\n") if bad in l), bad)
            return "printed %r: %s" % (bad, line.strip()[:200])
    if timed_out:
        # Our SIGKILL is excused; any other ending during the wait was seen as status above.
        return None if status == -signal.SIGKILL else "ended by signal %d after the timeout" % -status
    if status < 0:
        return "killed by signal %d (%s)" % (-status, signal.Signals(-status).name)
    allowed = {case.expect} if case.expect is not None else {0, 2, 3} | ({1} if case.allow_exit1 else set())
    if status not in allowed:
        last = [l for l in stderr.strip().split("\n") if l.strip()]
        return "exit %d (allowed %s): %s" % (status, sorted(allowed), (last[-1] if last else "")[:200])
    if status == 2 and not case.argv and "subcommand" in stderr:
        return None  # nothing given: naming the missing subcommand is all there is to say
    if status == 2 and not names_something(stderr, case, case_dir):
        return "exit 2 message names no key, file or argument: %s" % stderr.strip()[:200]
    return None


def keep_failure(keep_dir, root, case, binary, failure, stderr):
    dest = os.path.join(keep_dir, "case_%06d" % case.index)
    shutil.rmtree(dest, ignore_errors=True)
    src = os.path.join(root, "case_%06d" % case.index)
    # The inputs only (configs, sweep files); outputs of a run can be large.
    os.makedirs(dest, exist_ok=True)
    for rel, data in case.files.items():
        path = os.path.join(dest, rel)
        os.makedirs(os.path.dirname(path), exist_ok=True)
        with open(path, "wb") as f:
            f.write(data)
    if case.setup and os.path.exists(os.path.join(src, "run")):
        shutil.copytree(os.path.join(src, "run"), os.path.join(dest, "run"), dirs_exist_ok=True)
    with open(os.path.join(dest, "command.txt"), "w") as f:
        f.write("cd %s && %s\n# %s\n# %s\n\n%s\n" % (shlex.quote(dest), case.command_line(binary), case.note, failure,
                                                     stderr[-4000:]))


def make_base_runs(binary, root, timeout):
    """Tiny runs for the cases to copy: a finished one (render, export), one stopped after three
    outputs with a checkpoint at each, and a finished one of another seed (the mixed folders)."""
    def make(name, extra, status=0):
        run = os.path.join(root, name)
        argv = [binary, "run", "--set", "run.experiment=packing", "--set", "particles.packing=random_discs"]
        for key, value in TINY.items():
            argv += ["--set", key + "=" + value]
        argv += ["--set", "output.interval=2", "--set", "output.vtp=true", "--set", "output.checkpoint_every=1",
                 "--threads", "1", "--out", run] + extra
        env = dict(os.environ, OMP_NUM_THREADS="1", OMP_WAIT_POLICY="passive")
        r = subprocess.run(argv, stdin=subprocess.DEVNULL, capture_output=True, env=env, timeout=max(60, 6 * timeout))
        if r.returncode != status:
            sys.exit("fuzz_cli: cannot make the base run: %s\n%s" % (" ".join(argv), r.stderr.decode(errors="replace")))
        return run
    return {"finished": make("base_run", []), "stopped": make("stopped_run", ["--abort-after-outputs", "3"], 137),
            "other": make("other_run", ["--set", "run.seed=2"])}


def load_sources(binary):
    sources = []
    for name in sorted(os.listdir(EXAMPLES)):
        if name.endswith(".toml"):
            with open(os.path.join(EXAMPLES, name), encoding="utf-8") as f:
                sources.append((name, f.read()))
    r = subprocess.run([binary, "config"], stdin=subprocess.DEVNULL, capture_output=True, timeout=60)
    if r.returncode != 0:
        sys.exit("fuzz_cli: `orogen config` failed: " + r.stderr.decode(errors="replace"))
    default = r.stdout.decode()
    sources.append(("default config", default))
    default_keys = sorted(set(k for _, k in parse_keys(default)))
    return sources, default_keys


def main():
    parser = argparse.ArgumentParser(description="Fuzz the orogen command line (docs/testing.md).")
    parser.add_argument("--count", type=int, default=300, help="cases to run (default 300; a quarter of it with "
                        "OROGEN_TEST_SCALE=small, as the sanitizer build sets)")
    parser.add_argument("--seed", type=int, default=1, help="seed: case i depends only on (seed, i)")
    parser.add_argument("--binary", default=os.path.join(REPO, "build", "release", "orogen"), help="the orogen binary")
    parser.add_argument("--timeout", type=float, default=10.0, help="seconds per case before the harness kills it")
    parser.add_argument("--jobs", type=int, default=2, help="cases at once")
    parser.add_argument("--keep-failures", metavar="DIR", help="copy failing cases' inputs and command lines here")
    parser.add_argument("--memory-mb", type=int, default=4096, help="memory limit of each case in MiB (0: "
                        "none): its address space, or for a sanitizer build ASan's hard_rss_limit_mb")
    parser.add_argument("--verbose", action="store_true", help="also list the cases killed at the timeout")
    parser.add_argument("--first", type=int, default=0, help="index of the first case (to rerun one: --first I --count 1)")
    args = parser.parse_args()
    if args.count < 0 or args.jobs < 1 or not args.timeout > 0:
        parser.error("--count must be >= 0, --jobs >= 1, --timeout > 0")
    binary = os.path.abspath(args.binary)
    if not os.access(binary, os.X_OK):
        parser.error("--binary %s: not an executable file" % binary)
    count = args.count
    if os.environ.get("OROGEN_TEST_SCALE") == "small":
        count = max(1, count // 4)  # the sanitizer build is ~3x slower

    root = tempfile.mkdtemp(prefix="orogen_fuzz_")
    try:
        sources, default_keys = load_sources(binary)
        bases = make_base_runs(binary, root, args.timeout)
        base_toml = sweep_base_toml()
        cases = [generate(args.seed, i, sources, default_keys, bases, base_toml)
                 for i in range(args.first, args.first + count)]
        failed = passed = timeouts = 0
        endings = {}  # kind -> exit status -> cases: shows whether the mutations get past the checks
        with concurrent.futures.ThreadPoolExecutor(max_workers=args.jobs) as pool:
            memory_mb = args.memory_mb
            if sanitized(binary) and memory_mb:
                # ASan cannot run under an address-space limit; its own RSS limit reports instead.
                os.environ["ASAN_OPTIONS"] = (os.environ.get("ASAN_OPTIONS", "") +
                                              ":hard_rss_limit_mb=%d" % memory_mb).lstrip(":")
                memory_mb = 0
            futures = [pool.submit(run_case, c, binary, root, args.timeout, memory_mb) for c in cases]
            for future in futures:  # in case order: the report does not depend on --jobs
                case, failure, timed_out, stderr, status = future.result()
                key = "timeout" if timed_out else str(status)
                endings.setdefault(case.kind, {}).setdefault(key, 0)
                endings[case.kind][key] += 1
                timeouts += timed_out
                if args.verbose and not timed_out:
                    last = [l for l in stderr.strip().split("\n") if l.strip()]
                    print("case %d [%s] exit %d: %s" % (case.index, case.note[:60], status, (last[-1] if last else "")[:160]))
                if timed_out and args.verbose:
                    print("timeout case %d [%s]\n    %s" % (case.index, case.note[:100], case.command_line(binary)[:600]))
                if failure:
                    failed += 1
                    print("FAIL case %d [%s] %s\n    %s" % (case.index, case.note[:100], failure,
                                                            case.command_line(binary)[:600]), flush=True)
                    if args.keep_failures:
                        keep_failure(args.keep_failures, root, case, binary, failure, stderr)
                else:
                    passed += 1
                shutil.rmtree(os.path.join(root, "case_%06d" % case.index), ignore_errors=True)
        print("seed %d, cases %d..%d, %d killed at the %g s timeout (counted as passed)" %
              (args.seed, args.first, args.first + count - 1, timeouts, args.timeout))
        for kind in sorted(endings):
            print("  %-9s %s" % (kind, ", ".join("exit %s: %d" % (k, n) for k, n in sorted(endings[kind].items()))))
        print("%d passed, %d failed" % (passed, failed))
        return 1 if failed else 0
    finally:
        shutil.rmtree(root, ignore_errors=True)


if __name__ == "__main__":
    sys.exit(main())
