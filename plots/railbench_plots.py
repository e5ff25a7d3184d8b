"""Report figures for railbench result files (HDF5 written by the C++ engine).

Reading
    load_result(path) -> Result          validated, in-memory copy of the groups we plot

Figures (each returns a matplotlib Figure; nothing is written)
    fig_track_plan(result)               plan view x-y, ticks at segment transition points
    fig_curvature_cant(result)           curvature [1/km] and cant [mm] / cant angle vs s
    fig_irregularities(result)           alignment, vertical, gauge, cross level [mm] vs s
    fig_irregularity_psd(result)         Welch estimate vs target one-sided PSD, log-log
    fig_wheelsets(result)                lateral displacement [mm] and yaw [mrad] of every
                                         wheelset vs distance (paper Fig. 17, 19, 21)
    fig_bodies_car(result)               the same for bogies and car body (Fig. 20, 22)
    fig_kinematics(runs, names, title)   the same for any bodies, several runs overlaid
    fig_contact_forces(result)           normal force Q and Y/Q per wheel vs distance (Fig. 24,
                                         25), Nadal's limit when the file gives mu and the
                                         flange angle
    fig_flange_contact(result)           tread and flange patch normal forces (KEC two-point
                                         contact, LUT Hertz flange), LUT flange indentation,
                                         contact regime, per wheel
    fig_creep(result)                    creepages, spin and creep forces per wheelset
    fig_accelerations(result)            car body and bogie accelerations (/bodies/*/a[xyz])
    fig_elements(result)                 deflection and force of /elements/* versus time
    panel_points(fig)                    {panel id: data points drawn} of a vehicle figure

Vehicle results
    steady_state(result, fraction=0.2)   mean y [mm] and yaw [mrad] of every body over the
                                         last 20 % of its distance (paper Tables 5, 6)
    stats_summary(result)                one-line summary of /stats (None without /stats)
    add_failure_banner(fig, text)        red "FAILED at t = ..." line above a figure's title

Driver
    FIGURES                              registry: (suffix, is_available(result), make(result))
    build_figure(result, spec)           make one figure, with the failure banner if the run
                                         failed (/stats status "failed")
    make_figures(result, outdir, stem)   writes every available figure, returns the paths

Signal processing
    default_nperseg(n, ds, wavelength_max)   Welch segment length rule (documented there)
    welch_segment_starts(n, nperseg)         segment starts (>= 50 % overlap, whole record)
    welch_psd(x, ds, nperseg=None, ...)      one-sided PSD G(Omega) [units^2/(rad/m)]
    interp_loglog(x_new, x, y)               log-log interpolation (target PSD onto bins)
    octave_band_ratios(...)                  estimate/target averaged per octave band
    fractional_octave_average(...)           1/3-octave band means (display)

Conventions (docs: /work/shared/reference/track_irregularity_psd.md)
    Omega = 2*pi/lambda [rad/m].  A one-sided PSD G(Omega) over Omega > 0 satisfies
    variance = integral G dOmega.  With G_f the one-sided PSD in m^2/(cycle/m),
    G_Omega = G_f / (2*pi).

Adding figures for later groups: read them in load_result (or lazily with Result.read_group),
write a fig_* function and append a FigureSpec to FIGURES whose is_available() checks for the
group.  make_figures() and plot_run.py need no change.

Vehicle groups (/time, /bodies, /contact, /elements, /stats) are optional: a file holding only
the track still loads.  A figure is drawn only from what the file holds: a quantity the run
did not write, or that its contact method does not produce (the engine writes zeros for the
LUT-only flange_force and flange_indentation in KEC runs), gets no panel, and the figure says
so instead of showing an empty one (the same for creepages and creep forces of a run without
a creep law, and for guided wheelsets, whose y and yaw are zero by construction).  Time series
may be cut short (failed or interrupted run): every figure plots the samples it has and
truncates x/y pairs to their common length.

Only numpy, matplotlib (Agg) and h5py are used; no scipy.
"""
from __future__ import annotations

import math
import os
import sys
from dataclasses import dataclass, field
from typing import Callable, Dict, List, Optional, Sequence, Tuple

import numpy as np
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.patches import Patch  # noqa: E402
from matplotlib.ticker import NullLocator  # noqa: E402

__all__ = [
    "ResultFileError", "Result", "Track", "Irregularities", "load_result",
    "default_nperseg", "welch_segment_starts", "welch_psd", "interp_loglog", "octave_band_ratios", "fractional_octave_average",
    "fig_track_plan", "fig_curvature_cant", "fig_irregularities", "fig_irregularity_psd",
    "Body", "WheelsetContact", "Contact",
    "fig_wheelsets", "fig_bodies_car", "fig_kinematics", "fig_contact_forces", "fig_creep",
    "fig_flange_contact", "fig_accelerations", "fig_elements", "panel_points", "nadal_limit",
    "nadal_from_file", "acceleration_bodies", "ContactRow",
    "steady_state", "stats_summary", "failure_text", "add_failure_banner", "body_title",
    "FigureSpec", "FIGURES", "build_figure", "make_figures", "report_style",
]

# --------------------------------------------------------------------------------------------
# Style
# --------------------------------------------------------------------------------------------
DPI = 150
A4_WIDTH_IN = 6.5  # usable text width of an A4 page with ~2.3 cm margins

SEGMENT_NAMES = {0: "tangent", 1: "transition", 2: "curve"}
# Paper Fig. 17: white tangent, grey transition, blue curve.
SEGMENT_FILL = {0: "#ffffff", 1: "#d9d9d9", 2: "#d6e6f5"}
SEGMENT_LINE = {0: "#222222", 1: "#8c8c8c", 2: "#1f5fa8"}

CHANNELS = ("alignment", "vertical", "gauge", "cross_level")
CHANNEL_TITLES = {
    "alignment": "Alignment",
    "vertical": "Vertical profile",
    "gauge": "Gauge variation",
    "cross_level": "Cross level",
}
CHANNEL_COLORS = {
    "alignment": "#1f5fa8",
    "vertical": "#b2182b",
    "gauge": "#1b7837",
    "cross_level": "#6a3d9a",
}

# Overlaid runs (paper Fig. 17, 19-22: one colour per method); line styles keep them apart in
# black-and-white print.
RUN_COLORS = ("#1f5fa8", "#b2182b", "#1b7837", "#e08214", "#6a3d9a", "#555555")
RUN_STYLES = ("-", (0, (5, 2.5)), (0, (1.2, 1.6)), (0, (6, 2, 1.2, 2)), (0, (3, 1.5)), "-")
SIDE_STYLE = {"left": dict(color="#1f5fa8", ls="-"),
              "right": dict(color="#b2182b", ls=(0, (5, 2.5)))}
FAIL_COLOR = "#d00000"
KINEMATIC_KINDS = ("wheelset", "bogie", "car")

_RC = {
    "font.size": 8.5,
    "axes.titlesize": 9,
    "axes.labelsize": 8.5,
    "legend.fontsize": 7.5,
    "xtick.labelsize": 7.5,
    "ytick.labelsize": 7.5,
    "axes.grid": True,
    "grid.color": "#b0b0b0",
    "grid.linewidth": 0.4,
    "grid.alpha": 0.6,
    "axes.linewidth": 0.6,
    "lines.linewidth": 1.0,
    "xtick.direction": "in",
    "ytick.direction": "in",
    "xtick.major.width": 0.6,
    "ytick.major.width": 0.6,
    "legend.frameon": True,
    "legend.framealpha": 0.9,
    "legend.edgecolor": "#cccccc",
    "savefig.dpi": DPI,
    "figure.dpi": DPI,
    "axes.axisbelow": True,
}


def report_style():
    """Context manager with the report rcParams (use: `with report_style(): ...`)."""
    return plt.rc_context(_RC)


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
            print(f"railbench_plots: warning: {where}/{name} has units '{got}', expected '{units}'",
                  file=sys.stderr)
    return a


@dataclass
class Track:
    attrs: Dict[str, object]
    centreline: Dict[str, np.ndarray]  # s x y z heading slope cant_angle curvature cant
    segments: Dict[str, np.ndarray]    # start length kind radius side cant

    @property
    def n_segments(self) -> int:
        return int(self.segments["start"].size)

    def segment_bounds(self) -> np.ndarray:
        """Arc length of every segment boundary, start of the first to end of the last."""
        st, ln = self.segments["start"], self.segments["length"]
        if st.size == 0:
            s = self.centreline["s"]
            return np.array([s[0], s[-1]])
        return np.append(st, st[-1] + ln[-1])


@dataclass
class Irregularities:
    attrs: Dict[str, object]
    data: Dict[str, np.ndarray]                 # s, alignment, vertical, gauge, cross_level, ...
    target: Optional[Dict[str, np.ndarray]]     # omega + channels, or None (e.g. csv source)

    @property
    def step(self) -> float:
        s = self.data["s"]
        return float(np.median(np.diff(s))) if s.size > 1 else float("nan")

    def band(self) -> Tuple[Optional[float], Optional[float]]:
        lo, hi = self.attrs.get("wavelength_min"), self.attrs.get("wavelength_max")
        lo = float(lo) if isinstance(lo, (int, float)) and lo > 0 else None
        hi = float(hi) if isinstance(hi, (int, float)) and hi > 0 else None
        return lo, hi

    def describe(self) -> str:
        a = self.attrs
        src = a.get("source", "?")
        if src == "psd":
            txt = f"spectrum {a.get('spectrum', '?')}, seed {a.get('seed', '?')}"
        else:
            txt = f"source {src}"
        lo, hi = self.band()
        if lo and hi:
            txt += f", λ = {lo:g}–{hi:g} m"
        sc = a.get("scale")
        if isinstance(sc, (int, float)) and sc != 1:
            txt += f", scale {sc:g}"
        return txt


@dataclass
class Body:
    name: str
    kind: str                        # "car", "bogie", "wheelset", "frame" (or as the file says)
    data: Dict[str, np.ndarray]      # s y z roll pitch yaw (+ rates etc.), SI units as stored

    def has(self, *keys: str) -> bool:
        return all(k in self.data and self.data[k].size > 0 for k in keys)

    @property
    def title(self) -> str:
        return body_title(self.name)


def body_title(name: str) -> str:
    """Display name: "ws1" -> "wheelset 1", "bogie2" -> "bogie 2", "car" -> "car body"."""
    import re
    m = re.fullmatch(r"(ws|wheelset|bogie|car|carbody|car_body)[ _]?(\d*)", name, re.IGNORECASE)
    if not m:
        return name
    word = {"ws": "wheelset", "carbody": "car body", "car_body": "car body",
            "car": "car body"}.get(m.group(1).lower(), m.group(1).lower())
    return f"{word} {m.group(2)}".strip()


@dataclass
class WheelsetContact:
    name: str                                              # wheelset (body) name
    sides: Dict[str, Dict[str, np.ndarray]]                # "left"/"right" -> datasets
    data: Dict[str, np.ndarray]                            # datasets of the wheelset itself

    def side(self, side: str, key: str) -> Optional[np.ndarray]:
        v = self.sides.get(side, {}).get(key)
        return v if v is not None and v.size > 0 else None


@dataclass
class Contact:
    attrs: Dict[str, object]
    wheelsets: Dict[str, WheelsetContact]                  # in vehicle order

    def has_any(self, keys: Sequence[str]) -> bool:
        for wc in self.wheelsets.values():
            for k in keys:
                if any(wc.side(sd, k) is not None for sd in ("left", "right")):
                    return True
                if k in wc.data and wc.data[k].size:
                    return True
        return False


@dataclass
class Result:
    path: str
    attrs: Dict[str, object]
    groups: List[str]                    # top-level group/dataset names present in the file
    track: Optional[Track] = None
    irregularities: Optional[Irregularities] = None
    extra: Dict[str, object] = field(default_factory=dict)  # room for later groups
    time: Optional[np.ndarray] = None                       # /time [s]
    bodies: Dict[str, Body] = field(default_factory=dict)   # /bodies, in vehicle order
    contact: Optional[Contact] = None                       # /contact
    elements: Dict[str, Dict[str, np.ndarray]] = field(default_factory=dict)  # /elements
    element_units: Dict[str, Dict[str, str]] = field(default_factory=dict)    # their units
    stats: Optional[Dict[str, object]] = None               # /stats attributes

    @property
    def stem(self) -> str:
        return os.path.splitext(os.path.basename(self.path))[0]

    @property
    def failed(self) -> bool:
        return bool(self.stats) and str(self.stats.get("status", "ok")).strip().lower() == "failed"

    @property
    def contact_method(self) -> Optional[str]:
        """The wheel/rail contact method ("kec", "lut"); None without contact (track-only
        runs, and guided runs, whose file says "none (wheelsets guided)")."""
        m = self.attrs.get("contact_method")
        if not m and self.contact is not None:
            m = self.contact.attrs.get("method")
        m = str(m).strip() if m else ""
        return m if m and not m.lower().startswith("none") else None

    @property
    def guided(self) -> bool:
        """A vehicle run whose wheelsets follow the track (no contact block)."""
        return str(self.attrs.get("contact_method", "")).strip().lower().startswith("none")

    def label(self) -> str:
        """Short run label for legends: contact method in capitals (KEC, LUT), else the stem."""
        m = self.contact_method
        return m.upper() if m else self.stem

    def kinematic_bodies(self, kinds: Sequence[str] = KINEMATIC_KINDS) -> List[str]:
        """Names of bodies of the given kinds that can be drawn against distance (have s)."""
        return [n for n, b in self.bodies.items() if b.kind in kinds and b.has("s")]

    def t_reached(self) -> Optional[float]:
        t = self.stats.get("t_reached") if self.stats else None
        if isinstance(t, (int, float)) and math.isfinite(t):
            return float(t)
        if self.time is not None and self.time.size:
            ok = self.time[np.isfinite(self.time)]
            return float(ok[-1]) if ok.size else None
        return None

    def read_group(self, group: str) -> Dict[str, np.ndarray]:
        """All 1-D datasets directly under `group` (lazy reader for figures added later)."""
        import h5py
        with h5py.File(self.path, "r") as f:
            if group not in f:
                raise ResultFileError(f"missing group {group}")
            g = f[group]
            return {k: np.asarray(v[()], dtype=float) for k, v in g.items()
                    if isinstance(v, h5py.Dataset)}


_CENTRELINE = {"s": "m", "x": "m", "y": "m", "z": "m", "heading": "rad", "slope": "rad",
               "cant_angle": "rad", "curvature": "1/m", "cant": "m"}
_SEGMENTS = {"start": "m", "length": "m", "kind": "-", "radius": "m", "side": "-", "cant": "m"}
_IRR = {"s": "m", "alignment": "m", "vertical": "m", "gauge": "m", "cross_level": "m"}
_IRR_OPTIONAL = {"left_y": "m", "left_z": "m", "right_y": "m", "right_z": "m", "delta": "rad"}

# Vehicle groups.  Only these names are unit-checked; other 1-D numeric datasets (rates such as
# y_dot, later additions) are read as they are and ignored by the figures.
_BODY_DS = {"s": "m", "x": "m", "y": "m", "z": "m", "roll": "rad", "pitch": "rad", "yaw": "rad",
            "ax": "m/s^2", "ay": "m/s^2", "az": "m/s^2"}
# Per wheel, /contact/<wheelset>/<left|right>/ (workbench/app/run.cpp, runContact).
_CONTACT_DS = {"normal_force": "N", "normal_tread": "N", "normal_flange": "N",
               "creep_force_x": "N", "creep_force_y": "N", "creepage_x": "-", "creepage_y": "-",
               "spin": "1/m", "wheel_s": "m", "rail_s": "m", "contact_angle": "rad",
               "flange_indentation": "m", "flange_force": "N", "regime": "-", "y_over_q": "-"}


def _guess_kind(name: str) -> str:
    n = name.lower()
    if n.startswith(("ws", "wheelset")):
        return "wheelset"
    if n.startswith("bogie"):
        return "bogie"
    if n.startswith("car"):
        return "car"
    return "other"


def _names_attr(v) -> List[str]:
    """A newline-separated string (or an array of strings) -> list of names."""
    if isinstance(v, np.ndarray) and v.ndim == 1:
        items = [_str(x) for x in v]
    else:
        items = _str(v).splitlines()
    return [x.strip() for x in items if x.strip()]


def _read_series(group, where: str, units: Dict[str, str]) -> Dict[str, np.ndarray]:
    """All 1-D numeric datasets directly under `group` (others are skipped silently)."""
    import h5py
    out = {}
    for k, d in group.items():
        if not isinstance(d, h5py.Dataset) or d.dtype.kind not in "fiub" or d.ndim > 1:
            continue
        out[k] = _read_ds(group, k, where, units.get(k))
    return out


def _load_dynamics(f, res: Result) -> None:
    """Optional groups /time, /bodies, /contact, /elements, /stats into `res`."""
    import h5py
    ragged: List[str] = []
    n_t = None
    if "time" in f and isinstance(f["time"], h5py.Dataset):
        res.time = _read_ds(f, "time", "", "s")
        n_t = res.time.size

    def note_len(where, arrays):
        if n_t is not None:
            ragged.extend(f"{where}/{k}" for k, v in arrays.items() if v.size != n_t)

    if "bodies" in f and isinstance(f["bodies"], h5py.Group):
        g = f["bodies"]
        present = [k for k, v in g.items() if isinstance(v, h5py.Group)]
        names = _names_attr(g.attrs["names"]) if "names" in g.attrs else []
        missing = [n for n in names if n not in present]
        if missing:
            print(f"railbench_plots: warning: {res.path}: /bodies names {', '.join(missing)} "
                  f"without a group", file=sys.stderr)
        order = [n for n in names if n in present] + [n for n in present if n not in names]
        for n in order:
            bg = g[n]
            kind = _str(bg.attrs["kind"]).strip().lower() if "kind" in bg.attrs else _guess_kind(n)
            data = _read_series(bg, f"/bodies/{n}", _BODY_DS)
            note_len(f"/bodies/{n}", data)
            res.bodies[n] = Body(name=n, kind=kind, data=data)
        if res.bodies and not any("s" in b.data for b in res.bodies.values()):
            print(f"railbench_plots: warning: {res.path}: no body has an 's' dataset (distance); "
                  f"body figures skipped", file=sys.stderr)

    if "contact" in f and isinstance(f["contact"], h5py.Group):
        g = f["contact"]
        wss = [k for k, v in g.items() if isinstance(v, h5py.Group)]
        body_order = [n for n in res.bodies if n in wss]
        wss = body_order + sorted(n for n in wss if n not in body_order)
        cws = {}
        for w in wss:
            wg = g[w]
            sides = {}
            for side in ("left", "right"):
                if side in wg and isinstance(wg[side], h5py.Group):
                    sides[side] = _read_series(wg[side], f"/contact/{w}/{side}", _CONTACT_DS)
                    note_len(f"/contact/{w}/{side}", sides[side])
            data = _read_series(wg, f"/contact/{w}", {})
            note_len(f"/contact/{w}", data)
            cws[w] = WheelsetContact(name=w, sides=sides, data=data)
        res.contact = Contact(attrs=_attrs(g), wheelsets=cws)

    if "elements" in f and isinstance(f["elements"], h5py.Group):
        for k, v in f["elements"].items():
            if isinstance(v, h5py.Group):
                res.elements[k] = _read_series(v, f"/elements/{k}", {})
                res.element_units[k] = {d: _str(v[d].attrs["units"]).strip()
                                        for d in res.elements[k] if "units" in v[d].attrs}
                note_len(f"/elements/{k}", res.elements[k])

    if "stats" in f:
        res.stats = _attrs(f["stats"])

    if ragged:
        print(f"railbench_plots: warning: {res.path}: {len(ragged)} time series differ in length "
              f"from /time ({n_t} samples; interrupted run?), e.g. {ragged[0]}; plotted up to "
              f"their common length", file=sys.stderr)


def load_result(path: str) -> Result:
    """Open and validate a result file. Raises ResultFileError with a one-line message."""
    import h5py

    if not os.path.exists(path):
        hint = " (a run still in progress writes '<name>.tmp')" if os.path.exists(path + ".tmp") \
            else ""
        raise ResultFileError(f"no such file: {path}{hint}")
    if os.path.isdir(path):
        raise ResultFileError(f"is a directory, not a result file: {path}")
    try:
        f = h5py.File(path, "r")
    except OSError as e:
        msg = str(e).splitlines()[0] if str(e) else type(e).__name__
        raise ResultFileError(f"not a readable HDF5 file: {path} ({msg})") from None
    try:
        with f:
            res = Result(path=path, attrs=_attrs(f), groups=sorted(f.keys()))
            if "track" not in f:
                raise ResultFileError(f"{path}: no /track group (not a railbench result file?)")
            g = f["track"]
            for sub in ("centreline", "segments"):
                if sub not in g:
                    raise ResultFileError(f"{path}: missing group /track/{sub}")
            cl = {k: _read_ds(g["centreline"], k, "/track/centreline", u)
                  for k, u in _CENTRELINE.items()}
            n = cl["s"].size
            if n < 2:
                raise ResultFileError(f"{path}: /track/centreline/s has {n} sample(s)")
            bad = [k for k, v in cl.items() if v.size != n]
            if bad:
                raise ResultFileError(f"{path}: /track/centreline datasets differ in length "
                                      f"({', '.join(bad)} vs s={n})")
            sg = {k: _read_ds(g["segments"], k, "/track/segments", u) for k, u in _SEGMENTS.items()}
            m = sg["start"].size
            if any(v.size != m for v in sg.values()):
                raise ResultFileError(f"{path}: /track/segments datasets differ in length")
            res.track = Track(attrs=_attrs(g), centreline=cl, segments=sg)

            if "irregularities" in g:
                ig = g["irregularities"]
                data = {k: _read_ds(ig, k, "/track/irregularities", u) for k, u in _IRR.items()}
                for k, u in _IRR_OPTIONAL.items():
                    if k in ig:
                        data[k] = _read_ds(ig, k, "/track/irregularities", u)
                ni = data["s"].size
                if any(data[k].size != ni for k in _IRR):
                    raise ResultFileError(f"{path}: /track/irregularities datasets differ in length")
                target = None
                if "target_psd" in ig:
                    tg = ig["target_psd"]
                    target = {"omega": _read_ds(tg, "omega", "/track/irregularities/target_psd",
                                                "rad/m")}
                    for c in CHANNELS:
                        if c in tg:
                            target[c] = _read_ds(tg, c, "/track/irregularities/target_psd",
                                                 "m^2/(rad/m)")
                res.irregularities = Irregularities(attrs=_attrs(ig), data=data, target=target)
            _load_dynamics(f, res)
            return res
    except ResultFileError:
        raise
    except (OSError, KeyError, ValueError) as e:
        raise ResultFileError(f"{path}: cannot read ({str(e).splitlines()[0] if str(e) else e!r})") \
            from None


# --------------------------------------------------------------------------------------------
# PSD estimation
# --------------------------------------------------------------------------------------------
def default_nperseg(n: int, ds: float, wavelength_max: Optional[float] = None,
                    cycles: float = 4.0) -> int:
    """Welch segment length (samples).

    A segment must hold several periods of the longest wavelength of interest so that its
    frequency resolution df = 1/(nperseg*ds) puts Omega_min = 2*pi/lambda_max a few bins above
    DC (the Hann main lobe is +-2 bins wide).  We ask for `cycles` = 4 periods, i.e.
    4*lambda_max/ds samples, then take the largest power of two <= min(n, that); a power of two
    below the request trades a little resolution (>= 2 periods still) for more averaged
    segments.  Without lambda_max (e.g. measured irregularities from a csv file), a quarter of
    the record is used (7 half-overlapping segments).  Never below 16 samples (or n if
    shorter).
    """
    n = int(n)
    if n < 2:
        return max(n, 1)
    want = cycles * wavelength_max / ds if (wavelength_max and ds > 0) else n / 4.0
    cap = max(min(float(n), want), 16.0)
    m = 1 << int(math.floor(math.log2(cap)))
    return int(min(m, n))


def welch_segment_starts(n: int, nperseg: int, overlap: float = 0.5) -> np.ndarray:
    """Start indices of Welch segments: K = ceil((n-M)/hop)+1 segments, hop = M*(1-overlap),
    spread evenly over [0, n-M] so the whole record is used (actual overlap >= `overlap`)."""
    m = max(1, min(int(nperseg), int(n)))
    if n <= m:
        return np.array([0])
    hop = max(1, int(round(m * (1.0 - overlap))))
    k = int(math.ceil((n - m) / hop)) + 1
    return np.round(np.linspace(0, n - m, k)).astype(int)


def welch_psd(x: Sequence[float], ds: float, nperseg: Optional[int] = None,
              overlap: float = 0.5, detrend: Optional[str] = "constant",
              wavelength_max: Optional[float] = None) -> Tuple[np.ndarray, np.ndarray]:
    """One-sided PSD of a spatial signal by Welch's method, in units^2/(rad/m) over Omega.

    x       samples at constant spacing ds [m]
    nperseg segment length; default_nperseg(len(x), ds, wavelength_max) if None
    overlap minimum fractional overlap of consecutive segments (0.5).  The number of segments
            K = ceil((N - M)/(M*(1-overlap))) + 1 and their starts are spread evenly over
            [0, N-M], so no sample is dropped (the actual overlap is >= `overlap`).
    detrend "constant" (remove segment mean), "linear", or None

    Window: periodic Hann.  Scaling: per segment P_f = |FFT(w*x)|^2 * ds / sum(w^2) is the
    two-sided density in units^2/(cycle/m); bins 1..M/2-1 are doubled for the one-sided G_f,
    and G_Omega = G_f/(2*pi) at Omega = 2*pi*f.  Then sum(G_Omega)*dOmega equals the mean
    windowed segment variance (Parseval), i.e. variance = integral G dOmega.

    Returns (omega [rad/m], G [units^2/(rad/m)]), omega[0] = 0.
    """
    x = np.asarray(x, dtype=float).reshape(-1)
    n = x.size
    if n < 2 or not (ds > 0):
        raise ValueError("welch_psd needs at least 2 samples and ds > 0")
    m = int(nperseg) if nperseg else default_nperseg(n, ds, wavelength_max)
    m = max(2, min(m, n))
    starts = welch_segment_starts(n, m, overlap)
    w = 0.5 - 0.5 * np.cos(2.0 * np.pi * np.arange(m) / m)  # periodic Hann
    t = np.arange(m, dtype=float)
    acc = np.zeros(m // 2 + 1)
    for st in starts:
        seg = x[st:st + m]
        if detrend == "constant":
            seg = seg - seg.mean()
        elif detrend == "linear":
            seg = seg - np.polyval(np.polyfit(t, seg, 1), t)
        acc += np.abs(np.fft.rfft(w * seg)) ** 2
    p = acc / len(starts) * ds / np.sum(w ** 2)  # two-sided, per cycle/m
    p[1:] *= 2.0
    if m % 2 == 0:
        p[-1] /= 2.0  # Nyquist bin is not mirrored
    f = np.fft.rfftfreq(m, ds)
    return 2.0 * np.pi * f, p / (2.0 * np.pi)


def interp_loglog(x_new: np.ndarray, x: np.ndarray, y: np.ndarray) -> np.ndarray:
    """Interpolate y(x) linearly in log-log; zeros/negatives stay 0; NaN outside [x0, x-1]."""
    x_new = np.asarray(x_new, float)
    x, y = np.asarray(x, float), np.asarray(y, float)
    ok = (x > 0) & (y > 0)
    out = np.full(x_new.shape, np.nan)
    if ok.sum() < 2:
        if np.all(y == 0):
            out[(x_new >= x.min()) & (x_new <= x.max())] = 0.0
        return out
    inside = (x_new >= x[ok].min()) & (x_new <= x[ok].max()) & (x_new > 0)
    out[inside] = np.exp(np.interp(np.log(x_new[inside]), np.log(x[ok]), np.log(y[ok])))
    return out


def octave_band_ratios(omega: np.ndarray, g_est: np.ndarray, omega_t: np.ndarray,
                       g_target: np.ndarray, wavelength_min: float, wavelength_max: float
                       ) -> List[Tuple[float, float, float]]:
    """Mean of G_est/G_target over each full octave inside [2pi/lambda_max, 2pi/lambda_min].

    Octaves are stacked downwards from Omega_max = 2*pi/lambda_min; a remaining partial octave
    at the long-wavelength end is not used.  Returns [(Omega_lo, Omega_hi, ratio), ...] from
    short to long wavelengths; ratio is NaN if an octave holds no estimate bin.
    """
    o_lo, o_hi = 2 * np.pi / wavelength_max, 2 * np.pi / wavelength_min
    tgt = interp_loglog(omega, omega_t, g_target)
    out = []
    hi = o_hi
    while hi / 2.0 >= o_lo * (1 - 1e-12):
        lo = hi / 2.0
        sel = (omega >= lo) & (omega < hi) & np.isfinite(tgt) & (tgt > 0)
        r = float(np.mean(g_est[sel] / tgt[sel])) if sel.any() else float("nan")
        out.append((lo, hi, r))
        hi = lo
    return out


def fractional_octave_average(omega: np.ndarray, g: np.ndarray, fraction: int = 3,
                              omega_min: Optional[float] = None,
                              omega_max: Optional[float] = None
                              ) -> Tuple[np.ndarray, np.ndarray]:
    """Mean of g over 1/`fraction`-octave bands (for display of a noisy estimate).

    Band centres are 2**(k/fraction) rad/m (k integer) within [omega_min, omega_max]
    (default: the positive range of omega); bands holding no bin are dropped.
    Returns (band centre [rad/m], band mean)."""
    omega, g = np.asarray(omega, float), np.asarray(g, float)
    pos = omega > 0
    lo = omega_min if omega_min else omega[pos].min()
    hi = omega_max if omega_max else omega[pos].max()
    k = np.arange(math.floor(math.log2(lo) * fraction), math.ceil(math.log2(hi) * fraction) + 1)
    centres = 2.0 ** (k / fraction)
    half = 2.0 ** (0.5 / fraction)
    oc, gm = [], []
    for c in centres:
        sel = pos & (omega >= c / half) & (omega < c * half)
        if sel.any() and lo <= c <= hi:
            oc.append(c)
            gm.append(float(np.mean(g[sel])))
    return np.array(oc), np.array(gm)


# --------------------------------------------------------------------------------------------
# Figure helpers
# --------------------------------------------------------------------------------------------
def _shade_segments(ax, track: Track, alpha: float = 1.0):
    st, ln, kd = track.segments["start"], track.segments["length"], track.segments["kind"]
    for a, l, k in zip(st, ln, kd):
        k = int(round(k))
        if k != 0:  # tangent stays white
            ax.axvspan(a, a + l, color=SEGMENT_FILL.get(k, "#eeeeee"), alpha=alpha, lw=0,
                       zorder=0)
    for b in track.segment_bounds():
        ax.axvline(b, color="#9a9a9a", lw=0.5, zorder=0.5)


def _segment_legend_handles(track: Track):
    kinds = sorted({int(round(k)) for k in track.segments["kind"]})
    return [Patch(facecolor=SEGMENT_FILL.get(k, "#eee"), edgecolor="#9a9a9a", lw=0.5,
                  label=SEGMENT_NAMES.get(k, f"kind {k}")) for k in kinds]


def _segment_label(track: Track, i: int) -> str:
    sg = track.segments
    k = int(round(sg["kind"][i]))
    name = SEGMENT_NAMES.get(k, f"kind {k}")
    txt = f"{name}, {sg['length'][i]:g} m"
    r = sg["radius"][i]
    side = "left" if sg["side"][i] > 0 else "right"
    if k == 2 and r > 0:
        txt += f"\nR = {r:g} m {side}"
    elif k == 1:
        txt += f"\nto R = {r:g} m {side}" if r > 0 else "\nto straight"
    if k in (1, 2) and sg["cant"][i] != 0:
        txt += f", cant {sg['cant'][i] * 1e3:g} mm"
    return txt


def _interp_pose(track: Track, s_q: np.ndarray):
    cl = track.centreline
    s = cl["s"]
    hd = np.unwrap(cl["heading"])
    return np.interp(s_q, s, cl["x"]), np.interp(s_q, s, cl["y"]), np.interp(s_q, s, hd)


# --------------------------------------------------------------------------------------------
# Figures
# --------------------------------------------------------------------------------------------
def fig_track_plan(result: Result):
    """Plan view x-y (equal aspect), coloured by segment kind, with short lines perpendicular
    to the track at the segment transition points (paper Fig. 16/18).  Boundary ticks carry
    their arc length; segments are numbered on the outside of the curve and described in the
    legend (by kind only when there are more than 12 segments)."""
    from matplotlib.lines import Line2D

    tr = result.track
    cl = tr.centreline
    s, x, y = cl["s"], cl["x"], cl["y"]
    with report_style():
        fig, ax = plt.subplots(figsize=(A4_WIDTH_IN, 3.7), layout="constrained")
        ext = max(np.ptp(x), np.ptp(y), 1.0)
        tick = 0.05 * ext
        bounds = tr.segment_bounds()
        nseg = tr.n_segments
        detailed = nseg <= 12
        handles = []
        seen = set()
        ax.plot(x, y, color="#bbbbbb", lw=0.8, zorder=1)
        for i in range(nseg):
            a, b = bounds[i], bounds[i + 1]
            k = int(round(tr.segments["kind"][i]))
            sel = (s > a) & (s < b)
            xa, ya, _ = _interp_pose(tr, np.array([a, b]))
            xs = np.concatenate([[xa[0]], x[sel], [xa[1]]])
            ys = np.concatenate([[ya[0]], y[sel], [ya[1]]])
            col = SEGMENT_LINE.get(k, "k")
            ax.plot(xs, ys, color=col, lw=2.0, solid_capstyle="butt", zorder=2)
            if detailed:
                handles.append(Line2D([], [], color=col, lw=2.0,
                                      label=f"{i + 1}: " + _segment_label(tr, i).replace("\n", ", ")))
            elif k not in seen:
                handles.append(Line2D([], [], color=col, lw=2.0,
                                      label=SEGMENT_NAMES.get(k, f"kind {k}")))
                seen.add(k)
        # Outside of the curve = opposite to the net turning direction.
        turn = np.unwrap(cl["heading"])[-1] - np.unwrap(cl["heading"])[0]
        out_global = -1.0 if turn >= 0 else 1.0   # multiplies the left normal

        def out_side(a, b):
            """Outside of the curve over [a, b]: -sign(mean curvature), global if straight."""
            sel = (s >= a) & (s <= b)
            k = float(np.mean(cl["curvature"][sel])) if sel.any() else 0.0
            return -float(np.sign(k)) if abs(k) > 1e-9 else out_global

        bx, by, bh = _interp_pose(tr, bounds)
        span = 0.25 * (bounds[-1] - bounds[0]) / max(nseg, 1)
        for px, py, h, sb in zip(bx, by, bh, bounds):
            nx, ny = -np.sin(h), np.cos(h)
            out = out_side(sb - span, sb + span)
            ax.plot([px - nx * tick / 2, px + nx * tick / 2],
                    [py - ny * tick / 2, py + ny * tick / 2], color="k", lw=1.1, zorder=3)
            # arc-length label continues the tick on the inside of the curve
            ux, uy = -out * nx, -out * ny
            ang = math.degrees(math.atan2(uy, ux))
            ha = "left"
            if ang > 100 or ang <= -80:  # keep text readable (a little past vertical is fine)
                ang += 180 if ang <= -80 else -180
                ha = "right"
            lx, ly = px + ux * tick * 0.6, py + uy * tick * 0.6
            # invisible points along the label so that legend loc="best" avoids it
            ax.plot(lx + ux * tick * np.linspace(0, 1.6, 5), ly + uy * tick * np.linspace(0, 1.6, 5),
                    ls="none", marker="", alpha=0)
            ax.text(lx, ly, f"s = {sb:g} m", rotation=ang,
                    rotation_mode="anchor", ha=ha, va="center", fontsize=6.5, color="#333333",
                    zorder=4)
        if detailed:
            mids = 0.5 * (bounds[:-1] + bounds[1:])
            mx, my, mh = _interp_pose(tr, mids)
            for i, (px, py, h) in enumerate(zip(mx, my, mh)):
                nx, ny = -np.sin(h), np.cos(h)
                out = out_side(bounds[i], bounds[i + 1])
                ax.plot([px + out * nx * tick * 0.75], [py + out * ny * tick * 0.75], ls="none",
                        marker="", alpha=0)
                ax.text(px + out * nx * tick * 0.75, py + out * ny * tick * 0.75, str(i + 1),
                        ha="center", va="center", fontsize=7, zorder=5,
                        bbox=dict(boxstyle="circle,pad=0.2", fc="white",
                                  ec=SEGMENT_LINE.get(int(round(tr.segments["kind"][i])), "k"),
                                  lw=0.8))
        ax.plot(x[0], y[0], "o", ms=4.5, color="k", zorder=4)
        handles.append(Line2D([], [], ls="none", marker="o", ms=4.5, color="k",
                              label=f"start, s = {s[0]:g} m"))
        ax.set_aspect("equal", adjustable="datalim")
        pad = 0.1 * ext
        ax.set_xlim(x.min() - pad, x.max() + pad)
        ax.set_ylim(y.min() - pad, y.max() + pad)
        ax.set_xlabel("x [m]")
        ax.set_ylabel("y [m]")
        L = tr.attrs.get("length", s[-1] - s[0])
        ax.set_title(f"Track geometry, plan view: {float(L):g} m, {nseg} segment"
                     f"{'s' if nseg != 1 else ''} (ticks at segment transition points)")
        ax.legend(handles=handles, loc="best", handlelength=1.5, fontsize=7)
    return fig


def fig_curvature_cant(result: Result):
    """Curvature [1/km] and cant [mm] (+ cant angle [mrad]) versus s, segments shaded."""
    tr = result.track
    cl = tr.centreline
    s = cl["s"]
    with report_style():
        fig, (a1, a2) = plt.subplots(2, 1, figsize=(A4_WIDTH_IN, 4.6), sharex=True,
                                     layout="constrained")
        for ax in (a1, a2):
            _shade_segments(ax, tr)
        a1.plot(s, cl["curvature"] * 1e3, color="#1f5fa8", lw=1.3, label="curvature")
        a1.set_ylabel("curvature [1/km]\n(+ left)")
        a1.set_title("Track curvature and cant", loc="left")
        a1.axhline(0, color="k", lw=0.5)
        # Annotate radius of constant-curvature curves.
        for i in range(tr.n_segments):
            if int(round(tr.segments["kind"][i])) == 2 and tr.segments["radius"][i] > 0:
                a, l = tr.segments["start"][i], tr.segments["length"][i]
                kap = np.interp(a + 0.5 * l, s, cl["curvature"]) * 1e3
                a1.annotate(f"R = {tr.segments['radius'][i]:g} m", (a + 0.5 * l, kap),
                            xytext=(0, -11 if kap >= 0 else 4), textcoords="offset points",
                            ha="center", fontsize=7, color="#1f5fa8")
        h_seg = _segment_legend_handles(tr)
        a1.legend(handles=h_seg, loc="lower right", bbox_to_anchor=(1.0, 1.0), ncol=len(h_seg),
                  frameon=False, borderaxespad=0.2, handlelength=1.4, fontsize=7)
        lo, hi = a1.get_ylim()
        span = max(hi - lo, 1e-9)
        a1.set_ylim(lo - 0.08 * span, hi + 0.15 * span)

        c_mm = cl["cant"] * 1e3
        l1, = a2.plot(s, c_mm, color="#b2182b", lw=1.3, label="cant [mm] (left axis)")
        a2.set_ylabel("cant [mm]")
        a2.set_xlabel("s [m]")
        a2.axhline(0, color="k", lw=0.5)
        lo, hi = min(c_mm.min(), 0.0), max(c_mm.max(), 0.0)
        span = max(hi - lo, 1.0)
        a2.set_ylim(lo - 0.08 * span, hi + 0.2 * span)
        # Cant angle on a twin axis, scaled so that angle = asin(cant/cant_base) overlays the
        # cant line exactly when the file is consistent (a visual check).
        at = a2.twinx()
        at.grid(False)
        ang = cl["cant_angle"] * 1e3
        l2, = at.plot(s, ang, color="#333333", lw=1.0, ls=(0, (4, 3)), label="cant angle [mrad] (right axis)")
        base = tr.attrs.get("cant_base")
        y0, y1 = a2.get_ylim()
        if isinstance(base, (int, float)) and base > 0 and max(abs(y0), abs(y1)) < base * 1e3:
            at.set_ylim(np.arcsin(y0 / 1e3 / base) * 1e3, np.arcsin(y1 / 1e3 / base) * 1e3)
            note = f"cant base {base:g} m"
        else:
            note = None
        at.set_ylabel("cant angle [mrad]")
        # legend on the twin axes so that it is drawn above both lines
        at.legend(handles=[l1, l2], loc="best", title=note, title_fontsize=7, alignment="left")
        a2.set_xlim(s[0], s[-1])
    return fig


def fig_irregularities(result: Result):
    """Four stacked panels: alignment, vertical profile, gauge variation, cross level [mm]."""
    ir = result.irregularities
    s = ir.data["s"]
    with report_style():
        fig, axes = plt.subplots(4, 1, figsize=(A4_WIDTH_IN, 7.2), sharex=True,
                                 layout="constrained")
        for ax, c in zip(axes, CHANNELS):
            v = ir.data[c] * 1e3
            ax.plot(s, v, color=CHANNEL_COLORS[c], lw=0.7)
            ax.axhline(0, color="k", lw=0.4)
            ax.set_ylabel(f"{CHANNEL_TITLES[c].lower()}\n[mm]")
            peak = float(np.max(np.abs(v))) if v.size else 0.0
            if peak == 0.0:
                note = "channel disabled (all zeros)"
                ax.set_ylim(-1.0, 1.0)
            else:
                rms = float(np.sqrt(np.mean(v ** 2)))
                note = f"RMS {rms:.2f} mm, max |·| {peak:.2f} mm"
                ax.set_ylim(-1.3 * peak, 1.3 * peak)
            ax.text(0.995, 0.95, note, transform=ax.transAxes, ha="right", va="top", fontsize=7,
                    bbox=dict(boxstyle="round,pad=0.2", fc="white", ec="#cccccc", lw=0.5,
                              alpha=0.9))
        axes[-1].set_xlabel("s [m]")
        axes[-1].set_xlim(s[0], s[-1])
        fig.suptitle(f"Track irregularities — {ir.describe()}", fontsize=9.5)
    return fig


def _band_rms(omega_t, g_t, o_lo, o_hi) -> float:
    """sqrt(integral of G over [o_lo, o_hi]) with log-log interpolation of the target."""
    o = np.geomspace(o_lo, o_hi, 4000)
    gi = interp_loglog(o, omega_t, g_t)
    gi = np.where(np.isfinite(gi), gi, 0.0)
    return float(np.sqrt(np.sum(0.5 * (gi[1:] + gi[:-1]) * np.diff(o))))


def fig_irregularity_psd(result: Result, nperseg: Optional[int] = None):
    """Welch estimate vs target one-sided PSD G(Omega), one log-log panel per channel.

    x range: a factor 4 beyond the synthesis band on both sides (capped at the Nyquist
    wavenumber), or the target grid when no band is recorded.  The estimate falls by many
    decades outside the band (nothing was synthesised there); the y range follows the target
    and the in-band estimate so that this roll-off does not squash the plot.
    """
    from matplotlib.lines import Line2D

    ir = result.irregularities
    s = ir.data["s"]
    ds = ir.step
    lam_min, lam_max = ir.band()
    m = int(nperseg or default_nperseg(s.size, ds, lam_max))
    m = max(2, min(m, s.size))
    nseg = len(welch_segment_starts(s.size, m))
    o_nyq = np.pi / ds
    with report_style():
        fig, axes = plt.subplots(2, 2, figsize=(A4_WIDTH_IN, 5.8), layout="constrained")
        any_target = False
        for ax, c in zip(axes.flat, CHANNELS):
            x = ir.data[c]
            om, g = welch_psd(x, ds, nperseg=m)
            om, g = om[1:], g[1:]
            tgt = None
            if ir.target is not None and c in ir.target:
                ot, gt = ir.target["omega"], ir.target[c]
                if np.any(gt > 0):
                    tgt = (ot[ot > 0], gt[ot > 0])
            have_signal = bool(np.any(x != 0))
            if lam_min and lam_max:
                xl = (0.25 * 2 * np.pi / lam_max, min(4 * 2 * np.pi / lam_min, o_nyq))
            elif tgt is not None:
                xl = (max(tgt[0].min(), om[0] * 0.5), min(tgt[0].max(), o_nyq))
            else:
                xl = (om[0], om[-1])
            if lam_min and lam_max:
                ax.axvspan(2 * np.pi / lam_max, 2 * np.pi / lam_min, color="#f0f0f0", lw=0,
                           zorder=0)
                for lam in (lam_max, lam_min):
                    ax.axvline(2 * np.pi / lam, color="#555555", lw=0.8, ls="--", zorder=1)
            ys = []
            if tgt is not None:
                any_target = True
                ax.loglog(tgt[0], tgt[1], color="k", lw=1.3, zorder=3)
                sel = (tgt[0] >= xl[0]) & (tgt[0] <= xl[1])
                ys.append(tgt[1][sel])
            if have_signal:
                col = CHANNEL_COLORS[c]
                ax.loglog(om, g, color=col, lw=0.7, alpha=0.45, zorder=2)
                # 1/3-octave band means of the estimate: readable even with few segments
                bo_lo = 2 * np.pi / lam_max if lam_max else None
                bo_hi = 2 * np.pi / lam_min if lam_min else None
                oc3, g3 = fractional_octave_average(om, g, 3, bo_lo, bo_hi)
                ok = g3 > 0
                ax.loglog(oc3[ok], g3[ok], color=col, lw=1.0, marker="o", ms=2.8, zorder=4)
                inb = (om >= xl[0]) & (om <= xl[1])
                if lam_min and lam_max:
                    inb &= (om >= 2 * np.pi / lam_max) & (om <= 2 * np.pi / lam_min)
                ys.append(g[inb])
            ax.set_xscale("log")
            ax.set_yscale("log")
            ax.set_xlim(*xl)
            yy = np.concatenate(ys) if ys else np.array([])
            yy = yy[np.isfinite(yy) & (yy > 0)]
            if yy.size:
                top = yy.max() * 5.0
                ax.set_ylim(max(yy.min() * 0.2, top * 1e-9), top)
            rms = float(np.sqrt(np.mean((x - x.mean()) ** 2))) * 1e3
            ttl = f"{CHANNEL_TITLES[c]}: RMS {rms:.2f} mm"
            if not have_signal:
                ax.text(0.5, 0.5, "channel disabled (all zeros)", transform=ax.transAxes,
                        ha="center", va="center", fontsize=8, color="#555555",
                        bbox=dict(boxstyle="round,pad=0.3", fc="white", ec="#cccccc", lw=0.5))
                ttl = f"{CHANNEL_TITLES[c]}: disabled"
                if tgt is None:
                    ax.set_ylim(1e-12, 1e-4)
            elif tgt is not None and lam_min and lam_max:
                ttl += f" (target {_band_rms(tgt[0], tgt[1], 2 * np.pi / lam_max, 2 * np.pi / lam_min) * 1e3:.2f})"
            ax.set_title(ttl, fontsize=8)
            ax.set_xlabel("Ω [rad/m]")
            ax.set_ylabel("G(Ω) [m²/(rad/m)]")
            ax.grid(True, which="major", lw=0.4)
            ax.grid(True, which="minor", lw=0.25, alpha=0.35)
            sec = ax.secondary_xaxis("top", functions=(_om2lam, _om2lam))
            sec.set_xlabel("λ [m]", fontsize=7, labelpad=1)
            sec.tick_params(labelsize=6.5, direction="in")
            sec.xaxis.set_minor_locator(NullLocator())  # minor ticks here cost ~1 s per figure
        handles = [Line2D([], [], color="k", lw=1.3, label="target")] if any_target else []
        handles.append(Line2D([], [], color="#777777", lw=0.7, alpha=0.6,
                              label=f"Welch estimate (Hann, {nseg} × {m * ds:g} m)"))
        handles.append(Line2D([], [], color="#777777", lw=1.0, marker="o", ms=2.8,
                              label="1/3-octave means"))
        if lam_min and lam_max:
            handles.append(Patch(facecolor="#f0f0f0", edgecolor="#555555", ls="--", lw=0.8,
                                 label=f"band {lam_min:g}–{lam_max:g} m"))
        # (loc="outside ..." needs matplotlib >= 3.7; Debian 12 has 3.6: reserve a strip instead)
        fig.get_layout_engine().set(rect=(0.0, 0.045, 1.0, 0.955))
        fig.legend(handles=handles, loc="lower center", bbox_to_anchor=(0.5, 0.0),
                   ncol=len(handles), fontsize=7, frameon=False, handlelength=1.8)
        fig.suptitle(f"Irregularity PSD, one-sided in Ω: {ir.describe()}", fontsize=9.5)
    return fig


def _om2lam(v):
    v = np.asarray(v, dtype=float)
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.where(v > 0, 2 * np.pi / np.where(v > 0, v, 1.0), np.inf)


# --------------------------------------------------------------------------------------------
# Vehicle results: helpers
# --------------------------------------------------------------------------------------------
def _pair(x: np.ndarray, v: np.ndarray) -> Tuple[np.ndarray, np.ndarray]:
    """x and v cut to their common length (a failed run may leave ragged series)."""
    n = min(x.size, v.size)
    return x[:n], v[:n]


def _last_finite(x: np.ndarray, v: np.ndarray) -> Optional[Tuple[float, float]]:
    ok = np.flatnonzero(np.isfinite(x) & np.isfinite(v))
    return (float(x[ok[-1]]), float(v[ok[-1]])) if ok.size else None


def _num(v) -> Optional[float]:
    if isinstance(v, (bool, np.bool_)):
        return None
    if isinstance(v, (int, float, np.integer, np.floating)) and math.isfinite(float(v)):
        return float(v)
    return None


def failure_text(result: Result) -> Optional[str]:
    """'FAILED at t = 12.345 s: <message>' for a failed run (/stats status), else None."""
    if not result.failed:
        return None
    t = result.t_reached()
    head = f"FAILED at t = {t:.6g} s" if t is not None else "FAILED"
    msg = " ".join(str(result.stats.get("message", "")).split())
    return f"{head}: {msg}" if msg else head


def add_failure_banner(fig, text: str, max_chars: Optional[int] = None, max_lines: int = 3):
    """Red line(s) `text` at the very top of `fig`, above its suptitle (or axes title).

    For constrained-layout figures the layout rectangle is lowered by the banner height and
    an existing suptitle is moved just below the banner (its height reserved explicitly, since
    constrained layout only reserves room for a suptitle at its automatic position)."""
    import textwrap
    fs = 8.5
    if max_chars is None:  # bold DejaVu Sans: ~0.63 em per character on average
        max_chars = max(20, int(fig.get_size_inches()[0] * 72 * 0.95 / (0.63 * fs)))
    lines = textwrap.wrap(text, max_chars) or [text]
    if len(lines) > max_lines:
        lines = lines[:max_lines]
        lines[-1] = lines[-1][:max_chars - 1].rstrip() + "…"
    pad_in = 3.0 / 72
    line_in = fs * 1.25 / 72
    fig_h = fig.get_size_inches()[1]
    banner_in = len(lines) * line_in + pad_in
    reserve_in = banner_in + pad_in
    sup = getattr(fig, "_suptitle", None)
    if sup is not None and not sup.get_text():
        sup = None
    if sup is not None:
        sup_in = (sup.get_text().count("\n") + 1) * sup.get_fontsize() * 1.25 / 72
        reserve_in += sup_in + pad_in
    eng = fig.get_layout_engine()
    params = eng.get() if eng is not None else {}
    if "rect" in params:
        left, bottom, width, height = params["rect"]
        top = bottom + height
        eng.set(rect=(left, bottom, width, height - reserve_in / fig_h))
    else:  # not constrained layout: plain subplots
        top = 1.0
        fig.subplots_adjust(top=min(fig.subplotpars.top, 1.0 - reserve_in / fig_h))
    if sup is not None:
        fig.suptitle(sup.get_text(), y=top - (banner_in + pad_in) / fig_h, va="top",
                     fontsize=sup.get_fontsize(), fontweight=sup.get_fontweight(),
                     color=sup.get_color())
    fig.text(0.5, top - pad_in / fig_h, "\n".join(lines), ha="center", va="top", fontsize=fs,
             color=FAIL_COLOR, fontweight="bold", linespacing=1.1)
    return fig


def _run_info(result: Result) -> str:
    parts = [result.stem]
    m = result.contact_method
    if m:
        parts.append(f"{m.upper()} contact")
    elif result.guided:
        parts.append("guided wheelsets")
    sv = result.attrs.get("solver") or (result.stats or {}).get("method")
    if sv:
        parts.append(f"solver {sv}")
    return ", ".join(parts)


def _grid(n_items: int, n_quant: int, row_h: float, extra_h: float, max_cols: int = 4):
    """Axes for n_items columns (bodies / wheelsets) x n_quant rows (quantities).

    More than max_cols items wrap into further bands of n_quant rows.  The axes of one item
    share x (bodies of a vehicle are at different distances: in a short run a common x range
    would squeeze every column into a corner); only the bottom row of each item has x tick
    labels.  Returns (fig, cells, ncol), cells[i][q]."""
    nb = max(1, math.ceil(n_items / max_cols))
    ncol = max(1, math.ceil(n_items / nb))
    nrows = nb * n_quant
    fig_h = min(nrows * row_h + extra_h, 9.4)
    fig, axes = plt.subplots(nrows, ncol, figsize=(A4_WIDTH_IN, fig_h), squeeze=False,
                             layout="constrained")
    cells = []
    for i in range(nb * ncol):
        b, c = divmod(i, ncol)
        col = [axes[b * n_quant + q, c] for q in range(n_quant)]
        if i >= n_items:
            for ax in col:
                ax.set_visible(False)
            continue
        for ax in col[1:]:
            ax.sharex(col[0])
        for ax in col[:-1]:
            ax.xaxis.set_tick_params(labelbottom=False)
        cells.append(col)
    return fig, cells, ncol


def _share_rows(cells: List[List], keys: Sequence[str], ncol: int, labels: Sequence[str]):
    """Share y within each quantity row between items with the same key (e.g. body kind); y
    tick labels are dropped where the left neighbour already shows the same scale.  The first
    column of every band gets the row labels `labels`."""
    for q in range(len(cells[0]) if cells else 0):
        first: Dict[str, object] = {}
        for i, col in enumerate(cells):
            ax = col[q]
            if i % ncol == 0:
                ax.set_ylabel(labels[q])
            ref = first.get(keys[i])
            if ref is None:
                first[keys[i]] = ax
                continue
            ax.sharey(ref)
            if i % ncol != 0 and keys[i - 1] == keys[i]:
                ax.tick_params(labelleft=False)


def _min_span(ax, span: float):
    lo, hi = ax.get_ylim()
    if hi - lo < span:
        c = 0.5 * (lo + hi)
        ax.set_ylim(c - span / 2, c + span / 2)


def _bottom_legend(fig, groups: Sequence[Sequence], fig_h: float, max_per_row: int = 6):
    """Legend in a strip below the axes (matplotlib 3.6: no loc="outside ...").

    groups: lists of handles (e.g. runs, then segment kinds and markers).  They share one row
    when they fit in `max_per_row` entries, else each group gets a row of its own (split if
    longer), filled left to right."""
    from matplotlib.lines import Line2D

    groups = [list(g) for g in groups if g]
    if not groups:
        return
    flat = [h for g in groups for h in g]
    if len(flat) <= max_per_row:
        rows = [flat]
    else:
        rows = []
        for g in groups:
            rows += [g[i:i + max_per_row] for i in range(0, len(g), max_per_row)]
    ncol = max(len(r) for r in rows)
    blank = lambda: Line2D([], [], ls="none", label=" ")  # noqa: E731
    rows = [r + [blank() for _ in range(ncol - len(r))] for r in rows]
    handles = [rows[r][c] for c in range(ncol) for r in range(len(rows))]  # column-major
    strip = (0.1 + 0.17 * len(rows)) / fig_h
    eng = fig.get_layout_engine()
    left, bottom, width, height = eng.get()["rect"]
    eng.set(rect=(left, bottom + strip, width, height - strip))
    fig.legend(handles=handles, loc="lower center", bbox_to_anchor=(0.5, 0.0), ncol=ncol,
               fontsize=7, frameon=False, handlelength=2.2, columnspacing=1.4)


def _set_distance_range(ax, xmin: float, xmax: float, track: Optional[Track], to_end: bool):
    """x limits from the data; ends within 5 % of the track length snap to the track ends, and
    `to_end` (failed run) extends the range to the track end to show what is missing."""
    if track is not None:
        bounds = track.segment_bounds()
        b0, b1 = float(bounds[0]), float(bounds[-1])
        tol = 0.05 * (b1 - b0)
        if to_end:
            xmax = max(xmax, b1)
        if np.isfinite(xmin) and abs(xmin - b0) < tol:
            xmin = min(xmin, b0)
        if np.isfinite(xmax) and abs(xmax - b1) < tol:
            xmax = max(xmax, b1)
    if np.isfinite(xmin) and np.isfinite(xmax) and xmax > xmin:
        ax.set_xlim(xmin, xmax)


def _fail_marker(ax, x, v):
    p = _last_finite(x, v)
    if p is not None:
        ax.plot([p[0]], [p[1]], ls="none", marker="x", ms=5, mew=1.3, color=FAIL_COLOR, zorder=6)


def _fail_handle(label="last output of a failed run"):
    from matplotlib.lines import Line2D
    return Line2D([], [], ls="none", marker="x", ms=5, mew=1.3, color=FAIL_COLOR, label=label)


def _run_style(k: int) -> Dict[str, object]:
    """Colour, dash pattern and width of run k (dotted lines a little wider to stay visible)."""
    ls = RUN_STYLES[k % len(RUN_STYLES)]
    dotted = isinstance(ls, tuple) and ls[1][0] < 2
    return dict(color=RUN_COLORS[k % len(RUN_COLORS)], ls=ls, lw=1.3 if dotted else 1.0)


# Rows of the kinematics figures: dataset, scale to display unit, y label, minimum y span.
_KIN_ROWS = (
    ("y", 1e3, "lateral displacement\ny [mm]", 1.0),
    ("yaw", 1e3, "yaw angle\nψ [mrad]", 1.0),
)


def fig_kinematics(runs: Sequence[Tuple[Result, str]], names: Sequence[str], title: str):
    """Lateral displacement y [mm] (top row) and yaw angle ψ [mrad] (bottom row) of the bodies
    `names` (one column each, up to 4 per band) versus the travelled distance s of each body,
    segments shaded as in paper Fig. 17 (white tangent, grey transition, blue curve).

    runs: [(result, label), ...]; each run gets its own colour and line style (Fig. 19-22).
    The track of the first run is shaded.  Bodies of the same kind share the y scale in a row.
    A failed run ends with a red x at its last output; the x range then reaches the track end.
    """
    from matplotlib.lines import Line2D

    if not names:
        raise ValueError("fig_kinematics: no bodies to draw")
    tr = runs[0][0].track
    kinds = []
    for n in names:
        b = next((r.bodies[n] for r, _ in runs if n in r.bodies), None)
        kinds.append(b.kind if b is not None else "?")
    any_failed = any(r.failed for r, _ in runs)
    with report_style():
        fig, cells, ncol = _grid(len(names), len(_KIN_ROWS), row_h=1.55, extra_h=0.95)
        _share_rows(cells, kinds, ncol, [row[2] for row in _KIN_ROWS])
        fig_h = fig.get_size_inches()[1]
        for i, (n, col) in enumerate(zip(names, cells)):
            xmin, xmax = np.inf, -np.inf
            for q, (key, scale, ylab, _) in enumerate(_KIN_ROWS):
                ax = col[q]
                ax.set_gid(f"{key}:{n}")
                if tr is not None:
                    _shade_segments(ax, tr)
                ax.axhline(0, color="k", lw=0.4, zorder=0.6)
                for k, (r, _) in enumerate(runs):
                    b = r.bodies.get(n)
                    if b is None or not b.has("s", key):
                        continue
                    x, v = _pair(b.data["s"], b.data[key] * scale)
                    ax.plot(x, v, zorder=2 + k, gid="data", **_run_style(k))
                    if r.failed:
                        _fail_marker(ax, x, v)
                    fin = x[np.isfinite(x)]
                    if fin.size:
                        xmin, xmax = min(xmin, fin.min()), max(xmax, fin.max())
                if q == 0:
                    ax.set_title(body_title(n), fontsize=8.5)
                if q == len(_KIN_ROWS) - 1:
                    ax.set_xlabel("distance s [m]")
            _set_distance_range(col[0], xmin, xmax, tr, any_failed)
        for col in cells:
            for q, row in enumerate(_KIN_ROWS):
                _min_span(col[q], row[3])
        handles = []
        for k, (r, lab) in enumerate(runs):
            handles.append(Line2D([], [], label=lab + (" (failed)" if r.failed else ""),
                                  **_run_style(k)))
        marks = _segment_legend_handles(tr) if tr is not None else []
        if any_failed:
            marks.append(_fail_handle())
        _bottom_legend(fig, [handles, marks], fig_h)
        fig.suptitle(title, fontsize=9.5)
    return fig


def fig_wheelsets(result: Result):
    """Lateral displacement [mm] and yaw angle [mrad] of every wheelset vs distance (Fig. 19)."""
    names = result.kinematic_bodies(("wheelset",))
    return fig_kinematics([(result, result.label())], names,
                          f"Wheelsets: lateral displacement and yaw angle — {_run_info(result)}")


def fig_bodies_car(result: Result):
    """The same for the bogies and the car body (Fig. 20), bogies first."""
    names = result.kinematic_bodies(("bogie",)) + result.kinematic_bodies(("car",))
    return fig_kinematics([(result, result.label())], names,
                          f"Bogies and car body: lateral displacement and yaw angle — "
                          f"{_run_info(result)}")


# Quantities of the contact figures.  The engine writes every per-wheel column for both contact
# methods, so a KEC file holds zeros where only the LUT Hertz flange has a value
# (flange_force, flange_indentation): those zeros are not results and are never drawn as such.
@dataclass(frozen=True)
class ContactRow:
    key: str                                 # dataset under /contact/<ws>/<side>/
    scale: float                             # to the display unit
    label: str                               # y label
    min_span: float                          # smallest y span (display unit)
    methods: Tuple[str, ...] = ("kec", "lut")  # contact methods whose result holds it
    creep: bool = False                      # computed only with a creep law (not "none")


_ROW_Q = ContactRow("normal_force", 1e-3, "normal force\nQ [kN]", 5.0)
_ROW_YQ = ContactRow("y_over_q", 1.0, "derailment\nquotient Y/Q [-]", 0.1)
_ROW_TREAD = ContactRow("normal_tread", 1e-3, "tread patch\nnormal force [kN]", 5.0)
_ROW_FLANGE = ContactRow("normal_flange", 1e-3, "flange patch\nnormal force [kN]", 2.0)
_ROW_INDENT = ContactRow("flange_indentation", 1e3, "flange indentation\n[mm] (< 0: gap)", 0.05,
                         methods=("lut",))
_ROW_REGIME = ContactRow("regime", 1.0, "contact\nregime", 2.6)
_CONTACT_ROWS = (_ROW_Q, _ROW_YQ)
_FLANGE_ROWS = (_ROW_TREAD, _ROW_FLANGE, _ROW_INDENT, _ROW_REGIME)
_CREEP_ROWS = (
    ContactRow("creepage_x", 1e3, "long. creepage\nξx [‰]", 0.5, creep=True),
    ContactRow("creepage_y", 1e3, "lat. creepage\nξy [‰]", 0.5, creep=True),
    ContactRow("spin", 1.0, "spin\nφ [1/m]", 0.02, creep=True),
    ContactRow("creep_force_x", 1e-3, "long. creep\nforce Fx [kN]", 1.0, creep=True),
    ContactRow("creep_force_y", 1e-3, "lat. creep\nforce Fy [kN]", 1.0, creep=True),
)
REGIME_NAMES = ("tread", "two-point", "flange")
# Drawn a little apart so that both wheels stay visible where their regimes are equal.
_REGIME_OFFSET = {"left": -0.06, "right": 0.06}


def _method(result: Result) -> Optional[str]:
    """'kec' or 'lut' for a contact run, else None (also for files that do not say)."""
    m = result.contact.attrs.get("method") if result.contact is not None else None
    m = str(m).strip().lower() if m else (result.contact_method or "").lower()
    return m if m in ("kec", "lut") else None


def _contact_series(result: Result, wc: WheelsetContact, key: str,
                    side: str) -> Optional[np.ndarray]:
    v = wc.side(side, key)
    if v is None and key == "normal_flange" and _method(result) == "lut":
        v = wc.side(side, "flange_force")  # older LUT files: the Hertz force is the flange patch
    return v


def _row_present(result: Result, row: ContactRow) -> bool:
    """The file holds `row` for at least one wheel, and the run's contact method produces it."""
    c = result.contact
    if c is None:
        return False
    m = _method(result)
    if m is not None and m not in row.methods:
        return False
    # Without a creep law the engine writes zeros for creepages, spin and creep forces.
    if row.creep and str(c.attrs.get("creep", "")).strip().lower() == "none":
        return False
    return any(_contact_series(result, wc, row.key, sd) is not None
               for wc in c.wheelsets.values() for sd in ("left", "right"))


def _contact_rows(result: Result, rows) -> List[ContactRow]:
    return [row for row in rows if _row_present(result, row)]


def nadal_limit(mu: float, flange_angle: float) -> float:
    """Nadal's flange-climb limit of Y/Q: (tan γ - μ) / (1 + μ tan γ), γ the flange angle."""
    t = math.tan(flange_angle)
    return (t - mu) / (1.0 + mu * t)


def nadal_from_file(result: Result) -> Optional[Tuple[float, float, float]]:
    """(limit, mu, flange angle [rad]) from the /contact attributes `mu` and `flange_angle`
    [rad] (or `flange_angle_deg`); None when the file does not give both."""
    if result.contact is None:
        return None
    a = result.contact.attrs
    mu = _num(a.get("mu"))
    gam = _num(a.get("flange_angle"))
    if gam is None and _num(a.get("flange_angle_deg")) is not None:
        gam = math.radians(_num(a.get("flange_angle_deg")))
    if mu is None or gam is None or not (0.0 < gam < math.pi / 2) or mu < 0:
        return None
    return nadal_limit(mu, gam), mu, gam


def _contact_figure(result: Result, rows: Sequence[ContactRow], title: str,
                    notes: Sequence[str] = ()):
    """Rows = quantities, columns = wheelsets; left wheel solid blue, right wheel dashed red.

    Every panel is drawn from the file's data; `notes` (e.g. rows left out because the method
    does not produce them) go on a second title line."""
    from matplotlib.lines import Line2D

    c = result.contact
    tr = result.track
    wss = list(c.wheelsets)
    use_s = all(w in result.bodies and result.bodies[w].has("s") for w in wss)
    if use_s:
        xs = {w: result.bodies[w].data["s"] for w in wss}
        xlabel = "distance s [m]"
    elif result.time is not None:
        xs = {w: result.time for w in wss}
        xlabel = "time t [s]"
    else:  # no abscissa at all: sample index
        xs = {w: None for w in wss}
        xlabel = "output sample"
    nadal = nadal_from_file(result) if _ROW_YQ in rows else None
    with report_style():
        fig, cells, ncol = _grid(len(wss), len(rows), row_h=1.3, extra_h=1.1)
        _share_rows(cells, ["all"] * len(cells), ncol, [row.label for row in rows])
        fig_h = fig.get_size_inches()[1]
        for i, (w, col) in enumerate(zip(wss, cells)):
            wc = c.wheelsets[w]
            xmin, xmax = np.inf, -np.inf
            for q, row in enumerate(rows):
                ax = col[q]
                ax.set_gid(f"{row.key}:{w}")  # lets tests and scripts find a panel
                if use_s and tr is not None:
                    _shade_segments(ax, tr)
                if row.key not in ("normal_force", "regime"):  # Q stays near its static value
                    ax.axhline(0, color="k", lw=0.4, zorder=0.6)
                shown, nonzero = False, False
                for side in ("left", "right"):
                    v = _contact_series(result, wc, row.key, side)
                    if v is None:
                        continue
                    x = xs[w] if xs[w] is not None else np.arange(v.size, dtype=float)
                    x, v = _pair(x, v * row.scale)
                    kw = dict(lw=0.9, zorder=3, gid="data", **SIDE_STYLE[side])
                    if row is _ROW_REGIME:
                        v = v + _REGIME_OFFSET[side]
                        kw["drawstyle"] = "steps-post"
                    ax.plot(x, v, **kw)
                    shown = True
                    nonzero |= bool(np.any(np.abs(v[np.isfinite(v)]) > 0))
                    if result.failed:
                        _fail_marker(ax, x, v)
                    fin = x[np.isfinite(x)]
                    if fin.size:
                        xmin, xmax = min(xmin, fin.min()), max(xmax, fin.max())
                if not shown:
                    ax.text(0.5, 0.5, "not in this result", transform=ax.transAxes,
                            ha="center", va="center", fontsize=7, color="#777777")
                elif row is _ROW_FLANGE and not nonzero:
                    ax.text(0.5, 0.62, "no flange contact", transform=ax.transAxes,
                            ha="center", va="center", fontsize=7, color="#555555")
                if row is _ROW_REGIME:
                    ax.set_ylim(-0.4, 2.4)
                    ax.set_yticks(range(len(REGIME_NAMES)))
                    ax.set_yticklabels(REGIME_NAMES, fontsize=6.5)
                if row is _ROW_YQ and nadal is not None:
                    ax.axhline(nadal[0], color="k", lw=0.9, ls=(0, (6, 2, 1.2, 2)), zorder=2.5)
                if q == 0:
                    ax.set_title(body_title(w), fontsize=8.5)
                if q == len(rows) - 1:
                    ax.set_xlabel(xlabel)
            _set_distance_range(col[0], xmin, xmax, tr if use_s else None, result.failed)
        for col in cells:
            for q, row in enumerate(rows):
                if row is not _ROW_REGIME:
                    _min_span(col[q], row.min_span)
        handles = [Line2D([], [], lw=0.9, label=f"{sd} wheel", **SIDE_STYLE[sd])
                   for sd in ("left", "right")]
        if _ROW_YQ in rows:
            if nadal is not None:
                handles.append(Line2D([], [], color="k", lw=0.9, ls=(0, (6, 2, 1.2, 2)),
                                      label=f"Nadal limit {nadal[0]:.2f} (μ = {nadal[1]:g}, "
                                            f"flange angle {math.degrees(nadal[2]):.4g}°)"))
            else:
                handles.append(Line2D([], [], ls="none",
                                      label="Nadal limit not drawn: the file gives no μ and "
                                            "flange angle"))
        marks = _segment_legend_handles(tr) if (use_s and tr is not None) else []
        if result.failed:
            marks.append(_fail_handle("last output (run failed)"))
        _bottom_legend(fig, [handles, marks], fig_h, max_per_row=4)
        fig.suptitle("\n".join([title, *notes]), fontsize=9.5)
    return fig


def fig_contact_forces(result: Result):
    """Normal force Q [kN] per wheel and the derailment quotient Y/Q (lateral force of the
    rail on the wheel toward the track centre over Q) per wheelset versus distance (paper
    Fig. 24, 25), with Nadal's limit when the file gives μ and the flange angle."""
    rows = _contact_rows(result, _CONTACT_ROWS)
    return _contact_figure(result, rows,
                           f"Wheel–rail contact forces — {_run_info(result)}")


def fig_flange_contact(result: Result):
    """Where the flange carries load: the normal force of the tread patch and of the flange
    patch per wheel (KEC: the two points of the two-point contact; LUT: the tread contact and
    the Hertz flange force of Eq. 20), the LUT flange indentation (Eq. 21, negative: the gap
    still open), and the contact regime (tread, two-point, flange only)."""
    rows = _contact_rows(result, _FLANGE_ROWS)
    m = _method(result)
    notes = []
    if m == "kec":
        notes.append("KEC: flange load of the two-point contact (no indentation: constraint "
                     "contact)")
    elif m == "lut":
        notes.append("LUT: flange patch = Hertz flange force (Eq. 20)")
    left_out = [r.key for r in _FLANGE_ROWS if r not in rows and (m is None or m in r.methods)]
    if left_out:
        notes.append("not in this result: " + ", ".join(left_out))
    return _contact_figure(result, rows, f"Flange contact — {_run_info(result)}", notes)


def fig_creep(result: Result):
    """Creepages [‰], spin [1/m] and creep forces [kN] per wheelset and wheel vs distance."""
    rows = _contact_rows(result, _CREEP_ROWS)
    return _contact_figure(result, rows, f"Creepages and creep forces — {_run_info(result)}")


# Rows of the acceleration figure: dataset, label, minimum y span [m/s^2].
_ACC_ROWS = (
    ("ay", "lateral\n$a_y$ [m/s²]", 0.05),
    ("az", "vertical\n$a_z$ [m/s²]", 0.05),
    ("ax", "longitudinal\n$a_x$ [m/s²]", 0.05),
)


def acceleration_bodies(result: Result) -> List[str]:
    """Bodies with accelerations to draw: car body and bogies (what ride comfort needs; the
    wheelsets follow the rails), or every body with them when the vehicle has neither."""
    have = [n for n, b in result.bodies.items() if any(b.has(k) for k, _, _ in _ACC_ROWS)]
    main = [n for n in have if result.bodies[n].kind == "car"] + \
        [n for n in have if result.bodies[n].kind == "bogie"]
    return main or have


def fig_accelerations(result: Result):
    """Body accelerations (track-frame components of the absolute acceleration of the centre
    of mass) of the car body and bogies versus distance, with their RMS.  The longitudinal row
    is left out when it is zero throughout (a constant speed), and said so in the title."""
    from matplotlib.lines import Line2D

    names = acceleration_bodies(result)
    tr = result.track

    def series(n, key):
        b = result.bodies[n]
        return b.data[key] if b.has(key) else None

    rows = [r for r in _ACC_ROWS if any(series(n, r[0]) is not None for n in names)]
    notes = []
    ax_row = next((r for r in rows if r[0] == "ax"), None)
    if ax_row is not None and all(
            series(n, "ax") is None or not np.any(np.abs(series(n, "ax")) > 1e-9)
            for n in names):
        rows.remove(ax_row)
        notes.append("longitudinal acceleration zero throughout (not drawn)")
    kinds = [result.bodies[n].kind for n in names]
    with report_style():
        fig, cells, ncol = _grid(len(names), len(rows), row_h=1.45, extra_h=1.0)
        _share_rows(cells, kinds, ncol, [r[1] for r in rows])
        fig_h = fig.get_size_inches()[1]
        for n, col in zip(names, cells):
            b = result.bodies[n]
            use_s = b.has("s")
            xmin, xmax = np.inf, -np.inf
            for q, (key, label, span) in enumerate(rows):
                ax = col[q]
                ax.set_gid(f"{key}:{n}")
                if use_s and tr is not None:
                    _shade_segments(ax, tr)
                ax.axhline(0, color="k", lw=0.4, zorder=0.6)
                v = series(n, key)
                if v is None:
                    ax.text(0.5, 0.5, "not in this result", transform=ax.transAxes,
                            ha="center", va="center", fontsize=7, color="#777777")
                else:
                    x = b.data["s"] if use_s else (result.time if result.time is not None
                                                   else np.arange(v.size, dtype=float))
                    x, v = _pair(x, v)
                    ax.plot(x, v, color=RUN_COLORS[0], lw=0.8, zorder=3, gid="data")
                    if result.failed:
                        _fail_marker(ax, x, v)
                    ok = np.isfinite(v)
                    if ok.any():
                        rms = float(np.sqrt(np.mean(v[ok] ** 2)))
                        # as a legend: loc="best" keeps the label off the curve
                        ax.legend([Line2D([], [], ls="none")], [f"RMS {rms:.3g} m/s²"],
                                  loc="best", handlelength=0, handletextpad=0, fontsize=6.5,
                                  borderpad=0.25, framealpha=0.85)
                    fin = x[np.isfinite(x)]
                    if fin.size:
                        xmin, xmax = min(xmin, fin.min()), max(xmax, fin.max())
                if q == 0:
                    ax.set_title(body_title(n), fontsize=8.5)
                if q == len(rows) - 1:
                    ax.set_xlabel("distance s [m]" if use_s else "time t [s]")
            _set_distance_range(col[0], xmin, xmax, tr if use_s else None, result.failed)
        for col in cells:
            for q, r in enumerate(rows):
                _min_span(col[q], r[2])
        marks = _segment_legend_handles(tr) if tr is not None else []
        if result.failed:
            marks.append(_fail_handle("last output (run failed)"))
        _bottom_legend(fig, [marks], fig_h)
        fig.suptitle("\n".join([f"Body accelerations — {_run_info(result)}", *notes]),
                     fontsize=9.5)
    return fig


# Display scale and unit of element outputs, by the unit the file gives.
_ELEMENT_UNITS = {"m": (1e3, "mm"), "rad": (1e3, "mrad"), "N": (1e-3, "kN"),
                  "N m": (1e-3, "kN m"), "N*m": (1e-3, "kN m")}
MAX_ELEMENTS = 12


def _element_names(result: Result) -> List[str]:
    return [n for n, d in result.elements.items()
            if any(k in d and d[k].size for k in ("deflection", "force"))]


def fig_elements(result: Result, max_items: int = MAX_ELEMENTS):
    """Deflection and force of the suspension elements the run wrote (run.output.elements)
    versus time; the first `max_items` elements in file order, the others named in the title."""
    names = _element_names(result)
    shown = names[:max_items]
    notes = []
    if len(names) > len(shown):
        notes.append(f"first {len(shown)} of {len(names)} elements")
    quantities = ("deflection", "force")

    def unit(n, q):
        u = result.element_units.get(n, {}).get(q, "")
        return _ELEMENT_UNITS.get(u, (1.0, u or "?"))

    row_units = [{unit(n, q)[1] for n in shown} for q in quantities]
    labels = [f"{q}\n[{next(iter(us))}]" if len(us) == 1 else q
              for q, us in zip(quantities, row_units)]
    with report_style():
        fig, cells, ncol = _grid(len(shown), 2, row_h=1.45, extra_h=0.9)
        # share y only between elements of the same units
        _share_rows(cells, ["/".join(unit(n, q)[1] for q in quantities) for n in shown], ncol,
                    labels)
        fig_h = fig.get_size_inches()[1]
        for n, col in zip(shown, cells):
            d = result.elements[n]
            xmin, xmax = np.inf, -np.inf
            for q, key in enumerate(quantities):
                ax = col[q]
                ax.set_gid(f"{key}:{n}")
                ax.axhline(0, color="k", lw=0.4, zorder=0.6)
                scale, u = unit(n, key)
                v = d.get(key)
                if v is None or not v.size:
                    ax.text(0.5, 0.5, "not in this result", transform=ax.transAxes,
                            ha="center", va="center", fontsize=7, color="#777777")
                else:
                    x = result.time if result.time is not None else \
                        np.arange(v.size, dtype=float)
                    x, v = _pair(x, v * scale)
                    ax.plot(x, v, color=RUN_COLORS[0], lw=0.8, zorder=3, gid="data")
                    if result.failed:
                        _fail_marker(ax, x, v)
                    fin = x[np.isfinite(x)]
                    if fin.size:
                        xmin, xmax = min(xmin, fin.min()), max(xmax, fin.max())
                    if len(row_units[q]) > 1:
                        ax.text(0.01, 0.95, f"[{u}]", transform=ax.transAxes, ha="left",
                                va="top", fontsize=6.5, color="#333333")
                if q == 0:
                    ax.set_title(n, fontsize=7.5)
                if q == len(quantities) - 1:
                    ax.set_xlabel("time t [s]")
            _set_distance_range(col[0], xmin, xmax, None, False)
        if result.failed:
            _bottom_legend(fig, [[_fail_handle("last output (run failed)")]], fig_h)
        fig.suptitle("\n".join([f"Suspension elements — {_run_info(result)}", *notes]),
                     fontsize=9.5)
    return fig


def panel_points(fig) -> Dict[str, int]:
    """The panels of a vehicle figure made here, by id "<quantity>:<body, wheelset or
    element>" (e.g. "y_over_q:ws1", "ay:car", "force:prim_z_ws1_l"), each with the number of
    finite data points drawn in it: 0 means the panel shows no data."""
    out = {}
    for ax in fig.axes:
        gid = ax.get_gid()
        if not gid:
            continue
        n = 0
        for ln in ax.get_lines():
            if ln.get_gid() == "data":
                y = np.asarray(ln.get_ydata(), dtype=float)
                n += int(np.count_nonzero(np.isfinite(y)))
        out[gid] = n
    return out


def steady_state(result: Result, fraction: float = 0.2,
                 kinds: Sequence[str] = KINEMATIC_KINDS) -> List[Dict[str, object]]:
    """Steady-curving values (paper Tables 5, 6): per body, the mean lateral displacement
    [mm] and yaw angle [mrad] over the last `fraction` of the distance the body travelled
    (s >= s_end - fraction * (s_end - s_start), NaN samples ignored).

    Returns [{body, kind, y_mm, yaw_mrad, s_from_m, s_to_m, samples}, ...] in vehicle order."""
    out = []
    for n in result.kinematic_bodies(kinds):
        b = result.bodies[n]
        s = b.data["s"]
        fin = s[np.isfinite(s)]
        if not fin.size:
            continue
        s0, s1 = float(fin[0]), float(fin.max())
        lo = s1 - fraction * (s1 - s0)
        row = {"body": n, "kind": b.kind, "s_from_m": lo, "s_to_m": s1}
        cnt = 0
        for key, col in (("y", "y_mm"), ("yaw", "yaw_mrad")):
            val = float("nan")
            if b.has(key):
                x, v = _pair(s, b.data[key])
                sel = np.isfinite(x) & np.isfinite(v) & (x >= lo)
                if sel.any():
                    val = float(np.mean(v[sel])) * 1e3
                    cnt = max(cnt, int(sel.sum()))
            row[col] = val
        row["samples"] = cnt
        out.append(row)
    return out


def stats_summary(result: Result) -> Optional[str]:
    """One line from /stats: status, solver, CPU time, real-time factor (t_reached / CPU
    time), rhs evaluations, steps; None if the file has no /stats."""
    st = result.stats
    if st is None:
        return None
    status = str(st.get("status", "?")).strip() or "?"
    parts = ["FAILED" if status.lower() == "failed" else status]
    if st.get("method"):
        parts.append(f"solver {st['method']}")
    if result.contact_method:
        parts.append(f"contact {result.contact_method.upper()}")
    cpu = _num(st.get("cpu_time_s"))
    wall = _num(st.get("wall_time_s"))
    t = _num(st.get("t_reached"))
    if t is not None:
        parts.append(f"t = {t:.6g} s reached")
    if cpu is not None:
        parts.append(f"CPU {cpu:.4g} s" + (f" (wall {wall:.4g} s)" if wall is not None else ""))
        if t is not None and cpu > 0:
            parts.append(f"{t / cpu:.3g}x real time")
    rhs, jac = _num(st.get("rhs_evals")), _num(st.get("rhs_evals_jac"))
    if rhs is not None:
        parts.append(f"{int(rhs)} rhs evaluations"
                     + (f" (+ {int(jac)} for Jacobians)" if jac else ""))
    steps, rej = _num(st.get("steps")), _num(st.get("rejected_steps"))
    if steps is not None:
        parts.append(f"{int(steps)} steps" + (f" ({int(rej)} rejected)" if rej else ""))
    jev = _num(st.get("jacobian_evals"))
    if jev:
        parts.append(f"{int(jev)} Jacobians")
    txt = "stats: " + ", ".join(parts)
    msg = " ".join(str(st.get("message", "")).split())
    return f"{txt} — {msg}" if msg else txt


# --------------------------------------------------------------------------------------------
# Registry and driver
# --------------------------------------------------------------------------------------------
@dataclass
class FigureSpec:
    suffix: str                                  # file name: <stem>_<suffix>.png
    is_available: Callable[[Result], bool]
    make: Callable[[Result], "plt.Figure"]
    description: str = ""


FIGURES: List[FigureSpec] = [
    FigureSpec("track_plan", lambda r: r.track is not None, fig_track_plan,
               "plan view with segment transition ticks"),
    FigureSpec("track_curvature_cant", lambda r: r.track is not None, fig_curvature_cant,
               "curvature and cant versus s"),
    FigureSpec("irregularities", lambda r: r.irregularities is not None, fig_irregularities,
               "alignment, vertical, gauge, cross level versus s"),
    FigureSpec("irregularity_psd",
               lambda r: r.irregularities is not None and r.irregularities.data["s"].size >= 16,
               fig_irregularity_psd, "Welch PSD estimate against target"),
    # Guided wheelsets follow the track: their y and yaw are zero by construction, not results.
    FigureSpec("wheelsets", lambda r: bool(r.kinematic_bodies(("wheelset",))) and not r.guided,
               fig_wheelsets, "wheelset lateral displacement and yaw versus distance"),
    FigureSpec("bogies_car", lambda r: bool(r.kinematic_bodies(("bogie", "car"))), fig_bodies_car,
               "bogie and car body lateral displacement and yaw versus distance"),
    FigureSpec("contact_forces", lambda r: bool(_contact_rows(r, _CONTACT_ROWS)),
               fig_contact_forces, "normal force Q and Y/Q per wheel"),
    FigureSpec("flange_contact",
               lambda r: _row_present(r, _ROW_FLANGE) or _row_present(r, _ROW_INDENT),
               fig_flange_contact, "tread and flange normal force, flange indentation, regime"),
    FigureSpec("creep", lambda r: bool(_contact_rows(r, _CREEP_ROWS)), fig_creep,
               "creepages, spin and creep forces"),
    FigureSpec("accelerations", lambda r: bool(acceleration_bodies(r)), fig_accelerations,
               "car body and bogie accelerations versus distance"),
    FigureSpec("elements", lambda r: bool(_element_names(r)), fig_elements,
               "deflection and force of the recorded suspension elements"),
    # /stats is summarised in text (stats_summary, printed by plot_run.py), not drawn.
]


def build_figure(result: Result, spec) -> "plt.Figure":
    """Make the figure of `spec` (a FigureSpec or its suffix) for `result`; a failed run gets
    the red failure banner (failure_text) above the title."""
    if isinstance(spec, str):
        match = [f for f in FIGURES if f.suffix == spec]
        if not match:
            raise KeyError(f"no figure '{spec}' (known: {', '.join(f.suffix for f in FIGURES)})")
        spec = match[0]
    fig = spec.make(result)
    txt = failure_text(result)
    if txt:
        add_failure_banner(fig, txt)
    return fig


def make_figures(result: Result, outdir: Optional[str] = None, stem: Optional[str] = None,
                 dpi: int = DPI, fmt: str = "png") -> List[str]:
    """Write every figure the result's content allows; return the written paths."""
    outdir = outdir or (os.path.dirname(os.path.abspath(result.path)))
    stem = stem or result.stem
    os.makedirs(outdir, exist_ok=True)
    written = []
    for spec in FIGURES:
        if not spec.is_available(result):
            continue
        fig = build_figure(result, spec)
        path = os.path.join(outdir, f"{stem}_{spec.suffix}.{fmt}")
        try:
            fig.savefig(path, dpi=dpi)
        finally:
            plt.close(fig)
        written.append(path)
    return written
