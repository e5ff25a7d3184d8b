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
                                         peak Hertz pressure, contact regime, per wheel
    fig_creep(result)                    creepages, spin and creep forces per wheelset
    fig_accelerations(result)            car body and bogie accelerations (/bodies/*/a[xyz])
    fig_elements(result)                 deflection and force of /elements/* versus time
    fig_assessment(result)               /assessment (assessment.py): Y/Q, track shift force,
                                         wheel unloading, comfort N_c, stability rms, T-gamma,
                                         with limits and the summary (ok / EXCEEDED)
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

Conventions (docs/track.md, irregularity PSDs)
    Omega = 2*pi/lambda [rad/m].  A one-sided PSD G(Omega) over Omega > 0 satisfies
    variance = integral G dOmega.  With G_f the one-sided PSD in m^2/(cycle/m),
    G_Omega = G_f / (2*pi).

Adding figures for later groups: read them in load_result (or lazily with Result.read_group),
write a fig_* function and append a FigureSpec to FIGURES whose is_available() checks for the
group.  make_figures() and `railbench run` need no change.

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

from typing import Dict, List, Optional, Sequence

import numpy as np

from .common import FigureSpec, figure_command, write_figures
from .h5 import ResultFileError
from .style import DPI, KINEMATIC_KINDS, plt
from .result import Result, load_result
from .rails_figs import fig_rails, rail_sides
from .track_figs import fig_curvature_cant, fig_irregularities, fig_irregularity_psd, fig_track_plan
from .layout import _num, _pair, add_failure_banner, failure_text
from .vehicle_figs import _CONTACT_ROWS, _CREEP_ROWS, _ROW_FLANGE, _ROW_INDENT, _contact_rows, _row_present, fig_bodies_car, fig_contact_forces, fig_creep, fig_flange_contact, fig_wheelsets
from .dynamics_figs import _element_names, acceleration_bodies, fig_accelerations, fig_elements
from .assessment import fig_assessment, has_assessment
from .train_figs import fig_train, fig_train_assessment, train_assessed, train_connections


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
               fig_flange_contact, "tread and flange normal force, flange indentation, peak pressure, regime"),
    FigureSpec("creep", lambda r: bool(_contact_rows(r, _CREEP_ROWS)), fig_creep,
               "creepages, spin and creep forces"),
    FigureSpec("accelerations", lambda r: bool(acceleration_bodies(r)), fig_accelerations,
               "car body and bogie accelerations versus distance"),
    FigureSpec("elements", lambda r: bool(_element_names(r)), fig_elements,
               "deflection and force of the recorded suspension elements"),
    # Groups of /assessment the run did not write are panels left out (assessment.py).
    FigureSpec("assessment", has_assessment, fig_assessment,
               "assessment: Y/Q, track shift force, wheel unloading, comfort, stability, wear"),
    FigureSpec("rails", lambda r: bool(rail_sides(r)), fig_rails,
               "normal force and contact position of every wheel on every rail of a side with "
               "several rails (a switch blade, a crossing nose)"),
    FigureSpec("train", lambda r: bool(train_connections(r)), fig_train,
               "in-train forces per connection against distance, and the vehicles' speeds"),
    FigureSpec("train_assessment", lambda r: bool(train_assessed(r)), fig_train_assessment,
               "the whole train's assessment along the track, one line per vehicle"),
    # /stats is summarised in text (stats_summary, printed by `railbench run`), not drawn.
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


TRACK_FIGURES = ("track_plan", "track_curvature_cant", "irregularities", "irregularity_psd",
                 "train", "train_assessment")


def make_figures(result: Result, outdir: Optional[str] = None, stem: Optional[str] = None,
                 dpi: int = DPI, fmt: str = "png") -> List[str]:
    """Write every figure the result's content allows; return the written paths. A run of several
    vehicles: the track's figures once, then every vehicle's as <stem>_<vehicle>_<suffix>."""
    paths = write_figures(FIGURES, result, outdir, stem, dpi, fmt, build_figure)
    if result.vehicle:
        return paths
    vehicle_specs = [f for f in FIGURES if f.suffix not in TRACK_FIGURES]
    for name in result.vehicles:
        one = load_result(result.path, vehicle=name)
        paths += write_figures(vehicle_specs, one, outdir, f"{stem or result.stem}_{name}", dpi,
                               fmt, build_figure)
    return paths


def main(argv=None) -> int:
    return figure_command(argv, "run", "Draw report figures from a railbench HDF5 result.",
                          "result file (.h5) written by railbench", load_result, make_figures,
                          stats_summary, (ResultFileError,))
