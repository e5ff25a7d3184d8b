"""`workbench precision`: the figures and the markdown block of a precision folder
(docs/precision.md), drawn from the engine's answer.

    plots/rbplot precision OUT [--quantities y,yaw] [--levels 1,0.1,0.01] [--limit 0.001]
                               [--callgrind --workbench BIN --root ROOT]

Every number is the engine's (workbench/precision/answer.cpp), written by `workbench precision`
before this step: OUT/precision.csv (per case: cost, integration and total error per quantity),
precision_references.csv (the references, their bound, verified or not, and the table error),
precision_recommendation.csv (the cheapest setting per model and level) and precision.h5 (all of
these as datasets). This module reads them and draws one figure per model,
precision_<model>.png; with --callgrind it adds the instruction counts of the recommended
settings to precision_recommendation.csv.
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

from .common import parser, read_csv, write_csv
from .precision_errors import Quantity, QuantityError, parse_quantities
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


def engine_refs(outdir: str, qs: List[Quantity]) -> Dict[str, dict]:
    """Per default-table model, the engine's verification of its references (precision.h5,
    /reference_bound/<model>): verified, why, and per quantity the bound and the table error as
    (max, rms)."""
    path = os.path.join(outdir, "precision.h5")
    if not os.path.exists(path):
        raise FileNotFoundError(f"{path} not found: the answer is computed by `workbench "
                                f"precision` (run it again to write it)")
    out: Dict[str, dict] = {}
    with h5py.File(path, "r") as f:
        for model, g in f.get("reference_bound", {}).items():
            a = g.attrs

            def pair(key, q):
                mx, rms = a.get(f"{q.tag}_{key}max_{q.unit}"), a.get(f"{q.tag}_{key}rms_{q.unit}")
                if mx is None or math.isnan(float(mx)):
                    return None
                return (float(mx), float(rms) if rms is not None else math.nan)

            out[model] = dict(verified=bool(int(a.get("verified", 0))),
                              why=_str_attr(a.get("why", "")),
                              bound={q.tag: pair("", q) for q in qs if pair("", q)},
                              table={q.tag: pair("table_error_", q) for q in qs
                                     if pair("table_error_", q)})
    return out


def _str_attr(v) -> str:
    return v.decode() if isinstance(v, bytes) else str(v)


def _engine_csv(outdir: str, name: str) -> List[dict]:
    path = os.path.join(outdir, name)
    if not os.path.exists(path):
        raise FileNotFoundError(f"{path} not found: the answer is computed by `workbench "
                                f"precision` (run it again to write it)")
    return read_csv(path)


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
    del levels, limit  # the engine's answer holds them
    qs = parse_quantities(quantities)
    return markdown(_engine_csv(outdir, "precision.csv"), recommendation_rows(outdir),
                    engine_refs(outdir, qs), qs)


def _slug(model: str) -> str:
    return re.sub(r"[^a-z0-9]+", "_", model.lower()).strip("_")


def main(argv=None) -> int:
    ap = parser("precision", __doc__.split("\n\n")[0])
    ap.add_argument("outdir")
    ap.add_argument("--quantities", default="y,yaw")
    ap.add_argument("--levels", default="1,0.1,0.01")
    ap.add_argument("--limit", type=float, default=None,
                    help="accepted for the command line's sake: the engine verified the "
                         "references against its limit (precision.h5)")
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
    try:
        rows = _engine_csv(a.outdir, "precision.csv")
        refs = engine_refs(a.outdir, qs)
        rec_rows = recommendation_rows(a.outdir)
    except FileNotFoundError as e:
        print(f"railbench precision: {e}", file=sys.stderr)
        return 1
    if a.callgrind and a.workbench:
        # Adds the instruction counts of the recommended settings as columns.
        try:
            cases = _cases(a.outdir)
        except StudyError as e:
            print(f"railbench precision: {e}", file=sys.stderr)
            return 1
        _callgrind(rec_rows, cases, a.workbench, a.root)
        write_csv(os.path.join(a.outdir, "precision_recommendation.csv"), rec_rows)
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
