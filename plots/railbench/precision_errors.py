"""The numbers of `workbench precision` (docs/precision.md): errors of result files against a
reference on the quantities the user names, the verification bound of the reference, the error
split (table / integration) and Pareto fronts for the figures. Pure functions of result files and
rows, so that tests can check them on files of known content. The recommendation rule is the
engine's (workbench/precision/answer.cpp); the error rule is the same here and there."""
from __future__ import annotations

import math
import re
from dataclasses import dataclass
from typing import Dict, List, Sequence, Tuple

import h5py
import numpy as np

from .h5 import _str
from .result import _names_attr
from .study_data import on_grid

# Display unit per dataset: (scale from SI, unit).
_BODY_UNITS = {"y": (1e3, "mm"), "z": (1e3, "mm"), "s": (1e3, "mm"), "roll": (1e3, "mrad"),
               "pitch": (1e3, "mrad"), "yaw": (1e3, "mrad")}
# Per-wheel quantities: the wheel/rail normal force, the lateral creep force, and the EN 14363
# running-safety quantities of the contact output (track-lateral wheel force Y and Y/Q).
_WHEEL_TAGS = {"Q": ("normal_force", 1e-3, "kN"), "Fy": ("creep_force_y", 1e-3, "kN"),
               "Y": ("Y", 1e-3, "kN"), "YQ": ("y_over_q", 1.0, "-")}


class QuantityError(ValueError):
    """A --quantities entry that names nothing this command knows. One line."""


@dataclass(frozen=True)
class Quantity:
    """An error quantity: tag as the user wrote it, what it covers, its display unit."""
    tag: str
    group: str      # "wheelsets" (y, yaw: every wheelset; guided: every other body), "wheels",
                    # "body" (one named body)
    dataset: str
    scale: float
    unit: str
    body: str = ""

    @property
    def title(self) -> str:
        if self.group == "body":
            return f"{self.body} {self.dataset}"
        if self.group == "wheels":
            return f"{self.tag} (every wheel)"
        return f"{self.dataset} (every wheelset)"


def parse_quantities(text: str) -> List[Quantity]:
    out = []
    for tag in [t.strip() for t in (text or "y,yaw").split(",")]:
        if tag in ("y", "yaw"):
            sc, unit = _BODY_UNITS[tag]
            out.append(Quantity(tag, "wheelsets", tag, sc, unit))
        elif tag in _WHEEL_TAGS:
            ds, sc, unit = _WHEEL_TAGS[tag]
            out.append(Quantity(tag, "wheels", ds, sc, unit))
        elif re.fullmatch(r"[A-Za-z0-9_\-]+\.(y|z|roll|pitch|yaw)", tag):
            body, ds = tag.rsplit(".", 1)
            sc, unit = _BODY_UNITS[ds]
            out.append(Quantity(tag, "body", ds, sc, unit, body))
        else:
            raise QuantityError(f"--quantities: unknown '{tag}' (y, yaw, Q, Fy, Y, YQ or "
                                f"BODY.y|z|roll|pitch|yaw)")
    if not out:
        raise QuantityError("--quantities: no entry")
    return out


def _series(f: h5py.File, q: Quantity) -> Dict[str, np.ndarray]:
    """{name: series in SI} of quantity q in an open result file."""
    names = _names_attr(f["bodies"].attrs.get("names", "")) if "bodies" in f else []
    kinds = {n: _str(f["bodies/" + n].attrs.get("kind", "")) for n in names if "bodies/" + n in f}
    wheelsets = [n for n in names if kinds.get(n) == "wheelset"]
    out = {}
    if q.group == "body":
        path = f"bodies/{q.body}/{q.dataset}"
        if path in f:
            out[q.body] = np.asarray(f[path][()], float).reshape(-1)
    elif q.group == "wheels":
        for ws in wheelsets:
            for side in ("left", "right"):
                path = f"contact/{ws}/{side}/{q.dataset}"
                if path in f:
                    out[f"{ws} {side}"] = np.asarray(f[path][()], float).reshape(-1)
    else:
        # Guided wheelsets follow the track kinematically (no error of their own): on a vehicle
        # without contact the quantity covers every other body.
        chosen = wheelsets if "contact" in f else [n for n in names if kinds.get(n) != "wheelset"]
        for n in chosen:
            path = f"bodies/{n}/{q.dataset}"
            if path in f:
                out[n] = np.asarray(f[path][()], float).reshape(-1)
    return out


def errors(path: str, ref_path: str, quantities: Sequence[Quantity]
           ) -> Dict[str, Tuple[float, float]]:
    """{tag: (max |difference|, RMS difference)} of the result file `path` against `ref_path`
    in display units, on the reference's output times inside the run of `path` (a failed run:
    over the part it ran), over every series the quantity covers. A quantity absent from either
    file is left out."""
    out: Dict[str, Tuple[float, float]] = {}
    with h5py.File(path, "r") as f, h5py.File(ref_path, "r") as g:
        t = np.asarray(f["time"][()], float) if "time" in f else np.zeros(0)
        tr = np.asarray(g["time"][()], float) if "time" in g else np.zeros(0)
        if len(t) < 2 or len(tr) < 2:
            return out
        for q in quantities:
            s, r = _series(f, q), _series(g, q)
            mx, ssum, n = 0.0, 0.0, 0
            for key, rv in r.items():
                if key not in s:
                    continue
                # One rule with the engine (workbench/precision/answer.cpp): a non-finite
                # value of the run (diverged) makes its error infinite.
                if not np.all(np.isfinite(s[key][:len(t)])):
                    mx = math.inf
                m, v = on_grid(tr[:len(rv)], t, s[key])
                if not m.any():
                    continue
                d = (v - rv[:len(m)][m]) * q.scale
                if not np.all(np.isfinite(d)):
                    mx = math.inf
                d = d[np.isfinite(d)]
                if len(d):
                    mx = max(mx, float(np.max(np.abs(d))))
                    ssum += float(np.sum(d * d))
                    n += len(d)
            if n or math.isinf(mx):
                out[q.tag] = (mx, math.sqrt(ssum / n) if n and math.isfinite(mx) else math.inf)
    return out


def verify(bound: Dict[str, Tuple[float, float]], quantities: Sequence[Quantity], limit: float,
           both_ok: bool) -> Tuple[bool, str]:
    """Whether the two references agree: both ran to the end and their max difference on every
    quantity is at most `limit` (display units). (verified, reason when not)."""
    if not both_ok:
        return False, "a reference run failed"
    for q in quantities:
        if q.tag not in bound:
            return False, f"no {q.tag} in the references"
        if not bound[q.tag][0] <= limit:
            return False, (f"the references differ by {bound[q.tag][0]:.3g} {q.unit} in {q.tag} "
                           f"(limit {limit:g})")
    return True, ""


def pareto(points: Sequence[Tuple[float, float]]) -> List[int]:
    """Indices of the Pareto front of (error, cost) points: no other point is both cheaper (or
    as cheap) and more accurate. Ordered by cost."""
    order = sorted(range(len(points)), key=lambda i: (points[i][1], points[i][0]))
    front, best = [], math.inf
    for i in order:
        e = points[i][0]
        if e < best:
            front.append(i)
            best = e
    return front
