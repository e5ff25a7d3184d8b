"""Reading a study folder (summary_cases.csv, summary.csv, summary.h5) and the time series
of its cases."""
from __future__ import annotations

import math
import os
from dataclasses import dataclass, field
from typing import Dict, List, Optional, Tuple

import h5py
import numpy as np

from .common import read_csv
from .h5 import _str
from .result import _names_attr


# Overrides that change how a model is solved, not which model (work-precision matching).
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


# The failure record's columns of the summaries (workbench/study/summary.cpp).
FAILURE_COLUMNS = ("failure_kind", "failure_reason", "failure_body", "failure_t", "failure_s")


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
    solver: str = ""  # the solver part of the label (summary_cases.csv), "" for the base's solver
    # The failure record of its first failed run (summary_cases.csv, the result's /stats):
    # failure_kind, failure_reason, failure_body, failure_t, failure_s; "" where unknown.
    failure: Dict[str, str] = field(default_factory=dict)
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
                        a["solver"] = _str(f.attrs.get("solver", ""))
                        if "contact" in f:
                            for k, v in f["contact"].attrs.items():
                                a["contact_" + k] = _str(v) if isinstance(
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
    def max_step(self) -> Optional[float]:
        """The largest step of an adaptive case [s] (0: none); None when the case keeps the
        base scenario's."""
        return _num(self.overrides.get("solver.max_step"))

    @property
    def interpolation(self) -> str:
        """Interpolation of the contact tables: the override, else the result file's record,
        else the default "cubic"."""
        return (self.overrides.get("contact.table_interpolation") or
                str(self._file_attrs().get("contact_table_interpolation") or "") or "cubic")

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
        return self.solver or self.integrator

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
            elif k == "contact.table_interpolation":
                parts.append(f"{v} interpolation")
            elif k == "contact.normal_forces":
                continue  # follows the integrator in our studies; shown in the labels
            else:
                parts.append(f"{k}={v}")
        stem = os.path.splitext(os.path.basename(self.base))[0]
        if self.main_base and self.base != self.main_base:
            parts.append(f"[{stem}]")  # another base scenario than most cases
        return " ".join(parts) or stem

    def attr(self, name, default=None):
        return self._file_attrs().get(name, default)


@dataclass
class Study:
    outdir: str
    cases: List[Case]
    study_file: str = ""
    # summary_errors.csv, the engine's error of every case against the case it is measured
    # against (workbench/study/reference_errors.hpp): {(case id, against role): (reference id,
    # {quantity label: (max, rms, unit)})}.
    errors: Dict[Tuple[str, str], Tuple[str, Dict[str, Tuple[float, float, str]]]] = \
        field(default_factory=dict)

    def by_role(self, role: str) -> List[Case]:
        return [c for c in self.cases if c.role == role]

    def case(self, case_id: str) -> Optional[Case]:
        return next((c for c in self.cases if c.id == case_id), None)

    def errors_of(self, case: Case, against: str) -> Optional[Tuple[str, Dict]]:
        """(reference id, {quantity label: (max, rms, unit)}) of `case` against the case of role
        `against` it is measured against; None when it has none."""
        return self.errors.get((case.id, against))


def read_errors(outdir: str) -> Dict[Tuple[str, str], Tuple[str, Dict]]:
    """summary_errors.csv (empty for a folder written before it existed)."""
    path = os.path.join(outdir, "summary_errors.csv")
    if not os.path.exists(path):
        return {}
    labels = {tag: label for label, tag in QUANTITY_TAGS.items()}
    out: Dict[Tuple[str, str], Tuple[str, Dict]] = {}
    for r in read_csv(path):
        ref, errs = out.setdefault((r["case"], r["against"]), (r["reference"], {}))
        mx = _num(r.get("max"))
        if mx is not None and r["quantity"] in labels:
            errs[labels[r["quantity"]]] = (mx, _num(r.get("rms"), math.nan), r["unit"])
    return out


def load_study(outdir: str) -> Study:
    sc = os.path.join(outdir, "summary_cases.csv")
    sr = os.path.join(outdir, "summary.csv")
    if not os.path.exists(sc) or not os.path.exists(sr):
        raise StudyError(f"{outdir}: no summary_cases.csv / summary.csv (not a study folder, or "
                         f"written by an older workbench)")
    runs = read_csv(sr)
    per_case: Dict[str, List[dict]] = {}
    for r in runs:
        per_case.setdefault(r["case"], []).append(r)
    cases = []
    for r in read_csv(sc):
        if "label" not in r or "solver" not in r:
            raise StudyError(f"{sc}: no label or solver column (written by an older workbench; "
                             f"run the study again to refresh the summary)")
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
            counts=counts, file=f, solver=r["solver"], repeats=reps,
            failure={k: r.get(k, "") or "" for k in FAILURE_COLUMNS}))
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
                study_file = _str(f.attrs.get("study_file", ""))
        except OSError:
            pass
    return Study(outdir=outdir, cases=cases, study_file=study_file, errors=read_errors(outdir))


# --------------------------------------------------------------------------------------------
# Time series of a case
# --------------------------------------------------------------------------------------------
class Series:
    """Time and the wheelset/contact series of one result file (read lazily, cached)."""

    def __init__(self, path: str):
        self.path = path
        self._f = h5py.File(path, "r")
        self.t = np.asarray(self._f["time"][()], float) if "time" in self._f else np.zeros(0)
        names = _names_attr(self._f["bodies"].attrs.get("names", "")) if "bodies" in self._f \
            else []
        self.wheelsets = [n for n in names if "bodies/" + n in self._f and _str(
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
