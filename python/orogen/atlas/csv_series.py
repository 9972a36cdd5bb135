"""Orogen's CSV files (series.csv, summary.csv, results.csv, aggregate tables): `# name:
meaning [unit]` lines before the header row, then numbers."""
import math

import pandas as pd

from ..tables import column_docs, read_rows


def read(path):
    """{'columns': [...], 'units': {name: unit}, 'docs': {name: text}, 'rows': [[str...]]}."""
    units, docs = column_docs(path)  # the package's readers, as text ('' for a missing field)
    try:
        rows, header = read_rows(path)
    except pd.errors.EmptyDataError:
        return {"columns": [], "units": units, "docs": docs, "rows": []}
    return {"columns": header, "units": units, "docs": docs, "rows": [[row[c] for c in header] for row in rows]}


def number(text):
    """A float, or None for empty, nan or text (JSON has no NaN)."""
    try:
        v = float(text)
    except (TypeError, ValueError):
        return None
    return v if math.isfinite(v) else None


def columns_as_numbers(table):
    """{name: [float or None, ...]} for every column."""
    cols = {c: [] for c in table["columns"]}
    for row in table["rows"]:
        for i, c in enumerate(table["columns"]):
            cols[c].append(number(row[i]) if i < len(row) else None)
    return cols


def first_row(path):
    """summary.csv: {name: float or text} of its single row, {} when absent."""
    try:
        t = read(path)
    except OSError:
        return {}
    if not t["rows"]:
        return {}
    row = t["rows"][0]
    return {c: (number(row[i]) if number(row[i]) is not None else row[i]) for i, c in enumerate(t["columns"])
            if i < len(row)}
