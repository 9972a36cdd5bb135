"""orogen.open_run(DIR): everything a run folder holds, as pandas and xarray objects.

    r = orogen.open_run("runs/main")
    r.config["wedge"]["s_end"]        # config.toml as a dict
    r.series                          # series.csv: pandas DataFrame; r.units["H"] == "h0"
    r.series_dataset()                # the same as an xarray Dataset over `output`, units as attrs
    r.snapshots                       # xarray Dataset (output x particle), read lazily
    r.output(-1)                      # one output, `particle` = stable disc id
    r.removals, r.summary, r.analysis # removals.csv, summary.csv, analysis.h5 (None where absent)

The CSV readers need pandas only (h5py is imported when snapshots are read), so the chart
scripts read tables through read_csv on any machine with Debian's python3-pandas.
"""

import io
import re
import tomllib
from functools import cached_property
from pathlib import Path

import pandas as pd
import xarray as xr


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


class RunFolder:
    """A run folder written by `orogen run` (or orogen.run); attributes read on first use."""

    def __init__(self, path):
        self.path = Path(path)
        if not (self.path / "config.toml").is_file():
            raise FileNotFoundError(f"{self.path}: no run there (config.toml is missing)")

    def __repr__(self):
        return f"<orogen run {self.path}: {self.experiment}, {len(self.series)} outputs>"

    @cached_property
    def config(self):
        with open(self.path / "config.toml", "rb") as f:
            return tomllib.load(f)

    @property
    def experiment(self):
        return self.config["run"]["experiment"]

    @cached_property
    def _series(self):
        return read_csv(self.path / "series.csv")

    @property
    def series(self):
        """series.csv as a DataFrame, one row per output."""
        return self._series[0]

    @property
    def units(self):
        """Unit of each series column (h0 for a wedge's lengths, deg, -)."""
        return self._series[1]

    @property
    def descriptions(self):
        return self._series[2]

    def series_dataset(self):
        """series.csv as an xarray Dataset over `output`, units and descriptions as attrs."""
        ds = xr.Dataset.from_dataframe(self.series.rename_axis("output"))
        for name in ds.data_vars:
            ds[name].attrs.update(units=self.units.get(name, ""), description=self.descriptions.get(name, ""))
        return ds

    @cached_property
    def snapshots(self):
        """Every output's per-disc fields, lazily (orogen.snapshots.open_snapshots)."""
        from .snapshots import open_snapshots  # h5py: only when snapshots are asked for
        return open_snapshots(self.path)

    def output(self, k=-1):
        """Output k as a Dataset indexed by stable disc id."""
        from .snapshots import read_output
        return read_output(self.path, k)

    @cached_property
    def removals(self):
        """removals.csv as a DataFrame (empty where nothing was removed)."""
        path = self.path / "removals.csv"
        return pd.read_csv(path, comment="#") if path.exists() else pd.DataFrame()

    @cached_property
    def summary(self):
        """summary.csv's one row as a dict (None before the run finished)."""
        path = self.path / "summary.csv"
        return read_csv(path)[0].iloc[0].to_dict() if path.exists() else None

    @cached_property
    def analysis(self):
        """analysis.h5 of `orogen analyze` as an xarray Dataset, or None."""
        path = self.path / "analysis.h5"
        return xr.open_dataset(path, engine="h5netcdf") if path.exists() else None


def open_run(path):
    """The run folder at `path` (RunFolder)."""
    return RunFolder(path)
