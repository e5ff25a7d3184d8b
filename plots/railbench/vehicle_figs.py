"""Vehicle figures: kinematics of the bodies (paper Fig. 17, 19-22) and the contact
forces per wheel (Fig. 24, 25), flange contact and creep."""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import List, Optional, Sequence, Tuple

import numpy as np

from .style import SIDE_STYLE, report_style
from .result import Result, WheelsetContact, body_title
from .track_figs import _segment_legend_handles, _shade_segments
from .layout import _bottom_legend, _label_cell, _x_range, _fail_handle, _fail_marker, _grid, _min_span, _num, _pair, _run_info, _run_style, _set_distance_range, _share_rows


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
                    xmin, xmax = _x_range(x, xmin, xmax)
                _label_cell(ax, q, len(_KIN_ROWS), body_title(n), "distance s [m]")
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
_ROW_PRESSURE = ContactRow("max_pressure", 1e-6, "peak pressure\np0 [MPa]", 200.0)
_CONTACT_ROWS = (_ROW_Q, _ROW_YQ)
_FLANGE_ROWS = (_ROW_TREAD, _ROW_FLANGE, _ROW_INDENT, _ROW_PRESSURE, _ROW_REGIME)
_CREEP_ROWS = (
    ContactRow("creepage_x", 1e3, "long. creepage\nξx [‰]", 0.5, creep=True),
    ContactRow("creepage_y", 1e3, "lat. creepage\nξy [‰]", 0.5, creep=True),
    ContactRow("spin", 1.0, "spin\nφ [1/m]", 0.02, creep=True),
    ContactRow("creep_force_x", 1e-3, "long. creep\nforce Fx [kN]", 1.0, creep=True),
    ContactRow("creep_force_y", 1e-3, "lat. creep\nforce Fy [kN]", 1.0, creep=True),
)
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
                    # The regime's codes as the file names them (/schema/enums/contact_regime).
                    names = result.schema.names("contact_regime")
                    if names:
                        ax.set_yticks(sorted(names))
                        ax.set_yticklabels([names[k].replace("_", "-") for k in sorted(names)],
                                           fontsize=6.5)
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
    still open), the peak Hertz pressure p0 of the wheel's patches, and the contact regime
    (tread, two-point, flange only)."""
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
