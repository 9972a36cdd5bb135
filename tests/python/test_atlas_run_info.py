"""What the atlas reads of a run folder without building a site: the status and wall time from
run.log, for a run in one piece, a resumed run and a run still going; which folders are runs,
symbolic links to them included."""
import os
import sys
import tempfile
import unittest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import source_tree  # noqa: E402,F401  (the package of this source tree)
from orogen.atlas import discover, run_info  # noqa: E402


def status_and_wall(log_lines):
    with tempfile.TemporaryDirectory() as d:
        with open(os.path.join(d, "run.log"), "w") as f:
            f.write("\n".join(log_lines) + "\n")
        return run_info._status_and_wall(d, os.listdir(d))


class WallTime(unittest.TestCase):
    def test_one_piece_counts_first_to_last_line(self):
        self.assertEqual(status_and_wall([
            "[2026-11-25 01:00:00] orogen 0.1.0 run in runs/a with 2 thread(s)",
            "[2026-11-25 01:00:05] output 1 at step 10 (t = 1): 10 discs",
            "[2026-11-25 01:10:00] finished at step 100 (t = 10) after 100 steps in 598.2 s (1 M particle-steps/s)",
        ]), ("finished", 600.0))

    def test_a_resumed_run_sums_its_pieces_and_not_the_pause(self):
        self.assertEqual(status_and_wall([
            "[2026-11-25 01:00:00] orogen 0.1.0 run in runs/a with 2 thread(s)",
            "[2026-11-25 01:30:00] output 99 at step 990 (t = 99): 10 discs",
            "[2026-11-25 02:50:00] orogen 0.1.0 resume in runs/a with 1 thread(s)",
            "[2026-11-25 02:50:01] resumed at step 990 (t = 99) after output 99",
            "[2026-11-25 03:20:00] finished at step 2000 (t = 200) after 1010 steps in 1799.0 s (1 M particle-steps/s)",
        ]), ("finished", 1800.0 + 1800.0))

    def test_a_running_run_is_incomplete_with_the_time_so_far(self):
        self.assertEqual(status_and_wall([
            "[2026-11-25 01:00:00] orogen 0.1.0 run in runs/a with 2 thread(s)",
            "[2026-11-25 01:00:42] output 1 at step 10 (t = 1): 10 discs",
        ]), ("incomplete", 42.0))

    def test_a_log_without_two_timestamps_has_no_wall_time(self):
        self.assertEqual(status_and_wall(["[2026-11-25 01:00:00] orogen 0.1.0 run in runs/a"]), ("incomplete", None))


class Discovery(unittest.TestCase):
    def test_symbolic_links_to_runs_are_followed_once_and_cycles_end(self):
        # Issue 36: a folder of linked runs found "0 runs".
        with tempfile.TemporaryDirectory() as d:
            for run in ("store/a", "store/b"):
                os.makedirs(os.path.join(d, run))
                for name in ("config.toml", "series.csv"):
                    open(os.path.join(d, run, name), "w").close()
            linked = os.path.join(d, "linked")
            os.makedirs(linked)
            os.symlink(os.path.join(d, "store", "a"), os.path.join(linked, "a"))
            os.symlink(os.path.join(d, "store", "b"), os.path.join(linked, "b"))
            os.symlink(linked, os.path.join(linked, "loop"))  # a cycle
            runs, _ = discover.find(linked, os.path.join(d, "site"))
            self.assertEqual([rel for _, rel, _ in runs], ["a", "b"])


if __name__ == "__main__":
    unittest.main()
