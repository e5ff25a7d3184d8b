"""`workbench precision`: errors, reference bound, Pareto fronts, figures and the recommendation
table of a precision folder (docs/precision.md).

    plots/rbplot precision OUT [--quantities y,yaw] [--levels 1,0.1,0.01] [--limit 0.001]
                               [--callgrind --workbench BIN --root ROOT]

Reads OUT/precision_plan.csv (written by the command: every case, its model, integrator,
setting and role) and the study folders OUT/reference and OUT/cases. Writes into OUT:
precision.csv (per case: cost, integration and total error per quantity), precision_references.csv
(the references, their bound, verified or not, and the table error), precision_recommendation.csv
is the engine's (the cheapest setting per model and level, computed and printed by `workbench
precision` before this step: read here, never recomputed), precision.h5 (all of these as
datasets), and one figure per model, precision_<model>.png.
"""
from __future__ import annotations

import math
import os
import re
import subprocess
import sys
import tempfile
from typing import Dict, List, Optional

import h5py
import numpy as np

from .common import parser, read_csv, write_csv
from .precision_errors import Quantity, QuantityError, errors, parse_quantities, verify
from .study_data import Case, StudyError, load_study


def _fmt(v: Optional[float]) -> str:
    if v is None or (isinstance(v, float) and not math.isfinite(v)):
        return "" if v is None else "inf"
    return f"{v:.4g}"


def _cases(outdir: str) -> Dict[str, Case]:
    out = {}
    for sub in ("reference", "cases"):
        d = os.path.join(outdir, sub)
        if os.path.exists(os.path.join(d, "summary_cases.csv")):
            for c in load_study(d).cases:
                out[c.id] = c
    return out


def _err(case: Optional[Case], ref: Optional[Case], qs: List[Quantity]) -> dict:
    if case is None or ref is None or not case.file or not ref.file or \
            not os.path.exists(case.file) or not os.path.exists(ref.file):
        return {}
    try:
        return errors(case.file, ref.file, qs)
    except (OSError, KeyError):
        return {}


def reference_rows(plan: List[dict], cases: Dict[str, Case], qs: List[Quantity],
                   limit: float) -> Dict[str, dict]:
    """Per default-table model: its references, the bound (reference_check vs reference), whether
    verified, and the table error (same-tables reference vs reference)."""
    out = {}
    for model in dict.fromkeys(r["model"] for r in plan if r["role"] == "reference"):
        refs = {r["role"]: cases.get(r["case"]) for r in plan
                if r["model"] == model and r["folder"] == "reference"}
        ref, check, same = (refs.get("reference"), refs.get("reference_check"),
                            refs.get("reference_same_tables"))
        bound = _err(check, ref, qs)
        both_ok = bool(ref and check and ref.ok and check.ok)
        verified, why = verify(bound, qs, limit, both_ok)
        table = _err(same, ref, qs)
        out[model] = dict(ref=ref, check=check, same=same, bound=bound, verified=verified,
                          why=why, table=table)
    return out


def case_rows(plan: List[dict], cases: Dict[str, Case], refs: Dict[str, dict],
              qs: List[Quantity]) -> List[dict]:
    """One row per setting of the matrix: cost, integration error (against the reference on the
    same tables), total error (against the refined-table reference)."""
    rows = []
    for p in plan:
        if p["role"] != "case":
            continue
        base_model = p["model"].replace(" refined", "")
        rf = refs.get(base_model, {})
        c = cases.get(p["case"])
        ran = c is not None and p["status"] == "run"
        same = rf.get("ref") if p["tables"] == "refined" else rf.get("same")
        integ = _err(c, same, qs) if ran else {}
        total = _err(c, rf.get("ref"), qs) if ran else {}
        row = dict(model=p["model"], method=p["method"], tables=p["tables"],
                   integrator=p["integrator"], kind=p["kind"], value=p["value"], label=p["label"],
                   case=p["case"], status=(c.status if ran else p["status"]),
                   cpu_median_s=_fmt(c.cpu) if ran else "",
                   cpu_min_s=_fmt(c.cpu_min) if ran else "",
                   cpu_max_s=_fmt(c.cpu_max) if ran else "",
                   runs_ok=c.runs_ok if ran else "",
                   rhs_evals=int(c.counts["rhs_evals"]) if ran else "")
        for q in qs:
            for what, e in (("integration", integ), ("total", total)):
                v = e.get(q.tag)
                row[f"{q.tag}_{what}_max_{q.unit}"] = _fmt(v[0]) if v else ""
                row[f"{q.tag}_{what}_rms_{q.unit}"] = _fmt(v[1]) if v else ""
        note = p.get("note", "")
        if ran and not c.ok:
            note = "failed: error over the part it ran; " + (c.message or "")[:160]
        row["note"] = note
        rows.append(row)
    return rows


def _num(s) -> Optional[float]:
    try:
        v = float(s)
    except (TypeError, ValueError):
        return None
    return v


def recommendation_rows(outdir: str) -> List[dict]:
    """The recommendation as the engine computed it (`workbench precision` writes
    precision_recommendation.csv before any figure: the rule lives in
    workbench/precision/answer.cpp). This module only draws and tabulates it."""
    path = os.path.join(outdir, "precision_recommendation.csv")
    if not os.path.exists(path):
        raise FileNotFoundError(f"{path} not found: the recommendation is computed by "
                                f"`workbench precision` (run it again to write it)")
    return read_csv(path)


def _table_to_h5(g: h5py.Group, rows: List[dict]) -> None:
    if not rows:
        return
    for k in rows[0]:
        vals = [r.get(k, "") for r in rows]
        nums = [_num(v) for v in vals]
        if all(n is not None or v == "" for n, v in zip(nums, vals)) and any(
                n is not None for n in nums):
            g.create_dataset(k, data=np.array([np.nan if n is None else n for n in nums]))
        else:
            g.create_dataset(k, data=np.array([str(v) for v in vals], dtype=h5py.string_dtype()))


def _engine_model_errors(path: str) -> Dict[str, dict]:
    """The model errors the engine wrote (--model-reference), kept when the file is rewritten:
    they are the engine's answer, this module does not compute them."""
    out: Dict[str, dict] = {}
    if not os.path.exists(path):
        return out
    with h5py.File(path, "r") as f:
        for model, g in f.get("reference_bound", {}).items():
            out[model] = {k: v for k, v in g.attrs.items()
                          if "_model_error_" in k or k == "model_reference"}
    return out


def write_h5(path: str, rows, ref_rows, rec_rows, qs, levels, limit, refs) -> None:
    tmp = path + ".tmp"
    model_errors = _engine_model_errors(path)
    with h5py.File(tmp, "w") as f:
        f.attrs["quantities"] = ",".join(q.tag for q in qs)
        f.attrs["units"] = ",".join(q.unit for q in qs)
        f.attrs["levels"] = np.array(levels, float)
        f.create_dataset("levels", data=np.array(levels, float))  # as the engine writes it
        f.attrs["reference_limit"] = limit
        for model, rf in refs.items():
            g = f.create_group(f"reference_bound/{model}")
            g.attrs["verified"] = int(rf["verified"])
            g.attrs["why"] = rf["why"]
            for q in qs:
                b = rf["bound"].get(q.tag)
                t = rf["table"].get(q.tag)
                g.attrs[f"{q.tag}_max_{q.unit}"] = b[0] if b else np.nan
                g.attrs[f"{q.tag}_rms_{q.unit}"] = b[1] if b else np.nan
                g.attrs[f"{q.tag}_table_error_max_{q.unit}"] = t[0] if t else np.nan
            for k, v in model_errors.get(model, {}).items():
                g.attrs[k] = v
        _table_to_h5(f.create_group("cases"), rows)
        _table_to_h5(f.create_group("references"), ref_rows)
        _table_to_h5(f.create_group("recommendation"), rec_rows)
    os.replace(tmp, path)


def _reference_table(refs: Dict[str, dict], qs: List[Quantity], limit: float) -> List[dict]:
    out = []
    for model, rf in refs.items():
        for role in ("ref", "check", "same"):
            c = rf[role]
            row = dict(model=model, role={"ref": "reference", "check": "reference_check",
                                         "same": "reference_same_tables"}[role],
                       label=c.label if c else "", status=c.status if c else "missing",
                       cpu_median_s=_fmt(c.cpu) if c else "",
                       rhs_evals=int(c.counts["rhs_evals"]) if c else "")
            out.append(row)
        bound = dict(model=model, role="bound (reference_check vs reference)", label="",
                     status="verified" if rf["verified"] else "UNVERIFIED: " + rf["why"],
                     cpu_median_s="", rhs_evals="", limit=f"{limit:g}")
        table = dict(model=model, role="table error (same-tables reference vs reference)",
                     label="", status="", cpu_median_s="", rhs_evals="")
        for q in qs:
            b, t = rf["bound"].get(q.tag), rf["table"].get(q.tag)
            bound[f"{q.tag}_max_{q.unit}"] = _fmt(b[0]) if b else ""
            bound[f"{q.tag}_rms_{q.unit}"] = _fmt(b[1]) if b else ""
            table[f"{q.tag}_max_{q.unit}"] = _fmt(t[0]) if t else ""
            table[f"{q.tag}_rms_{q.unit}"] = _fmt(t[1]) if t else ""
        out += [bound, table]
    return out


def _callgrind(rec_rows: List[dict], cases: Dict[str, Case], workbench: str, root: str) -> None:
    """Instructions of the recommended settings (each run once under callgrind, collecting only
    inside the integration, as plots/railbench/effects.py)."""
    from .effects import callgrind_total
    done: Dict[str, tuple] = {}
    with tempfile.TemporaryDirectory(prefix="rb_precision_cg_") as tmp:
        for r in rec_rows:
            c = cases.get(r["case"])
            if c is None:
                continue
            if c.id not in done:
                out, cg = os.path.join(tmp, c.id + ".h5"), os.path.join(tmp, c.id + ".cg")
                cmd = ["valgrind", "--tool=callgrind", f"--callgrind-out-file={cg}",
                       "--toggle-collect=rb::integ::integrate*", workbench, "--root", root,
                       "run", c.base, "--out", out, "--quiet"]
                for k, v in c.overrides.items():
                    cmd += ["--set", f"{k}={v}"]
                try:
                    p = subprocess.run(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE,
                                       text=True)
                    ok = p.returncode == 0 and os.path.exists(cg)
                except OSError:
                    ok = False
                if ok:
                    with h5py.File(out, "r") as h:
                        ev = int(h["stats"].attrs["rhs_evals"])
                    done[c.id] = (callgrind_total(cg), ev)
                else:
                    done[c.id] = None
                    print(f"precision: callgrind of {c.label} failed", file=sys.stderr)
            d = done[c.id]
            r["instructions"] = d[0] if d else ""
            r["instructions_per_eval"] = f"{d[0] / d[1]:.1f}" if d and d[1] else ""


def markdown(rows: List[dict], rec_rows: List[dict], refs: Dict[str, dict],
             qs: List[Quantity]) -> str:
    """The results as a markdown block: the references (bound, verified, table error), the
    spread of the integration error, the recommendation table and the figures."""
    q = qs[0]
    out = ["| model | reference | bound max " + q.tag + " [" + q.unit + "] | table error max " +
           q.tag + " [" + q.unit + "] | integration error range [" + q.unit + "] | decades |",
           "|---|---|---|---|---|---|"]
    for model, rf in refs.items():
        b, t = rf["bound"].get(q.tag), rf["table"].get(q.tag)
        errs = [_num(r[f"{q.tag}_integration_max_{q.unit}"]) for r in rows
                if r["model"] == model and r["status"] == "ok"]
        errs = [e for e in errs if e and e > 0 and math.isfinite(e)]
        span = f"{min(errs):.3g} ... {max(errs):.3g}" if errs else ""
        dec = f"{math.log10(max(errs) / min(errs)):.1f}" if errs else ""
        out.append(f"| {model} | {'verified' if rf['verified'] else 'UNVERIFIED'} | "
                   f"{_fmt(b[0]) if b else ''} | {_fmt(t[0]) if t else ''} | {span} | {dec} |")
    out += ["", f"| model | level [{q.unit}] | cheapest setting | CPU [s] | rhs evaluations | "
                f"error [{q.unit}] | note |", "|---|---|---|---|---|---|---|"]
    for r in rec_rows:
        out.append(f"| {r['model']} | {r['level']} | {r['setting']} | {r['cpu_median_s']} | "
                   f"{r['rhs_evals']} | {r['error_max']} | {r['note']} |")
    out.append("")
    for model in dict.fromkeys(r["model"] for r in rows):
        out.append(f"![work-precision {model}](figures/precision_{_slug(model)}.png)")
    return "\n".join(out) + "\n"


def block_from_folder(outdir: str, quantities: str = "y,yaw", levels: str = "1,0.1,0.01",
                      limit: Optional[float] = None) -> str:
    """The markdown block of a precision folder (for the docs generator): as --markdown."""
    qs = parse_quantities(quantities)
    lv = sorted((float(x) for x in levels.split(",")), reverse=True)
    lim = limit if limit is not None else lv[-1] / 10
    plan = read_csv(os.path.join(outdir, "precision_plan.csv"))
    cases = _cases(outdir)
    refs = reference_rows(plan, cases, qs, lim)
    rows = case_rows(plan, cases, refs, qs)
    return markdown(rows, recommendation_rows(outdir), refs, qs)


def _slug(model: str) -> str:
    return re.sub(r"[^a-z0-9]+", "_", model.lower()).strip("_")


def main(argv=None) -> int:
    ap = parser("precision", __doc__.split("\n\n")[0])
    ap.add_argument("outdir")
    ap.add_argument("--quantities", default="y,yaw")
    ap.add_argument("--levels", default="1,0.1,0.01")
    ap.add_argument("--limit", type=float, default=None,
                    help="verification limit of the references (default: smallest level / 10)")
    ap.add_argument("--callgrind", action="store_true")
    ap.add_argument("--workbench", default="")
    ap.add_argument("--root", default="")
    ap.add_argument("--markdown", default="",
                    help="also write the results as a markdown block (docs/precision.md) here")
    a = ap.parse_args(argv)
    try:
        qs = parse_quantities(a.quantities)
        levels = sorted((float(x) for x in a.levels.split(",")), reverse=True)
    except (QuantityError, ValueError) as e:
        print(f"railbench precision: {e}", file=sys.stderr)
        return 1
    limit = a.limit if a.limit is not None else levels[-1] / 10
    plan_path = os.path.join(a.outdir, "precision_plan.csv")
    if not os.path.exists(plan_path):
        print(f"railbench precision: {plan_path} not found (run `workbench precision` first)",
              file=sys.stderr)
        return 1
    plan = read_csv(plan_path)
    try:
        cases = _cases(a.outdir)
    except StudyError as e:
        print(f"railbench precision: {e}", file=sys.stderr)
        return 1
    refs = reference_rows(plan, cases, qs, limit)
    rows = case_rows(plan, cases, refs, qs)
    ref_rows = _reference_table(refs, qs, limit)
    try:
        rec_rows = recommendation_rows(a.outdir)
    except FileNotFoundError as e:
        print(f"railbench precision: {e}", file=sys.stderr)
        return 1
    write_csv(os.path.join(a.outdir, "precision.csv"), rows)
    write_csv(os.path.join(a.outdir, "precision_references.csv"), ref_rows)
    if a.callgrind and a.workbench:
        # Adds the instruction counts of the recommended settings as columns.
        _callgrind(rec_rows, cases, a.workbench, a.root)
        write_csv(os.path.join(a.outdir, "precision_recommendation.csv"), rec_rows)
    write_h5(os.path.join(a.outdir, "precision.h5"), rows, ref_rows, rec_rows, qs, levels, limit,
             refs)
    if a.markdown:
        with open(a.markdown, "w") as f:
            f.write(markdown(rows, rec_rows, refs, qs))
    from .precision_figs import fig_model
    from .style import DPI
    import matplotlib.pyplot as plt
    for model in dict.fromkeys(r["model"] for r in rows):
        fig = fig_model(model, [r for r in rows if r["model"] == model],
                        refs.get(model.replace(" refined", ""), {}), qs, levels,
                        refined=model.endswith("refined"),
                        recommended=[r for r in rec_rows if r["model"] == model and r["case"]])
        if fig is not None:
            path = os.path.join(a.outdir, f"precision_{_slug(model)}.png")
            fig.savefig(path, dpi=DPI)
            plt.close(fig)
            print(path)
    return 0


if __name__ == "__main__":
    sys.exit(main())
