"""scripts/cohesion_table.py keeps each run's row (--save-rows) and brings kept rows back (--rows):
the values come back as they were written (an unknown one as NaN), and a run read from its folder
takes the place of a kept row of the same h0, strength and seed."""

import importlib.util
import math
import os
import tempfile
import unittest

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
spec = importlib.util.spec_from_file_location("cohesion_table", os.path.join(ROOT, "scripts", "cohesion_table.py"))
cohesion_table = importlib.util.module_from_spec(spec)
spec.loader.exec_module(cohesion_table)


def a_row(h0, strength, seed, height, breaks=0, intact=0):
    r = {k: 0.5 for k in cohesion_table.ROW_KEYS}
    r.update(h0=h0, strength=strength, seed=seed, H=height, beta=math.nan, breaks=breaks, intact=intact)
    return r


class KeptRows(unittest.TestCase):
    def test_rows_come_back_as_written(self):
        rows = [a_row(40.0, 40.0, 1, 1.1, breaks=620, intact=364), a_row(40.0, 0.0, 2, 0.8768)]
        rows[0]["spacing"] = math.nan  # a value the run did not have
        with tempfile.TemporaryDirectory() as tmp:
            path = os.path.join(tmp, "kept.csv")
            cohesion_table.save_rows(rows, path)
            back = cohesion_table.read_kept_rows(path)
        self.assertEqual(len(back), 2)
        for written, read in zip(rows, back):
            for k in cohesion_table.ROW_KEYS:
                if isinstance(written[k], float) and math.isnan(written[k]):
                    self.assertTrue(math.isnan(read[k]), k)
                else:
                    self.assertEqual(read[k], written[k], k)
        self.assertIsInstance(back[0]["seed"], int)
        self.assertIsInstance(back[0]["breaks"], int)
        with tempfile.TemporaryDirectory() as tmp:  # and written again, the same file
            first, second = os.path.join(tmp, "first.csv"), os.path.join(tmp, "second.csv")
            cohesion_table.save_rows(rows, first)
            cohesion_table.save_rows(cohesion_table.read_kept_rows(first), second)
            with open(first) as a, open(second) as b:
                self.assertEqual(a.read(), b.read())

    def test_a_run_read_takes_the_place_of_its_kept_row(self):
        read = [a_row(40.0, 0.0, 2, 0.9)]
        kept = [a_row(40.0, 0.0, 2, 0.1), a_row(40.0, 0.0, 1, 0.88), a_row(20.0, 40.0, 3, 1.4)]
        rows = cohesion_table.merged(read, kept)
        self.assertEqual([(r["h0"], r["strength"], r["seed"]) for r in rows],
                         [(20.0, 40.0, 3), (40.0, 0.0, 1), (40.0, 0.0, 2)])
        self.assertEqual(rows[-1]["H"], 0.9)


if __name__ == "__main__":
    unittest.main()
