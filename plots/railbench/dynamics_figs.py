"""Body accelerations and suspension element outputs versus distance or time."""
from __future__ import annotations

from typing import List

import numpy as np

from .style import RUN_COLORS, report_style
from .result import Result, body_title
from .track_figs import _segment_legend_handles, _shade_segments
from .layout import _bottom_legend, _label_cell, _x_range, _fail_handle, _fail_marker, _grid, _min_span, _pair, _run_info, _set_distance_range, _share_rows


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
                    xmin, xmax = _x_range(x, xmin, xmax)
                _label_cell(ax, q, len(rows), body_title(n),
                            "distance s [m]" if use_s else "time t [s]")
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


# An external force (external_force{}) has no deflection: its cell in the deflection row draws its
# components in the frame it was given.
_COMPONENTS = ("force_x", "force_y", "force_z")


def _external(d) -> bool:
    return all(k in d for k in _COMPONENTS)


def _element_names(result: Result) -> List[str]:
    return [n for n, d in result.elements.items()
            if any(k in d and d[k].size for k in ("deflection", "force"))]


def fig_elements(result: Result, max_items: int = MAX_ELEMENTS):
    """Deflection and force of the suspension elements the run wrote (run.output.elements)
    versus time, and of every external force its components and value; the first `max_items`
    elements in file order, the others named in the title."""
    names = _element_names(result)
    shown = names[:max_items]
    notes = []
    if len(names) > len(shown):
        notes.append(f"first {len(shown)} of {len(names)} elements")
    quantities = ("deflection", "force")

    def unit(n, q):
        if q == "deflection" and _external(result.elements[n]):
            q = _COMPONENTS[0]
        u = result.element_units.get(n, {}).get(q, "")
        return _ELEMENT_UNITS.get(u, (1.0, u or "?"))

    row_units = [{unit(n, q)[1] for n in shown} for q in quantities]
    external = [_external(result.elements[n]) for n in shown]
    names = list(quantities)
    if any(external):
        names[0] = "force components" if all(external) else "deflection or\nforce components"
    labels = [f"{q}\n[{next(iter(us))}]" if len(us) == 1 else q
              for q, us in zip(names, row_units)]
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
                if key == "deflection" and _external(d):
                    x = result.time if result.time is not None else \
                        np.arange(d[_COMPONENTS[0]].size, dtype=float)
                    for c, comp in enumerate(_COMPONENTS):
                        xc, vc = _pair(x, d[comp] * scale)
                        ax.plot(xc, vc, color=RUN_COLORS[c % len(RUN_COLORS)], lw=0.8, zorder=3,
                                gid="data", label=comp[-1])
                        fin = xc[np.isfinite(xc)]
                        if fin.size:
                            xmin, xmax = min(xmin, fin.min()), max(xmax, fin.max())
                    ax.legend(fontsize=6, loc="center right", handlelength=1.2)
                    if len(row_units[q]) > 1:
                        ax.text(0.99, 0.95, f"[{u}]", transform=ax.transAxes, ha="right",
                                va="top", fontsize=6.5, color="#333333")
                elif v is None or not v.size:
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
