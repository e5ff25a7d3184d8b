"""Reading contact-table files (/profiles, /tables/{lut,kec,derived}) and the profile
geometry the table figures draw."""
from __future__ import annotations

import math
import os
from dataclasses import dataclass, field
from typing import Dict, List, Optional, Tuple

import numpy as np

from .h5 import ResultFileError, open_h5, _attrs, _read_ds, _str


# y values [m] of the contact figure (paper Fig. 1 uses a "set of discrete values")
CONTACT_Y = (0.0, 3e-3, 6e-3, 8e-3)
Y_COLORS = ("#1f5fa8", "#1b7837", "#e08214", "#b2182b", "#6a3d9a", "#555555")
RAIL_FILL, RAIL_EDGE = "#d9d9d9", "#444444"
TRANS_FILL = "#f2c7a5"       # regularised transition intervals
FLANGE_NEAR = 0.1e-3         # flange point drawn when its gap is below this [m]


class TablesFileError(ResultFileError):
    """Missing file, not HDF5, not a tables file, or a broken group. Message is one line."""


# --------------------------------------------------------------------------------------------
# Reading
# --------------------------------------------------------------------------------------------
@dataclass
class Profile:
    name: str
    s: np.ndarray          # [m]
    h: np.ndarray          # [m] wheel radius / rail head height


@dataclass
class Lut:
    y: np.ndarray                          # [ny] m
    xi_g: np.ndarray                       # [ng] m
    ch: Dict[str, np.ndarray]              # channel -> [ng, ny]
    attrs: Dict[str, object]
    two_point: Dict[str, np.ndarray]       # y, xi_g, side (+1 left wheel, -1 right); may be empty

    def row(self, xi: float = 0.0) -> int:
        return int(np.argmin(np.abs(self.xi_g - xi)))

    def get(self, name: str, row: int) -> Optional[np.ndarray]:
        v = self.ch.get(name)
        return None if v is None else v[row]

    def two_points(self, xi: float, tol: float = 1e-9) -> List[Tuple[float, int]]:
        """(y, side) of the two-point contacts at gauge variation xi."""
        tp = self.two_point
        if not tp or tp["y"].size == 0:
            return []
        sel = np.abs(tp["xi_g"] - xi) <= tol
        return [(float(a), int(round(b))) for a, b in zip(tp["y"][sel], tp["side"][sel])]


@dataclass
class Kec:
    s_k: np.ndarray
    data: Dict[str, np.ndarray]            # left_f, left_s_w, ..., right_transition_hi
    attrs: Dict[str, object]

    def sides(self) -> List[str]:
        return [sd for sd in ("left", "right") if f"{sd}_s_w" in self.data]

    def get(self, side: str, key: str) -> Optional[np.ndarray]:
        return self.data.get(f"{side}_{key}")

    def transitions(self, side: str) -> List[Tuple[float, float, float]]:
        s, lo, hi = (self.get(side, k) for k in ("transition_s", "transition_lo", "transition_hi"))
        if s is None or lo is None or hi is None:
            return []
        return [(float(a), float(b), float(c)) for a, b, c in zip(s, lo, hi)]


@dataclass
class Tables:
    path: str
    attrs: Dict[str, object]
    geom: Dict[str, object]                # /tables attrs: lw, lr, beta, r0, config_hash
    wheel: Optional[Profile] = None
    rail: Optional[Profile] = None
    lut: Optional[Lut] = None
    kec: Optional[Kec] = None
    derived: Optional[Dict[str, np.ndarray]] = None
    groups: List[str] = field(default_factory=list)

    @property
    def stem(self) -> str:
        return os.path.splitext(os.path.basename(self.path))[0]

    def g(self, key: str) -> Optional[float]:
        v = self.geom.get(key)
        return float(v) if isinstance(v, (int, float)) and np.isfinite(v) else None

    @property
    def has_geometry(self) -> bool:
        return all(self.g(k) is not None for k in ("lw", "lr", "beta", "r0"))

    @property
    def conicity(self) -> Optional[Tuple[np.ndarray, np.ndarray]]:
        d = self.derived or {}
        a, t = d.get("conicity_amplitude"), d.get("tan_gamma_e")
        if a is None or t is None:
            return None
        ok = np.isfinite(a) & np.isfinite(t)
        return (a[ok], t[ok]) if ok.any() else None


def _ds(group, name, where, units=None, ndim=1) -> np.ndarray:
    a = _read_ds(group, name, where, units)
    if ndim == 2:
        shape = group[name].shape
        if len(shape) != 2:
            raise TablesFileError(f"dataset {where}/{name} is not 2-D (shape {shape})")
        a = a.reshape(shape)
    return a


def _read_profile(f, name: str) -> Optional[Profile]:
    where = f"/profiles/{name}"
    if "profiles" not in f or name not in f["profiles"]:
        return None
    g = f["profiles"][name]
    s, h = _ds(g, "s", where, "m"), _ds(g, "h", where, "m")
    if s.size < 2 or s.size != h.size:
        raise TablesFileError(f"{where}: s and h differ in length or have < 2 points")
    return Profile(name=_str(g.attrs.get("name", name)), s=s, h=h)


def _read_lut(g) -> Lut:
    W = "/tables/lut"
    y, xi = _ds(g, "y", W, "m"), _ds(g, "xi_g", W, "m")
    if y.size < 2 or xi.size < 1:
        raise TablesFileError(f"{W}: y has {y.size} and xi_g {xi.size} values")
    ch = {}
    for name in g:
        if name in ("y", "xi_g") or not hasattr(g[name], "shape"):
            continue
        if len(g[name].shape) != 2:
            continue
        a = _ds(g, name, W, ndim=2)
        if a.shape != (xi.size, y.size):
            raise TablesFileError(f"{W}/{name} has shape {a.shape}, expected "
                                  f"[xi_g {xi.size}][y {y.size}]")
        ch[name] = a
    for need in ("z", "phi"):
        if need not in ch:
            raise TablesFileError(f"missing dataset {W}/{need}")
    tp = {}
    if "two_point" in g:
        tg = g["two_point"]
        tp = {k: _ds(tg, k, W + "/two_point") for k in ("y", "xi_g", "side")}
        if len({v.size for v in tp.values()}) != 1:
            raise TablesFileError(f"{W}/two_point datasets differ in length")
    return Lut(y=y, xi_g=xi, ch=ch, attrs=_attrs(g), two_point=tp)


def _read_kec(g) -> Kec:
    W = "/tables/kec"
    sk = _ds(g, "s_k", W, "m")
    data = {}
    for name in g:
        if name == "s_k" or not hasattr(g[name], "shape"):
            continue
        data[name] = _ds(g, name, W)
    sides = [sd for sd in ("left", "right") if f"{sd}_s_w" in data or f"{sd}_f" in data]
    if not sides:
        raise TablesFileError(f"missing dataset {W}/left_s_w")
    for sd in sides:
        for k in ("f", "s_w"):
            if f"{sd}_{k}" not in data:
                raise TablesFileError(f"missing dataset {W}/{sd}_{k}")
        for k in ("f", "s_w", "s_r", "weight"):
            v = data.get(f"{sd}_{k}")
            if v is not None and v.size != sk.size:
                raise TablesFileError(f"{W}/{sd}_{k} has {v.size} values, s_k {sk.size}")
        t = [data.get(f"{sd}_transition_{k}") for k in ("s", "lo", "hi")]
        if all(v is not None for v in t) and len({v.size for v in t}) != 1:
            raise TablesFileError(f"{W}/{sd}_transition_* differ in length")
    if sk.size < 2:
        raise TablesFileError(f"{W}/s_k has {sk.size} value(s)")
    return Kec(s_k=sk, data=data, attrs=_attrs(g))


def _read_derived(g) -> Dict[str, np.ndarray]:
    W = "/tables/derived"
    d = {"y": _ds(g, "y", W, "m"), "delta_r": _ds(g, "delta_r", W, "m")}
    for k, u in (("z", "m"), ("phi", "rad"), ("r_left", "m"), ("r_right", "m"),
                 ("delta_gamma", "rad")):
        if k in g:
            d[k] = _ds(g, k, W, u)
    bad = [k for k, v in d.items() if v.size != d["y"].size]
    if bad:
        raise TablesFileError(f"{W}: {', '.join(bad)} differ in length from y")
    if "conicity_amplitude" in g or "tan_gamma_e" in g:
        a = _ds(g, "conicity_amplitude", W, "m")
        t = _ds(g, "tan_gamma_e", W, "-")
        if a.size != t.size:
            raise TablesFileError(f"{W}: conicity_amplitude and tan_gamma_e differ in length")
        d["conicity_amplitude"], d["tan_gamma_e"] = a, t
    jumps = {"jump_y": "m", "jump_delta_r_left": "m", "jump_delta_r_right": "m"}
    if all(k in g for k in jumps):  # delta r jumps (engine's located contact-point jumps)
        j = {k: _ds(g, k, W, u) for k, u in jumps.items()}
        if len({v.size for v in j.values()}) != 1:
            raise TablesFileError(f"{W}: jump_y and jump_delta_r_* differ in length")
        d.update(j)
    return d


def delta_r_with_jumps(d: Dict[str, np.ndarray]) -> Tuple[np.ndarray, np.ndarray]:
    """delta r [m] against y [m], with every located jump drawn as a vertical break: the node
    samples, and at each jump the left limit, a NaN gap and the right limit (no line across)."""
    y, dr = d["y"], d["delta_r"]
    if "jump_y" not in d or d["jump_y"].size == 0:
        return y, dr
    ys, vs = list(y), list(dr)
    for yj, lft, rgt in zip(d["jump_y"], d["jump_delta_r_left"], d["jump_delta_r_right"]):
        k = int(np.searchsorted(ys, yj))
        ys[k:k] = [yj, yj, yj]
        vs[k:k] = [lft, np.nan, rgt]
    return np.asarray(ys), np.asarray(vs)


def load_tables(path: str) -> Tables:
    """Open and validate a tables file. Raises TablesFileError with a one-line message."""
    f = open_h5(path, TablesFileError, "tables file")
    try:
        with f:
            if "tables" not in f and "profiles" not in f:
                raise TablesFileError(f"{path}: no /tables group (not a railbench tables file?)")
            t = Tables(path=path, attrs=_attrs(f), groups=sorted(f.keys()),
                       geom=_attrs(f["tables"]) if "tables" in f else {})
            t.wheel = _read_profile(f, "wheel_left")
            t.rail = _read_profile(f, "rail_left")
            if "tables" in f:
                g = f["tables"]
                if "lut" in g:
                    t.lut = _read_lut(g["lut"])
                if "kec" in g:
                    t.kec = _read_kec(g["kec"])
                if "derived" in g:
                    t.derived = _read_derived(g["derived"])
            return t
    except ResultFileError as e:
        if isinstance(e, TablesFileError):
            raise
        raise TablesFileError(f"{path}: {e}") from None
    except (OSError, KeyError, ValueError, TypeError) as e:
        msg = str(e).splitlines()[0] if str(e) else repr(e)
        raise TablesFileError(f"{path}: cannot read ({msg})") from None


# --------------------------------------------------------------------------------------------
# Geometry helpers
# --------------------------------------------------------------------------------------------
def knife_point(y, z, phi, r0: float, lr: float, y_ir=0.0):
    """(s_k, f_k) of the left wheel for a wheelset pose (Eq. 22, docs' form, z_ir = 0).

    s (1 + phi^2) = y_ir - y - phi r0 - phi (z - r0 + phi Lr),  f = z - r0 + phi (Lr + s)."""
    y, z, phi = (np.asarray(v, float) for v in (y, z, phi))
    s = (y_ir - y - phi * r0 - phi * (z - r0 + phi * lr)) / (1.0 + phi * phi)
    return s, z - r0 + phi * (lr + s)


def _wheel_track(p: Profile, y, z, phi, lw, s=None):
    s = p.s if s is None else np.asarray(s, float)
    h = np.interp(s, p.s, p.h)
    return y + lw + s + phi * h, z + phi * (lw + s) - h


def _rail_track(p: Profile, lr, beta, xi=0.0, s=None):
    s = p.s if s is None else np.asarray(s, float)
    h = np.interp(s, p.s, p.h)
    c, sn = math.cos(beta), math.sin(beta)
    return lr + xi / 2 + c * s - sn * h, sn * s + c * h


def _mm(v):
    return np.asarray(v, float) * 1e3


def _fmt_mm(v: float) -> str:
    """Millimetres, short: 0, 3, 6.3, 0.036 (v in metres)."""
    v = float(v)
    if not np.isfinite(v):
        return "?"
    if abs(v) < 1e-9:
        return "0"
    return f"{v * 1e3:.2g}" if abs(v) < 1e-3 else f"{v * 1e3:.2f}".rstrip("0").rstrip(".")


def _contact_nodes(lut: Lut, row: int) -> List[Tuple[int, str]]:
    """LUT nodes (index, tag) for the contact figure: CONTACT_Y inside the grid and the first node
    at or past the left wheel's two-point contact."""
    y = lut.y
    picks = {}
    for v in CONTACT_Y:
        if y[0] - 1e-9 <= v <= y[-1] + 1e-9:
            picks[int(np.argmin(np.abs(y - v)))] = ""
    tps = [ty for ty, side in lut.two_points(float(lut.xi_g[row])) if side > 0]
    if tps:
        i = int(np.searchsorted(y, tps[0] - 1e-12))
        if i < y.size:
            close = [k for k in picks if abs(y[k] - y[i]) < 0.25e-3]
            for k in close:
                del picks[k]
            picks[i] = "two-point"
    return sorted(picks.items(), key=lambda kv: y[kv[0]])


# --------------------------------------------------------------------------------------------
