"""Reading HDF5 result and tables files: string attributes, unit-checked datasets."""
from __future__ import annotations

import os
import sys
from typing import Dict, Optional

import numpy as np


# --------------------------------------------------------------------------------------------
# Reading
# --------------------------------------------------------------------------------------------
class ResultFileError(Exception):
    """The file is missing, not HDF5, or lacks what the layout promises. Message is one line."""


def _str(v) -> str:
    """HDF5 string attributes arrive as str, bytes or numpy.bytes_ (fixed length)."""
    if isinstance(v, np.ndarray) and v.shape == ():
        v = v[()]
    if isinstance(v, (bytes, np.bytes_)):
        return v.decode("utf-8", "replace").rstrip("\x00")
    return str(v)


def _attrs(obj) -> Dict[str, object]:
    out = {}
    for k, v in obj.attrs.items():
        if isinstance(v, (bytes, np.bytes_, str)):
            out[k] = _str(v)
        elif isinstance(v, np.ndarray) and v.size == 1:
            out[k] = v.reshape(()).item()
        elif isinstance(v, np.generic):
            out[k] = v.item()
        else:
            out[k] = v
    return out


# Units the layout promises, with accepted spellings. A mismatch only warns (stderr): plotting
# must not fail because someone wrote "1/m" as "m^-1", but a silent rescale would be worse.
_UNIT_ALIASES = {
    "m": {"m"},
    "m/s^2": {"m/s^2", "m/s2", "m s^-2"},
    "rad": {"rad"},
    "1/m": {"1/m", "m^-1", "m-1", "rad/m"},
    "-": {"-", "", "1"},
    "rad/m": {"rad/m", "1/m"},
    "m^2/(rad/m)": {"m^2/(rad/m)", "m2/(rad/m)", "m^2/(rad m^-1)", "m^3/rad", "m^2 m/rad"},
}


def _read_ds(group, name: str, where: str, units: Optional[str] = None) -> np.ndarray:
    if name not in group:
        raise ResultFileError(f"missing dataset {where}/{name}")
    ds = group[name]
    try:
        a = np.asarray(ds[()], dtype=float).reshape(-1)
    except (TypeError, ValueError) as e:
        raise ResultFileError(f"dataset {where}/{name} is not numeric ({e})") from None
    if units is not None and "units" in ds.attrs:
        got = _str(ds.attrs["units"]).strip()
        if got not in _UNIT_ALIASES.get(units, {units}):
            print(f"railbench: warning: {where}/{name} has units '{got}', expected '{units}'",
                  file=sys.stderr)
    return a


def open_h5(path: str, error: type, what: str, hint: str = ""):
    """The HDF5 file at `path`, open for reading; `error` (a ResultFileError class) with a
    one-line message when it is missing, a directory or not HDF5."""
    import h5py

    if not os.path.exists(path):
        raise error(f"no such file: {path}{hint}")
    if os.path.isdir(path):
        raise error(f"is a directory, not a {what}: {path}")
    try:
        return h5py.File(path, "r")
    except OSError as e:
        msg = str(e).splitlines()[0] if str(e) else type(e).__name__
        raise error(f"not a readable HDF5 file: {path} ({msg})") from None
