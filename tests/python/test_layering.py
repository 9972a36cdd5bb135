"""The folders of src/ keep the order of docs/architecture.md's table "Folders": a folder includes
only itself and the folders below it there, so the drivers (run, sweep, ensemble, commands)
sit on the engine and never the reverse; and the table names every folder of src/. The same
for the Python package python/orogen and the table "Python modules": a module imports only
its own row and the rows below it, and the table names every module.

Run from the repository root:
    /usr/bin/python3 -m unittest tests/python/test_layering.py
"""

import ast
import os
import re
import unittest

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
SRC = os.path.join(REPO, "src")
DOC = os.path.join(REPO, "docs", "architecture.md")
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"/]+)/[^"]+"', re.MULTILINE)
PACKAGE = os.path.join(REPO, "python", "orogen")


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


def module_rows():
    """The rows of the table under "### Python modules", top to bottom: lists of module names."""
    with open(DOC, encoding="utf-8") as f:
        text = f.read()
    section = text.split("\n### Python modules\n", 1)[1].split("\n## ", 1)[0]
    rows = []
    for line in section.splitlines():
        first = line.split("|")[1] if line.startswith("| `orogen") else ""
        if first:
            rows.append(re.findall(r"`(orogen[a-z_.]*)`", first))
    return rows


def package_modules():
    """{module name: file} of every .py file of the package but its top-level __init__."""
    found = {}
    for root, _, files in os.walk(PACKAGE):
        for name in sorted(files):
            if name.endswith(".py"):
                rel = os.path.relpath(os.path.join(root, name), os.path.dirname(PACKAGE))[:-3].replace(os.sep, ".")
                module = rel[: -len(".__init__")] if rel.endswith(".__init__") else rel
                if module != "orogen":
                    found[module] = os.path.join(root, name)
    return found


def imported_modules(module, file):
    """The modules of the package that a file imports (absolute and relative, at any depth)."""
    with open(file, encoding="utf-8") as f:
        tree = ast.parse(f.read(), file)
    package = module if file.endswith("__init__.py") else module.rpartition(".")[0]
    names = []
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            names += [a.name for a in node.names]
        elif isinstance(node, ast.ImportFrom):
            base = node.module or ""
            if node.level:
                parts = package.split(".")
                base = ".".join(parts[: len(parts) - node.level + 1] + ([base] if base else []))
            names += ([base] if node.module else []) + [f"{base}.{a.name}" for a in node.names]
    return [n for n in names if n == "orogen" or n.startswith("orogen.")]


class PythonLayering(unittest.TestCase):
    def row_of(self, rows, module):
        """The index of the row holding module (the longest name of the table it starts with)."""
        best = None
        for i, row in enumerate(rows):
            for name in row:
                if (module == name or module.startswith(name + ".")) and (best is None or len(name) > best[1]):
                    best = (i, len(name))
        return None if best is None else best[0]

    def test_table_names_every_module(self):
        rows = module_rows()
        self.assertGreater(len(rows), 5)
        missing = [m for m in package_modules() if self.row_of(rows, m) is None]
        self.assertEqual(missing, [], "modules the table of docs/architecture.md does not name")

    def test_imports_point_down_the_table(self):
        rows, modules = module_rows(), package_modules()
        wrong = []
        for module, file in modules.items():
            mine = self.row_of(rows, module)
            for target in imported_modules(module, file):
                if target not in modules:
                    continue  # the package itself, or a name from a module (from .tables import read_csv)
                row = self.row_of(rows, target)
                if row < mine:
                    wrong.append(f"{module} imports {target}, which is above it in the table")
        self.assertEqual(wrong, [], "\n" + "\n".join(wrong))


if __name__ == "__main__":
    unittest.main()
