"""Reading HDF5 result and tables files: string attributes, unit-checked datasets."""
from __future__ import annotations

import os
import stat
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


# Deflate's largest compression ratio (zlib: 1032:1): a filtered dataset cannot expand to more
# than this times the bytes its chunks occupy in the file.
_MAX_INFLATE = 1032


def check_declared_size(ds, where: str, error: type = None) -> None:
    """Raises `error` (ResultFileError) when the dataset declares more data than its file can
    hold (a forged size; reading it would allocate from the declared size), as the workbench's
    reader does (workbench/io/result_reader.hpp)."""
    error = error or ResultFileError
    try:
        limit = os.path.getsize(ds.file.filename)
    except OSError:
        return
    file_bytes = limit
    if ds.id.get_create_plist().get_nfilters() > 0:
        limit += _MAX_INFLATE * ds.id.get_storage_size()
    declared = int(ds.size or 0) * max(int(ds.dtype.itemsize), 1)
    if declared > limit:
        raise error(f"{ds.file.filename}: {where} declares {ds.size} values of "
                    f"{ds.dtype.itemsize} bytes ({declared} bytes) in a file of {file_bytes} "
                    "bytes: more than the file can hold")


def _read_ds(group, name: str, where: str, units: Optional[str] = None,
             finite: bool = False) -> np.ndarray:
    """The dataset as float; with `finite`, every sample must be finite (a signal of a run's
    result: one NaN would be drawn as a gap or spread through what is computed from it)."""
    if name not in group:
        raise ResultFileError(f"missing dataset {where}/{name}")
    ds = group[name]
    check_declared_size(ds, f"{where}/{name}")
    try:
        a = np.asarray(ds[()], dtype=float).reshape(-1)
    except (TypeError, ValueError) as e:
        raise ResultFileError(f"dataset {where}/{name} is not numeric ({e})") from None
    if finite and not np.all(np.isfinite(a)):
        k = int(np.flatnonzero(~np.isfinite(a))[0])
        raise ResultFileError(f"{ds.file.filename}: {where}/{name} holds {a[k]} at sample {k} of "
                              f"{a.size}; a signal of a result must be finite")
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
    # A FIFO would block the open, a device is no result (workbench/io/result_reader.hpp).
    mode = os.stat(path).st_mode
    if not stat.S_ISREG(mode):
        kind = "a FIFO" if stat.S_ISFIFO(mode) else (
            "a device" if stat.S_ISCHR(mode) or stat.S_ISBLK(mode) else "not a regular file")
        raise error(f"{path}: is {kind}, not a {what}")
    try:
        f = h5py.File(path, "r")
    except OSError as e:
        msg = str(e).splitlines()[0] if str(e) else type(e).__name__
        raise error(f"not a readable HDF5 file: {path} ({msg})") from None
    leaving = _link_leaving_file(f)
    if leaving:
        f.close()
        raise error(f"{path}: {leaving}; a result file is read only from itself (links to other "
                    "files are refused, nothing is read through them)")
    return f


def _link_leaving_file(f) -> str:
    """The first external or user-defined link of the open file, in words ("" when none): a soft
    link names a path of the same file and stays inside once no external link exists."""
    import h5py

    found = []

    def visit(name, info):
        if info.type in (h5py.h5l.TYPE_HARD, h5py.h5l.TYPE_SOFT):
            return None
        path = "/" + name.decode("utf-8", "replace")
        if info.type == h5py.h5l.TYPE_EXTERNAL:
            link = f.get(path, getlink=True)
            found.append(f"{path} is an external link to '{link.filename}:{link.path}'")
        else:
            found.append(f"{path} is a user-defined link")
        return True  # stops the visit

    f.id.links.visit(visit, info=True)
    return found[0] if found else ""
