"""snapshots.h5 as one lazily read xarray Dataset (output x particle).

Each output is its own file, snapshots/output_NNNNNN.h5 (docs/output-files.md), read through
its group in snapshots.h5 (orogen.frames: the complete outputs only); the number of discs
changes between outputs (erosion, inflow), so `particle` is the position in an output, padded
to the largest: NaN for floats and -1 for integers past an output's `n_discs`. The `id`
variable links a disc across outputs. Only shapes and attributes are read when opening; values
are read when indexed or loaded (xarray's lazy indexing, one output at a time).
"""

from pathlib import Path

import h5py
import numpy as np
import xarray as xr
from xarray.backends import BackendArray
from xarray.core import indexing

from .frames import Snapshots, attrs_of


def _fill(dtype):
    return np.nan if np.issubdtype(dtype, np.floating) else -1


def _open(run_dir):
    return Snapshots(Path(run_dir) / "snapshots.h5")


class _Padded(BackendArray):
    """One per-disc dataset of every output, padded to (outputs, max discs); reads on demand."""

    def __init__(self, run_dir, n_outputs, name, dtype, trailing=()):
        self.run_dir, self.name = run_dir, name
        self.dtype = np.dtype(dtype if not np.issubdtype(dtype, np.integer) else np.int64)
        self.trailing = tuple(trailing)
        self.shape = (n_outputs, 0) + self.trailing

    def set_width(self, width):
        self.shape = (self.shape[0], width) + self.trailing

    def __getitem__(self, key):
        return indexing.explicit_indexing_adapter(key, self.shape, indexing.IndexingSupport.BASIC, self._raw)

    def _raw(self, key):
        key = tuple(key) + (slice(None),) * (len(self.shape) - len(key))
        outputs = np.arange(self.shape[0])[key[0]]
        rows = []
        with _open(self.run_dir) as snaps:
            for k in np.atleast_1d(outputs):
                full = np.full(self.shape[1:], _fill(self.dtype), dtype=self.dtype)
                g = snaps.group(int(k))
                if self.name in g:
                    data = g[self.name][()]
                    full[: data.shape[0], ...] = data
                rows.append(full[key[1:]])
        out = np.stack(rows)
        return out[0] if np.ndim(outputs) == 0 else out


def open_snapshots(run_dir):
    """The outputs of a run as an xarray Dataset, read lazily (module docstring)."""
    arrays, var_attrs, n_discs, n_walls, scalars = {}, {}, [], [], {}
    with _open(run_dir) as snaps:
        n_outputs, root_attrs = len(snaps), snaps.attrs
        for k in range(n_outputs):
            g = snaps.group(k)
            n = g["x"].shape[0] if "x" in g else 0
            n_discs.append(n)
            n_walls.append(g["walls"].shape[0] if "walls" in g else 0)
            for name, ds in g.items():
                if not isinstance(ds, h5py.Dataset):
                    continue  # optional groups (contacts, stress): read them with h5py
                if name not in arrays:
                    arrays[name] = _Padded(run_dir, n_outputs, name, ds.dtype, ds.shape[1:])
                    var_attrs[name] = attrs_of(ds)
            for a, v in attrs_of(g).items():
                if a != "config_toml":
                    scalars.setdefault(a, [np.nan] * n_outputs)[k] = v
    width = max(n_discs, default=0)
    data_vars = {}
    for name, arr in arrays.items():
        if name == "walls":
            arr.set_width(max(n_walls, default=0))
            dims = ("output", "wall", "end")
        else:
            arr.set_width(width)
            dims = ("output", "particle") + tuple(f"{name}_dim{i}" for i in range(1, len(arr.shape) - 1))
        data_vars[name] = xr.Variable(dims, indexing.LazilyIndexedArray(arr), var_attrs[name])
    coords = {"output": ("output", np.arange(n_outputs))}
    for a, values in scalars.items():
        coords[a] = ("output", np.asarray(values))
    data_vars["n_discs"] = xr.Variable("output", np.asarray(n_discs, dtype=np.int64),
                                       {"units": "-", "description": "discs in the output (the rest is padding)"})
    ds = xr.Dataset(data_vars, coords=coords, attrs=root_attrs)
    if "walls" in ds:
        ds = ds.assign_coords(end=["ax", "ay", "bx", "by"])
    for c, units in (("step", "-"), ("time", "sqrt(d/g)"), ("S", "-")):
        if c in ds.coords:
            ds[c].attrs["units"] = units
    return ds


def read_output(run_dir, k):
    """Output k (negative: from the end) as a Dataset over its discs, `particle` = stable id."""
    with _open(run_dir) as snaps:
        g = snaps.group(k)
        ids = g["id"][()]
        data_vars = {}
        for name, ds in g.items():
            if isinstance(ds, h5py.Dataset):
                dims = ("wall", "end") if name == "walls" else ("particle",) + tuple(
                    f"{name}_dim{i}" for i in range(1, ds.ndim))
                data_vars[name] = xr.Variable(dims, ds[()], attrs_of(ds))
        attrs = dict(snaps.attrs)
        attrs.update(attrs_of(g))
    data_vars.pop("id", None)
    return xr.Dataset(data_vars, coords={"particle": ids}, attrs=attrs)
