"""`workbench stress`: classification of every run of a stress folder, stress.csv, the stability
map (stress_map.png, and as text) and the expectation check (docs/stress.md).

    plots/rbplot stress DIR [--tolerance MM] [--expect FILE] [--no-figure] [--dpi N]

DIR is the output folder of `workbench stress` (stress_cases.csv: which case is which axis value
and integrator setting; the study summaries of runStudySpec). Every run is classified by the
checks of stress_checks.py and its error against the reference of the same hardened case:

    ok               finished, passes the checks, wheelset lateral error against its own
                     reference at most --tolerance (default 1 mm)
    inaccurate       finished and passes the checks, but the error is larger (or cannot be
                     established: the reference stopped, or failed badly)
    failed cleanly   exit 2 with a diagnostic naming time and distance, partial result kept and
                     consistent, no NaN (or a fixed step the check refused before the run)
    failed badly     exit 3, a signal, no result, NaN/Inf, an inconsistent partial result or an
                     implausible state in a finished run

Exit status: 0 the map was made, 2 no run left a result, 4 the figure failed, 5 an outcome
differs from the expectation file (the mismatches are listed), 1 bad input.
"""
from __future__ import annotations

import fnmatch
import os
import re
import sys
from typing import Dict, List, Optional, Tuple

from .common import error, parser, read_csv, save_figure, write_csv
from .stress_checks import BOUNDS, VALIDITY_REASONS, classify_run, failure_summary
from .study_data import StudyError, load_study
from .study_precision import _errors

OUTCOMES = ("ok", "inaccurate", "failed cleanly", "failed badly")
COLORS = {"ok": "#4dac26", "inaccurate": "#f1c232", "failed cleanly": "#e08214",
          "failed badly": "#b2182b"}
SHORT = {"ok": "ok", "inaccurate": "inacc", "failed cleanly": "clean-fail",
         "failed badly": "BAD"}
Y_ERROR = "lateral displacement y"


class StressError(Exception):
    """Bad input of the command (one line)."""


def _num(v, default=0.0) -> float:
    try:
        return float(v)
    except (TypeError, ValueError):
        return default


def _run_row(meta: dict, case, outcome: str, fields: dict, message: str,
             error_mm: Optional[float]) -> dict:
    return {
        "axis": meta["axis"], "value": meta["value"], "value_label": meta["value_label"],
        "integrator": meta["integrator"], "role": meta["role"], "outcome": outcome,
        "error_y_mm": "" if error_mm is None else "%.6g" % error_mm,
        "t_reached": fields.get("t_reached", ""), "t_end": meta["t_end"],
        "cpu_s": "%.6g" % case.cpu if case else "",
        "rhs_evals": int(case.counts.get("rhs_evals", 0)) if case else "",
        "rhs_evals_jac": int(case.counts.get("rhs_evals_jac", 0)) if case else "",
        "steps": int(case.counts.get("steps", 0)) if case else "",
        "max_abs_y_mm": fields.get("max_abs_y_mm", ""),
        "min_normal_kN": fields.get("min_normal_kN", ""),
        "message": message, "case": meta["case"], "file": case.file if case else ""}


def _validity(failure: dict) -> str:
    """What a clean failure of a reference means: the model leaves its validity (wheel lift,
    contact outside its table: docs/contact_dynamics.md), or "" (the reference's own solver gave
    up: too much work, step too small). From its failure record, never its message."""
    if (failure or {}).get("failure_reason") in VALIDITY_REASONS:
        return "the model leaves its validity there, this run went on through it"
    return ""


def _y_error(case, ref) -> Optional[float]:
    e = _errors(case, ref)
    if not e or Y_ERROR not in e:
        return None
    return e[Y_ERROR][0]


def _judge(case, ref, ref_outcome: str, tol: float) -> Tuple[str, Optional[float], str]:
    """A finished run that passed its own checks: ok or inaccurate, its error, the reason."""
    if ref is None or ref_outcome == "failed badly":
        return "inaccurate", None, "no valid reference (it failed badly): accuracy not established"
    err = _y_error(case, ref)
    if ref_outcome == "failed cleanly":
        return ("inaccurate", err,
                "its reference stops at t = %.4g s (%s): %s; error up to there %s mm"
                % (ref.counts.get("t_reached", 0.0), failure_summary(ref.failure),
                   _validity(ref.failure) or "accuracy beyond it not established",
                   "?" if err is None else "%.3g" % err))
    if err is None:
        return "inaccurate", None, "no common output times with the reference"
    if err > tol:
        return "inaccurate", err, "lateral error %.3g mm > %.3g mm" % (err, tol)
    return "ok", err, ""


def evaluate(outdir: str, tol: float) -> List[dict]:
    """One row per run (the references first in each hardened case)."""
    path = os.path.join(outdir, "stress_cases.csv")
    if not os.path.exists(path):
        raise StressError(f"{outdir}: no stress_cases.csv (not a `workbench stress` folder)")
    metas = read_csv(path)
    study = load_study(outdir)
    by_id = {c.id: c for c in study.cases}
    rows = []
    groups: Dict[Tuple[str, str], List[dict]] = {}
    for m in metas:
        groups.setdefault((m["axis"], m["value"]), []).append(m)
    for (_axis, _value), ms in groups.items():
        ref_meta = next((m for m in ms if m["role"] == "reference"), None)
        ref = by_id.get(ref_meta["case"]) if ref_meta else None
        ref_outcome = "failed badly"
        if ref_meta is not None:
            ref_outcome, fields, problems, _ = _classify(ref, ref_meta)
            msg = "; ".join(problems) if problems else (
                failure_summary(ref.failure) + "; " + (
                    "the model leaves its validity there" if _validity(ref.failure) else
                    "the reference itself could not be computed past it")
                if ref_outcome == "failed cleanly" else "")
            rows.append(_run_row(dict(ref_meta, integrator="reference " + ref_meta["integrator"]),
                                 ref, ref_outcome, fields, msg, 0.0 if ref_outcome == "ok"
                                 else None))
        for m in ms:
            if m is ref_meta:
                continue
            case = by_id.get(m["case"])
            outcome, fields, problems, _ = _classify(case, m)
            err, msg = None, "; ".join(problems)
            if outcome == "ok":
                outcome, err, msg = _judge(case, ref, ref_outcome, tol)
            elif outcome == "failed cleanly":
                msg = failure_summary(case.failure if case else {})
                if ref_outcome == "failed cleanly":
                    msg += "; the reference fails too"
            rows.append(_run_row(m, case, outcome, fields, msg, err))
    return rows


def _classify(case, meta) -> Tuple[str, dict, List[str], List[str]]:
    if case is None:
        return "failed badly", {}, ["the run is missing from the study summary"], []
    return classify_run(case.status, case.message, case.file, _num(meta["t_end"]), BOUNDS)


# ---- the map -----------------------------------------------------------------------------------

def _axes(rows: List[dict]) -> List[str]:
    out = []
    for r in rows:
        if r["axis"] not in out:
            out.append(r["axis"])
    return out


def _grid(rows: List[dict], axis: str) -> Tuple[List[str], List[str], Dict[Tuple[str, str], dict]]:
    values, integrators, cells = [], [], {}
    for r in rows:
        if r["axis"] != axis:
            continue
        if r["value_label"] not in values:
            values.append(r["value_label"])
        if r["integrator"] not in integrators:
            integrators.append(r["integrator"])
        cells[(r["value_label"], r["integrator"])] = r
    return values, integrators, cells


def _cell_text(r: Optional[dict]) -> str:
    if r is None:
        return "-"
    t = SHORT[r["outcome"]]
    if r["error_y_mm"] != "" and r["outcome"] in ("ok", "inaccurate") and \
            not r["integrator"].startswith("reference"):
        t += " %.2g" % float(r["error_y_mm"])
    return t


def text_map(rows: List[dict], tol: float) -> str:
    lines = [f"stability map (error = max wheelset lateral error [mm] vs the case's own "
             f"reference; ok <= {tol:g} mm)"]
    for axis in _axes(rows):
        values, integrators, cells = _grid(rows, axis)
        head = [axis] + integrators
        body = [[v] + [_cell_text(cells.get((v, i))) for i in integrators] for v in values]
        w = [max(len(x[k]) for x in [head] + body) for k in range(len(head))]
        lines.append("")
        lines.append("  ".join(h.ljust(w[k]) for k, h in enumerate(head)))
        for b in body:
            lines.append("  ".join(c.ljust(w[k]) for k, c in enumerate(b)))
    counts = {o: sum(1 for r in rows if r["outcome"] == o) for o in OUTCOMES}
    lines.append("")
    lines.append("runs: " + ", ".join(f"{counts[o]} {o}" for o in OUTCOMES))
    notes = [f"- {r['axis']}={r['value_label']} {r['integrator']}: {r['outcome']}: "
             f"{r['message'][:300]}" for r in rows if r["message"]]
    if notes:
        lines.append("")
        lines += notes
    return "\n".join(lines)


def figure(rows: List[dict], tol: float):
    from matplotlib.patches import Patch

    from .style import plt
    axes_names = _axes(rows)
    n = len(axes_names)
    ncol = min(n, 3)
    nrow = (n + ncol - 1) // ncol
    fig, axs = plt.subplots(nrow, ncol, figsize=(4.2 * ncol, 0.9 + 1.9 * nrow), squeeze=False)
    for k, axis in enumerate(axes_names):
        ax = axs[k // ncol][k % ncol]
        values, integrators, cells = _grid(rows, axis)
        for yi, v in enumerate(values):
            for xi, i in enumerate(integrators):
                r = cells.get((v, i))
                color = COLORS[r["outcome"]] if r else "#ffffff"
                ax.add_patch(plt.Rectangle((xi, yi), 1, 1, facecolor=color, edgecolor="white"))
                ax.text(xi + 0.5, yi + 0.5, _cell_text(r), ha="center", va="center", fontsize=6)
        ax.set_xlim(0, len(integrators))
        ax.set_ylim(0, len(values))
        ax.set_xticks([x + 0.5 for x in range(len(integrators))])
        ax.set_xticklabels([i.replace("reference ", "ref ") for i in integrators], rotation=30,
                           ha="right", fontsize=6)
        ax.set_yticks([y + 0.5 for y in range(len(values))])
        ax.set_yticklabels(values, fontsize=6)
        ax.set_title(axis, fontsize=8)
    for k in range(n, nrow * ncol):
        axs[k // ncol][k % ncol].axis("off")
    fig.legend(handles=[Patch(color=COLORS[o], label=o) for o in OUTCOMES], loc="lower center",
               ncol=4, fontsize=7, frameon=False)
    fig.suptitle(f"Stability map: outcome per axis value and integrator setting (ok: lateral "
                 f"error <= {tol:g} mm vs the case's own reference)", fontsize=8)
    fig.tight_layout(rect=(0, 0.06, 1, 0.95))
    return fig


# ---- expectations ------------------------------------------------------------------------------

def read_expectations(path: str) -> List[dict]:
    """Lines `AXIS, VALUE, INTEGRATOR, OUTCOME[|OUTCOME...]`; '#' starts a comment; AXIS,
    VALUE and INTEGRATOR are shell patterns ('*' any), VALUE also a number (compared with the
    axis value), INTEGRATOR "reference*" for the reference row."""
    out = []
    with open(path) as f:
        for no, line in enumerate(f, 1):
            line = line.split("#", 1)[0].strip()
            if not line:
                continue
            parts = [p.strip() for p in line.split(",")]
            if len(parts) != 4:
                raise StressError(f"{path}:{no}: expected AXIS, VALUE, INTEGRATOR, OUTCOME")
            allowed = [o.strip() for o in parts[3].split("|")]
            bad = [o for o in allowed if o not in OUTCOMES]
            if bad:
                raise StressError(f"{path}:{no}: unknown outcome {bad[0]!r} "
                                  f"(one of {', '.join(OUTCOMES)})")
            out.append({"where": f"{path}:{no}", "axis": parts[0], "value": parts[1],
                        "integrator": parts[2], "allowed": allowed})
    return out


def _value_matches(pattern: str, row: dict) -> bool:
    if pattern == "*":
        return True
    try:
        p, v = float(pattern), float(row["value"])
        return abs(p - v) <= 1e-9 * max(abs(p), abs(v))
    except ValueError:
        return fnmatch.fnmatch(row["value_label"], pattern)


def check_expectations(rows: List[dict], expectations: List[dict]) -> List[str]:
    mismatches = []
    for e in expectations:
        hits = [r for r in rows if fnmatch.fnmatch(r["axis"], e["axis"]) and
                _value_matches(e["value"], r) and fnmatch.fnmatch(r["integrator"], e["integrator"])]
        if not hits:
            mismatches.append(f"{e['where']}: no run matches {e['axis']}, {e['value']}, "
                              f"{e['integrator']}")
        for r in hits:
            if r["outcome"] not in e["allowed"]:
                mismatches.append(f"{e['where']}: {r['axis']}={r['value_label']} "
                                  f"{r['integrator']}: {r['outcome']}, expected "
                                  f"{' or '.join(e['allowed'])} ({r['message'][:200]})")
    return mismatches


def main(argv=None) -> int:
    ap = parser("stress", "classification and stability map of a `workbench stress` folder")
    ap.add_argument("dir", help="output folder of workbench stress")
    ap.add_argument("--tolerance", type=float, default=1.0,
                    help="largest wheelset lateral error [mm] of an ok run (default 1)")
    ap.add_argument("--expect", default=None, help="expectation file (docs/stress.md)")
    ap.add_argument("--no-figure", action="store_true", help="no stress_map.png")
    ap.add_argument("--dpi", type=int, default=150)
    args = ap.parse_args(argv)
    try:
        expectations = read_expectations(args.expect) if args.expect else []
        rows = evaluate(args.dir, args.tolerance)
    except (StressError, StudyError, OSError) as e:
        return error("stress", str(e))
    write_csv(os.path.join(args.dir, "stress.csv"), rows)
    print(text_map(rows, args.tolerance))
    print(os.path.join(args.dir, "stress.csv"))
    rc = 0
    if not args.no_figure and rows:
        try:
            png = os.path.join(args.dir, "stress_map.png")
            save_figure(figure(rows, args.tolerance), png, dpi=args.dpi)
            print(png)
        except Exception as e:  # the classification stands without its figure
            print(f"railbench stress: the figure failed: {e}", file=sys.stderr)
            rc = 4
    if rows and all(re.match(r"no result", r["message"]) for r in rows):
        print("railbench stress: no run left a result", file=sys.stderr)
        return 2
    mismatches = check_expectations(rows, expectations)
    if mismatches:
        print(f"\n{len(mismatches)} outcomes differ from {args.expect}:")
        for m in mismatches:
            print("  " + m)
        return 5
    if expectations:
        print(f"every outcome as expected ({len(expectations)} expectations, {args.expect})")
    return rc
