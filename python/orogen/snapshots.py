"""snapshots.h5 as one lazily read xarray Dataset (output x particle).

Each output is its own file, snapshots/output_NNNNNN.h5 (docs/output-files.md); the number of
discs changes between outputs (erosion, inflow), so `particle` is the position in an output,
padded to the largest: NaN for floats and -1 for integers past an output's `n_discs`. The
`id` variable links a disc across outputs. Only shapes and attributes are read when opening;
values are read when indexed or loaded (xarray's lazy indexing, one output file at a time).
"""

from pathlib import Path

import h5py
import numpy as np
import xarray as xr
from xarray.backends import BackendArray
from xarray.core import indexing


def _text(v):
    return v.decode("utf-8", "replace") if isinstance(v, bytes) else (v.item() if isinstance(v, np.generic) else v)


def _fill(dtype):
    return np.nan if np.issubdtype(dtype, np.floating) else -1


def output_files(run_dir):
    """The complete outputs' files, in order (outputs past n_outputs, left by a killed run, are skipped)."""
    run_dir = Path(run_dir)
    with h5py.File(run_dir / "snapshots.h5", "r") as f:
        n = int(f.attrs.get("n_outputs", 0))
        root_attrs = {k: _text(v) for k, v in f.attrs.items()}
    return [run_dir / "snapshots" / f"output_{k:06d}.h5" for k in range(n)], root_attrs


class _Padded(BackendArray):
    """One per-disc dataset of every output, padded to (outputs, max discs); reads on demand."""

    def __init__(self, files, name, dtype, trailing=()):
        self.files, self.name = files, name
        self.dtype = np.dtype(dtype if not np.issubdtype(dtype, np.integer) else np.int64)
        self.trailing = tuple(trailing)
        self.shape = (len(files), 0) + self.trailing

    def set_width(self, width):
        self.shape = (len(self.files), width) + self.trailing

    def __getitem__(self, key):
        return indexing.explicit_indexing_adapter(key, self.shape, indexing.IndexingSupport.BASIC, self._raw)

    def _raw(self, key):
        key = tuple(key) + (slice(None),) * (len(self.shape) - len(key))
        outputs = np.arange(self.shape[0])[key[0]]
        rows = []
        for k in np.atleast_1d(outputs):
            full = np.full(self.shape[1:], _fill(self.dtype), dtype=self.dtype)
            with h5py.File(self.files[k], "r") as f:
                if self.name in f:
                    data = f[self.name][()]
                    full[: data.shape[0], ...] = data
            rows.append(full[key[1:]])
        out = np.stack(rows)
        return out[0] if np.ndim(outputs) == 0 else out


def open_snapshots(run_dir):
    """The outputs of a run as an xarray Dataset, read lazily (module docstring)."""
    files, root_attrs = output_files(run_dir)
    arrays, attrs_of, n_discs, n_walls, scalars = {}, {}, [], [], {}
    for k, path in enumerate(files):
        with h5py.File(path, "r") as f:
            n = f["x"].shape[0] if "x" in f else 0
            n_discs.append(n)
            n_walls.append(f["walls"].shape[0] if "walls" in f else 0)
            for name, ds in f.items():
                if not isinstance(ds, h5py.Dataset):
                    continue  # optional groups (contacts, stress): read them with h5py
                if name not in arrays:
                    arrays[name] = _Padded(files, name, ds.dtype, ds.shape[1:])
                    attrs_of[name] = {a: _text(v) for a, v in ds.attrs.items()}
            for a, v in f.attrs.items():
                if a != "config_toml":
                    scalars.setdefault(a, [np.nan] * len(files))[k] = _text(v)
    width = max(n_discs, default=0)
    data_vars = {}
    for name, arr in arrays.items():
        if name == "walls":
            arr.set_width(max(n_walls, default=0))
            dims = ("output", "wall", "end")
        else:
            arr.set_width(width)
            dims = ("output", "particle") + tuple(f"{name}_dim{i}" for i in range(1, len(arr.shape) - 1))
        data_vars[name] = xr.Variable(dims, indexing.LazilyIndexedArray(arr), attrs_of[name])
    coords = {"output": ("output", np.arange(len(files)))}
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
    files, root_attrs = output_files(run_dir)
    path = files[k]
    with h5py.File(path, "r") as f:
        ids = f["id"][()]
        data_vars = {}
        for name, ds in f.items():
            if isinstance(ds, h5py.Dataset):
                dims = ("wall", "end") if name == "walls" else ("particle",) + tuple(
                    f"{name}_dim{i}" for i in range(1, ds.ndim))
                data_vars[name] = xr.Variable(dims, ds[()], {a: _text(v) for a, v in ds.attrs.items()})
        attrs = dict(root_attrs)
        attrs.update({a: _text(v) for a, v in f.attrs.items()})
    data_vars.pop("id", None)
    return xr.Dataset(data_vars, coords={"particle": ids}, attrs=attrs)
