"""The package's one reader of Orogen's CSV files (series.csv, summary.csv, profile.csv,
removals.csv, a sweep's results.csv, an ensemble's members.csv and aggregate tables): `# name:
meaning [unit]` lines, a header row, rows (`nan` for NaN), read by pandas.

    frame, units, meanings = read_csv("runs/a/series.csv")    # numbers: a DataFrame
    columns, descriptions = read_table("runs/a/series.csv")   # numbers: {name: float array}
    rows, header = read_rows("runs/s/results.csv")            # text: [{name: str}], names in order
"""

import io
import re

import pandas as pd


class RunError(Exception):
    """A folder or file that is not what the caller asked for (the message says why)."""


_COLUMN_DOC = re.compile(r"^#\s*(\S+):\s*(.*?)\s*(?:\[([^\]]*)\])?\s*$")


def read_csv(path):
    """A series-format CSV (`# name: meaning [unit]` lines, a header row, rows; `nan` for NaN)
    as (DataFrame, {column: unit}, {column: meaning})."""
    return (read_complete_rows(path),) + column_docs(path)


def column_docs(path):
    """The `# name: meaning [unit]` lines above a CSV's header as ({column: unit}, {column: meaning})."""
    units, meanings = {}, {}
    with open(path, encoding="utf-8") as f:
        for line in f:
            if not line.startswith("#"):
                break
            m = _COLUMN_DOC.match(line.strip())
            if m and " " not in m.group(1):
                meanings[m.group(1)] = m.group(2)
                if m.group(3) is not None:
                    units[m.group(1)] = m.group(3)
    return units, meanings


def read_complete_rows(path):
    """The rows of a CSV with as many fields as its header, as a DataFrame.

    The program rewrites its CSVs atomically, but a file can still end in a cut row (copied or
    synced while being written, or written by another tool), and a cut row must not pass for a
    row with missing values: pandas pads a short row with NaN, so a text-only read first (the
    python engine gives None for a missing field, '' for an empty one) tells which rows are
    whole, and only those are parsed (so an integer column stays integer). Rows with too many
    fields are skipped; empty fields and `nan` are NaN; floats parse as Python's float()."""
    options = dict(comment="#", skip_blank_lines=True, on_bad_lines="skip")
    text = pd.read_csv(path, engine="python", dtype=str, na_filter=False, **options)
    whole = text.notna().all(axis=1)
    source = path if whole.all() else io.StringIO(text[whole].to_csv(index=False))
    return pd.read_csv(source, float_precision="round_trip", **options)


def to_float(v):
    """float(v), NaN where v is not a number."""
    try:
        return float(v)
    except (TypeError, ValueError):
        return float("nan")


def read_table(path):
    """A series-format CSV (series.csv, summary.csv, profile.csv) read by orogen.read_csv
    (pandas; rows with the wrong number of fields, such as a cut last row, are skipped).

    Returns (columns, descriptions): columns maps each header name to a float array (NaN for
    'nan', empty or non-numeric fields), descriptions maps names to their `# name: meaning`
    text (with its [unit])."""
    try:
        frame = read_complete_rows(path)
    except pd.errors.EmptyDataError:
        raise RunError("%s: no CSV header row" % path) from None
    columns = {name: pd.to_numeric(frame[name], errors="coerce").to_numpy(dtype=float) for name in frame.columns}
    return columns, _descriptions(path)


def read_summary(path):
    """summary.csv as (dict name -> float of its first row, descriptions); {} without rows."""
    columns, descriptions = read_table(path)
    return {k: float(v[0]) for k, v in columns.items() if len(v)}, descriptions


def read_results(path):
    """A sweep's results.csv: (rows, header, descriptions); rows are dicts name -> text ('' for
    an empty or missing field), header the column names in order (name, the swept keys,
    exit_status, ...)."""
    rows, header = read_rows(path)
    return rows, header, _descriptions(path)


def read_rows(path):
    """A CSV with `#` comment lines (results.csv, members.csv, fits.csv, ...) as text, by pandas:
    (rows: dicts name -> text, '' for an empty or missing field; header: the names in order).
    RFC 4180 quoting; a row longer than the header keeps its first fields."""
    with open(path, "r", encoding="utf-8", newline="") as f:
        body = "".join(line for line in f if not line.startswith("#"))  # not comment="#": '#' may be in a quoted field
    header = list(pd.read_csv(io.StringIO(body), nrows=0).columns)
    frame = pd.read_csv(io.StringIO(body), dtype=str, keep_default_na=False, engine="python",
                        on_bad_lines=lambda fields: fields[: len(header)])
    return frame.fillna("").to_dict("records"), header


def _descriptions(path):
    units, meanings = column_docs(path)
    return {name: "%s [%s]" % (text, units[name]) if name in units else text for name, text in meanings.items()}
