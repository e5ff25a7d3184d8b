"""The validation figures of docs/validation.md (the paper's Fig. 17, 19-22 and 27), drawn by
`plots/rbplot validation-tables OUT_DIR` (railbench/validation.py) beside its tables:

    study_fig17_case1.png              case 1: lateral displacement y and yaw angle psi of the
                                       wheelset against its travelled distance, one column per
                                       curve radius, KEC and LUT (paper Fig. 17)
    study_fig19_case2_wheelsets.png    case 2: the four wheelsets, KEC and LUT (Fig. 19)
    study_fig20_case2_bodies.png       case 2: bogies and car body (Fig. 20)
    study_fig21_case3_wheelsets.png    case 3, the same as Fig. 19 (Fig. 21)
    study_fig22_case3_bodies.png       case 3, the same as Fig. 20 (Fig. 22)
    study_fig27_bumpstop.png           force of the lateral bump stop against its deflection
                                       (Fig. 27)

The kinematics come from the result files of the scenario-solver runs (summary_cases.csv), the
segment shading (white tangent, grey transition, blue curve) and the radius of each column from
the file's /track/segments. `plots/rbplot docs` copies each figure that docs/ shows to
docs/figures/validation_<name>.png.

Fig. 27 is the bump-stop law as the engine evaluates it: the workbench runs a small rig
(BUMPSTOP_RIG, written to OUT_DIR/bumpstop_law.lua) that takes the bump stop of the case-2
vehicle file unchanged and drives it through its whole table, and the figure draws the element
output /elements/bump (deflection, force) of that run, with the table points the vehicle file
gives (printed by the rig). No number of the law is typed here.
"""
from __future__ import annotations

import os
import re
import subprocess
import sys
from typing import Dict, List, Optional, Sequence, Tuple

import numpy as np

from .common import save_figure
from .h5 import ResultFileError
from .layout import _bottom_legend, _grid, _label_cell, _min_span, _pair, _run_style, _set_distance_range, _share_rows, _x_range, _fail_handle, _fail_marker
from .provenance import ROOT
from .result import Result, load_result
from .style import A4_WIDTH_IN, plt, report_style
from .track_figs import _segment_legend_handles, _shade_segments
from .vehicle_figs import _KIN_ROWS, fig_kinematics

# (case, radius [m] as in the scenario name or "", method) -> result file
CaseFiles = Dict[Tuple[int, str, str], str]

METHODS = ("kec", "lut")
# The program that runs the rig: $RAILBENCH_WORKBENCH (as the tests set it), else this
# checkout's build.
WORKBENCH = os.environ.get("RAILBENCH_WORKBENCH") or os.path.join(ROOT, "build", "workbench",
                                                                  "app", "workbench")
VEHICLE_MODULE = "vehicles.manchester_wagon1"   # when no case-2 result names its vehicle file

# The rig of Fig. 27: a mass on a kinematic frame that follows the track centreline, joined by
# the vehicle file's bump stop (its table unchanged; attachments at the mass's centre) and by
# soft restraints, on an S-shaped track (left curve, then right curve, clothoids between) at
# constant speed. The centrifugal force m V^2 kappa(s) then pushes the mass into the stop on both
# sides, beyond the table's last point (1.5 times its force), slowly enough that the output
# samples the whole law densely. The dynamics of the rig do not matter: the figure draws the
# element's own (deflection, force) pairs.
BUMPSTOP_RIG = """\
-- Written by plots/railbench/validation_figs.py (paper Fig. 27): the bump stop of
-- {module} driven through its table by a mass on a kinematic frame, on an S curve.
local v = require "{module}" {{}}
local stop
for _, e in ipairs(v.elements) do
  if stop == nil and type(e) == "table" and e.table ~= nil then stop = e end
end
assert(stop, "{module}: no bump stop (an element with a table)")
for _, p in ipairs(stop.table) do print(("bumpstop_table %.17g %.17g"):format(p[1], p[2])) end
print("bumpstop_name " .. stop.name)
local speed, radius = 20, 100
local f_end = stop.table[#stop.table][2]
local mass = 1.5 * f_end * radius / speed ^ 2
track {{ segments = {{ tangent {{ length = 10 }},
                     transition {{ length = 100, radius = radius, side = "left" }},
                     transition {{ length = 200, radius = radius, side = "right" }},
                     transition {{ length = 100, radius = 0 }} }}, step = 0.5 }}
local h = 0.4   -- the mass's centre above the frame's
local el = {{ bumpstop {{ name = "bump", from = "frame", to = "mass", at_from = {{ 0, 0, h }},
                        at_to = {{ 0, 0, 0 }}, direction = stop.direction, table = stop.table }} }}
-- Restraints damped near critically (for the whole mass): the stop is reached without impact.
local function restraint(name, dir, x, y, k, share)
  el[#el + 1] = spring_damper {{ name = name, from = "frame", to = "mass", at_from = {{ x, y, h }},
                                at_to = {{ x, y, 0 }}, direction = dir, stiffness = k,
                                damping = 2 * math.sqrt(k * mass / share) }}
end
for i, p in ipairs({{ {{ 1, 1 }}, {{ 1, -1 }}, {{ -1, 1 }}, {{ -1, -1 }} }}) do
  restraint("z" .. i, "z", p[1], p[2], 4e6, 4)
end
restraint("x1", "x", 0, 1, 4e6, 2)
restraint("x2", "x", 0, -1, 4e6, 2)
-- Lateral: soft (a static equilibrium inside the clearance), damped as if the stop were engaged.
el[#el + 1] = spring_damper {{ name = "y", from = "frame", to = "mass", at_from = {{ 0, 0, h }},
                              at_to = {{ 0, 0, 0 }}, direction = "y", stiffness = 2e5,
                              damping = 2 * math.sqrt(f_end / (stop.table[#stop.table][1] -
                                stop.table[1][1]) * mass) }}
vehicle {{ name = "bumpstop_rig", speed = speed, bodies = {{
  body {{ name = "frame", kind = "frame", mass = 1, inertia = {{ 1, 1, 1 }}, height = 0.6 }},
  body {{ name = "mass", kind = "car", mass = mass, inertia = {{ mass, mass, mass }},
         height = 0.6 + h }} }}, elements = el }}
run {{ output = {{ every = 0.005, elements = {{ "bump" }} }} }}
"""


def _note(text: str) -> None:
    print(f"railbench validation-tables: note: {text}", file=sys.stderr)


def _load(path: Optional[str]) -> Optional[Result]:
    if not path:
        return None
    try:
        return load_result(path)
    except ResultFileError as e:
        _note(f"{e} (its validation figures are not drawn)")
        return None


def vehicle_module(path: Optional[str]) -> str:
    """The vehicle module ("vehicles.NAME") a result file's scenario loaded (its root attribute
    scenario_modules holds each module's text after a "-- file: scenarios/..." line)."""
    import h5py
    if path and os.path.exists(path):
        try:
            with h5py.File(path, "r") as f:
                text = f.attrs.get("scenario_modules", b"")
        except OSError:
            text = b""
        text = text.decode() if isinstance(text, bytes) else str(text)
        m = re.search(r"^-- file: scenarios/(vehicles/[\w/]+)\.lua$", text, re.M)
        if m:
            return m.group(1).replace("/", ".")
    return VEHICLE_MODULE


def _curve_radius(result: Result) -> Optional[float]:
    """Radius of the circular curve of the run's track (/track/segments, kind "curve")."""
    tr = result.track
    if tr is None:
        return None
    sg = tr.segments
    r = [float(rr) for k, rr in zip(sg["kind"], sg["radius"])
         if tr.kind_name(k) == "curve" and rr > 0]
    return r[0] if r else None


# ---- Fig. 17 ---------------------------------------------------------------------------------

def fig17_case1(columns: Sequence[Tuple[str, Sequence[Tuple[Result, str]]]]):
    """Paper Fig. 17: y [mm] (top) and psi [mrad] (bottom) of the case-1 wheelset against its
    travelled distance, one column per curve radius (title from the track), the runs (KEC, LUT)
    overlaid; each column shaded with its own track's segments. columns: [(wheelset name,
    [(result, label), ...]), ...]."""
    from matplotlib.lines import Line2D

    with report_style():
        fig, cells, ncol = _grid(len(columns), len(_KIN_ROWS), row_h=1.55, extra_h=0.95)
        _share_rows(cells, ["wheelset"] * len(columns), ncol, [r[2] for r in _KIN_ROWS])
        fig_h = fig.get_size_inches()[1]
        labels: List[str] = []
        failed = False
        for (ws, runs), col in zip(columns, cells):
            tr = runs[0][0].track
            radius = _curve_radius(runs[0][0])
            xmin, xmax = np.inf, -np.inf
            for q, (key, scale, _, _) in enumerate(_KIN_ROWS):
                ax = col[q]
                ax.set_gid(f"{key}:R{radius:g}" if radius else key)
                _shade_segments(ax, tr)
                ax.axhline(0, color="k", lw=0.4, zorder=0.6)
                for k, (r, lab) in enumerate(runs):
                    b = r.bodies.get(ws)
                    if b is None or not b.has("s", key):
                        continue
                    x, v = _pair(b.data["s"], b.data[key] * scale)
                    ax.plot(x, v, zorder=2 + k, gid="data", label=lab, **_run_style(k))
                    if r.failed:
                        _fail_marker(ax, x, v)
                    xmin, xmax = _x_range(x, xmin, xmax)
                    if lab not in labels:
                        labels.append(lab)
                title = f"R = {radius:g} m" if radius else runs[0][0].stem
                _label_cell(ax, q, len(_KIN_ROWS), title, "distance s [m]")
            failed = failed or any(r.failed for r, _ in runs)
            _set_distance_range(col[0], xmin, xmax, tr, any(r.failed for r, _ in runs))
        for col in cells:
            for q, row in enumerate(_KIN_ROWS):
                _min_span(col[q], row[3])
        handles = [Line2D([], [], label=lab, **_run_style(k)) for k, lab in enumerate(labels)]
        marks = _segment_legend_handles(columns[0][1][0][0].track)
        if failed:
            marks.append(_fail_handle())
        _bottom_legend(fig, [handles, marks], fig_h)
        fig.suptitle("Case 1, single wheelset: lateral displacement and yaw angle against the "
                     "travelled distance", fontsize=9.5)
    return fig


# ---- Fig. 27 ---------------------------------------------------------------------------------

def run_bumpstop_rig(outdir: str, workbench: str = WORKBENCH, root: str = ROOT,
                     module: str = VEHICLE_MODULE) -> Optional[Tuple[str, str, np.ndarray]]:
    """Runs BUMPSTOP_RIG with `module`'s bump stop: (result file, element name in the vehicle
    file, table points [[d, F], ...] as the vehicle file gives them), or None (with a note) when
    the workbench cannot run it."""
    if not os.path.exists(workbench):
        _note(f"{workbench} missing: Fig. 27 (bump stop) not drawn")
        return None
    lua = os.path.join(outdir, "bumpstop_law.lua")
    h5 = os.path.join(outdir, "bumpstop_law.h5")
    with open(lua, "w") as f:
        f.write(BUMPSTOP_RIG.format(module=module))
    r = subprocess.run([workbench, "--root", root, "run", lua, "--out", h5, "--quiet"],
                       capture_output=True, text=True, timeout=300)
    if r.returncode != 0 or not os.path.exists(h5):
        tail = " ".join((r.stderr or r.stdout).split())[-300:]
        _note(f"bump-stop rig failed (exit {r.returncode}): {tail}")
        return None
    printed = r.stdout + "\n" + r.stderr   # the scenario's print() goes to stderr
    pts = [tuple(float(v) for v in m.groups())
           for m in re.finditer(r"^bumpstop_table (\S+) (\S+)$", printed, re.M)]
    name = re.search(r"^bumpstop_name (\S+)$", printed, re.M)
    label = f"{name.group(1)} of {module}" if name else module
    return h5, label, np.array(pts).reshape(-1, 2)


def fig27_bumpstop(result: Result, element: str = "bump", name: str = "",
                   table: Optional[np.ndarray] = None):
    """Paper Fig. 27: force [kN] of the bump stop against its deflection [mm], the element output
    /elements/<element> of `result` (every sample, sorted by deflection); the table points as
    markers (mirrored: the law is odd). Left: the whole range; right: the clearance end and the
    stiffening before the table's steep last interval."""
    e = result.elements.get(element)
    if not e or "deflection" not in e or "force" not in e:
        raise ResultFileError(f"{result.path}: no /elements/{element} deflection and force")
    d, f = _pair(e["deflection"], e["force"])
    order = np.argsort(d, kind="stable")
    d_mm, f_kn = d[order] * 1e3, f[order] * 1e-3
    with report_style():
        fig, axes = plt.subplots(1, 2, figsize=(A4_WIDTH_IN, 2.9), layout="constrained")
        for ax in axes:
            ax.axhline(0, color="k", lw=0.4, zorder=0.6)
            ax.axvline(0, color="k", lw=0.4, zorder=0.6)
            ax.plot(d_mm, f_kn, color="#1f5fa8", lw=1.2, zorder=2, gid="data",
                    label="element output of the rig run")
            if table is not None and len(table):
                td, tf = table[:, 0] * 1e3, table[:, 1] * 1e-3
                ax.plot(np.concatenate([-td[::-1], td]), np.concatenate([-tf[::-1], tf]),
                        ls="none", marker="o", ms=3.2, mfc="white", mec="#b2182b", mew=0.9,
                        zorder=3, gid="table", label="table points of the vehicle file")
            ax.set_xlabel("relative displacement d [mm]")
        axes[0].set_ylabel("force F [kN]")
        axes[0].set_title("whole range (linear beyond the last point)", fontsize=8.5)
        if table is not None and len(table) > 2:
            # Zoom: from the clearance to the second-to-last table point.
            lo, hi = float(table[0, 0]), float(table[-2, 0])
            zero = table[table[:, 1] == 0, 0]
            lo = float(zero.max()) if zero.size else lo
            span = hi - lo
            axes[1].set_xlim((lo - 0.1 * span) * 1e3, (hi + 0.1 * span) * 1e3)
            axes[1].set_ylim(-0.05 * table[-2, 1] * 1e-3, 1.15 * table[-2, 1] * 1e-3)
            axes[1].set_title("clearance end and stiffening (positive side)", fontsize=8.5)
        axes[0].legend(loc="upper left", fontsize=7)
        what = f" ({name})" if name else ""
        fig.suptitle(f"Lateral bump stop{what}: force against deflection", fontsize=9.5)
    return fig


# ---- all figures -----------------------------------------------------------------------------

def _pair_runs(files: CaseFiles, case: int, radius: str = "") -> List[Tuple[Result, str]]:
    runs = []
    for m in METHODS:
        r = _load(files.get((case, radius, m)))
        if r is not None and r.track is not None:
            runs.append((r, m.upper()))
    return runs


def _case1_columns(files: CaseFiles):
    radii = sorted({rad for (c, rad, _) in files if c == 1 and rad}, key=float)
    columns = []
    for rad in radii:
        runs = _pair_runs(files, 1, rad)
        if not runs:
            continue
        ws = runs[0][0].kinematic_bodies(("wheelset",))
        if ws:
            columns.append((ws[0], runs))
    return columns


def make_figures(outdir: str, files: CaseFiles, workbench: str = WORKBENCH,
                 root: str = ROOT) -> List[str]:
    """Every figure whose inputs exist, as OUT_DIR/study_<name>.png; returns the paths."""
    written: List[str] = []
    columns = _case1_columns(files)
    if columns:
        save_figure(fig17_case1(columns), os.path.join(outdir, "study_fig17_case1.png"), written)
    for case, (fw, fb) in ((2, (19, 20)), (3, (21, 22))):
        runs = _pair_runs(files, case)
        if not runs:
            continue
        first = runs[0][0]
        what = "no irregularities" if case == 2 else "irregular track"
        ws = first.kinematic_bodies(("wheelset",))
        bodies = first.kinematic_bodies(("bogie",)) + first.kinematic_bodies(("car",))
        for num, names, part, title in (
                (fw, ws, "wheelsets", "wheelsets"), (fb, bodies, "bodies", "bogies and car body")):
            if names:
                fig = fig_kinematics(runs, names, f"Case {case} ({what}), {title}: lateral "
                                     f"displacement and yaw angle")
                save_figure(fig, os.path.join(outdir, f"study_fig{num}_case{case}_{part}.png"),
                            written)
    rig = run_bumpstop_rig(outdir, workbench, root, vehicle_module(files.get((2, "", "kec"))))
    if rig is not None:
        res = _load(rig[0])
        if res is not None:
            save_figure(fig27_bumpstop(res, name=rig[1], table=rig[2]),
                        os.path.join(outdir, "study_fig27_bumpstop.png"), written)
    return written
