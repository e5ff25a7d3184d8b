"""Figures and tables of a railbench study folder (written by `workbench study`).

A study folder holds summary.csv (one row per run), summary_cases.csv (one row per case) and one
HDF5 result per run (<case>_r<repeat>.h5).  Everything here reads those and writes PNG + CSV.

Reading
    load_study(outdir) -> Study            cases with their overrides parsed (method,
                                           integrator, tolerance / step, flange stiffness K,
                                           refined tables), runs, status and reason
Analyses (each returns rows = list of dicts; the CSV columns are the dict keys)
    cost_rows(study)                       paper Tables 7, 12-16 (one row per case)
    failure_rows(study)                    every run that is not ok, with its reason
    accuracy_rows(study)                   paper Eq. 33 / Table 8: LUT vs KEC pairs (same solver)
    work_precision_rows(study)             error of every case against its reference case
    effect_rows(study)                     cost per evaluation of each variant vs the baseline
Figures
    fig_cost(study)                        paper Fig. 23 / 26: CPU time and evaluations per case
    fig_accuracy(study, rows)              Table 8 as bars
    fig_lut_integrators(study)             Fig. 24: y, flange indentation and force of the LUT
                                           cases with every integrator at one K
    fig_lut_stiffness(study, solver)       Fig. 25: flange indentation and force per K
    fig_work_precision(rows, stat)         error vs CPU time, log-log, per quantity
    fig_effects(rows)                      microseconds per evaluation per variant
    fig_tables(study)                      contact table build time and size (default/refined)
Driver
    make_study_outputs(outdir)             everything that applies; returns the written paths

Case roles (the study file's `role` key in a case): "reference" (work-precision reference,
one per contact model, e.g. on the refined tables), "reference_check" (the reference at a
tighter tolerance: the difference between the two is the reference's own error),
"reference_same_tables" (the reference's settings on the cases' own tables: errors against it
are integration errors only, its difference to the reference is the tables' error),
"baseline" (full model of an effects study).  Reference and case are matched by their model (the overrides that are not
numerical settings: solver.*, profiles.refined_tables, contact.normal_forces, run.output.*,
and the base scenario).

Only numpy, matplotlib (Agg) and h5py are used.
"""
from __future__ import annotations

import csv
import math
import os
import re
import sys
from dataclasses import dataclass, field
from typing import Dict, List, Optional, Sequence, Tuple

import h5py
import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import railbench_plots as rp  # noqa: E402

plt = rp.plt

# Overrides that change how a model is solved, not which model (work-precision matching).
NUMERICAL_PREFIXES = ("solver.", "run.output.")
NUMERICAL_KEYS = ("profiles.refined_tables", "contact.normal_forces")
WHEELSET_QUANTITIES = (  # (label, group, dataset, scale to display unit, unit)
    ("lateral displacement y", "bodies", "y", 1e3, "mm"),
    ("yaw angle", "bodies", "yaw", 1e3, "mrad"),
    ("normal force Q", "contact", "normal_force", 1e-3, "kN"),
    ("lateral creep force", "contact", "creep_force_y", 1e-3, "kN"),
)
QUANTITY_TAGS = {"lateral displacement y": "y", "yaw angle": "yaw", "normal force Q": "Q",
                 "lateral creep force": "Fy"}
INTEGRATOR_COLORS = {"rk4": "#1f5fa8", "abm": "#b2182b", "dopri5": "#1b7837", "bdf": "#e08214",
                     "ida": "#6a3d9a"}
METHOD_MARKERS = {"kec": ("o", "-"), "lut": ("s", (0, (5, 2.5)))}


class StudyError(Exception):
    """The folder is not a study folder (no summary). One line."""


# --------------------------------------------------------------------------------------------
# Reading
# --------------------------------------------------------------------------------------------
def _num(text, default=None):
    try:
        v = float(text)
    except (TypeError, ValueError):
        return default
    return v


def compact(v: float) -> str:
    """1e-06 -> 1e-6, 7.075e+13 -> 7.075e13 (the labels of workbench/scenario/study.cpp)."""
    t = f"{v:g}"
    return t.replace("e-0", "e-").replace("e+0", "e").replace("e+", "e")


def parse_overrides(text: str) -> Dict[str, str]:
    out = {}
    for tok in (text or "").split():
        k, _, v = tok.partition("=")
        out[k] = v
    return out


def solver_text(ov: Dict[str, str]) -> str:
    """'rk4 h=0.25ms', 'bdf tol=1e-6 hmax=1ms' from the solver.* overrides ('' if none)."""
    parts = []
    if "solver.method" in ov:
        parts.append(ov["solver.method"])
    if "solver.step" in ov and _num(ov["solver.step"]) is not None:
        parts.append(f"h={compact(_num(ov['solver.step']) * 1e3)}ms")
    r, a = ov.get("solver.rtol"), ov.get("solver.atol")
    if r is not None and r == a:
        parts.append(f"tol={compact(_num(r, 0))}")
    else:
        if r is not None:
            parts.append(f"rtol={compact(_num(r, 0))}")
        if a is not None:
            parts.append(f"atol={compact(_num(a, 0))}")
    if "solver.max_step" in ov and _num(ov["solver.max_step"]) is not None:
        parts.append(f"hmax={compact(_num(ov['solver.max_step']) * 1e3)}ms")
    for k in sorted(ov):
        if k.startswith("solver.") and k not in ("solver.method", "solver.step", "solver.rtol",
                                                 "solver.atol", "solver.max_step",
                                                 "solver.max_steps"):
            parts.append(f"{k[7:]}={ov[k]}")
    return " ".join(parts)


@dataclass
class Case:
    id: str
    label: str
    role: str
    base: str
    overrides: Dict[str, str]
    status: str
    message: str
    runs: int
    runs_ok: int
    cpu_median: float
    cpu_min: float
    cpu_max: float
    counts: Dict[str, float]
    file: str
    repeats: List[dict] = field(default_factory=list)
    common: frozenset = frozenset()  # (key, value) overrides every case of the study has
    main_base: str = ""  # the base scenario of most cases
    _attrs: Optional[dict] = None

    # --- what the case is ---
    @property
    def ok(self) -> bool:
        return self.status == "ok"

    def _file_attrs(self) -> dict:
        """Root attributes, /contact attributes and wheelset names of the result file."""
        if self._attrs is None:
            a = {}
            if self.file and os.path.exists(self.file):
                try:
                    with h5py.File(self.file, "r") as f:
                        a["solver"] = rp._str(f.attrs.get("solver", ""))
                        if "contact" in f:
                            for k, v in f["contact"].attrs.items():
                                a["contact_" + k] = rp._str(v) if isinstance(
                                    v, (bytes, str, np.bytes_)) else float(np.asarray(v))
                except OSError:
                    pass
            self._attrs = a
        return self._attrs

    @property
    def cpu(self) -> float:
        """Median CPU time of the ok repeats; for a failed case, of its runs (up to the failure)."""
        if self.runs_ok:
            return self.cpu_median
        v = [_num(r.get("cpu_time_s"), 0.0) for r in self.repeats]
        return float(np.median(v)) if v else 0.0

    @property
    def method(self) -> str:
        """Contact method: kec, lut, or '' (guided / unknown)."""
        m = self.overrides.get("contact.method") or self._file_attrs().get("contact_method", "")
        return m.lower()

    @property
    def integrator(self) -> str:
        return self.overrides.get("solver.method") or self._file_attrs().get("solver", "") or "?"

    @property
    def tol(self) -> Optional[float]:
        return _num(self.overrides.get("solver.rtol"))

    @property
    def step(self) -> Optional[float]:
        return _num(self.overrides.get("solver.step"))

    @property
    def K(self) -> Optional[float]:
        if self.method != "lut":
            return None
        return _num(self.overrides.get("contact.flange_stiffness"), 1e10)  # schema default

    @property
    def refined(self) -> bool:
        return self.overrides.get("profiles.refined_tables") == "true"

    @property
    def solver_key(self) -> str:
        return solver_text(self.overrides) or self.integrator

    @property
    def model_key(self) -> str:
        """Every override that is not a solver setting, and the base (cost figure series)."""
        parts = []
        if self.method:
            parts.append(self.method.upper())
        if self.K is not None:
            parts.append(f"K={compact(self.K)}")
        for k in sorted(self.overrides):
            if k.startswith("solver.") or k in ("contact.method", "contact.flange_stiffness"):
                continue
            if (k, self.overrides[k]) in self.common:
                continue  # the same in every case of the study
            v = self.overrides[k]
            if k == "profiles.refined_tables":
                parts.append("refined" if v == "true" else "default tables")
            elif k == "contact.normal_forces":
                continue  # follows the integrator in our studies; shown in the labels
            else:
                parts.append(f"{k}={v}")
        stem = os.path.splitext(os.path.basename(self.base))[0]
        if self.main_base and self.base != self.main_base:
            parts.append(f"[{stem}]")  # another base scenario than most cases
        return " ".join(parts) or stem

    def physical_key(self) -> Tuple:
        """The model without numerical settings (work-precision reference matching)."""
        keep = tuple(sorted((k, v) for k, v in self.overrides.items()
                            if not k.startswith(NUMERICAL_PREFIXES) and k not in NUMERICAL_KEYS))
        return (self.base, keep)

    def attr(self, name, default=None):
        return self._file_attrs().get(name, default)


@dataclass
class Study:
    outdir: str
    cases: List[Case]
    study_file: str = ""

    def by_role(self, role: str) -> List[Case]:
        return [c for c in self.cases if c.role == role]


def _read_csv(path: str) -> List[dict]:
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def load_study(outdir: str) -> Study:
    sc = os.path.join(outdir, "summary_cases.csv")
    sr = os.path.join(outdir, "summary.csv")
    if not os.path.exists(sc) or not os.path.exists(sr):
        raise StudyError(f"{outdir}: no summary_cases.csv / summary.csv (not a study folder, or "
                         f"written by an older workbench)")
    runs = _read_csv(sr)
    per_case: Dict[str, List[dict]] = {}
    for r in runs:
        per_case.setdefault(r["case"], []).append(r)
    cases = []
    for r in _read_csv(sc):
        if "label" not in r:
            raise StudyError(f"{sc}: no label column (written by an older workbench; run the "
                             f"study again to refresh the summary)")
        counts = {k: _num(r.get(k), 0.0) for k in (
            "rhs_evals", "rhs_evals_jac", "steps", "rejected_steps", "jacobian_evals",
            "nonlinear_iters", "t_reached", "model_evaluations")}
        f = r.get("file", "")
        if f and not os.path.isabs(f) and not os.path.exists(f):
            alt = os.path.join(outdir, os.path.basename(f))
            f = alt if os.path.exists(alt) else f
        reps = per_case.get(r["case"], [])
        for rep in reps:
            g = rep.get("file", "")
            if g and not os.path.exists(g):
                alt = os.path.join(outdir, os.path.basename(g))
                rep["file"] = alt if os.path.exists(alt) else g
        cases.append(Case(
            id=r["case"], label=r["label"], role=r.get("role", ""), base=r.get("base", ""),
            overrides=parse_overrides(r.get("overrides", "")), status=r.get("status", ""),
            message=r.get("message", ""), runs=int(_num(r.get("runs"), 0)),
            runs_ok=int(_num(r.get("runs_ok"), 0)), cpu_median=_num(r["median_cpu_time_s"], 0.0),
            cpu_min=_num(r.get("min_cpu_time_s"), 0.0), cpu_max=_num(r.get("max_cpu_time_s"), 0.0),
            counts=counts, file=f, repeats=reps))
    if len(cases) > 1:
        common = frozenset.intersection(*(frozenset(c.overrides.items()) for c in cases))
        bases = [c.base for c in cases]
        main = max(set(bases), key=bases.count)
        for c in cases:
            c.common = common
            c.main_base = main
    study_file = ""
    h5 = os.path.join(outdir, "summary.h5")
    if os.path.exists(h5):
        try:
            with h5py.File(h5, "r") as f:
                study_file = rp._str(f.attrs.get("study_file", ""))
        except OSError:
            pass
    return Study(outdir=outdir, cases=cases, study_file=study_file)


# --------------------------------------------------------------------------------------------
# Time series of a case
# --------------------------------------------------------------------------------------------
class Series:
    """Time and the wheelset/contact series of one result file (read lazily, cached)."""

    def __init__(self, path: str):
        self.path = path
        self._f = h5py.File(path, "r")
        self.t = np.asarray(self._f["time"][()], float) if "time" in self._f else np.zeros(0)
        names = rp._names_attr(self._f["bodies"].attrs.get("names", "")) if "bodies" in self._f \
            else []
        self.wheelsets = [n for n in names if "bodies/" + n in self._f and rp._str(
            self._f["bodies/" + n].attrs.get("kind", "")) == "wheelset"] or \
            [n for n in names if n.startswith("ws")]

    def close(self):
        self._f.close()

    def get(self, where: str) -> Optional[np.ndarray]:
        if where not in self._f:
            return None
        a = np.asarray(self._f[where][()], float).reshape(-1)
        n = min(len(a), len(self.t))
        return a[:n]

    def body(self, ws: str, q: str):
        return self.get(f"bodies/{ws}/{q}")

    def wheel(self, ws: str, side: str, q: str):
        return self.get(f"contact/{ws}/{side}/{q}")

    def quantity(self, group: str, ds: str) -> List[Tuple[str, np.ndarray]]:
        """[(name, series)] over every wheelset (bodies) or wheel (contact)."""
        out = []
        for ws in self.wheelsets:
            if group == "bodies":
                a = self.body(ws, ds)
                if a is not None:
                    out.append((ws, a))
            else:
                for side in ("left", "right"):
                    a = self.wheel(ws, side, ds)
                    if a is not None:
                        out.append((f"{ws} {side}", a))
        return out


_SERIES_CACHE: Dict[str, Series] = {}


def series(case: Case) -> Optional[Series]:
    if not case.file or not os.path.exists(case.file):
        return None
    if case.file not in _SERIES_CACHE:
        try:
            _SERIES_CACHE[case.file] = Series(case.file)
        except (OSError, KeyError):
            return None
    return _SERIES_CACHE[case.file]


def close_all():
    for s in _SERIES_CACHE.values():
        s.close()
    _SERIES_CACHE.clear()


def on_grid(t_ref: np.ndarray, t: np.ndarray, v: np.ndarray) -> Tuple[np.ndarray, np.ndarray]:
    """v interpolated onto the part of t_ref inside [t0, t_end] of t: (mask on t_ref, values)."""
    n = min(len(t), len(v))
    t, v = t[:n], v[:n]
    if n < 2:
        return np.zeros(len(t_ref), bool), np.zeros(0)
    ok = np.isfinite(v)
    t, v = t[ok], v[ok]
    m = (t_ref >= t[0] - 1e-12) & (t_ref <= t[-1] + 1e-12)
    return m, np.interp(t_ref[m], t, v)


# --------------------------------------------------------------------------------------------
# Cost (paper Tables 7, 12-16; Fig. 23, 26)
# --------------------------------------------------------------------------------------------
def cost_rows(study: Study) -> List[dict]:
    rows = []
    for c in study.cases:
        ev = c.counts["rhs_evals"]
        cpu_runs = [_num(r.get("cpu_time_s"), 0.0) for r in c.repeats if r.get("status") == "ok"]
        rows.append(dict(
            case=c.id, label=c.label, role=c.role, model=c.model_key, solver=c.solver_key,
            method=c.method, integrator=c.integrator,
            tol="" if c.tol is None else compact(c.tol),
            step_s="" if c.step is None else f"{c.step:g}",
            K="" if c.K is None else compact(c.K), refined_tables=str(c.refined).lower(),
            status=c.status, runs=c.runs, runs_ok=c.runs_ok,
            cpu_median_s=f"{c.cpu_median:.4f}", cpu_min_s=f"{c.cpu_min:.4f}",
            cpu_max_s=f"{c.cpu_max:.4f}", cpu_runs_s=";".join(f"{x:.4f}" for x in cpu_runs),
            rhs_evals=int(ev), rhs_evals_jac=int(c.counts["rhs_evals_jac"]),
            steps=int(c.counts["steps"]), rejected_steps=int(c.counts["rejected_steps"]),
            jacobian_evals=int(c.counts["jacobian_evals"]),
            model_evaluations=int(c.counts["model_evaluations"]),
            us_per_eval=f"{c.cpu_median / ev * 1e6:.3f}" if c.ok and ev > 0 else "",
            t_reached_s=f"{c.counts['t_reached']:.4f}",
            table_build_time_s=_fmt(c.attr("contact_table_build_time_s")),
            table_bytes=_fmt(c.attr("contact_table_bytes"), "{:.0f}"),
            message=c.message, file=c.file))
    return rows


def _fmt(v, f="{:.4g}"):
    return "" if v is None else f.format(v)


def failure_rows(study: Study) -> List[dict]:
    rows = []
    for c in study.cases:
        for r in c.repeats:
            if r.get("status") != "ok":
                rows.append(dict(case=c.id, label=c.label, repeat=r.get("repeat", ""),
                                 status=r.get("status", ""),
                                 t_reached_s=r.get("t_reached", ""), reason=r.get("message", ""),
                                 overrides=r.get("overrides", ""), file=r.get("file", "")))
    return rows


def _groups(study: Study):
    """Solver keys (x groups, in study order) and model keys (series, in study order)."""
    sk, mk = [], []
    for c in study.cases:
        if c.solver_key not in sk:
            sk.append(c.solver_key)
        if c.model_key not in mk:
            mk.append(c.model_key)
    return sk, mk


def fig_cost(study: Study, title: str = ""):
    """CPU time (median, min-max bar) and evaluations per case: groups = solver settings,
    bars = models (method, K, tables, ...); failed cases as red hatched stubs marked 'failed'."""
    sk, mk = _groups(study)
    nb = max(1, len(mk))
    width = 0.8 / nb
    w_in = min(16.0, max(rp.A4_WIDTH_IN, 0.22 * len(study.cases) + 1.5))
    cmap = plt.get_cmap("tab10" if nb <= 10 else "tab20")
    n_fail = any(not c.ok for c in study.cases)
    ncol = max(1, min(len(mk) + n_fail, int(w_in / 2.2)))
    leg_rows = math.ceil((len(mk) + n_fail) / ncol)
    leg_h = 0.18 * leg_rows + 0.15
    with rp.report_style():
        fig = plt.figure(figsize=(w_in, 6.2 + leg_h), layout="constrained")
        gs = fig.add_gridspec(3, 1, height_ratios=[3.1, 3.1, leg_h])
        ax0 = fig.add_subplot(gs[0])
        axes = [ax0, fig.add_subplot(gs[1], sharex=ax0)]
        lax = fig.add_subplot(gs[2])
        lax.axis("off")
        for ax, key, ylabel in ((axes[0], "cpu", "CPU time [s] (median)"),
                                (axes[1], "rhs_evals", "right-hand side evaluations")):
            vals = [c.cpu_median if key == "cpu" else c.counts["rhs_evals"]
                    for c in study.cases if c.ok]
            good = [v for v in vals if v > 0]
            lo = min(good) / 3 if good else 0.1
            for c in study.cases:
                i, j = sk.index(c.solver_key), mk.index(c.model_key)
                x = i - 0.4 + width * (j + 0.5)
                col = cmap(j % cmap.N)
                if c.ok:
                    v = c.cpu_median if key == "cpu" else c.counts["rhs_evals"]
                    ax.bar(x, v, width * 0.92, color=col, edgecolor="none", bottom=0)
                    if key == "cpu" and c.runs_ok > 1:
                        ax.plot([x, x], [c.cpu_min, c.cpu_max], color="k", lw=0.7)
                else:
                    ax.bar(x, lo * 2.2, width * 0.92, bottom=lo, color="none",
                           edgecolor=rp.FAIL_COLOR, hatch="xxx", lw=0.6)
                    ax.text(x, lo * 3.4, "failed", rotation=90, ha="center", va="bottom",
                            fontsize=6, color=rp.FAIL_COLOR)
            ax.set_yscale("log")
            if good:
                ax.set_ylim(lo, max(good) * 3)
            ax.set_ylabel(ylabel)
        axes[1].set_xticks(range(len(sk)))
        axes[1].set_xticklabels(sk, rotation=30, ha="right")
        plt.setp(axes[0].get_xticklabels(), visible=False)
        handles = [rp.Patch(color=cmap(j % cmap.N), label=m) for j, m in enumerate(mk)]
        if n_fail:
            handles.append(rp.Patch(facecolor="none", edgecolor=rp.FAIL_COLOR, hatch="xxx",
                                    label="failed (reason: study_failures.csv)"))
        lax.legend(handles=handles, ncols=ncol, loc="center", fontsize=6.5)
        _title(fig, title or "Computation cost per case (paper Fig. 23, Tables 7, 12-16)")
    return fig


def fig_tables(study: Study):
    """Contact table build time and size per model (paper Tables 9-10), or None."""
    seen = {}
    for c in study.cases:
        bt, nb = c.attr("contact_table_build_time_s"), c.attr("contact_table_bytes")
        if bt is None or nb is None:
            continue
        seen.setdefault(c.model_key, []).append((bt, nb))
    if not seen or not any(c.refined for c in study.cases):
        return None
    names = list(seen)
    with rp.report_style():
        fig, axes = plt.subplots(1, 2, figsize=(rp.A4_WIDTH_IN, 2.8), layout="constrained")
        axes[0].bar(range(len(names)), [np.median([v[0] for v in seen[n]]) for n in names],
                    color="#1f5fa8")
        axes[0].set_ylabel("table build time [s] (median)")
        axes[1].bar(range(len(names)), [seen[n][0][1] / 1024 for n in names], color="#b2182b")
        axes[1].set_ylabel("table memory [KiB]")
        for ax in axes:
            ax.set_xticks(range(len(names)))
            ax.set_xticklabels(names, rotation=30, ha="right", fontsize=6.5)
        fig.suptitle("Contact tables: default vs refined grids (paper Tables 9, 10)")
    return fig


# --------------------------------------------------------------------------------------------
# Accuracy: LUT vs KEC (paper Eq. 33, Table 8, Fig. 24, 25)
# --------------------------------------------------------------------------------------------
def _pair_key(c: Case) -> Tuple:
    ov = {k: v for k, v in c.overrides.items()
          if k not in ("contact.method", "contact.flange_stiffness", "contact.flange_damping")}
    return (c.base, tuple(sorted(ov.items())))


def lut_kec_pairs(study: Study) -> List[Tuple[Case, Case]]:
    """(LUT case, KEC case) with every other override equal (same integrator and tolerance)."""
    kec = {}
    for c in study.cases:
        if c.method == "kec" and not c.role.startswith("reference"):
            kec.setdefault(_pair_key(c), c)
    return [(c, kec[_pair_key(c)]) for c in study.cases
            if c.method == "lut" and not c.role.startswith("reference") and _pair_key(c) in kec]


def accuracy_rows(study: Study) -> List[dict]:
    """Per pair and wheelset: max and mean |y_KEC - y_LUT| [mm] on the LUT output times inside
    both runs, and Eq. 33 (the same divided by max |y_LUT|); wheelset 'all': max / mean over
    the four wheelsets."""
    rows = []
    for lut, kec in lut_kec_pairs(study):
        sl, sk = series(lut), series(kec)
        extra = " ".join(t for t in lut.model_key.split()[1:] if not t.startswith("K="))
        base = dict(lut_case=lut.id, kec_case=kec.id, lut_label=lut.label, kec_label=kec.label,
                    group=(lut.solver_key + " " + extra).strip(), solver=lut.solver_key,
                    integrator=lut.integrator, K=compact(lut.K), lut_status=lut.status,
                    kec_status=kec.status)
        if sl is None or sk is None or len(sl.t) < 2 or len(sk.t) < 2:
            rows.append(dict(base, wheelset="all", max_abs_mm="", mean_abs_mm="",
                             eq33_max="", eq33_mean="", t_from_s="", t_to_s="", samples=0,
                             note="result file missing"))
            continue
        maxes, means = [], []
        for ws in sl.wheelsets:
            yl, yk = sl.body(ws, "y"), sk.body(ws, "y")
            if yl is None or yk is None:
                continue
            m, ykg = on_grid(sl.t[:len(yl)], sk.t, yk)
            if not m.any():
                continue
            ylm = yl[:len(m)][m]
            d = np.abs(ykg - ylm)
            den = np.max(np.abs(ylm)) or 1.0
            maxes.append(d.max())
            means.append(d.mean())
            tm = sl.t[:len(m)][m]
            rows.append(dict(base, wheelset=ws, max_abs_mm=f"{d.max() * 1e3:.5g}",
                             mean_abs_mm=f"{d.mean() * 1e3:.5g}",
                             eq33_max=f"{d.max() / den:.4g}", eq33_mean=f"{d.mean() / den:.4g}",
                             t_from_s=f"{tm[0]:.3f}", t_to_s=f"{tm[-1]:.3f}", samples=int(m.sum()),
                             note="" if lut.ok and kec.ok else "a run failed: compared up to its "
                                                               "end"))
        if maxes:
            rows.append(dict(base, wheelset="all", max_abs_mm=f"{max(maxes) * 1e3:.5g}",
                             mean_abs_mm=f"{np.mean(means) * 1e3:.5g}", eq33_max="",
                             eq33_mean="", t_from_s="", t_to_s="", samples="",
                             note="max / mean over the wheelsets"))
    return rows


def _title(fig, text: str):
    import textwrap
    width = max(40, int(fig.get_size_inches()[0] * 72 / (0.6 * 10.5)))
    fig.suptitle("\n".join(textwrap.wrap(text, width)))


def fig_accuracy(rows: List[dict]):
    """Table 8 as bars: max and mean |y_KEC - y_LUT| over the wheelsets per solver and K."""
    rows = [r for r in rows if r["wheelset"] == "all" and r["max_abs_mm"] != ""]
    if not rows:
        return None
    solvers = list(dict.fromkeys(r["group"] for r in rows))
    Ks = sorted(set(r["K"] for r in rows), key=float)
    cmap = plt.get_cmap("viridis")
    w = 0.8 / len(Ks)
    with rp.report_style():
        fig, axes = plt.subplots(2, 1, figsize=(max(rp.A4_WIDTH_IN, 0.9 * len(solvers) + 2), 5),
                                 sharex=True, layout="constrained")
        for ax, key, lab in ((axes[0], "max_abs_mm", "max |y_KEC - y_LUT| [mm]"),
                             (axes[1], "mean_abs_mm", "mean |y_KEC - y_LUT| [mm]")):
            for r in rows:
                i, j = solvers.index(r["group"]), Ks.index(r["K"])
                failed = r["lut_status"] != "ok" or r["kec_status"] != "ok"
                ax.bar(i - 0.4 + w * (j + 0.5), float(r[key]), w * 0.92,
                       color=cmap(j / max(1, len(Ks) - 1)),
                       hatch="xxx" if failed else None,
                       edgecolor=rp.FAIL_COLOR if failed else "none")
            ax.set_ylabel(lab)
            ax.set_ylim(bottom=0)
        axes[1].set_xticks(range(len(solvers)))
        axes[1].set_xticklabels(solvers, rotation=30, ha="right")
        handles = [rp.Patch(color=cmap(j / max(1, len(Ks) - 1)), label=f"LUT K = {k} N/m^1.5")
                   for j, k in enumerate(Ks)]
        if any(r["lut_status"] != "ok" or r["kec_status"] != "ok" for r in rows):
            handles.append(rp.Patch(facecolor="none", edgecolor=rp.FAIL_COLOR, hatch="xxx",
                                    label="a run failed: compared up to where it stopped"))
        axes[0].legend(handles=handles, fontsize=6.5, ncols=3)
        _title(fig, "LUT vs KEC with the same integrator: wheelset lateral displacement "
                    "difference, max / mean over time and the four wheelsets (paper Eq. 33, "
                    "Table 8)")
    return fig


def flange_wheel(cases: Sequence[Case]) -> Optional[Tuple[str, str]]:
    """(wheelset, side) with the largest flange force in any of the cases."""
    best, arg = -1.0, None
    for c in cases:
        s = series(c)
        if s is None:
            continue
        for ws in s.wheelsets:
            for side in ("left", "right"):
                f = s.wheel(ws, side, "flange_force")
                if f is not None and len(f) and np.nanmax(f) > best:
                    best, arg = float(np.nanmax(f)), (ws, side)
    return arg


def _lut_panels(runs: Sequence[Tuple[Case, str]], wheel: Tuple[str, str], title: str,
                with_y: bool):
    ws, side = wheel
    rows = ([("y", "lateral displacement y [mm]", 1e3)] if with_y else []) + [
        ("flange_indentation", "flange indentation [mm]\n(< 0: clearance)", 1e3),
        ("flange_force", "flange normal force [kN]", 1e-3)]
    with rp.report_style():
        fig, axes = plt.subplots(len(rows), 1, figsize=(rp.A4_WIDTH_IN, 1.9 * len(rows) + 0.8),
                                 sharex=True, layout="constrained")
        for k, (c, lab) in enumerate(runs):
            s = series(c)
            if s is None:
                continue
            st = rp._run_style(k)
            for ax, (q, ylab, sc) in zip(axes, rows):
                a = s.body(ws, q) if q == "y" else s.wheel(ws, side, q)
                if a is None:
                    continue
                t = s.t[:len(a)]
                ax.plot(t, a * sc, label=lab + ("" if c.ok else " (failed)"), **st)
                ax.set_ylabel(ylab)
        axes[-1].set_xlabel("time [s]")
        axes[0].legend(fontsize=6.5, ncols=2)
        _title(fig, f"{title}; {ws}, {side} wheel (the largest flange force of these runs)")
    return fig


def fig_lut_integrators(study: Study):
    """Fig. 24: LUT with every solver at K = 1e12 (else the largest K with runs)."""
    lut = [c for c in study.cases
           if c.method == "lut" and not c.role.startswith("reference") and c.file]
    if len({c.solver_key for c in lut}) < 2:
        return None
    Ks = sorted({c.K for c in lut})
    K = 1e12 if 1e12 in Ks else Ks[-1]
    sel = [c for c in lut if c.K == K and c.model_key == min(
        (x.model_key for x in lut if x.K == K), key=len)]
    wheel = flange_wheel(sel)
    if wheel is None:
        return None
    return _lut_panels([(c, c.solver_key) for c in sel], wheel,
                       f"LUT, K = {compact(K)} N/m^1.5, every integrator (paper Fig. 24)", True)


def fig_lut_stiffness(study: Study, solver: str):
    """Fig. 25: LUT flange indentation and force per K with one solver setting."""
    sel = [c for c in study.cases
           if c.method == "lut" and not c.role.startswith("reference") and c.file
           and c.solver_key == solver and not c.refined]
    if len({c.K for c in sel}) < 2:
        return None
    sel.sort(key=lambda c: c.K)
    wheel = flange_wheel(sel)
    if wheel is None:
        return None
    return _lut_panels([(c, f"K = {compact(c.K)}") for c in sel], wheel,
                       f"LUT flange contact per stiffness, {solver} (paper Fig. 25)", False)


# --------------------------------------------------------------------------------------------
# Work precision
# --------------------------------------------------------------------------------------------
def _errors(case: Case, ref: Case) -> Optional[Dict[str, Tuple[float, float, str]]]:
    """{quantity: (max abs, rms, unit)} of case vs ref on the reference output times inside the
    case's run (display units), over every wheelset (and wheel)."""
    s, r = series(case), series(ref)
    if s is None or r is None or len(r.t) < 2 or len(s.t) < 2:
        return None
    out = {}
    for name, group, ds, scale, unit in WHEELSET_QUANTITIES:
        sq, rq = dict(s.quantity(group, ds)), dict(r.quantity(group, ds))
        mx, sq_sum, n = 0.0, 0.0, 0
        for key, rv in rq.items():
            if key not in sq:
                continue
            m, v = on_grid(r.t[:len(rv)], s.t, sq[key])
            if not m.any():
                continue
            d = (v - rv[:len(m)][m]) * scale
            d = d[np.isfinite(d)]
            if not len(d):
                continue
            mx = max(mx, float(np.max(np.abs(d))))
            sq_sum += float(np.sum(d * d))
            n += len(d)
        if n:
            out[name] = (mx, math.sqrt(sq_sum / n), unit)
    return out


def find_reference(study: Study, case: Case, role: str = "reference") -> Optional[Case]:
    refs = [c for c in study.by_role(role) if c.file]
    same = [c for c in refs if c.physical_key() == case.physical_key()]
    return same[0] if same else None


def work_precision_rows(study: Study, against: str = "reference") -> List[dict]:
    """Error of every case against the reference case of the same model (role `against`):
    "reference" (total error: the reference runs on the refined tables) or
    "reference_same_tables" (integration error only: a reference on the cases' own tables).
    With against = "reference", special rows (column `kind`): "reference_check" (the
    reference's own error) and "table_error" (the same-tables reference vs the reference: the
    error of the default contact tables, a floor for every default-table case)."""
    rows = []
    if not study.by_role(against):
        return rows
    for c in study.cases:
        if c.role == "reference" and against == "reference":
            targets = []
            for role, kind, note in (
                    ("reference_check", "reference_check",
                     "reference_check vs reference (the reference's own error)"),
                    ("reference_same_tables", "table_error",
                     "same-tables reference vs reference (the contact tables' error)")):
                other = find_reference(study, c, role)
                if other is not None:
                    targets.append((other, c, kind, note))
        elif c.role.startswith("reference"):
            continue
        else:
            ref = find_reference(study, c, against)
            if ref is None:
                rows.append(dict(against=against, kind="case", case=c.id, label=c.label,
                                 model=c.model_key, integrator=c.integrator,
                                 solver=c.solver_key, setting=_setting(c),
                                 order=_order(c), reference="",
                                 status=c.status, cpu_median_s=f"{c.cpu:.4f}",
                                 rhs_evals=int(c.counts["rhs_evals"]),
                                 note="no reference case with the same model"))
                continue
            targets = [(c, ref, "case", "")]
        for case, ref, kind, note in targets:
            errs = _errors(case, ref) or {}
            row = dict(against=against, kind=kind, case=case.id, label=case.label,
                       model=case.model_key, integrator=case.integrator,
                       solver=case.solver_key, setting=_setting(case), order=_order(case),
                       reference=ref.label,
                       status=case.status, cpu_median_s=f"{case.cpu:.4f}",
                       rhs_evals=int(case.counts["rhs_evals"]),
                       note=note or ("" if case.ok else "failed: error over the part it ran; "
                                     + case.message[:120]))
            for name, _, _, _, unit in WHEELSET_QUANTITIES:
                e = errs.get(name)
                tag = QUANTITY_TAGS[name]
                row[f"{tag}_max_{unit}"] = "" if e is None else f"{e[0]:.4g}"
                row[f"{tag}_rms_{unit}"] = "" if e is None else f"{e[1]:.4g}"
            rows.append(row)
    return rows


def _order(c: Case) -> str:
    """Tolerance or step: the order of the cases along a work-precision line."""
    v = c.tol if c.tol is not None else c.step
    return "" if v is None else f"{v:g}"


def _setting(c: Case) -> str:
    if c.tol is not None:
        return f"tol={compact(c.tol)}"
    if c.step is not None:
        return f"h={compact(c.step * 1e3)}ms"
    return ""


def fig_work_precision(rows: List[dict], stat: str = "max", against: str = "reference"):
    """Error (x) vs CPU time (y), log-log; one panel per quantity; colour = integrator, marker
    and line style = contact method; lines through the tolerances / steps; failed cases as red
    crosses; the reference's own error (reference_check) as a grey band."""
    data = [r for r in rows if r.get("y_max_mm", "") != ""]
    if not data:
        return None
    refrows = [r for r in data if r["kind"] == "reference_check"]
    tablerows = [r for r in data if r["kind"] == "table_error"]
    cases = [r for r in data if r["kind"] == "case"]
    cols = [("y", "mm", "lateral displacement y"), ("yaw", "mrad", "yaw angle"),
            ("Q", "kN", "normal force Q"), ("Fy", "kN", "lateral creep force")]
    with rp.report_style():
        fig, axes = plt.subplots(2, 2, figsize=(rp.A4_WIDTH_IN * 1.2, 7.6))
        # One line per model and integrator setting apart from the tolerance / step (so that,
        # e.g., dopri5 with and without a largest step are separate lines); the same in every panel.
        groups: Dict[Tuple[str, str], List[dict]] = {}
        for r in cases:
            rest = re.sub(r"\b(tol|h)=\S+\s*", "", r.get("solver", "")).strip()
            groups.setdefault((r["model"], rest or r["integrator"]), []).append(r)
        for ax, (tag, unit, name) in zip(axes.flat, cols):
            key = f"{tag}_{stat}_{unit}"
            for (model, integ), rs in groups.items():
                method = model.split()[0].lower() if model else ""
                mk, ls = METHOD_MARKERS.get(method, ("^", ":"))
                if "prescribed" in model:  # another model of the same method
                    mk, ls = "v", "-."
                col = INTEGRATOR_COLORS.get(rs[0]["integrator"], "#555555")
                if ("hmax" not in integ or "hmax=0ms" in integ) and \
                        rs[0]["integrator"] in ("dopri5", "bdf", "ida"):
                    mk, ls = "D", ":"  # no largest step: the error control alone
                ok = [r for r in rs if r["status"] == "ok" and r[key] not in ("", None)
                      and float(r[key]) > 0]
                # Through the tolerances / steps, coarse to fine (not sorted by the error).
                ok.sort(key=lambda r: -float(r["order"]) if r["order"] else 0.0)
                if ok:
                    ax.plot([float(r[key]) for r in ok], [float(r["cpu_median_s"]) for r in ok],
                            marker=mk, ls=ls, color=col, ms=4, label=f"{model} {integ}")
                for r in rs:
                    if r["status"] != "ok" and r[key] not in ("", None) and float(r[key]) > 0:
                        ax.plot(float(r[key]), max(float(r["cpu_median_s"]), 1e-6), "x",
                                color=rp.FAIL_COLOR, ms=5)
            xs = [float(r[key]) for r in data if r[key] not in ("", None) and float(r[key]) > 0]
            ax.set_xscale("log")
            if xs:
                ax.set_xlim(min(xs) / 2, max(xs) * 2)
            for r in refrows:
                if r[key] not in ("", None) and float(r[key]) > 0:
                    ax.axvspan(min(xs) / 10, float(r[key]), color="#bbbbbb", alpha=0.35, lw=0)
            for r in tablerows:
                if r[key] not in ("", None) and float(r[key]) > 0:
                    method = r["model"].split()[0].lower() if r["model"] else ""
                    ax.axvline(float(r[key]), color="#444444", lw=0.8,
                               ls=METHOD_MARKERS.get(method, ("", ":"))[1])
            ax.set_yscale("log")
            ax.set_xlabel(f"{stat} |error| of {name} [{unit}]")
            ax.set_ylabel("CPU time [s]")
        h, lab = axes.flat[0].get_legend_handles_labels()
        h.append(plt.Line2D([], [], marker="x", ls="none", color=rp.FAIL_COLOR))
        lab.append("failed (error over the part it ran)")
        if refrows:
            h.append(rp.Patch(color="#bbbbbb", alpha=0.35))
            lab.append("below the reference's own error")
        if tablerows:
            h.append(plt.Line2D([], [], color="#444444", lw=0.8))
            lab.append("error of the default tables (KEC solid, LUT dashed)")
        what = "maximum" if stat == "max" else "RMS"
        ref = "the reference (refined tables)" if against == "reference" else \
            "a reference on the same tables (integration error only)"
        _title(fig, f"Work-precision: {what} error against {ref} vs CPU time "
                    f"(all wheelsets / wheels)")
        # The legend below the panels (matplotlib 3.6: no "outside" legend with constrained
        # layout), so that it hides no data.
        rows_needed = (len(lab) + 2) // 3
        bottom = min(0.4, 0.02 + 0.017 * rows_needed)
        fig.tight_layout(rect=(0, bottom, 1, 0.95))
        fig.legend(h, lab, loc="lower center", ncol=3, fontsize=5.5, frameon=False)
    return fig


# --------------------------------------------------------------------------------------------
# Effects: cost per evaluation
# --------------------------------------------------------------------------------------------
def effect_rows(study: Study) -> List[dict]:
    base = study.by_role("baseline")
    if not base:
        return []
    rows = []
    for c in study.cases:
        same = [b for b in base if b.method == c.method and b.solver_key == c.solver_key] or base
        b = same[0]
        ev, bev = c.counts["rhs_evals"], b.counts["rhs_evals"]
        # A failed run still gives its cost per evaluation (up to where it stopped).
        us = c.cpu / ev * 1e6 if ev > 0 and c.cpu > 0 else float("nan")
        bus = b.cpu / bev * 1e6 if bev > 0 and b.cpu > 0 else float("nan")
        rows.append(dict(case=c.id, label=c.label, role=c.role, method=c.method,
                         baseline=b.label, status=c.status, runs_ok=c.runs_ok,
                         cpu_median_s=f"{c.cpu_median:.4f}", cpu_min_s=f"{c.cpu_min:.4f}",
                         cpu_max_s=f"{c.cpu_max:.4f}", rhs_evals=int(ev),
                         us_per_eval=f"{us:.3f}" if np.isfinite(us) else "",
                         relative_to_baseline=f"{us / bus:.4f}" if np.isfinite(us / bus) else "",
                         spread_percent=f"{(c.cpu_max - c.cpu_min) / c.cpu_median * 100:.1f}"
                         if c.ok and c.cpu_median > 0 else "",
                         evals_differ="yes" if ev != bev else "",
                         message=c.message))
    return rows


def fig_effects(rows: List[dict]):
    if not rows:
        return None
    rows = list(rows)
    with rp.report_style():
        fig, ax = plt.subplots(figsize=(rp.A4_WIDTH_IN, 0.28 * len(rows) + 1.3),
                               layout="constrained")
        y = np.arange(len(rows))[::-1]
        for yi, r in zip(y, rows):
            if r["us_per_eval"] == "":
                ax.text(0, yi, "  failed", va="center", color=rp.FAIL_COLOR, fontsize=7)
                continue
            v = float(r["us_per_eval"])
            col = "#555555" if r["role"] == "baseline" else "#1f5fa8"
            failed = r["status"] != "ok"
            ax.barh(yi, v, color="none" if failed else col, height=0.7,
                    edgecolor=rp.FAIL_COLOR if failed else "none", hatch="xxx" if failed else None)
            rel = float(r["relative_to_baseline"]) if r["relative_to_baseline"] else float("nan")
            txt = f" {v:.1f} µs ({(rel - 1) * 100:+.1f} %)" if r["role"] != "baseline" \
                else f" {v:.1f} µs (baseline)"
            if r["spread_percent"]:
                txt += f"  spread {r['spread_percent']} %"
            if failed:
                txt += "  FAILED (up to where it stopped)"
            ax.text(v, yi, txt, va="center", fontsize=6.5)
        ax.set_yticks(y)
        ax.set_yticklabels([r["label"] for r in rows], fontsize=6.5)
        ax.set_xlabel("CPU time per right-hand side evaluation [µs] (median over the repeats)")
        xm = max([float(r["us_per_eval"]) for r in rows if r["us_per_eval"]] or [1])
        ax.set_xlim(0, xm * 1.6)
        _title(fig, "Cost of each effect: CPU time per evaluation relative to the full model")
    return fig


# --------------------------------------------------------------------------------------------
# Driver
# --------------------------------------------------------------------------------------------
def write_csv(path: str, rows: List[dict]):
    cols = []
    for r in rows:
        for k in r:
            if k not in cols:
                cols.append(k)
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=cols)
        w.writeheader()
        for r in rows:
            w.writerow(r)


def _save(fig, path, written, dpi):
    if fig is None:
        return
    try:
        fig.savefig(path, dpi=dpi)
    finally:
        plt.close(fig)
    written.append(path)


def make_study_outputs(outdir: str, dpi: int = rp.DPI) -> List[str]:
    study = load_study(outdir)
    p = lambda name: os.path.join(outdir, name)  # noqa: E731
    written: List[str] = []
    try:
        write_csv(p("study_cost.csv"), cost_rows(study))
        written.append(p("study_cost.csv"))
        write_csv(p("study_failures.csv"), failure_rows(study))
        written.append(p("study_failures.csv"))
        name = os.path.splitext(os.path.basename(study.study_file))[0]
        _save(fig_cost(study, f"Computation cost per case — {name}" if name else ""),
              p("study_cost.png"), written, dpi)
        _save(fig_tables(study), p("study_tables.png"), written, dpi)

        acc = accuracy_rows(study)
        if acc:
            write_csv(p("study_accuracy_lut_vs_kec.csv"), acc)
            written.append(p("study_accuracy_lut_vs_kec.csv"))
            _save(fig_accuracy(acc), p("study_accuracy_lut_vs_kec.png"), written, dpi)
        _save(fig_lut_integrators(study), p("study_lut_integrators.png"), written, dpi)
        for solver in dict.fromkeys(c.solver_key for c in study.cases if c.method == "lut"):
            safe = "".join(ch if ch.isalnum() or ch in "-." else "_" for ch in solver)
            _save(fig_lut_stiffness(study, solver), p(f"study_lut_stiffness_{safe}.png"),
                  written, dpi)

        wp = work_precision_rows(study)
        wpi = work_precision_rows(study, "reference_same_tables")
        if wp or wpi:
            write_csv(p("study_work_precision.csv"), wp + wpi)
            written.append(p("study_work_precision.csv"))
        for rows, against, suffix in ((wp, "reference", ""),
                                      (wpi, "reference_same_tables", "_integration")):
            if rows:
                _save(fig_work_precision(rows, "max", against),
                      p(f"study_work_precision{suffix}.png"), written, dpi)
                _save(fig_work_precision(rows, "rms", against),
                      p(f"study_work_precision{suffix}_rms.png"), written, dpi)

        eff = effect_rows(study)
        if eff:
            write_csv(p("study_effects.csv"), eff)
            written.append(p("study_effects.csv"))
            _save(fig_effects(eff), p("study_effects.png"), written, dpi)
    finally:
        close_all()
    return written
