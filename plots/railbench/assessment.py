"""The engineering assessment of one run (/assessment of a result file, layout in
docs/assessment.md): reading it, its summary as text, and its figure.

    read_assessment(path) -> Assessment or None      None when the file has no /assessment
    summary_items(summary) -> [SummaryItem]          /assessment/summary, one item per quantity
    fig_assessment(result)                           the figure, panels (a)-(f):
        (a) Y/Q: 2 m sliding mean per wheel against s, limit (EN 14363, 0.8) and Nadal's limit
        (b) track shift force ΣY: 2 m sliding mean per wheelset, limit alpha (10 kN + 2 Q0/3)
        (c) wheel unloading ΔQ/Q0 per wheel, limit
        (d) continuous comfort N_c (EN 12299) per floor position and axis, N_MV in the legend
        (e) running stability: sliding rms of the bogie-frame lateral acceleration per bogie
            position, limit (12 - m+/5)/2
        (f) wear number T-gamma per wheel
    A group the run did not write gets no panel (never an error); the summary (value against
    limit, ok / EXCEEDED) is written under the title.
"""
from __future__ import annotations

import math
import re
from dataclasses import dataclass, field
from typing import Dict, List, Optional, Tuple

import numpy as np

from .h5 import ResultFileError, _attrs, _str, check_declared_size, open_h5
from .layout import _bottom_legend, _num, _pair, _run_info, _set_distance_range
from .style import A4_WIDTH_IN, FAIL_COLOR, RUN_COLORS, plt, report_style
from .track_figs import _segment_legend_handles, _shade_segments


@dataclass
class Quantity:
    """One assessed quantity's group: its attributes (unit, value, limit, margin, ok, clause,
    at_s, ...) and its 1-D datasets."""
    attrs: Dict[str, object]
    data: Dict[str, np.ndarray] = field(default_factory=dict)

    def series(self, key: str) -> Optional[np.ndarray]:
        v = self.data.get(key)
        return v if v is not None and v.size else None


@dataclass
class Assessment:
    attrs: Dict[str, object]
    summary: Dict[str, object]
    time: Optional[np.ndarray] = None            # /assessment/time [s]
    distance: Optional[np.ndarray] = None        # /assessment/distance [m]
    safety_s: Optional[np.ndarray] = None        # /assessment/safety/s [m] (older files)
    s_offset: Dict[Tuple[str, str], float] = field(default_factory=dict)      # (ws, side) [m]
    sections: List["Section"] = field(default_factory=list)                   # in track order
    y_over_q: Dict[Tuple[str, str], Quantity] = field(default_factory=dict)   # (ws, side)
    dq_over_q: Dict[Tuple[str, str], Quantity] = field(default_factory=dict)  # (ws, side)
    sum_y: Dict[str, Quantity] = field(default_factory=dict)                  # ws
    stability: Dict[Tuple[str, str], Quantity] = field(default_factory=dict)  # (bogie, position)
    comfort: Dict[str, Quantity] = field(default_factory=dict)                # floor position
    wear: Dict[Tuple[str, str], Quantity] = field(default_factory=dict)       # (ws, side)

    def panels(self) -> List[str]:
        """The panels the file allows, in figure order."""
        have = {"y_over_q": self.y_over_q, "sum_y": self.sum_y, "dq_over_q": self.dq_over_q,
                "comfort": self.comfort, "stability": self.stability, "wear": self.wear}
        return [k for k in PANELS if have[k]]


@dataclass
class Section:
    """One track section of /assessment/sections: name, kind, zone, range, radius, and its
    attributes (per quantity: value, _limit, _ok, _where, _at_s)."""
    name: str
    attrs: Dict[str, object]

    def get(self, key: str) -> Optional[float]:
        return _num(self.attrs.get(key))

    def text(self) -> str:
        """"curve3 (curve, zone 3, R 500 m, 150–500 m): Y/Q 0.35 · ΣY 15.6 kN · ..."."""
        a = self.attrs
        head = [str(a.get("kind", "")), str(a.get("zone", ""))]
        head = [h for h in head if h and h != "none"]
        r = self.get("radius")
        if r is not None and math.isfinite(r):
            head.append(f"R {r:.0f} m")
        lo, hi = self.get("from"), self.get("to")
        if lo is not None and hi is not None:
            head.append(f"{lo:.0f}–{hi:.0f} m")
        parts = []
        for key, label, scale, unit in SECTION_COLUMNS:
            v = self.get(key)
            if v is None:
                continue
            ok = a.get(key + "_ok")
            bad = ok is not None and not bool(ok)
            digits = 2 if scale == 1.0 else 1
            parts.append(f"{label} {v * scale:.{digits}f}{unit}" + (" EXCEEDED" if bad else ""))
        return f"{self.name} ({', '.join(head)}): " + (" · ".join(parts) if parts else "not run")


SECTION_COLUMNS = (("y_over_q", "Y/Q", 1.0, ""), ("sum_y", "ΣY", 1e-3, ""),
                   ("dq_over_q", "ΔQ/Q0", 1.0, ""), ("y_qst", "Y_qst", 1e-3, ""),
                   ("q_qst", "Q_qst", 1e-3, ""), ("q_max", "Q_max", 1e-3, ""))


PANELS = ("y_over_q", "sum_y", "dq_over_q", "comfort", "stability", "wear")
SIDES = ("left", "right")


def _natural(name: str):
    """ws2 before ws10."""
    return [int(t) if t.isdigit() else t for t in re.split(r"(\d+)", name)]


def _group_items(g):
    import h5py
    return sorted(((k, v) for k, v in g.items() if isinstance(v, h5py.Group)),
                  key=lambda kv: _natural(kv[0]))


def _ok_run(f) -> bool:
    stats = f.get("stats")
    return stats is not None and _str(stats.attrs.get("status", "")) == "ok"


def _series(v) -> np.ndarray:
    """A dataset of /assessment as float, its declared size checked against the file's, and in
    the result of a run that finished ok every sample finite (ResultFileError naming its path
    otherwise: such a run never writes a NaN, and one would be drawn as a gap in a quantity that
    the figure presents as assessed)."""
    check_declared_size(v, v.name)
    a = np.asarray(v[()], dtype=float).reshape(-1)
    if not np.all(np.isfinite(a)) and _ok_run(v.file):
        k = int(np.flatnonzero(~np.isfinite(a))[0])
        raise ResultFileError(f"{v.file.filename}: {v.name} holds {a[k]} at sample {k} of "
                              f"{a.size}; a signal of a result must be finite")
    return a


def _quantity(g) -> Quantity:
    import h5py
    data = {}
    for k, v in g.items():
        if isinstance(v, h5py.Dataset):
            try:
                data[k] = _series(v)
            except (TypeError, ValueError):
                continue
    return Quantity(_attrs(g), data)


def _dataset(g, name: str) -> Optional[np.ndarray]:
    import h5py
    v = g.get(name)
    if isinstance(v, h5py.Dataset):
        a = _series(v)
        return a if a.size else None
    return None


def _read_safety(g, a: Assessment) -> None:
    a.safety_s = _dataset(g, "s")
    for ws, wg in _group_items(g):
        if "sum_y" in wg:
            a.sum_y[ws] = _quantity(wg["sum_y"])
        for side in SIDES:
            sg = wg.get(side)
            if sg is None:
                continue
            off = _num(_attrs(sg).get("s_offset"))
            if off is not None:
                a.s_offset[(ws, side)] = off
            if "y_over_q" in sg:
                a.y_over_q[(ws, side)] = _quantity(sg["y_over_q"])
            if "dq_over_q" in sg:
                a.dq_over_q[(ws, side)] = _quantity(sg["dq_over_q"])


def _read(f) -> Optional[Assessment]:
    g = f.get("assessment")
    if g is None:
        return None
    a = Assessment(_attrs(g), _attrs(g["summary"]) if "summary" in g else {})
    a.time, a.distance = _dataset(g, "time"), _dataset(g, "distance")
    if "safety" in g:
        _read_safety(g["safety"], a)
    if "sections" in g:
        sg = g["sections"]
        names = [n for n in str(_attrs(sg).get("names", "")).split("\n") if n in sg]
        a.sections = [Section(n, _attrs(sg[n])) for n in names]
    for bogie, bg in _group_items(g["stability"]) if "stability" in g else ():
        for pos, pg in _group_items(bg):
            a.stability[(bogie, pos)] = _quantity(pg)
    if "comfort" in g:
        comfort = {pos: _quantity(pg) for pos, pg in _group_items(g["comfort"])}
        # Front of the car first (largest x offset), as the floor points sit along the car.
        order = sorted(comfort, key=lambda p: -(_num(comfort[p].attrs.get("x_offset")) or 0.0))
        a.comfort = {p: comfort[p] for p in order}
    for ws, wg in _group_items(g["wear"]) if "wear" in g else ():
        for side in SIDES:
            if side in wg:
                a.wear[(ws, side)] = _quantity(wg[side])
    return a


def read_assessment(path: str, prefix: str = "") -> Optional[Assessment]:
    """/assessment of the result file at `path` (of the vehicle at `prefix`, "/vehicles/<name>",
    in a run of several); None when the file has none."""
    with open_h5(path, ResultFileError, "result file") as f:
        return _read(f[prefix] if prefix else f)


def result_assessment(result) -> Optional[Assessment]:
    """The Assessment of a loaded Result, read once and kept in result.extra."""
    if "assessment" not in result.extra:
        has = "assessment" in (result.groups or [])
        result.extra["assessment"] = (read_assessment(result.path, result.prefix) if has
                                      else None)
    return result.extra["assessment"]


def has_assessment(result) -> bool:
    """The file has /assessment with at least one panel to draw."""
    a = result_assessment(result)
    return a is not None and bool(a.panels())


# ---- the summary ------------------------------------------------------------------------------

@dataclass(frozen=True)
class SummaryQuantity:
    key: str          # attribute name in /assessment/summary
    label: str        # display name
    unit: str         # display unit
    scale: float      # SI value -> display unit
    spec: str         # number format


SUMMARY_QUANTITIES = (
    SummaryQuantity("y_over_q", "(Y/Q)_2m", "-", 1.0, "{:.3f}"),
    SummaryQuantity("sum_y", "(ΣY)_2m", "kN", 1e-3, "{:.1f}"),
    SummaryQuantity("dq_over_q", "ΔQ/Q0", "-", 1.0, "{:.3f}"),
    SummaryQuantity("y_qst", "Y_qst", "kN", 1e-3, "{:.1f}"),
    SummaryQuantity("q_qst", "Q_qst", "kN", 1e-3, "{:.1f}"),
    SummaryQuantity("q_max", "Q_max", "kN", 1e-3, "{:.1f}"),
    SummaryQuantity("stability_rms", "stability rms", "m/s²", 1.0, "{:.2f}"),
    SummaryQuantity("n_mv", "N_MV", "-", 1.0, "{:.2f}"),
    SummaryQuantity("wz_lateral", "Wz lateral", "-", 1.0, "{:.2f}"),
    SummaryQuantity("wz_vertical", "Wz vertical", "-", 1.0, "{:.2f}"),
    SummaryQuantity("t_gamma_max", "T-gamma max", "N", 1.0, "{:.0f}"),
)
SUMMARY_BY_KEY = {q.key: q for q in SUMMARY_QUANTITIES}


@dataclass
class SummaryItem:
    quantity: SummaryQuantity
    value: float                  # SI
    limit: Optional[float]        # SI; None: not assessed against a limit (T-gamma)
    ok: Optional[bool]            # None without a limit
    where: str

    def number(self, v: float) -> str:
        return self.quantity.spec.format(v * self.quantity.scale)

    @property
    def verdict(self) -> str:
        return "" if self.ok is None else ("ok" if self.ok else "EXCEEDED")

    def against(self) -> str:
        """"0.412 ≤ 0.800 ok", "0.912 > 0.800 EXCEEDED", or the value alone without a limit."""
        if self.limit is None:
            return self.number(self.value)
        rel = "≤" if self.value <= self.limit else ">"
        return f"{self.number(self.value)} {rel} {self.number(self.limit)} {self.verdict}"

    def text(self) -> str:
        """"(ΣY)_2m [kN] 30.0 ≤ 43.3 ok (ws1)"."""
        unit = "" if self.quantity.unit == "-" else f" [{self.quantity.unit}]"
        where = f" ({self.where})" if self.where else ""
        return f"{self.quantity.label}{unit} {self.against()}{where}"


def _ok_flag(summary: Dict[str, object], key: str, value: float,
             limit: Optional[float]) -> Optional[bool]:
    if limit is None:
        return None
    ok = summary.get(key + "_ok")
    if isinstance(ok, (bool, np.bool_, int, np.integer, float)) and not isinstance(ok, str):
        return bool(ok)
    return value <= limit


def summary_items(summary: Dict[str, object]) -> List[SummaryItem]:
    """The quantities of /assessment/summary with a value, in the order of SUMMARY_QUANTITIES;
    `ok` from Q_ok (else value <= limit)."""
    out = []
    for q in SUMMARY_QUANTITIES:
        value = _num(summary.get(q.key))
        if value is None:
            continue
        limit = _num(summary.get(q.key + "_limit"))
        where = " ".join(str(summary.get(q.key + "_where", "")).split())
        out.append(SummaryItem(q, value, limit, _ok_flag(summary, q.key, value, limit), where))
    return out


def _candidates(a: Assessment, key: str) -> Dict[tuple, Quantity]:
    """The groups a summary quantity is the largest of, by their name parts."""
    if key == "sum_y":
        return {(ws,): q for ws, q in a.sum_y.items()}
    return {"y_over_q": a.y_over_q, "dq_over_q": a.dq_over_q,
            "stability_rms": a.stability}.get(key, {})


def locate(a: Assessment, key: str, item: SummaryItem) -> Optional[float]:
    """s [m] where a summary quantity occurs: the at_s of its group, the one whose name parts
    all appear in the summary's `where` (else the one whose value is the summary's value)."""
    at = _num(a.summary.get(key + "_at_s"))
    if at is not None:
        return at
    groups = _candidates(a, key)
    words = set(re.split(r"[\s,;/]+", item.where))
    match = [q for name, q in groups.items() if set(name) <= words]
    if len(match) != 1:
        match = [q for q in groups.values() if _num(q.attrs.get("value")) is not None and
                 math.isclose(_num(q.attrs.get("value")), item.value, rel_tol=1e-9)][:1]
    return _num(match[0].attrs.get("at_s")) if match else None


def summary_lines(a: Assessment, width: int = 125) -> List[str]:
    """The summary items joined with " · " into lines of at most `width` characters (an item
    is never split)."""
    lines: List[str] = []
    for t in (it.text() for it in summary_items(a.summary)):
        if lines and len(lines[-1]) + 3 + len(t) <= width:
            lines[-1] += " · " + t
        else:
            lines.append(t)
    return lines


# ---- the figure -------------------------------------------------------------------------------

LIMIT_STYLE = dict(color="k", lw=0.9, ls=(0, (6, 2, 1.2, 2)), zorder=2.5)
NADAL_STYLE = dict(color="#555555", lw=0.9, ls=(0, (3, 2)), zorder=2.5)
AXIS_STYLE = {"x": ":", "y": "-", "z": (0, (5, 2.5))}
_SIDE_LS = {"left": "-", "right": (0, (5, 2.5))}


def _wheel_style(index: Dict[str, int], ws: str, side: str) -> Dict[str, object]:
    """Colour per wheelset, line style per side (left solid, right dashed, as SIDE_STYLE)."""
    return dict(color=RUN_COLORS[index[ws] % len(RUN_COLORS)], ls=_SIDE_LS.get(side, "-"))


def _limits(quantities, key: str = "limit") -> List[float]:
    vals = sorted({round(v, 12) for q in quantities
                   for v in [_num(q.attrs.get(key))] if v is not None})
    return vals


def _limit_lines(ax, values: List[float], scale: float, data_min: float, style, label: str):
    """A horizontal line per limit value (its label in the legend); the mirrored line at -limit
    too when the data reach below -limit/4 (quantities checked by their absolute value)."""
    for v in values:
        ax.axhline(v * scale, label=label.format(v * scale), **style)
        if data_min < -0.25 * v * scale:
            ax.axhline(-v * scale, **style)


def _plot(ax, x, v, scale=1.0, **kw):
    """x, v (scaled) cut to their common length; returns the finite minimum of v."""
    if x is None or v is None:
        return math.inf
    x, v = _pair(x, v * scale)
    ax.plot(x, v, lw=0.9, zorder=3, gid="data", **kw)
    fin = v[np.isfinite(v)]
    return float(fin.min()) if fin.size else math.inf


def _sample_axis(a: Assessment) -> Tuple[Optional[np.ndarray], str]:
    """Abscissa of the series at /assessment/time: the distance when the file gives it."""
    if a.distance is not None:
        return a.distance, "distance s [m]"
    return a.time, "time t [s]"


def _own(a: Assessment, x: Optional[np.ndarray], ws: str, side: str) -> Optional[np.ndarray]:
    """The sample axis as this wheel's own distance (the leading wheelset's plus its s_offset)
    when the axis is the distance."""
    if x is None or a.distance is None or x is not a.distance:
        return x
    return x + a.s_offset.get((ws, side), 0.0)


def _wheel_index(a: Assessment) -> Dict[str, int]:
    names = {k[0] for k in list(a.y_over_q) + list(a.dq_over_q) + list(a.wear)} | set(a.sum_y)
    return {w: i for i, w in enumerate(sorted(names, key=_natural))}


def _panel_y_over_q(ax, a: Assessment, idx):
    lo = math.inf
    for (ws, side), q in a.y_over_q.items():
        s = q.series("s") if q.series("s") is not None else a.safety_s
        lo = min(lo, _plot(ax, s, q.series("value"), label=f"{ws} {side}",
                           **_wheel_style(idx, ws, side)))
    limits = _limits(a.y_over_q.values())
    _limit_lines(ax, limits, 1.0, lo, LIMIT_STYLE, "limit {:.2f}")
    nadal = [v for v in _limits(a.y_over_q.values(), "nadal_limit")
             if all(abs(v - w) > 1e-6 for w in limits)]
    _limit_lines(ax, nadal, 1.0, lo, NADAL_STYLE, "Nadal limit {:.2f}")
    ax.set_ylabel("(Y/Q)$_{2m}$ [-]")
    return "(a) derailment quotient Y/Q, 2 m sliding mean per wheel", "distance s [m]"


def _panel_sum_y(ax, a: Assessment, idx):
    lo = math.inf
    for ws, q in a.sum_y.items():
        s = q.series("s") if q.series("s") is not None else a.safety_s
        lo = min(lo, _plot(ax, s, q.series("value"), 1e-3, label=ws,
                           color=RUN_COLORS[idx[ws] % len(RUN_COLORS)]))
    _limit_lines(ax, _limits(a.sum_y.values()), 1e-3, lo, LIMIT_STYLE, "limit {:.1f} kN")
    ax.set_ylabel("(ΣY)$_{2m}$ [kN]")
    return "(b) track shift force ΣY, 2 m sliding mean per wheelset", "distance s [m]"


def _panel_dq_over_q(ax, a: Assessment, idx):
    x, xlabel = _sample_axis(a)
    for (ws, side), q in a.dq_over_q.items():
        _plot(ax, _own(a, x, ws, side), q.series("value"), label=f"{ws} {side}",
              **_wheel_style(idx, ws, side))
    _limit_lines(ax, _limits(a.dq_over_q.values()), 1.0, math.inf, LIMIT_STYLE, "limit {:.2f}")
    ax.set_ylabel("ΔQ/Q$_0$ [-]")
    return "(c) wheel unloading ΔQ/Q0 per wheel", xlabel


def _panel_comfort(ax, a: Assessment, idx):
    from matplotlib.lines import Line2D

    x, xlabel = _sample_axis(a)
    handles = []
    for k, (pos, q) in enumerate(a.comfort.items()):
        color = RUN_COLORS[k % len(RUN_COLORS)]
        for axis, ls in AXIS_STYLE.items():
            _plot(ax, x, q.series("nc_" + axis), color=color, ls=ls)
        n_mv, limit = _num(q.attrs.get("n_mv")), _num(q.attrs.get("limit"))
        lab = pos + (f": N_MV = {n_mv:.2f}" if n_mv is not None else "")
        if n_mv is not None and limit is not None:
            lab += f" (target {limit:g}, {'ok' if n_mv <= limit else 'EXCEEDED'})"
        handles.append(Line2D([], [], color=color, lw=0.9, label=lab))
    handles += [Line2D([], [], color="#444444", lw=0.9, ls=ls, label=f"N$_{{c{axis}}}$")
                for axis, ls in AXIS_STYLE.items()]
    ax.set_ylabel("N$_c$ [-]")
    return "(d) continuous comfort N_c (EN 12299) per floor position and axis", xlabel, handles


def _panel_stability(ax, a: Assessment, idx):
    for k, ((bogie, pos), q) in enumerate(a.stability.items()):
        _plot(ax, q.series("s"), q.series("rms"), label=f"{bogie} over {pos}",
              color=RUN_COLORS[k % len(RUN_COLORS)])
    _limit_lines(ax, _limits(a.stability.values()), 1.0, math.inf, LIMIT_STYLE,
                 "limit {:.2f} m/s²")
    ax.set_ylabel("sliding rms\n$\\ddot{y}^+$ [m/s²]")
    return ("(e) running stability: bogie-frame lateral acceleration, 100 m sliding rms",
            "distance s [m]")


def _panel_wear(ax, a: Assessment, idx):
    x, xlabel = _sample_axis(a)
    for (ws, side), q in a.wear.items():
        mx = _num(q.attrs.get("max"))
        lab = f"{ws} {side}" + (f" (max {mx:.0f} N)" if mx is not None else "")
        _plot(ax, _own(a, x, ws, side), q.series("t_gamma"), label=lab,
              **_wheel_style(idx, ws, side))
    ax.set_ylabel("Tγ [N]")
    return "(f) wear number T-gamma per wheel", xlabel


_PANEL_DRAW = {"y_over_q": _panel_y_over_q, "sum_y": _panel_sum_y,
               "dq_over_q": _panel_dq_over_q, "comfort": _panel_comfort,
               "stability": _panel_stability, "wear": _panel_wear}


def _summary_lines(a: Assessment) -> List[str]:
    """The verdict line (the quantities over their limits, or that every limit is kept), then
    the summary."""
    items = summary_items(a.summary)
    if not items:
        return []
    exceeded = [it.quantity.label for it in items if it.ok is False]
    head = ("EXCEEDED: " + ", ".join(exceeded)) if exceeded else "every assessed limit kept"
    sections = [sec.text() for sec in a.sections] if len(a.sections) > 1 else []
    if sections:
        sections.insert(0, "per section (worst wheel; forces in kN):")
    return [head] + summary_lines(a) + sections


def _summary_box(ax, lines: List[str]) -> None:
    """The summary as text in an axes without frame: the verdict line first (red when a limit
    is exceeded), then every value against its limit."""
    ax.axis("off")
    exceeded = lines[0].startswith("EXCEEDED")
    ax.text(0.0, 1.0, lines[0], transform=ax.transAxes, ha="left", va="top", fontsize=7.2,
            fontweight="bold", color=FAIL_COLOR if exceeded else "#1b7837")
    ax.text(0.0, 1.0 - 1.0 / len(lines), "\n".join(lines[1:]), transform=ax.transAxes,
            ha="left", va="top", fontsize=6.8, linespacing=1.15, color="#222222")


def _draw_panel(ax, key: str, a: Assessment, idx, track) -> None:
    if track is not None:
        _shade_segments(ax, track)
    out = _PANEL_DRAW[key](ax, a, idx)
    title, xlabel = out[0], out[1]
    handles = out[2] if len(out) > 2 else ax.get_legend_handles_labels()[0]
    ax.set_gid(key)
    ax.set_title(title, fontsize=8.5, loc="left")
    ax.set_xlabel(xlabel)
    if handles:
        ax.legend(handles=handles, loc="upper left", bbox_to_anchor=(1.01, 1.0), fontsize=6.5,
                  borderaxespad=0.0, handlelength=2.2)


def fig_assessment(result):
    """The assessment figure of a run: panels (a)-(f) of the module doc for what /assessment
    holds, one below the other against the distance travelled (the comfort, unloading and wear
    series against /assessment/distance, or time when the file does not give it), track segments
    shaded, limits as dash-dotted lines with their values in the legend, and the summary
    (value against limit, ok / EXCEEDED, where) under the title. None when the file has no
    panel to draw."""
    a = result_assessment(result)
    keys = a.panels() if a is not None else []
    if not keys:
        return None
    idx = _wheel_index(a)
    track = result.track
    summary = _summary_lines(a)
    with report_style():
        box_h = 0.13 * len(summary) + 0.12 if summary else 0.0
        # The panels keep their height however long the summary (sections) is.
        fig_h = min(1.3 * len(keys) + 0.75 + box_h + (0.3 if track is not None else 0.0),
                    9.4 + box_h)
        ratios = ([box_h] if summary else []) + [1.3] * len(keys)
        fig, axes = plt.subplots(len(ratios), 1, figsize=(A4_WIDTH_IN, fig_h), squeeze=False,
                                 layout="constrained", gridspec_kw=dict(height_ratios=ratios))
        axes = list(axes[:, 0])
        if summary:
            _summary_box(axes.pop(0), summary)
        for ax, key in zip(axes, keys):
            _draw_panel(ax, key, a, idx, track if _uses_distance(key, a) else None)
        if all(_uses_distance(k, a) for k in keys):  # one distance axis: labelled once
            for ax in axes[:-1]:
                ax.sharex(axes[-1])
                ax.set_xlabel("")
                ax.xaxis.set_tick_params(labelbottom=False)
            _set_distance_range(axes[-1], *_data_range(axes), track, result.failed)
        if track is not None:
            _bottom_legend(fig, [_segment_legend_handles(track)], fig_h)
        fig.suptitle(f"Assessment — {_run_info(result)}", fontsize=9.5)
    return fig


def _data_range(axes) -> Tuple[float, float]:
    """The smallest and largest finite x of the data lines of `axes`."""
    lo, hi = math.inf, -math.inf
    for ax in axes:
        for ln in ax.get_lines():
            x = np.asarray(ln.get_xdata(), dtype=float)
            if ln.get_gid() == "data" and np.isfinite(x).any():
                lo, hi = min(lo, np.nanmin(x)), max(hi, np.nanmax(x))
    return lo, hi


def _uses_distance(key: str, a: Assessment) -> bool:
    return key in ("y_over_q", "sum_y", "stability") or a.distance is not None
