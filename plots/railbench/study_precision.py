"""Work-precision diagrams against the study's reference and the relative cost of model
effects."""
from __future__ import annotations

import re
from typing import Dict, List, Tuple

from matplotlib.patches import Patch
import numpy as np

from .style import A4_WIDTH_IN, FAIL_COLOR, plt, report_style
from .study_data import Case, INTEGRATOR_COLORS, METHOD_MARKERS, QUANTITY_TAGS, Study, WHEELSET_QUANTITIES, compact
from .study_cost import _title


# Work precision
# --------------------------------------------------------------------------------------------
def work_precision_rows(study: Study, against: str = "reference") -> List[dict]:
    """Error of every case against the reference case of the same model (role `against`), as the
    engine computed it (summary_errors.csv, workbench/study/reference_errors.hpp):
    "reference" (total error: the reference runs on the refined tables) or
    "reference_same_tables" (integration error only: a reference on the cases' own tables).
    With against = "reference", special rows (column `kind`): "reference_check" (the
    reference's own error) and "table_error" (the same-tables reference vs the reference: the
    error of the default contact tables, a floor for every default-table case)."""
    rows = []
    if not study.by_role(against):
        return rows
    notes = {"reference_check": ("reference_check",
                                 "reference_check vs reference (the reference's own error)"),
             "reference_same_tables": ("table_error", "same-tables reference vs reference (the "
                                                      "contact tables' error)")}
    for c in study.cases:
        if c.role == "reference" and against == "reference":
            targets = []
            for role, (kind, note) in notes.items():
                for other in study.by_role(role):
                    e = study.errors_of(other, "reference")
                    if e is not None and e[0] == c.id:
                        targets.append((other, c, kind, note, e[1]))
        elif c.role.startswith("reference"):
            continue
        else:
            e = study.errors_of(c, against)
            ref = study.case(e[0]) if e is not None else None
            if ref is None:
                rows.append(dict(against=against, kind="case", case=c.id, label=c.label,
                                 model=c.model_key, integrator=c.integrator,
                                 solver=c.solver_key, setting=_setting(c),
                                 order=_order(c), reference="",
                                 status=c.status, cpu_median_s=f"{c.cpu:.4f}",
                                 rhs_evals=int(c.counts["rhs_evals"]),
                                 note="no reference case with the same model"))
                continue
            targets = [(c, ref, "case", "", e[1])]
        for case, ref, kind, note, errs in targets:
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
    with report_style():
        fig, axes = plt.subplots(2, 2, figsize=(A4_WIDTH_IN * 1.2, 7.6))
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
                                color=FAIL_COLOR, ms=5)
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
        h.append(plt.Line2D([], [], marker="x", ls="none", color=FAIL_COLOR))
        lab.append("failed (error over the part it ran)")
        if refrows:
            h.append(Patch(color="#bbbbbb", alpha=0.35))
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
    with report_style():
        fig, ax = plt.subplots(figsize=(A4_WIDTH_IN, 0.28 * len(rows) + 1.3),
                               layout="constrained")
        y = np.arange(len(rows))[::-1]
        for yi, r in zip(y, rows):
            if r["us_per_eval"] == "":
                ax.text(0, yi, "  failed", va="center", color=FAIL_COLOR, fontsize=7)
                continue
            v = float(r["us_per_eval"])
            col = "#555555" if r["role"] == "baseline" else "#1f5fa8"
            failed = r["status"] != "ok"
            ax.barh(yi, v, color="none" if failed else col, height=0.7,
                    edgecolor=FAIL_COLOR if failed else "none", hatch="xxx" if failed else None)
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
