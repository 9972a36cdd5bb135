"""The folders of src/ keep the order of docs/architecture.md's table "Folders": a folder includes
only itself and the folders below it there, so the drivers (run, sweep, ensemble, commands)
sit on the engine and never the reverse; and the table names every folder of src/.

Run from the repository root:
    /usr/bin/python3 -m unittest tests/python/test_layering.py
"""

import os
import re
import unittest

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
SRC = os.path.join(REPO, "src")
DOC = os.path.join(REPO, "docs", "architecture.md")
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"/]+)/[^"]+"', re.MULTILINE)


def table_order():
    """The folders of the table under "## Folders", top to bottom."""
    with open(DOC, encoding="utf-8") as f:
        text = f.read()
    section = text.split("\n## Folders\n", 1)[1].split("\n## ", 1)[0]
    return re.findall(r"^\| `src/([a-z_]+)/` \|", section, re.MULTILINE)


def includes_by_folder():
    """{folder: [(file, included folder), ...]} for every #include "folder/..." under src/."""
    found = {}
    for folder in sorted(os.listdir(SRC)):
        path = os.path.join(SRC, folder)
        if not os.path.isdir(path):
            continue
        rows = found.setdefault(folder, [])
        for root, _, files in os.walk(path):
            for name in sorted(files):
                if not name.endswith((".hpp", ".cpp")):
                    continue
                file = os.path.join(root, name)
                with open(file, encoding="utf-8") as f:
                    for target in INCLUDE.findall(f.read()):
                        rows.append((os.path.relpath(file, REPO), target))
    return found


class Layering(unittest.TestCase):
    def test_table_names_every_folder_once(self):
        order = table_order()
        self.assertEqual(len(order), len(set(order)), f"a folder twice in the table: {order}")
        folders = sorted(d for d in os.listdir(SRC) if os.path.isdir(os.path.join(SRC, d)))
        self.assertEqual(sorted(order), folders, "docs/architecture.md's table of folders and src/ differ")

    def test_includes_point_down_the_table(self):
        order = table_order()
        rank = {folder: i for i, folder in enumerate(order)}
        wrong = []
        for folder, rows in includes_by_folder().items():
            for file, target in rows:
                if target not in rank:
                    wrong.append(f"{file} includes {target}/, a folder the table does not name")
                elif rank[target] < rank.get(folder, len(order)):
                    wrong.append(f"{file} includes {target}/, which is above {folder}/ in the table")
        self.assertEqual(wrong, [], "\n" + "\n".join(wrong))

    def test_drivers_are_above_the_engine(self):
        order = table_order()
        for driver in ("commands", "ensemble", "sweep", "run"):
            self.assertLess(order.index(driver), order.index("experiments"), driver)


if __name__ == "__main__":
    unittest.main()
