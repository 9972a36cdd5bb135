"""The complete outputs of snapshots.h5, one at a time (h5py and numpy only).

The package's one low-level snapshot reader: orogen.snapshots builds its lazy xarray Dataset
on it, and the charts read their frames through it (orogen.folders.read_frame,
orogen.charts.wedge). Output k is the group output_NNNNNN of snapshots.h5: in a run folder an
external link to snapshots/output_NNNNNN.h5, which HDF5 follows by itself, in the chart tests'
fixtures a group written there directly; reading through snapshots.h5 covers both. Only the
first n_outputs groups are complete; those past it (left by a killed run) are never opened.

    with Snapshots("runs/a/snapshots.h5") as s:
        last = s.frame(-1)                     # dict: x, y, radius, ..., walls, attrs, file_attrs
"""

import h5py
import numpy as np


def attr_value(v):
    """An HDF5 attribute as a plain Python value (text as str, a numpy scalar as int or float)."""
    if isinstance(v, bytes):
        return v.decode("utf-8", "replace")
    if isinstance(v, np.generic):
        return v.item()
    return v


def attrs_of(obj):
    """The attributes of an HDF5 file, group or dataset as a dict of plain values."""
    return {k: attr_value(v) for k, v in obj.attrs.items()}


class Snapshots:
    """snapshots.h5 open for reading: len() complete outputs, the file's attributes as `attrs`,
    and output k (a Python index over the complete outputs) as an h5py group or a frame."""

    def __init__(self, path):
        self.path = path
        self._file = h5py.File(path, "r")
        self.attrs = attrs_of(self._file)
        self.n_outputs = max(0, int(self._file.attrs.get("n_outputs", 0)))

    def __len__(self):
        return self.n_outputs

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    def close(self):
        self._file.close()

    def number(self, k):
        """The output number of index k (0 the first, -1 the last); IndexError past n_outputs."""
        if not -self.n_outputs <= k < self.n_outputs:
            raise IndexError(f"{self.path}: no complete output {k} (n_outputs = {self.n_outputs})")
        return k % self.n_outputs

    def group(self, k):
        """Output k as an h5py group (its datasets, attributes and optional groups)."""
        return self._file["output_%06d" % self.number(k)]

    def frame(self, k, fields=None):
        """Output k as a dict: each per-disc dataset (1-D, as long as x; only those named in
        `fields` when given) as an array of its own dtype, walls (n x 4: ax, ay, bx, by), the
        group's attributes (step, time, S, ...) under 'attrs', the file's under 'file_attrs',
        and 'output' (its number)."""
        g = self.group(k)
        frame = {"output": self.number(k), "file_attrs": dict(self.attrs), "attrs": attrs_of(g)}
        n_discs = g["x"].shape[0] if "x" in g else None
        for name, ds in g.items():  # every per-disc field: none is dropped
            if fields is not None and name not in fields:
                continue
            if isinstance(ds, h5py.Dataset) and ds.ndim == 1 and ds.shape[0] == n_discs and name != "walls":
                frame[name] = np.asarray(ds[:])
        frame["walls"] = np.asarray(g["walls"][:], dtype=float).reshape(-1, 4) if "walls" in g else np.zeros((0, 4))
        return frame


def read_frame(path, index=-1, fields=None):
    """Output `index` of snapshots.h5 (Snapshots.frame), or None where there is no such complete output."""
    with Snapshots(path) as s:
        if not -len(s) <= index < len(s):
            return None
        return s.frame(index, fields)
