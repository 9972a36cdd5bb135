"""orogen.open_run(DIR): everything a run folder holds, as pandas and xarray objects.

    r = orogen.open_run("runs/main")
    r.config["wedge"]["s_end"]        # config.toml as a dict
    r.series                          # series.csv: pandas DataFrame; r.units["H"] == "h0"
    r.series_dataset()                # the same as an xarray Dataset over `output`, units as attrs
    r.snapshots                       # xarray Dataset (output x particle), read lazily
    r.output(-1)                      # one output, `particle` = stable disc id
    r.removals, r.analysis            # removals.csv (DataFrame), analysis.h5 (None where absent)
    r.summary                         # summary.csv's row: {column: float}, {} before the end
    r.value("contact.mu"), r.file("snapshots.h5"), r.series_columns["H"]   # what charts use

Tables need pandas only (h5py is imported when snapshots are read, xarray for the Datasets).
"""

import math
import os
import tomllib
from functools import cached_property
from pathlib import Path

import pandas as pd
import xarray as xr

from .tables import read_complete_rows, read_csv, read_summary, read_table, to_float


class RunFolder:
    """A run folder written by `orogen run` (or orogen.run); attributes read on first use.

    The package's one run-folder model: the Python API, the charts, the statistics and the
    atlas all read runs through it. A run of a sweep may also carry its row of the sweep's
    results.csv (`results_row`, the swept keys `swept`): its summary and swept values then
    come from that row where the folder lacks them (or where no folder is left, path None)."""

    def __init__(self, path, name=None, results_row=None, swept=()):
        self.path = Path(path) if path else None
        self.name = name or (os.path.basename(os.path.normpath(path)) if path else "run")
        self.results_row = results_row or {}
        self.swept = tuple(swept)
        if self.path and not results_row and not (self.path / "config.toml").is_file():
            raise FileNotFoundError(f"{self.path}: no run there (config.toml is missing)")

    def __repr__(self):
        return f"<orogen run {self.path}: {self.experiment}, {len(self.series)} outputs>"

    @property
    def dir(self):
        """The folder as text (None for a sweep's row without a folder)."""
        return os.path.abspath(self.path) if self.path else None

    def file(self, name):
        """Path (text) of a file in the run folder, or None when it is not there."""
        path = self.path / name if self.path else None
        return str(path) if path and path.is_file() else None

    @cached_property
    def config(self):
        """config.toml as a dict ({} where there is none)."""
        path = self.file("config.toml")
        if not path:
            return {}
        with open(path, "rb") as f:
            return tomllib.load(f)

    @property
    def experiment(self):
        return self.value("run.experiment")

    def value(self, key, default=None):
        """A dotted configuration key ("contact.mu"), from config.toml or else the sweep's
        column of that key; default where neither has it."""
        v = config_value(self.config, key)
        if v is None and self.results_row.get(key, "") != "":
            text = self.results_row[key]
            v = to_float(text)
            if math.isnan(v):
                v = text
        return default if v is None else v

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
        return read_complete_rows(path) if path.exists() else pd.DataFrame()

    @cached_property
    def series_columns(self):
        """series.csv as {column: float array} ({} where there is none): what the charts draw."""
        path = self.file("series.csv")
        return read_table(path)[0] if path else {}

    @cached_property
    def _summary(self):
        path = self.file("summary.csv")
        if path:
            return read_summary(path)
        # A sweep's results.csv has the summary's columns too (after the fixed ones).
        return {k: to_float(v) for k, v in self.results_row.items()
                if k not in ("name", "exit_status", "render_status") and k not in self.swept and v != ""}, {}

    @property
    def summary(self):
        """summary.csv's one row as {column: float} ({} before the run finished)."""
        return self._summary[0]

    @property
    def summary_descriptions(self):
        """{column: meaning [unit]} of summary.csv."""
        return self._summary[1]

    @cached_property
    def analysis(self):
        """analysis.h5 of `orogen analyze` as an xarray Dataset, or None."""
        path = self.path / "analysis.h5"
        return xr.open_dataset(path, engine="h5netcdf") if path.exists() else None


def open_run(path):
    """The run folder at `path` (RunFolder)."""
    return RunFolder(path)


def config_value(config, key, default=None):
    """A dotted key ("contact.mu") of a configuration dict."""
    node = config
    for part in key.split("."):
        if not isinstance(node, dict) or part not in node:
            return default
        node = node[part]
    return node
