"""The progress line on a terminal: `orogen run` under a pseudo-terminal draws its progress
line, and every log line still starts at column 0 (the progress line is erased first), while
run.log holds no terminal codes.

The binary is $OROGEN_BINARY (CTest sets it), else build/release/orogen."""

import os
import pty
import re
import shutil
import subprocess
import tempfile
import unittest

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
BINARY = os.environ.get("OROGEN_BINARY", os.path.join(ROOT, "build", "release", "orogen"))
PRESET = os.path.join(ROOT, "examples", "wedge_main_modest.toml")
# A tiny wedge of a few seconds: long enough for the progress line (redrawn every 0.25 s) to
# be drawn between the output log lines.
TINY = ["layer.thickness=5", "wedge.tile_length=4", "wedge.retro_length=4", "wedge.initial_active=4",
        "wedge.s_end=0.6", "wedge.outputs=6", "output.vtp=false", "run.threads=1"]
TIMESTAMP = re.compile(r"\[\d{4}-\d\d-\d\d \d\d:\d\d:\d\d\] ")
ERASE = "\r\x1b[K"


def run_on_terminal(args):
    """Runs args with stdout and stderr on a pseudo-terminal; returns (exit code, everything written)."""
    master, slave = pty.openpty()
    proc = subprocess.Popen(args, stdin=subprocess.DEVNULL, stdout=slave, stderr=slave, close_fds=True)
    os.close(slave)
    chunks = []
    while True:
        try:
            data = os.read(master, 65536)
        except OSError:  # EIO: the child closed the terminal
            break
        if not data:
            break
        chunks.append(data)
    os.close(master)
    return proc.wait(), b"".join(chunks).decode("utf-8", "replace").replace("\r\n", "\n")


class ProgressLineTest(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.mkdtemp()

    def tearDown(self):
        shutil.rmtree(self.tmp)

    def test_log_lines_start_at_column_zero(self):
        out = os.path.join(self.tmp, "run")
        args = [BINARY, "run", PRESET, "--out", out]
        for s in TINY:
            args += ["--set", s]
        code, text = run_on_terminal(args)
        self.assertEqual(code, 0, text)
        self.assertIn("particle-steps/s  left", text, "the progress line was never drawn:\n" + text)
        starts = [m.start() for m in TIMESTAMP.finditer(text)]
        self.assertGreater(len(starts), 5, text)
        for i in starts:
            before = text[:i]
            clean = before == "" or before.endswith("\n") or before.endswith(ERASE)
            self.assertTrue(clean, "progress text before a log line: " + repr(text[max(0, i - 120):i + 40]))
        # Some log line did follow a drawn progress line (else the test proves nothing).
        self.assertTrue(any(text[:i].endswith(ERASE) for i in starts), repr(text))
        with open(os.path.join(out, "run.log")) as f:
            log = f.read()
        self.assertNotIn("\x1b", log)
        self.assertNotIn("\r", log)

    def test_no_progress_line_off_a_terminal(self):
        out = os.path.join(self.tmp, "run")
        args = [BINARY, "run", PRESET, "--out", out]
        for s in TINY:
            args += ["--set", s]
        r = subprocess.run(args, capture_output=True, text=True)
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertNotIn("particle-steps/s  left", r.stderr)
        self.assertNotIn("\x1b", r.stderr)


if __name__ == "__main__":
    unittest.main()
