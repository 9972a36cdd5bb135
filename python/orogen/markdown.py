"""Markdown tables of numbers, for the tables the statistics and the analyses print for the docs:

    print(md_table(["run", "H [h0]"], [["main", 1.2345]], numeric=[False, True]))
"""

import math

import numpy as np


def shown(x):
    """A cell: text as it is, integers whole, other numbers to four significant digits, NaN empty."""
    if isinstance(x, str):
        return x
    if isinstance(x, (int, np.integer)):
        return str(int(x))
    x = float(x)
    return f"{x:.4g}" if math.isfinite(x) else ""


def md_table(header, rows, numeric=None):
    """A Markdown table; `numeric` marks the columns to align right (all unless given)."""
    numeric = numeric or [True] * len(header)
    out = "| " + " | ".join(header) + " |\n|" + "".join("---:|" if n else "---|" for n in numeric) + "\n"
    for r in rows:
        out += "| " + " | ".join(shown(v).replace("|", "\\|") for v in r) + " |\n"
    return out
