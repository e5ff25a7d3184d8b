"""Report figures for railbench contact-table files (`workbench tables SCENARIO.lua --out F.h5`).

Reading
    load_tables(path) -> Tables          validated, in-memory copy of /profiles and /tables

Figures (each returns a matplotlib Figure; nothing is written)
    fig_profiles_contact(t)   (a) left wheel on left rail in the wheelset track frame for a few
                              lateral displacements y (LUT nodes: tread contact, flange point
                              when within 0.1 mm); (b) the KEC solved at the same y: knife edge
                              on the equivalent profile f_k(s_k) and the mapped real contact
                              s_w(s_k) on the real wheel profile (paper Fig. 1)
    fig_lut_z(t)              z(y) - z(0) and phi(y) for every gauge variation xi_g, and the
                              z table over (y, xi_g) with the two-point contact line (Fig. 7)
    fig_kec_map(t)            real wheel parameter s_w versus equivalent s_k per wheel, the
                              regularised transitions [lo, hi] shaded, weight w of the flange
                              point B, zoom on the transitions around the largest s_w jump
                              with their end points A and B (Fig. 9, 10)
    fig_rolling_radius(t)     delta r(y) = r_l - r_r and delta gamma(y), two-point contact marked
    fig_conicity(t)           EN 15302 equivalent conicity tan(gamma_e) versus amplitude

Geometry
    knife_point(y, z, phi, r0, lr)      (s_k, f_k) of the left wheel for a wheelset pose
    kec_solve(kec, y, r0, lr)           KEC pose (z, phi, s_lk, s_rk) at y (Eq. 22, Newton)

Driver
    FIGURES                   registry: (suffix, is_available(t), make(t))
    make_figures(t, outdir)   writes every available figure, returns the paths
    summary_line(t)           one-line summary (build times, sizes, conicity at 3 mm, ...)

Conventions (docs/contact_geometry.md, docs/profiles.md): Y to the left, Z up; left wheel
s_w > 0 and left rail s_r > 0 toward the field side; wheel h = radius, rail h = head height
(origin crown top of the uninclined head); rails at +-(Lr + xi_g/2) rotated by +-beta, wheels at
+-Lw; roll enters linearised, A = [[1, -phi], [phi, 1]]:
    wheel point  (y, z) + A (Lw + s_w, -h_w(s_w))
    rail point   (Lr + xi_g/2, 0) + Rx(beta) (s_r, h_r(s_r))
KEC knife point (Eq. 22 in the docs' form, zero irregularity):
    y + s_k + phi (r0 + f_k) - xi_g/2 = 0,   z + phi (Lr + s_k) - r0 - f_k = 0.
A group that is absent only removes its figures; a group that is present but broken (missing
or mis-shaped datasets) makes load_tables raise TablesFileError (one-line message).

Only numpy, matplotlib (Agg) and h5py are used; no scipy.
"""
from __future__ import annotations

import math
import os
from dataclasses import dataclass, field
from typing import Callable, Dict, List, Optional, Tuple

import numpy as np
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.lines import Line2D  # noqa: E402
from matplotlib.patches import Patch  # noqa: E402

import railbench_plots as rp  # noqa: E402
from railbench_plots import A4_WIDTH_IN, DPI, SIDE_STYLE, report_style  # noqa: E402

__all__ = [
    "TablesFileError", "Tables", "Profile", "Lut", "Kec", "load_tables",
    "knife_point", "kec_solve", "fig_profiles_contact", "fig_lut_z", "fig_kec_map",
    "fig_rolling_radius",
    "fig_conicity", "FIGURES", "make_figures", "summary_line", "conicity_at",
]

# y values [m] of the contact figure (paper Fig. 1 uses a "set of discrete values")
CONTACT_Y = (0.0, 3e-3, 6e-3, 8e-3)
Y_COLORS = ("#1f5fa8", "#1b7837", "#e08214", "#b2182b", "#6a3d9a", "#555555")
RAIL_FILL, RAIL_EDGE = "#d9d9d9", "#444444"
TRANS_FILL = "#f2c7a5"       # regularised transition intervals
FLANGE_NEAR = 0.1e-3         # flange point drawn when its gap is below this [m]


class TablesFileError(rp.ResultFileError):
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
    a = rp._read_ds(group, name, where, units)
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
    return Profile(name=rp._str(g.attrs.get("name", name)), s=s, h=h)


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
    return Lut(y=y, xi_g=xi, ch=ch, attrs=rp._attrs(g), two_point=tp)


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
    return Kec(s_k=sk, data=data, attrs=rp._attrs(g))


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
    return d


def load_tables(path: str) -> Tables:
    """Open and validate a tables file. Raises TablesFileError with a one-line message."""
    import h5py

    if not os.path.exists(path):
        raise TablesFileError(f"no such file: {path}")
    if os.path.isdir(path):
        raise TablesFileError(f"is a directory, not a tables file: {path}")
    try:
        f = h5py.File(path, "r")
    except OSError as e:
        msg = str(e).splitlines()[0] if str(e) else type(e).__name__
        raise TablesFileError(f"not a readable HDF5 file: {path} ({msg})") from None
    try:
        with f:
            if "tables" not in f and "profiles" not in f:
                raise TablesFileError(f"{path}: no /tables group (not a railbench tables file?)")
            t = Tables(path=path, attrs=rp._attrs(f), groups=sorted(f.keys()),
                       geom=rp._attrs(f["tables"]) if "tables" in f else {})
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
    except rp.ResultFileError as e:
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
# Figures
# --------------------------------------------------------------------------------------------
def _short(name: str) -> str:
    """'S1002 left wheel' -> 'S1002', '60E1 left rail' -> '60E1'."""
    words = [w for w in name.split() if w.lower() not in ("left", "right", "wheel", "rail")]
    return " ".join(words) or name


def _title(t: Tables) -> str:
    """'<stem> (<wheel> on <rail>)' for the figure titles."""
    if t.wheel is not None and t.rail is not None:
        return f"{t.stem} ({_short(t.wheel.name)} on {_short(t.rail.name)})"
    return t.stem


def _suptitle(fig, text: str, fontsize: float = 9.5):
    """Figure title, split after its ' — ' when it would not fit on one line."""
    max_chars = int(fig.get_size_inches()[0] * 72 / (0.56 * fontsize))
    if len(text) > max_chars and " — " in text:
        head, tail = text.split(" — ", 1)
        text = f"{head} —\n{tail}"
    fig.suptitle(text, fontsize=fontsize)


def _knife_marker():
    """Upward wedge with its tip at the data point (the knife edge of the KEC)."""
    return [(0.0, 0.0), (-0.28, -1.0), (0.28, -1.0), (0.0, 0.0)]


def kec_solve(kec: Kec, y: float, r0: float, lr: float, guess=(None, 0.0, None, None),
              tol: float = 1e-11, max_iter: int = 60
              ) -> Optional[Tuple[float, float, float, float]]:
    """KEC pose (z, phi, s_lk, s_rk) at lateral displacement y, zero irregularity: Newton on the
    four rows of Eq. 22 (docs' form) with f_l, f_r interpolated linearly in the table (slopes
    from the node differences).  None when it does not converge or the table has no right wheel.
    """
    sk = kec.s_k
    fl, fr = kec.get("left", "f"), kec.get("right", "f")
    if fl is None or fr is None:
        return None
    dfl, dfr = np.gradient(fl, sk), np.gradient(fr, sk)
    z0, phi, sl, sr = guess
    if sl is None:
        sl = -y
    if sr is None:
        sr = -y
    z = r0 + float(np.interp(sl, sk, fl)) if z0 is None else z0
    x = np.array([z, phi, sl, sr], float)
    step_max = np.array([1e-3, 5e-3, 1e-3, 1e-3])
    for _ in range(max_iter):
        z, phi, sl, sr = x
        f1, f2 = np.interp(sl, sk, fl), np.interp(sr, sk, fr)
        d1, d2 = np.interp(sl, sk, dfl), np.interp(sr, sk, dfr)
        r = np.array([y + sl + phi * (r0 + f1),
                      y + sr + phi * (r0 + f2),
                      z + phi * (lr + sl) - r0 - f1,
                      z + phi * (-lr + sr) - r0 - f2])
        if np.max(np.abs(r)) < tol:
            return float(z), float(phi), float(sl), float(sr)
        J = np.array([[0.0, r0 + f1, 1 + phi * d1, 0.0],
                      [0.0, r0 + f2, 0.0, 1 + phi * d2],
                      [1.0, lr + sl, phi - d1, 0.0],
                      [1.0, -lr + sr, 0.0, phi - d2]])
        try:
            dx = np.linalg.solve(J, -r)
        except np.linalg.LinAlgError:
            return None
        scale = np.max(np.abs(dx) / step_max)
        x = x + (dx / scale if scale > 1 else dx)
    return None


def fig_profiles_contact(t: Tables):
    """Paper Fig. 1: (a) the left wheel on the left rail in the wheelset track frame at a few
    lateral displacements (LUT nodes at xi_g nearest 0: tread contact, flange point when its gap
    is below 0.1 mm); (b) the KEC at the same y (Eq. 22): knife edge on the equivalent profile
    f_k(s_k) and the mapped contact s_w(s_k) on the real wheel profile."""
    lut, wh, rl = t.lut, t.wheel, t.rail
    lw, lr, beta = t.g("lw"), t.g("lr"), t.g("beta")
    row = lut.row(0.0)
    xi = float(lut.xi_g[row])
    nodes = _contact_nodes(lut, row)
    kec_ok = t.kec is not None and "left_f" in t.kec.data

    # --- data of (a), to size the figure for an equal aspect ratio
    ry, rz = _rail_track(rl, lr, beta, xi)
    x_r, z_r = _mm(ry - lr), _mm(rz)
    wheels = []
    for k, (i, tag) in enumerate(nodes):
        y, z, phi = (float(lut.y[i]), float(lut.ch["z"][row, i]), float(lut.ch["phi"][row, i]))
        wy, wz = _wheel_track(wh, y, z, phi, lw)
        wheels.append((i, tag, y, z, phi, _mm(wy - lr), _mm(wz)))
    # x: the rail head with the whole flange (to 45 mm beyond the gauge side) and 12 mm field side
    x_flange = min([float(w[5].min()) for w in wheels] + [float(x_r.min()) - 25.0])
    x0 = max(x_flange - 3.0, float(x_r.min()) - 45.0)
    x1 = float(x_r.max()) + 12.0
    z_lo, z_hi = float(z_r.min()), 0.0
    for w in wheels:
        vis = (w[5] > x0) & (w[5] < x1)
        if vis.any():
            z_lo, z_hi = min(z_lo, float(w[6][vis].min())), max(z_hi, float(w[6][vis].max()))
    z0, z1 = z_lo - 2.0, z_hi + 2.0
    ax_w_in = A4_WIDTH_IN - 0.62
    ax_h_in = ax_w_in * (z1 - z0) / (x1 - x0)
    n_leg = math.ceil((len(nodes) + 2) / 2)
    h_a = ax_h_in + 0.45 + 0.13 * n_leg
    h_b = 2.9
    with report_style():
        fig = plt.figure(figsize=(A4_WIDTH_IN, h_a + (h_b if kec_ok else 0.0) + 0.3),
                         layout="constrained")
        gs = fig.add_gridspec(2 if kec_ok else 1, 1, height_ratios=[h_a, h_b] if kec_ok else [1])
        ax = fig.add_subplot(gs[0])
        # rail head, fixed in the track frame; its sides continue below the axes
        zb = z0 - 10.0
        xs = np.concatenate([[x_r[0]], x_r, [x_r[-1]]])
        zs = np.concatenate([[zb], z_r, [zb]])
        ax.fill(xs, zs, color=RAIL_FILL, lw=0, zorder=1)
        ax.plot(xs, zs, color=RAIL_EDGE, lw=1.0, zorder=2)
        ax.text(0.5 * (x_r.min() + x_r.max()), z0 + 1.0, rl.name, ha="center",
                va="bottom", fontsize=7, color="#333333", zorder=3)
        handles = []
        sw, fd, fs = (lut.get(n, row) for n in ("left_s_w", "left_flange_delta",
                                                "left_flange_s_w"))
        for k, (i, tag, y, z, phi, xw, zw) in enumerate(wheels):
            col = Y_COLORS[k % len(Y_COLORS)]
            ax.plot(xw, zw, color=col, lw=1.0, zorder=4)
            lab = f"y = {_fmt_mm(y)} mm"
            if tag:
                lab += f" ({tag})"
            if sw is not None:
                cy, cz = _wheel_track(wh, y, z, phi, lw, s=sw[i])
                ax.plot(_mm(cy - lr), _mm(cz), "o", ms=4.5, color=col, mec="white", mew=0.6,
                        zorder=6)
            if fd is not None and fs is not None and fd[i] > -FLANGE_NEAR:
                cy, cz = _wheel_track(wh, y, z, phi, lw, s=fs[i])
                ax.plot(_mm(cy - lr), _mm(cz), "D", ms=4.5, mfc="white", mec=col, mew=1.2,
                        zorder=6)
                lab += (f", flange {'gap' if fd[i] < 0 else 'indentation'} "
                        f"{abs(fd[i]) * 1e3:.2g} mm")
            handles.append(Line2D([], [], color=col, lw=1.0, label=lab))
        handles.append(Line2D([], [], ls="none", marker="o", ms=4.5, color="#555555",
                              mec="white", label="tread contact (LUT)"))
        if any("flange" in h.get_label() for h in handles):
            handles.append(Line2D([], [], ls="none", marker="D", ms=4.5, mfc="white",
                                  mec="#555555", mew=1.2, label="flange point (LUT, elastic)"))
        ax.set_xlim(x0, x1)
        ax.set_ylim(z0, z1)
        ax.set_aspect("equal", adjustable="datalim")
        ax.set_xlabel("Y − $L_r$ [mm]  (track frame, left rail profile origin at 0)")
        ax.set_ylabel("Z [mm]")
        ax.set_title(f"(a) left wheel on left rail in the wheelset track frame, LUT at "
                     f"$\\xi_g$ = {_fmt_mm(xi)} mm", loc="left")
        from matplotlib.transforms import offset_copy
        ax.legend(handles=handles, loc="upper center", bbox_to_anchor=(0.5, 0.0),
                  bbox_transform=offset_copy(ax.transAxes, fig=fig, y=-25, units="points"),
                  ncol=2, fontsize=6.5, handlelength=1.8, columnspacing=1.2, frameon=False)
        if kec_ok:
            _panel_kec_profile(fig.add_subplot(gs[1]), t, wheels)
        _suptitle(fig, f"Wheel/rail profiles and contact points — {_title(t)}")
        # equal aspect: resize (a) until its box matches the data range (no stretched limits)
        for _ in range(3):
            fig.canvas.draw()
            ax.set_xlim(x0, x1)
            ax.set_ylim(z0, z1)
            W, H = fig.get_size_inches()
            pos = ax.get_position(original=True)
            w_in, h_in = pos.width * W, pos.height * H
            delta = w_in * (z1 - z0) / (x1 - x0) - h_in
            if abs(delta) < 0.02:
                break
            h_a = max(h_a + delta, 0.8)
            fig.set_size_inches(W, H + delta)
            if kec_ok:
                gs.set_height_ratios([h_a, h_b])
    return fig


def _panel_kec_profile(ax, t: Tables, wheels):
    wh, kec = t.wheel, t.kec
    lr, r0 = t.g("lr"), t.g("r0")
    sk, fk, swk = kec.s_k, kec.get("left", "f"), kec.get("left", "s_w")
    ax.plot(_mm(wh.s), -_mm(wh.h - r0), color="#777777", lw=0.9, ls=(0, (6, 2, 1.2, 2)),
            label="real wheel $-(h_w(s_w) - r_0)$ vs $s_w$", zorder=2)
    ax.plot(_mm(sk), -_mm(fk), color="black", lw=1.2,
            label="KEC-equivalent $-f_k(s_k)$ vs $s_k$", zorder=3)
    for _, lo, hi in kec.transitions("left"):
        ax.axvspan(_mm(lo), _mm(hi), color=TRANS_FILL, lw=0, alpha=0.8, zorder=0)
    failed = []
    for k, (i, tag, y, z, phi, _, _) in enumerate(wheels):
        col = Y_COLORS[k % len(Y_COLORS)]
        s_l, _ = knife_point(y, z, phi, r0, lr)
        s_r, _ = knife_point(-y, z, -phi, r0, lr)
        sol = kec_solve(kec, y, r0, lr, guess=(z, phi, float(s_l), -float(s_r)))
        if sol is None:
            failed.append(_fmt_mm(y))
            continue
        s_k = sol[2]
        f_k = float(np.interp(s_k, sk, fk))
        ax.plot(_mm(s_k), -_mm(f_k), marker=_knife_marker(), ms=11, color=col, mec="black",
                mew=0.4, ls="none", zorder=5)
        if swk is not None:
            s_w = float(np.interp(s_k, sk, swk))
            h = float(np.interp(s_w, wh.s, wh.h))
            ax.plot(_mm(s_w), -_mm(h - r0), "o", ms=4.5, color=col, mec="white", mew=0.6,
                    zorder=5)
            ax.annotate("", xy=(_mm(s_w), -_mm(h - r0)), xytext=(_mm(s_k), -_mm(f_k)),
                        arrowprops=dict(arrowstyle="-", color=col, lw=0.7, ls=":",
                                        shrinkA=2, shrinkB=2), zorder=4)
    lo = min(float(sk.min()), float(wh.s.min()))
    hi = max(float(sk.max()), float(wh.s.max()))
    ax.set_xlim(_mm(lo) - 2, _mm(hi) + 2)
    handles, _ = ax.get_legend_handles_labels()
    handles += [Line2D([], [], ls="none", marker=_knife_marker(), ms=9, color="#555555",
                       mec="black", mew=0.4, label="knife edge at $s_k$ (KEC, Eq. 22)"),
                Line2D([], [], ls="none", marker="o", ms=4.5, color="#555555", mec="white",
                       label="real contact $s_w(s_k)$ (KEC map)")]
    if kec.transitions("left"):
        handles.append(Patch(color=TRANS_FILL, label="regularised transitions"))
    ax.legend(handles=handles, loc="lower right", fontsize=6.5, ncol=1, handlelength=2.2)
    if failed:
        ax.text(0.01, 0.03, f"KEC solve failed at y = {', '.join(failed)} mm",
                transform=ax.transAxes, fontsize=6.5, color="#d00000")
    ax.set_xlabel("profile parameter $s_w$, $s_k$ [mm]  (left wheel, + field side)")
    ax.set_ylabel("$-(h_w - r_0)$, $-f_k$ [mm]")
    ax.set_title("(b) KEC (Eq. 22) at the same y: equivalent and real contact points",
                 loc="left")


def _xi_colors(xi: np.ndarray):
    import matplotlib.colors as mcolors
    n = xi.size
    cmap = plt.get_cmap("coolwarm")
    if n == 1:
        return ["black"], None, None
    edges = np.concatenate([[xi[0] - 0.5 * (xi[1] - xi[0])], 0.5 * (xi[1:] + xi[:-1]),
                            [xi[-1] + 0.5 * (xi[-1] - xi[-2])]]) * 1e3
    norm = mcolors.BoundaryNorm(edges, cmap.N)
    cols = [cmap(norm(v * 1e3)) for v in xi]
    return cols, cmap, norm


def fig_lut_z(t: Tables):
    """Paper Fig. 7: (a) z(y, xi_g) - z(0, 0) and (b) phi(y, xi_g) for every gauge variation,
    (c) the z table over (y, xi_g) with the two-point contact positions."""
    lut = t.lut
    y = _mm(lut.y)
    xi = lut.xi_g
    r0 = lut.row(0.0)
    i0 = int(np.argmin(np.abs(lut.y)))
    z0 = float(lut.ch["z"][r0, i0])
    cols, cmap, norm = _xi_colors(xi)
    tp = lut.two_point if lut.two_point and lut.two_point["y"].size else None
    table = xi.size > 1
    with report_style():
        if table:
            fig, axes = plt.subplots(3, 1, figsize=(A4_WIDTH_IN, 7.4), sharex=True,
                                     layout="constrained", height_ratios=[1, 1, 1.05])
            a1, a2, a3 = axes
        else:
            fig, axes = plt.subplots(2, 1, figsize=(A4_WIDTH_IN, 5.0), sharex=True,
                                     layout="constrained")
            a1, a2 = axes
        for k in range(xi.size):
            main = k == r0
            kw = dict(color="black" if main else cols[k], lw=1.5 if main else 0.9,
                      zorder=3 if main else 2)
            a1.plot(y, _mm(lut.ch["z"][k] - z0), **kw)
            a2.plot(y, lut.ch["phi"][k] * 1e3, **kw)
        if tp is not None:
            for ty, tx in zip(tp["y"], tp["xi_g"]):
                k = lut.row(tx)
                if abs(xi[k] - tx) > 1e-9:   # not one of the stored gauge rows
                    continue
                a1.plot(ty * 1e3, np.interp(ty, lut.y, lut.ch["z"][k] - z0) * 1e3, "o", ms=4,
                        mfc="white", mec="black", mew=0.9, zorder=5)
                a2.plot(ty * 1e3, np.interp(ty, lut.y, lut.ch["phi"][k]) * 1e3, "o", ms=4,
                        mfc="white", mec="black", mew=0.9, zorder=5)
        a1.set_ylabel("$z - z(0)$ [mm]")
        a1.set_title(f"(a) wheelset vertical displacement, $z(0)$ = z at y = 0, "
                     f"$\\xi_g$ = {_fmt_mm(xi[r0])} mm: $z(0) - r_0$ = "
                     f"{(z0 - (t.g('r0') or z0)) * 1e3:+.4f} mm" if t.g("r0") is not None
                     else "(a) wheelset vertical displacement", loc="left")
        a2.set_ylabel("$\\phi$ [mrad]")
        a2.set_title("(b) wheelset roll angle (+ lifts the left wheel)", loc="left")
        hl = [Line2D([], [], color="black", lw=1.5, label=f"$\\xi_g$ = {_fmt_mm(xi[r0])} mm")]
        if xi.size > 1:
            hl.append(Line2D([], [], color=cols[0], lw=0.9, label="other $\\xi_g$ (colour bar)"))
        if tp is not None:
            hl.append(Line2D([], [], ls="none", marker="o", ms=4, mfc="white", mec="black",
                             label="two-point contact"))
        a1.legend(handles=hl, loc="upper center", fontsize=7)
        # (c) the table itself
        Z = _mm(lut.ch["z"] - z0)
        if table:
            xe = np.concatenate([[y[0]], 0.5 * (y[1:] + y[:-1]), [y[-1]]])
            ge = np.concatenate([[xi[0] - 0.5 * (xi[1] - xi[0])], 0.5 * (xi[1:] + xi[:-1]),
                                 [xi[-1] + 0.5 * (xi[-1] - xi[-2])]]) * 1e3
            pm = a3.pcolormesh(xe, ge, Z, cmap="viridis", shading="flat", rasterized=True)
            cb = fig.colorbar(pm, ax=a3, pad=0.01, fraction=0.04)
            cb.set_label("$z - z(0)$ [mm]")
            if np.ptp(Z) > 0:
                cs = a3.contour(y, xi * 1e3, Z, levels=8, colors="white", linewidths=0.4,
                                alpha=0.8)
                a3.clabel(cs, fontsize=6, fmt="%.2g")
            if tp is not None:
                for side, mk in ((1, ">"), (-1, "<")):
                    sel = np.round(tp["side"]) == side
                    if sel.any():
                        o = np.argsort(tp["xi_g"][sel])
                        a3.plot(tp["y"][sel][o] * 1e3, tp["xi_g"][sel][o] * 1e3, color="#d00000",
                                lw=1.0, marker=mk, ms=3.5,
                                label=f"two-point contact ({'left' if side > 0 else 'right'} "
                                      "wheel)")
            a3.set_ylabel("$\\xi_g$ [mm]")
            a3.grid(False)
            # discrete colour bar of the gauge variations, shared by (a) and (b)
            sm = plt.cm.ScalarMappable(norm=norm, cmap=cmap)
            cb2 = fig.colorbar(sm, ax=[a1, a2], pad=0.01, fraction=0.04, ticks=xi * 1e3)
            cb2.set_label("gauge variation $\\xi_g$ [mm]")
            cb2.ax.set_yticklabels([_fmt_mm(v) for v in xi])
            a3.set_title("(c) contact lookup table $z(y, \\xi_g) - z(0)$"
                         + (", two-point contact in red (▶ left, ◀ right wheel)"
                            if tp is not None else ""), loc="left")
        axes[-1].set_xlabel("lateral displacement y [mm]  (+ left)")
        axes[-1].set_xlim(y[0], y[-1])
        _suptitle(fig, f"Contact lookup table (LUT), {lut.y.size} × {xi.size} nodes — "
                       f"{_title(t)}")
    return fig


def _kec_real_points(t: Tables, side: str):
    """(s_k, s_w) of the real LUT contact at xi_g nearest 0, from the centre up to the two-point
    contact of this side's flange (the LUT keeps the tread contact beyond it)."""
    lut = t.lut
    if lut is None or t.g("r0") is None or t.g("lr") is None:
        return None
    row = lut.row(0.0)
    sw = lut.get(f"{side}_s_w", row)
    if sw is None:
        return None
    sgn = 1.0 if side == "left" else -1.0
    y, z, phi = lut.y, lut.ch["z"][row], lut.ch["phi"][row]
    xi = float(lut.xi_g[row])
    # mirror: the right wheel's knife point is the left one of the mirrored pose, negated
    s_k, _ = knife_point(sgn * y, z, sgn * phi, t.g("r0"), t.g("lr"), y_ir=xi / 2)
    s_k = sgn * s_k
    keep = np.ones_like(y, bool)
    for ty, ts in lut.two_points(xi):
        if ts > 0:
            keep &= y < ty
        else:
            keep &= y > ty
    return s_k[keep], sw[keep]


def _main_cluster(kec: Kec, side: str) -> List[Tuple[float, float, float]]:
    """The transitions of `side` whose intervals touch each other, grouped; returns the group
    with the largest change of s_w across it (the tread-flange transition), [] if none."""
    sw = kec.get(side, "s_w")
    trs = sorted(kec.transitions(side), key=lambda tr: tr[1])
    groups: List[List[Tuple[float, float, float]]] = []
    for tr in trs:
        if groups and tr[1] <= groups[-1][-1][2] + 1e-7:
            groups[-1].append(tr)
        else:
            groups.append([tr])
    best, jump = [], -1.0
    for g in groups:
        lo, hi = g[0][1], max(tr[2] for tr in g)
        d = abs(float(np.interp(hi, kec.s_k, sw) - np.interp(lo, kec.s_k, sw)))
        if d > jump:
            best, jump = g, d
    return best


def fig_kec_map(t: Tables):
    """Paper Fig. 9/10: s_w(s_k) of each wheel with the regularised transitions, the weight w of
    the flange-side point B, and a zoom on the largest transition with A (tread end) and B."""
    kec = t.kec
    sides = kec.sides()
    sk = kec.s_k
    zoom = any(_main_cluster(kec, sd) for sd in sides)
    weight = any(kec.get(sd, "weight") is not None for sd in sides)
    any_tr = any(kec.transitions(sd) for sd in sides)
    rows = ["map"] + (["weight"] if weight else []) + (["zoom"] if zoom else [])
    hr = {"map": 1.5, "weight": 0.7, "zoom": 1.4}
    with report_style():
        fig, axes = plt.subplots(len(rows), len(sides),
                                 figsize=(A4_WIDTH_IN, 0.8 + sum(1.45 * hr[r] for r in rows)),
                                 squeeze=False, layout="constrained",
                                 height_ratios=[hr[r] for r in rows])
        for c, sd in enumerate(sides):
            col = SIDE_STYLE[sd]["color"]
            sw = kec.get(sd, "s_w")
            w = kec.get(sd, "weight")
            trs = kec.transitions(sd)
            a1 = axes[0, c]
            a2 = axes[1, c] if weight else None
            if a2 is not None:
                a2.sharex(a1)
            for _, lo, hi in trs:
                for a in (a1, a2):
                    if a is not None:
                        a.axvspan(_mm(lo), _mm(hi), color=TRANS_FILL, lw=0, alpha=0.8, zorder=0)
            real = _kec_real_points(t, sd)
            if real is not None and real[0].size:
                a1.plot(_mm(real[0]), _mm(real[1]), ".", ms=2.2, color="#888888", zorder=2,
                        label="real contact (LUT, $\\xi_g$ = 0)")
            a1.plot(_mm(sk), _mm(sw), color=col, lw=1.1, zorder=3, label="KEC table $s_w(s_k)$")
            a1.set_title(f"{sd} wheel", loc="left")
            a1.set_ylabel("$s_w$ [mm]")
            a1.legend(loc="upper left", fontsize=6.5)
            a1.set_xlim(_mm(sk[0]), _mm(sk[-1]))
            if a2 is not None:
                if w is not None:
                    a2.plot(_mm(sk), w, color=col, lw=1.0)
                else:
                    a2.text(0.5, 0.5, "no weight dataset", transform=a2.transAxes, ha="center",
                            va="center", fontsize=7, color="#777777")
                a2.set_ylim(-0.08, 1.12)
                a2.set_ylabel("weight w of B")
            (a2 or a1).set_xlabel("equivalent parameter $s_k$ [mm]")
            if zoom:
                _kec_zoom(axes[-1, c], t, sd, col, real)
        if any_tr:
            hl = [Patch(color=TRANS_FILL, label="regularised transition [lo, hi]: $\\hat d$ = "
                        f"{_fmt_mm(kec.attrs.get('dhat', np.nan))} mm (flange side), $\\bar d$ = "
                        f"{_fmt_mm(kec.attrs.get('dbar', np.nan))} mm")]
            rp._bottom_legend(fig, [hl], fig.get_size_inches()[1])
        _suptitle(fig, f"KEC lookup table: real versus equivalent wheel parameter — {_title(t)}")
    return fig


def _kec_zoom(ax, t: Tables, sd: str, col, real):
    """Zoom on the main group of transitions: s_w(s_k), the real LUT contact, the end points A
    (field-side end, w = 0) and B (flange-side end, w = 1) of every transition, w dashed."""
    kec = t.kec
    sk, sw, w = kec.s_k, kec.get(sd, "s_w"), kec.get(sd, "weight")
    group = _main_cluster(kec, sd)
    if not group:
        ax.text(0.5, 0.5, "no transition", transform=ax.transAxes, ha="center", va="center")
        ax.set_axis_off()
        return
    lo, hi = group[0][1], max(tr[2] for tr in group)
    width = hi - lo
    x0, x1 = lo - 0.6 * width, hi + 0.6 * width
    # shading and the dashed weight on a twin axis drawn below the s_w axis
    tw = ax.twinx()
    tw.grid(False)
    tw.set_zorder(ax.get_zorder() - 1)
    ax.patch.set_visible(False)
    for _, a, b in kec.transitions(sd):
        if b > x0 and a < x1:
            tw.axvspan(_mm(a), _mm(b), color=TRANS_FILL, lw=0, alpha=0.8, zorder=0)
    sel = (sk >= x0) & (sk <= x1)
    if real is not None:
        rs = (real[0] >= x0) & (real[0] <= x1)
        ax.plot(_mm(real[0][rs]), _mm(real[1][rs]), ".", ms=3, color="#888888", zorder=2)
    ax.plot(_mm(sk[sel]), _mm(sw[sel]), color=col, lw=1.2, marker=".", ms=2.5, zorder=3)
    # A: field-side end (w = 0), B: flange-side end (w = 1); left flange side = smaller s_k
    ends: Dict[float, List[str]] = {}
    n = len(group)
    order = group if sd == "right" else group[::-1]   # numbered from the field side
    for k, (sj, a, b) in enumerate(order):
        ax.axvline(_mm(sj), color="#555555", lw=0.6, ls=":", zorder=1)
        sub = f"$_{k + 1}$" if n > 1 else ""
        pa, pb = (b, a) if sd == "left" else (a, b)
        for key, name in ((pa, "A"), (pb, "B")):
            match = next((e for e in ends if abs(e - key) < 1e-7), key)
            ends.setdefault(match, []).append(name + sub)
    rising = float(np.interp(hi, sk, sw)) >= float(np.interp(lo, sk, sw))
    for at, names in ends.items():
        v = float(np.interp(at, sk, sw))
        ax.plot(_mm(at), _mm(v), "o", ms=5, mfc="white", mec="black", mew=1.0, zorder=5)
        ax.annotate(f"{' = '.join(names)}: {v * 1e3:.1f} mm", (_mm(at), _mm(v)),
                    xytext=(-5 if rising else 5, 5), textcoords="offset points",
                    ha="right" if rising else "left", va="bottom", fontsize=6.5,
                    bbox=dict(boxstyle="round,pad=0.15", fc="white", ec="none", alpha=0.8),
                    zorder=6)
    ax.set_xlim(_mm(x0), _mm(x1))
    lo_y, hi_y = ax.get_ylim()
    pad = 0.12 * (hi_y - lo_y)
    ax.set_ylim(lo_y - pad, hi_y + pad)
    ax.set_ylabel("$s_w$ [mm]")
    ax.set_xlabel("$s_k$ [mm]")
    js = ", ".join(f"{tr[0] * 1e3:.2f}" for tr in group)
    ax.set_title(f"zoom: jump{'s' if n > 1 else ''} at $s_k$ = {js} mm", loc="left", fontsize=8)
    tw.set_ylim(-0.08, 1.12)
    if w is not None:
        tw.plot(_mm(sk[sel]), w[sel], color="#333333", lw=0.9, ls=(0, (4, 2.5)))
        tw.set_ylabel("weight w (dashed)", fontsize=7)
    else:
        tw.set_yticks([])


def fig_rolling_radius(t: Tables):
    """delta r(y) = r_l - r_r [mm] (with r_l - r0, r_r - r0) and delta gamma(y) [deg] at
    xi_g = 0, two-point contact positions marked."""
    d = t.derived
    y = _mm(d["y"])
    has_g = "delta_gamma" in d
    tps = t.lut.two_points(float(t.lut.xi_g[t.lut.row(0.0)])) if t.lut is not None else []
    with report_style():
        fig, axes = plt.subplots(2 if has_g else 1, 1, figsize=(A4_WIDTH_IN, 4.9 if has_g else 2.9),
                                 sharex=True, squeeze=False, layout="constrained")
        a1 = axes[0, 0]
        a1.plot(y, _mm(d["delta_r"]), color="black", lw=1.4, label="$\\Delta r = r_l - r_r$",
                zorder=3)
        r0 = t.g("r0")
        if r0 is not None:
            for sd in ("left", "right"):
                if f"r_{sd}" in d:
                    a1.plot(y, _mm(d[f"r_{sd}"] - r0), lw=0.8, label=f"$r_{sd[0]} - r_0$",
                            **SIDE_STYLE[sd])
        a1.axhline(0, color="k", lw=0.5)
        a1.set_ylabel("rolling radius [mm]")
        a1.set_title("(a) rolling radius difference ($\\xi_g$ = 0)", loc="left")
        axs = [a1]
        if has_g:
            a2 = axes[1, 0]
            a2.plot(y, np.degrees(d["delta_gamma"]), color="black", lw=1.4,
                    label="$\\Delta\\gamma = \\gamma_l - \\gamma_r$")
            a2.axhline(0, color="k", lw=0.5)
            a2.set_ylabel("$\\Delta\\gamma$ [deg]")
            a2.set_title("(b) contact angle difference", loc="left")
            axs.append(a2)
        for ty, side in tps:
            for a in axs:
                a.axvline(ty * 1e3, color="#d00000", lw=0.8, ls=(0, (4, 2)), zorder=1)
        if tps:
            top = a1.secondary_xaxis("top")
            top.set_xticks([ty * 1e3 for ty, _ in tps])
            top.set_xticklabels([f"two-point ({'left' if s > 0 else 'right'} wheel)\n"
                                 f"y = {ty * 1e3:+.2f} mm" for ty, s in tps], fontsize=6.5,
                                color="#d00000")
            top.tick_params(direction="out", length=3, color="#d00000")
        a1.legend(loc="lower right", fontsize=7)
        axs[-1].set_xlabel("lateral displacement y [mm]  (+ left)")
        axs[-1].set_xlim(y[0], y[-1])
        _suptitle(fig, f"Rolling radius and contact angle difference — {_title(t)}")
    return fig


def conicity_at(t: Tables, amplitude: float) -> Optional[float]:
    c = t.conicity
    if c is None:
        return None
    a, g = c
    if amplitude < a.min() - 1e-12 or amplitude > a.max() + 1e-12:
        return None
    return float(np.interp(amplitude, a, g))


def fig_conicity(t: Tables):
    """EN 15302 equivalent conicity tan(gamma_e) versus amplitude, with delta r / (2 y)."""
    a, g = t.conicity
    with report_style():
        fig, ax = plt.subplots(figsize=(A4_WIDTH_IN, 3.4), layout="constrained")
        ax.plot(_mm(a), g, color="#1f5fa8", lw=1.5, marker="o", ms=2.5,
                label="tan $\\gamma_e$ (EN 15302, Annex B method)", zorder=3)
        d = t.derived
        if d is not None:
            y, dr = d["y"], d["delta_r"]
            sel = (y > 0.25e-3) & (y <= a.max() * 1.05)
            if sel.any():
                ax.plot(_mm(y[sel]), dr[sel] / (2 * y[sel]), color="#777777", lw=0.9,
                        ls=(0, (4, 2.5)), label="$\\Delta r(y) / (2y)$ (local, for comparison)",
                        zorder=2)
        v3 = conicity_at(t, 3e-3)
        if v3 is not None:
            ax.plot([3.0, 3.0], [0, v3], color="#b2182b", lw=0.7, ls=":")
            ax.plot([0, 3.0], [v3, v3], color="#b2182b", lw=0.7, ls=":")
            ax.plot(3.0, v3, "o", ms=6, mfc="white", mec="#b2182b", mew=1.4, zorder=4)
            ax.annotate(f"tan $\\gamma_e$ = {v3:.3f} at $\\hat y$ = 3 mm", (3.0, v3),
                        xytext=(0.5, v3 * 0.45), textcoords="data", fontsize=8, color="#b2182b",
                        ha="left", va="center",
                        bbox=dict(boxstyle="round,pad=0.25", fc="white", ec="#b2182b", lw=0.5),
                        arrowprops=dict(arrowstyle="-", color="#b2182b", lw=0.6,
                                        shrinkA=0, shrinkB=4), zorder=5)
        ax.set_xlim(0, max(_mm(a.max()) * 1.03, 3.5))
        hi = float(np.nanmax(g))
        ax.set_ylim(0, hi * 1.25 if hi > 0 else 1)
        ax.set_xlabel("amplitude $\\hat y$ [mm]")
        ax.set_ylabel("equivalent conicity tan $\\gamma_e$ [-]")
        ax.legend(loc="upper right", fontsize=7)
        ax.set_title("from the rolling radius difference $\\Delta r(y)$ at $\\xi_g$ = 0",
                     loc="left")
        _suptitle(fig, f"Equivalent conicity (EN 15302) — {_title(t)}")
    return fig


# --------------------------------------------------------------------------------------------
# Registry, driver, summary
# --------------------------------------------------------------------------------------------
@dataclass
class FigureSpec:
    suffix: str
    is_available: Callable[[Tables], bool]
    make: Callable[[Tables], "plt.Figure"]
    description: str = ""


FIGURES: List[FigureSpec] = [
    FigureSpec("profiles_contact",
               lambda t: t.lut is not None and t.wheel is not None and t.rail is not None
               and t.has_geometry, fig_profiles_contact,
               "profiles in the wheelset frame, contact points, KEC-equivalent profile"),
    FigureSpec("lut_z", lambda t: t.lut is not None, fig_lut_z,
               "z(y) - z(0) and phi(y) for every gauge variation, z table"),
    FigureSpec("kec_map", lambda t: t.kec is not None, fig_kec_map,
               "s_w versus s_k with the regularised transitions and the weight"),
    FigureSpec("rolling_radius", lambda t: t.derived is not None, fig_rolling_radius,
               "delta r(y) and delta gamma(y)"),
    FigureSpec("conicity", lambda t: t.conicity is not None, fig_conicity,
               "EN 15302 tan gamma_e versus amplitude"),
]


def make_figures(t: Tables, outdir: Optional[str] = None, stem: Optional[str] = None,
                 dpi: int = DPI, fmt: str = "png") -> List[str]:
    """Write every figure the file's content allows; return the written paths."""
    outdir = outdir or os.path.dirname(os.path.abspath(t.path))
    stem = stem or t.stem
    os.makedirs(outdir, exist_ok=True)
    written = []
    for spec in FIGURES:
        if not spec.is_available(t):
            continue
        fig = spec.make(t)
        path = os.path.join(outdir, f"{stem}_{spec.suffix}.{fmt}")
        try:
            fig.savefig(path, dpi=dpi)
        finally:
            plt.close(fig)
        written.append(path)
    return written


def _bytes(v) -> str:
    v = float(v)
    return f"{v / 1e6:.2f} MB" if v >= 1e5 else f"{v / 1e3:.1f} kB"


def _stats(a: Dict[str, object]) -> List[str]:
    out = []
    bt = a.get("build_time_s")
    if isinstance(bt, (int, float)):
        out.append(f"{bt:.3g} s")
    if isinstance(a.get("bytes"), (int, float)):
        out.append(_bytes(a["bytes"]))
    fl = a.get("failures")
    if isinstance(fl, (int, float)) and fl:
        out.append(f"{int(fl)} FAILURES")
    wn = [w for w in str(a.get("warnings", "")).split("\n") if w.strip()]
    if wn:
        out.append(f"{len(wn)} warning{'s' if len(wn) > 1 else ''}")
    return out


def summary_line(t: Tables) -> str:
    """'tables: LUT 361 x 11 (y x xi_g) 0.15 s, 4.84 MB; KEC 465 points 0.06 s, 0.22 MB;
    tan(gamma_e) at 3 mm = 0.177; two-point contact at y = 6.260 mm; config <hash>'."""
    parts = []
    if t.lut is not None:
        parts.append(f"LUT {t.lut.y.size} x {t.lut.xi_g.size} (y x xi_g) "
                     + ", ".join(_stats(t.lut.attrs)))
    if t.kec is not None:
        parts.append(f"KEC {t.kec.s_k.size} points " + ", ".join(_stats(t.kec.attrs)))
    if t.derived is not None:
        v3 = conicity_at(t, 3e-3)
        parts.append(f"tan(gamma_e) at 3 mm = {v3:.3f}" if v3 is not None
                     else "tan(gamma_e) at 3 mm: n/a")
    if t.lut is not None:
        tps = t.lut.two_points(float(t.lut.xi_g[t.lut.row(0.0)]))
        if tps:
            parts.append("two-point contact at y = " + ", ".join(
                f"{ty * 1e3:+.3f} mm" for ty, _ in sorted(tps)))
    h = t.geom.get("config_hash")
    if h:
        parts.append(f"config {h}")
    return "tables: " + ("; ".join(p.strip() for p in parts) if parts else "no tables")
