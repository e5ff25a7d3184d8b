"""Generated blocks of docs/studies.md that put our study results beside the paper's tables,
column by column: Tables 7 and 12-16 (efficiency_case3), 9-10, 11, 17 and 18 (refinement), and the
KEC/LUT ratios of the flange-loaded matrix (flange_stiffness) beside the paper's Tables 12-16.

Ours come from OUT/<study>/study_cost.csv (`plots/rbplot study`), the paper's from
docs/data/paper_efficiency.csv (its Appendix B and Tables 7, 11) and PAPER_TABLES_9_10 (its
Tables 9-10, text). Every table has the KEC/LUT ratio of CPU time and of evaluations, ours and
the paper's: for a LUT table against KEC with the same tables, for a KEC table against the LUT
with K = 1e10 (the pair of the paper's Fig. 26).
"""
from __future__ import annotations

import os
import re
from dataclasses import dataclass
from typing import Dict, List, Optional, Sequence, Tuple

from .docs_blocks import fmt, missing, num, paper_rows, read_csv, table, total_evals


@dataclass(frozen=True)
class PaperTable:
    """One of the paper's cost tables and the cases of ours that stand beside it."""
    no: str          # the paper's table number
    study: str       # our study folder
    method: str      # "kec" or "lut"
    K: str           # LUT flange stiffness [N/m^1.5] ("" for KEC)
    refined: bool    # refined tables (paper Tables 9-10)
    title: str
    partner: str     # the paper's table of the KEC/LUT partner (same tables)
    partner_K: str   # our partner's K ("" = KEC)
    default: str = ""  # the paper's table of the same model before refinement


PAPER_TABLES = (
    PaperTable("7", "efficiency_case3", "lut", "7.075e13", False,
               "LUT, Hertzian flange stiffness K = 7.075e13 N/m^1.5", "16", ""),
    PaperTable("12", "efficiency_case3", "lut", "1e9", False, "LUT, K = 1e9 N/m^1.5", "16", ""),
    PaperTable("13", "efficiency_case3", "lut", "1e10", False, "LUT, K = 1e10 N/m^1.5", "16", ""),
    PaperTable("14", "efficiency_case3", "lut", "1e11", False, "LUT, K = 1e11 N/m^1.5", "16", ""),
    PaperTable("15", "efficiency_case3", "lut", "1e12", False, "LUT, K = 1e12 N/m^1.5", "16", ""),
    PaperTable("16", "efficiency_case3", "kec", "", False, "KEC", "13", "1e10"),
    PaperTable("11", "refinement", "lut", "7.075e13", True,
               "LUT refined, K = 7.075e13 N/m^1.5", "17", "", default="7"),
    PaperTable("17", "refinement", "kec", "", True, "KEC refined", "18", "1e10", default="16"),
    PaperTable("18", "refinement", "lut", "1e10", True, "LUT refined, K = 1e10 N/m^1.5", "17", "",
               default="13"),
)

# The integrators in the paper's row order and their names there.
INTEGRATORS = (("bdf", "ode15s"), ("dopri5", "ode45"), ("rk4", "RK4"), ("abm", "ABM"))
PAPER_NAME = dict(INTEGRATORS)
FIXED_STEP = 1e-3  # the paper's RK4 / ABM step (section 5.3)

# Paper Tables 9-10 (section 5.5): grids, matrix sizes and Matlab storage of one table.
PAPER_TABLES_9_10 = (  # (method, refined, grid, matrix size, storage)
    ("kec", False, "s from -46.4 to 46.4 mm, step 0.2 mm", "465 x 1", "4 kB"),
    ("kec", True, "s from -46.4 to 46.4 mm, step 0.018 mm", "5001 x 1", "12 kB"),
    ("lut", False, "gauge -5 to 5 mm step 1 mm; y -18 to 18 mm step 0.1 mm", "361 x 11", "25 kB"),
    ("lut", True, "gauge -5 to 5 mm step 1 mm; y -18 to 18 mm step 0.05 mm", "721 x 11",
     "46 kB"),
)


# ---- reading our rows and the paper's ----------------------------------------------------------

def max_step(r: dict) -> float:
    """The largest step of a cost row [s], 0 for none: the max_step_s column, else the
    solver label's "hmax=...ms"."""
    v = num(r.get("max_step_s"))
    if v is not None:
        return v
    m = re.search(r"hmax=([0-9.e+-]+)ms", r.get("solver") or "")
    return float(m.group(1)) * 1e-3 if m else 0.0


def interpolation(r: dict) -> str:
    return r.get("interpolation") or "cubic"


def _same_tol(a, b) -> bool:
    x, y = num(a), num(b)
    return x is not None and y is not None and abs(x - y) <= 1e-9 * abs(y)


def paper_setting(r: dict) -> bool:
    """A row at the paper's section 5.3 settings: fixed steps of 1 ms, adaptive without cap."""
    if r.get("tol"):
        return max_step(r) == 0
    step = num(r.get("step_s"))
    return step is not None and abs(step - FIXED_STEP) < 1e-12


def ours(rows: Sequence[dict], method: str, K: str, integ: str, tol: str, refined: bool,
         interp: Optional[str] = None) -> Optional[dict]:
    """Our case of a model (method, K, refined tables, interpolation) at the paper's setting of
    integ / tol; None when the study has none."""
    for r in rows:
        if (r["method"] == method and (method == "kec" or num(r["K"]) == num(K)) and
                r["integrator"] == integ and paper_setting(r) and
                (r["tol"] == "" if not tol else _same_tol(r["tol"], tol)) and
                r.get("refined_tables", "false") == ("true" if refined else "false") and
                (interp is None or interpolation(r) == interp)):
            return r
    return None


def paper(prows: Sequence[dict], no: str, integ: str, tol: str) -> Optional[dict]:
    """The paper's row of table `no` for our integrator integ at tol."""
    name = PAPER_NAME.get(integ, integ)
    for p in prows:
        if p["table"] == no and p["integrator"] == name and (
                not p["tol"] and not tol or tol and _same_tol(p["tol"], tol)):
            return p
    return None


def paper_cpu(p: Optional[dict]) -> Optional[float]:
    """The paper's CPU time of a row: the median of its five runs (Tables 12-18), else the one
    time it gives (the average: Tables 7, 11)."""
    if p is None or (p.get("status") or "ok") != "ok":
        return None
    v = num(p.get("cpu_median_s"))
    return v if v is not None else num(p.get("cpu_mean_s"))


def paper_evals(p: Optional[dict]) -> Optional[float]:
    if p is None or (p.get("status") or "ok") != "ok":
        return None
    return num(p.get("evaluations"))


def our_cpu(r: Optional[dict]) -> Optional[float]:
    return num(r["cpu_median_s"]) if r is not None and r["status"] == "ok" else None


def our_evals(r: Optional[dict]) -> Optional[float]:
    return float(total_evals(r)) if r is not None and r["status"] == "ok" else None


def tol_text(tol: str) -> str:
    """A tolerance as the paper writes it: 0.0001 -> 1e-4; "" -> the fixed 1 ms step."""
    v = num(tol)
    if v is None:
        return "1 ms step"
    mantissa, _, exponent = f"{v:e}".partition("e")
    return f"{float(mantissa):g}e{int(exponent)}"


def ratio(a: Optional[float], b: Optional[float]) -> str:
    return "–" if a is None or b is None or not b else f"{a / b:.2f}"


# ---- cells -------------------------------------------------------------------------------------

def our_cell(r: Optional[dict], what: str) -> str:
    """CPU time [s] or evaluations of our case; "failed" (with the time reached) or "–"."""
    if r is None:
        return "–"
    if r["status"] != "ok":
        return f"failed at {num(r['t_reached_s'], 0):.2f} s" if what == "cpu" else "failed"
    return f"{num(r['cpu_median_s']):.2f}" if what == "cpu" else str(total_evals(r))


def paper_cell(p: Optional[dict], what: str) -> str:
    if p is None:
        return "–"
    status = p.get("status") or "ok"
    if status != "ok":
        return "failed" if status == "failed" else "–"
    v = paper_cpu(p) if what == "cpu" else paper_evals(p)
    return fmt(v, "{:.2f}" if what == "cpu" else "{:.0f}")


# ---- one paper table beside ours ---------------------------------------------------------------

def settings(spec: PaperTable, rows: Sequence[dict], prows: Sequence[dict]) -> List[Tuple[str, str]]:
    """(integrator, tol) of the paper's rows of the table and of our cases of its model at the
    paper's settings, in the paper's order (per integrator, tightest tolerance first)."""
    found = set()
    for p in prows:
        if p["table"] == spec.no:
            integ = next((o for o, n in INTEGRATORS if n == p["integrator"]), p["integrator"])
            found.add((integ, p["tol"]))
    for r in rows:
        if (r["method"] == spec.method and (spec.method == "kec" or num(r["K"]) == num(spec.K))
                and r.get("refined_tables", "false") == ("true" if spec.refined else "false")
                and paper_setting(r)):
            tol = next((t for i, t in found if i == r["integrator"] and _same_tol(t, r["tol"])),
                       r["tol"])
            found.add((r["integrator"], tol))
    order = {o: k for k, (o, _) in enumerate(INTEGRATORS)}
    return sorted(found, key=lambda s: (order.get(s[0], 9), num(s[1], 0.0)))


def _pair(spec: PaperTable, this, partner):
    """(KEC, LUT) of a table's row and its partner's."""
    return (this, partner) if spec.method == "kec" else (partner, this)


def paper_table(spec: PaperTable, rows: Sequence[dict], prows: Sequence[dict],
                variants: Sequence[Optional[str]]) -> str:
    """Table `spec.no` of the paper beside ours: per quantity, our column (one per table
    interpolation of `variants`; None: whatever the study ran) and the paper's."""
    partner_method = "lut" if spec.method == "kec" else "kec"
    ratio_name = "KEC/LUT" + (f" K={spec.partner_K}" if spec.partner_K else "")

    def ours_label(q: str, v: Optional[str]) -> str:
        return f"{q} ours" + (f" ({v})" if v else "")

    quantities = ["CPU [s]", "evals", f"{ratio_name} CPU", f"{ratio_name} evals"]
    if spec.default:
        quantities.append("refined/default CPU")
    head = ["integrator", "tol"]
    for q in quantities:
        head += [ours_label(q, v) for v in variants] + [f"{q} paper"]
    body = []
    for integ, tol in settings(spec, rows, prows):
        p = paper(prows, spec.no, integ, tol)
        pp = paper(prows, spec.partner, integ, tol)
        pk, pl = _pair(spec, p, pp)
        mine = [(ours(rows, spec.method, spec.K, integ, tol, spec.refined, v),
                 ours(rows, partner_method, spec.partner_K, integ, tol, spec.refined, v))
                for v in variants]
        line = [f"{PAPER_NAME.get(integ, integ)} ({integ})", tol_text(tol)]
        line += [our_cell(r, "cpu") for r, _ in mine] + [paper_cell(p, "cpu")]
        line += [our_cell(r, "evals") for r, _ in mine] + [paper_cell(p, "evals")]
        for get, pget in ((our_cpu, paper_cpu), (our_evals, paper_evals)):
            for r, partner in mine:
                k, lut = _pair(spec, r, partner)
                line.append(ratio(get(k), get(lut)))
            line.append(ratio(pget(pk), pget(pl)))
        if spec.default:
            for (r, _), v in zip(mine, variants):
                d = ours(rows, spec.method, spec.K, integ, tol, False, v)
                line.append(ratio(our_cpu(r), our_cpu(d)))
            line.append(ratio(paper_cpu(p), paper_cpu(paper(prows, spec.default, integ, tol))))
        body.append(line)
    return table(head, body)


def study_variants(rows: Sequence[dict]) -> List[Optional[str]]:
    """The table interpolations of a study, linear (the paper's) first; [None] for one."""
    kinds = sorted({interpolation(r) for r in rows}, key=lambda k: (k != "linear", k))
    return list(kinds) if len(kinds) > 1 else [None]


def paper_table_blocks(outdir: str) -> Dict[str, str]:
    """Blocks paper_table7, paper_table11 ... paper_table18: the paper's table beside ours."""
    prows = paper_rows()
    out = {}
    for spec in PAPER_TABLES:
        rows = read_csv(os.path.join(outdir, spec.study, "study_cost.csv"))
        name = f"paper_table{spec.no}"
        if not rows:
            out[name] = missing(f"out/studies/{spec.study}/study_cost.csv")
            continue
        variants = study_variants(rows)
        note = (f"Paper Table {spec.no} ({spec.title}) beside {spec.study}; CPU: ours the median "
                f"of the repeats (C++), the paper's " +
                ("the one time it gives (the average of five runs, Matlab)" if spec.no in ("7", "11")
                 else "the median of its five runs (Matlab)") +
                "; evals: rhs evaluations incl. finite-difference Jacobian columns.")
        if variants != [None]:
            note += (" Ours with the tables interpolated linearly (the paper's, section 5.5) and "
                     "cubic (our default).")
        out[name] = note + "\n\n" + paper_table(spec, rows, prows, variants)
    return out


# ---- Tables 9-10: the tables before and after refinement ---------------------------------------

def tables_9_10_block(outdir: str) -> str:
    """Paper Tables 9-10 (grid, matrix size, storage of one table) beside the size and build or
    load time our result files record (median over the cases of each kind)."""
    rows = read_csv(os.path.join(outdir, "refinement", "study_cost.csv"))
    if not rows:
        return missing("out/studies/refinement/study_cost.csv")
    kinds = sorted({interpolation(r) for r in rows}, key=lambda k: (k != "linear", k))
    body = []
    for method, refined, grid, size, storage in PAPER_TABLES_9_10:
        for kind in kinds:
            sel = [r for r in rows if r["method"] == method and interpolation(r) == kind and
                   r.get("refined_tables") == ("true" if refined else "false") and
                   num(r.get("table_bytes")) is not None]
            if not sel:
                continue
            nbytes = sorted(num(r["table_bytes"]) for r in sel)[len(sel) // 2]
            times = sorted(num(r.get("table_build_time_s"), 0.0) for r in sel)
            body.append([f"{method.upper()} {'refined' if refined else 'default'}", kind,
                         f"{nbytes / 1e3:.0f} kB", f"{times[len(times) // 2]:.3f} s", grid, size,
                         storage])
    if not body:
        return missing("table_bytes in out/studies/refinement/study_cost.csv")
    return ("Paper Tables 9 (KEC) and 10 (LUT): one table of the paper (its grid, matrix size, "
            "Matlab storage) beside all the tables of one of our runs (every channel of both "
            "wheels and their interpolation coefficients: size and build time, or load time "
            "from the disk cache, as the result files record them; median over the cases):\n\n" +
            table(["tables", "interpolation (ours)", "size ours", "build or load time ours",
                   "grid (paper)", "matrix (paper)", "storage (paper)"], body))


# ---- the flange-loaded matrix beside the paper's ratios -----------------------------------------

def flange_paper_block(outdir: str, study: str = "flange_stiffness") -> str:
    """KEC/LUT ratios of CPU time and evaluations per setting and K on the flange-loaded curve
    beside the paper's (Tables 12-16, its case 3)."""
    rows = read_csv(os.path.join(outdir, study, "study_cost.csv"))
    if not rows:
        return missing(f"out/studies/{study}/study_cost.csv")
    prows = paper_rows()
    by_k = {spec.K: spec.no for spec in PAPER_TABLES if spec.method == "lut" and not spec.refined}
    Ks = sorted({r["K"] for r in rows if r["method"] == "lut" and r["K"]}, key=lambda k: num(k))
    kec = PaperTable("16", study, "kec", "", False, "KEC", "", "")
    body = []
    for integ, tol in settings(kec, rows, prows):
        if integ not in PAPER_NAME:
            continue
        k = ours(rows, "kec", "", integ, tol, False)
        pk = paper(prows, "16", integ, tol)
        for K in Ks:
            lut = ours(rows, "lut", K, integ, tol, False)
            no = next((n for kk, n in by_k.items() if num(kk) == num(K)), None)
            pl = paper(prows, no, integ, tol) if no else None
            body.append([f"{PAPER_NAME[integ]} ({integ})", tol_text(tol), K,
                         ratio(our_cpu(k), our_cpu(lut)), ratio(paper_cpu(pk), paper_cpu(pl)),
                         ratio(our_evals(k), our_evals(lut)),
                         ratio(paper_evals(pk), paper_evals(pl)),
                         our_cell(lut, "evals")])
    return ("KEC/LUT at the paper's section 5.3 settings (adaptive methods without a largest "
            "step), ours on the flange-loaded curve, the paper's on its case 3 (Tables 12-16; "
            "– where the paper has no such row or a run failed):\n\n" +
            table(["integrator", "tol", "LUT K", "KEC/LUT CPU ours", "KEC/LUT CPU paper",
                   "KEC/LUT evals ours", "KEC/LUT evals paper", "LUT evals ours"], body))
