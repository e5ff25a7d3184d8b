#!/usr/bin/env python3
"""Regenerates every run-derived table and figure of docs/ (studies.md, performance.md,
validation.md, hard_cases.md, integrators.md) from the outputs of `./wb studies`: no number that
comes from a run is typed into docs/ by hand.

    /usr/bin/python3 plots/update_docs.py OUT_DIR [--build BUILD_DIR] [--docs DOCS_DIR]

OUT_DIR holds one folder per study (efficiency_case3, flange_stiffness, refinement,
work_precision, effects, speed, each with the study_*.csv / *.png of plot_study.py; validation,
with the validation_*.csv of plots/validation_tables.py), bench_wagon.json (Google Benchmark,
one wagon evaluation and its parts) and bench_integrators.json (the integrators' overhead). BUILD_DIR/hard/hard_cases.csv is the hard-case suite's
record; BUILD_DIR/dynamics/coupling_*.csv (written by the coupling refinement tests of
test_dynamics and test_dynamics_long) feed the block of docs/contact_dynamics.md, which is left
as it is when they are missing and can be regenerated alone:

    /usr/bin/python3 plots/update_docs.py - --build BUILD_DIR --only contact_dynamics

Every generated block sits between the markers

    <!-- generated: NAME (plots/update_docs.py) -->
    ...
    <!-- end: NAME -->

in the markdown files: the text around them is written by hand and is kept; a block whose input
is missing is replaced by a line saying so (never by stale numbers). Every other block starts
with a stamp naming the git commit (and date) its runs were made with, from the provenance
records written when the runs were made (OUT_DIR/<study>/provenance.json and
OUT_DIR/<benchmark>.provenance.json by `./wb studies`, the `commit` column of hard_cases.csv by
tests/hard/hard_cases.py; plots/provenance.py); runs of a tree with uncommitted changes are
stamped as such. Figures are copied to docs/figures/<study>_<name>.png.
"""
import argparse
import csv
import json
import os
import re
import shutil
import sys
from typing import Dict, List, Optional

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import provenance  # noqa: E402

def read_csv(path: str) -> List[dict]:
    if not os.path.exists(path):
        return []
    with open(path, newline="") as f:
        return list(csv.DictReader(row for row in f if not row.startswith("#")))


def num(v, default=None) -> Optional[float]:
    try:
        x = float(v)
        return x
    except (TypeError, ValueError):
        return default


def fmt(x, spec="{:.3g}", empty="–") -> str:
    return empty if x is None else spec.format(x)


def table(header: List[str], rows: List[List[str]]) -> str:
    out = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    out += ["| " + " | ".join(str(c) for c in r) + " |" for r in rows]
    return "\n".join(out)


BLOCK_RE = re.compile(r"<!-- generated: ([\w.-]+) \(plots/update_docs\.py\) -->\n(.*?)<!-- end: \1 -->",
                      re.S)
NOT_GENERATED = "*Not generated: "


def replace_block(text: str, name: str, body: str, stamp: str = "") -> str:
    """Replaces the block NAME by body, with the stamp line first (not for a "Not generated"
    line: nothing was run)."""
    start = f"<!-- generated: {name} (plots/update_docs.py) -->"
    end = f"<!-- end: {name} -->"
    pat = re.compile(re.escape(start) + r".*?" + re.escape(end), re.S)
    if not pat.search(text):
        raise KeyError(f"marker '{name}' not found")
    body = body.strip()
    if stamp and not body.startswith(NOT_GENERATED):
        body = stamp + "\n\n" + body
    return pat.sub(lambda _: start + "\n" + body + "\n" + end, text)


def doc_blocks(text: str) -> Dict[str, str]:
    """The generated blocks of a page: name -> content between the markers."""
    return {m.group(1): m.group(2) for m in BLOCK_RE.finditer(text)}


def missing(what: str) -> str:
    return NOT_GENERATED + f"{what} is missing. Run `./wb studies` (see the top of this page).*"


# ---- efficiency (paper Tables 7, 12-16) --------------------------------------------------------

PAPER_INTEGRATOR = {"dopri5": "ode45", "bdf": "ode15s", "rk4": "RK4", "abm": "ABM"}


def solver_setting(r: dict) -> str:
    if r.get("tol"):
        return f"{r['integrator']} {r['tol']}"
    if r.get("step_s"):
        return f"{r['integrator']} {num(r['step_s']) * 1e3:g} ms"
    return r.get("integrator", "")


def paper_rows() -> List[dict]:
    here = os.path.dirname(os.path.abspath(__file__))
    return read_csv(os.path.join(here, "..", "docs", "data", "paper_efficiency.csv"))


def paper_lookup(paper, method, K, tables, integrator, tol) -> Optional[dict]:
    pi = PAPER_INTEGRATOR.get(integrator, integrator)
    for p in paper:
        if (p["method"] == method and p["integrator"] == pi and p["tables"] == tables and
                (method == "kec" or num(p["flange_stiffness"]) == num(K)) and
                (not p["tol"] or num(p["tol"]) == num(tol))):
            return p
    return None


def total_evals(r: dict) -> int:
    """rhs evaluations including the finite-difference Jacobian columns (Matlab's ode15s counts
    its numjac evaluations in nfevals too)."""
    return int(r["rhs_evals"]) + int(r.get("rhs_evals_jac") or 0)


def cost_cell(r: Optional[dict], sim: float) -> str:
    if r is None:
        return "–"
    if r["status"] != "ok":
        return "failed"
    cpu = num(r["cpu_median_s"])
    return f"{cpu:.2f} s / {total_evals(r)} ({sim / cpu:.0f}x)"


def efficiency_block(outdir: str, study: str = "efficiency_case3",
                     name: str = "efficiency") -> Dict[str, str]:
    rows = read_csv(os.path.join(outdir, study, "study_cost.csv"))
    if not rows:
        return {name: missing(f"out/studies/{study}/study_cost.csv"),
                name + "_paper": missing(f"out/studies/{study}/study_cost.csv")}
    sim = max(num(r["t_reached_s"], 0) for r in rows)
    models = [("kec", "")] + [("lut", k) for k in sorted({r["K"] for r in rows if r["K"]},
                                                         key=lambda k: num(k))]
    settings = []
    for r in rows:
        s = solver_setting(r)
        if s not in settings:
            settings.append(s)
    order = {"rk4": 0, "abm": 1, "dopri5": 2, "bdf": 3, "ida": 4}
    settings.sort(key=lambda s: (order.get(s.split()[0], 9), s))

    def find(method, K, s):
        for r in rows:
            if r["method"] == method and (method == "kec" or r["K"] == K) and \
                    solver_setting(r) == s:
                return r
        return None

    head = ["solver"] + [("KEC" if m == "kec" else f"LUT K={k}") for m, k in models]
    body = [[s] + [cost_cell(find(m, k, s), sim) for m, k in models] for s in settings]
    eff = (f"CPU time (median of the repeats) / rhs evaluations incl. finite-difference Jacobian "
           f"columns (x real time over {sim:.2f} s simulated):\n\n" + table(head, body))

    # Beside the paper: evaluation counts directly, CPU times as LUT/KEC ratios.
    paper = paper_rows()
    prow = []
    for s in settings:
        integ, _, tol = s.partition(" ")
        tol = tol if not tol.endswith("ms") else ""
        kec = find("kec", "", s)
        pk = paper_lookup(paper, "kec", "", "default", integ, tol)
        for m, k in models[1:]:
            lut = find(m, k, s)
            pl = paper_lookup(paper, "lut", k, "default", integ, tol)
            if lut is None:
                continue
            ours_ratio = (num(lut["cpu_median_s"]) / num(kec["cpu_median_s"])
                          if kec and lut["status"] == "ok" and kec["status"] == "ok" else None)
            paper_ratio = (num(pl["cpu_median_s"]) / num(pk["cpu_median_s"])
                           if pl and pk else None)
            prow.append([s, k, total_evals(lut) if lut["status"] == "ok" else "failed",
                         pl["evaluations"] if pl else "–",
                         total_evals(kec) if kec and kec["status"] == "ok" else "–",
                         pk["evaluations"] if pk else "–",
                         fmt(ours_ratio, "{:.2f}"), fmt(paper_ratio, "{:.2f}")])
    paper_tab = table(["solver", "LUT K", "LUT evals (ours)", "LUT evals (paper)",
                       "KEC evals (ours)", "KEC evals (paper)", "CPU LUT/KEC (ours)",
                       "CPU LUT/KEC (paper)"], prow)
    return {name: eff, name + "_paper": paper_tab}


# ---- accuracy (paper Eq. 33, Table 8) ----------------------------------------------------------

def accuracy_block(outdir: str, study: str = "efficiency_case3") -> str:
    rows = read_csv(os.path.join(outdir, study, "study_accuracy_lut_vs_kec.csv"))
    rows = [r for r in rows if r.get("wheelset") == "all"]
    if not rows:
        return missing(f"out/studies/{study}/study_accuracy_lut_vs_kec.csv")
    Ks = sorted({r["K"] for r in rows}, key=lambda k: num(k))
    solvers = []
    for r in rows:
        if r["solver"] not in solvers:
            solvers.append(r["solver"])
    body = []
    for s in solvers:
        line = [s]
        for k in Ks:
            r = next((x for x in rows if x["solver"] == s and x["K"] == k), None)
            if r is None or not r["max_abs_mm"]:
                line.append("–")
            else:
                flag = "" if r["lut_status"] == "ok" and r["kec_status"] == "ok" else " (failed run)"
                line.append(f"{num(r['max_abs_mm']):.3f} / {num(r['mean_abs_mm']):.3f}{flag}")
        body.append(line)
    return ("max / mean |y_KEC - y_LUT| [mm] over all four wheelsets and the whole run:\n\n" +
            table(["solver"] + [f"K={k}" for k in Ks], body))


# ---- refinement (paper Tables 9-11, 17-18) -----------------------------------------------------

def refinement_block(outdir: str) -> str:
    rows = read_csv(os.path.join(outdir, "refinement", "study_cost.csv"))
    if not rows:
        return missing("out/studies/refinement/study_cost.csv")
    sim = max(num(r["t_reached_s"], 0) for r in rows)
    keys = []
    for r in rows:
        k = (r["method"], r["K"], solver_setting(r))
        if k not in keys:
            keys.append(k)
    body = []
    for method, K, s in keys:
        d = next((r for r in rows if (r["method"], r["K"], solver_setting(r)) == (method, K, s)
                  and r["refined_tables"] == "false"), None)
        f = next((r for r in rows if (r["method"], r["K"], solver_setting(r)) == (method, K, s)
                  and r["refined_tables"] == "true"), None)
        ratio = (num(f["cpu_median_s"]) / num(d["cpu_median_s"])
                 if d and f and d["status"] == "ok" and f["status"] == "ok" else None)
        body.append([method.upper() + (f" K={K}" if K else ""), s, cost_cell(d, sim),
                     cost_cell(f, sim), fmt(ratio, "{:.2f}")])
    builds = []
    for method in ("kec", "lut"):
        for ref in ("false", "true"):
            r = next((x for x in rows if x["method"] == method and x["refined_tables"] == ref
                      and x["table_build_time_s"]), None)
            if r:
                builds.append([method.upper(), "refined" if ref == "true" else "default",
                               f"{num(r['table_build_time_s']):.3f} s",
                               f"{num(r['table_bytes']) / 1e6:.2f} MB"])
    return (table(["model", "solver", "default tables", "refined tables", "CPU refined/default"],
                  body) + "\n\nContact tables (as recorded in the result files; a run that "
                  "loaded them from the disk cache records the load time):\n\n" +
            table(["method", "tables", "build or load time", "size"], builds))


# ---- work precision ----------------------------------------------------------------------------

def work_precision_block(outdir: str) -> str:
    rows = read_csv(os.path.join(outdir, "work_precision", "study_work_precision.csv"))
    if not rows:
        return missing("out/studies/work_precision/study_work_precision.csv")
    total = [r for r in rows if r["against"] == "reference"]
    out = []
    special = [r for r in total if r["kind"] in ("reference_check", "table_error")]
    if special:
        out.append("Reference quality (max error of wheelset y [mm] / yaw [mrad] / normal force "
                   "[kN]):\n")
        out.append(table(["model", "what", "y", "yaw", "Q"],
                         [[r["model"], r["kind"].replace("_", " "),
                           r.get("y_max_mm", ""), r.get("yaw_max_mrad", ""),
                           r.get("Q_max_kN", "")] for r in special]))
    # The cheapest setting per integrator setting that reaches each accuracy level in wheelset y:
    # total error (against the refined-table reference) and integration error only (against
    # the reference on the cases' own tables).
    levels = [1.0, 0.1, 0.01, 0.001]
    for against, what in (("reference", "total error against the refined-table reference"),
                          ("reference_same_tables", "integration error only: against the "
                           "reference on the same (default) tables")):
        cases = [r for r in rows if r["against"] == against and r["kind"] == "case"]
        if not cases:
            continue
        def group(r):  # the model and the integrator setting apart from tolerance / step
            return r["model"], re.sub(r"\b(tol|h)=\S+\s*", "", r["solver"]).strip()

        groups = []
        for r in cases:
            if group(r) not in groups:
                groups.append(group(r))
        body = []
        for g in sorted(groups):
            line = list(g)
            for lev in levels:
                best = None
                for r in cases:
                    if group(r) != g or r["status"] != "ok":
                        continue
                    e = num(r.get("y_max_mm"))
                    if e is not None and e <= lev:
                        cpu = num(r["cpu_median_s"])
                        if best is None or cpu < best[0]:
                            best = (cpu, r["setting"])
                line.append("–" if best is None else f"{best[0]:.2f} s ({best[1]})")
            body.append(line)
        out.append(f"\nCheapest setting that keeps the largest error of the wheelsets' lateral "
                   f"displacement below each level ({what}; CPU seconds, setting; – = no setting "
                   f"of the study gets there):\n")
        out.append(table(["model", "integrator"] + [f"y err <= {lev:g} mm" for lev in levels],
                         body))
    return "\n".join(out)


# ---- effects -----------------------------------------------------------------------------------

def effects_block(outdir: str) -> str:
    rows = read_csv(os.path.join(outdir, "effects", "study_effects.csv"))
    if not rows:
        return missing("out/studies/effects/study_effects.csv")
    instr = read_csv(os.path.join(outdir, "effects", "study_effects_instructions.csv"))

    def strip(label: str) -> str:
        return re.sub(r"\b(kec|lut)\b", "", label, flags=re.I).strip(" ,")

    labels = []
    for r in rows:
        if strip(r["label"]) not in labels:
            labels.append(strip(r["label"]))

    def time_cell(method, lab):
        for r in rows:
            if r["method"] == method and strip(r["label"]) == lab:
                if not r["us_per_eval"]:
                    return "failed"
                return (f"{num(r['us_per_eval']):.2f} µs ({num(r['relative_to_baseline']):.2f}, "
                        f"±{r['spread_percent'] or '?'} %)")
        return "–"

    def instr_cell(method, lab):
        for r in instr:
            if r["method"] == method and strip(r["label"]) == lab:
                if not r["instructions_per_eval"]:
                    return "failed"
                return (f"{num(r['instructions_per_eval']) / 1e3:.1f}k "
                        f"({num(r['relative_to_baseline']):.3f})")
        return "–"

    head = ["variant", "KEC instructions / eval (rel.)", "LUT instructions / eval (rel.)",
            "KEC CPU / eval (rel., spread)", "LUT CPU / eval (rel., spread)"]
    body = [[lab, instr_cell("kec", lab), instr_cell("lut", lab), time_cell("kec", lab),
             time_cell("lut", lab)] for lab in labels]
    note = ("" if instr else "\n\n" + missing("out/studies/effects/study_effects_instructions.csv "
                                               "(plots/effects_instructions.py)"))
    return ("Per right-hand-side evaluation, each variant relative to the full model: callgrind "
            "instructions (repeatable; first 8 s of the run, integration only, "
            "`plots/effects_instructions.py`) and CPU time (median of 5 repeats over the whole "
            "run, ABM 0.25 ms, free spin; spread = (max - min) / median):\n\n" +
            table(head, body) + note)


# ---- speed targets -----------------------------------------------------------------------------

def speed_block(outdir: str) -> str:
    rows = read_csv(os.path.join(outdir, "speed", "study_cost.csv"))
    if not rows:
        return missing("out/studies/speed/study_cost.csv")
    body = []
    for r in rows:
        sim = num(r["t_reached_s"], 0)
        cpu = num(r["cpu_median_s"])
        ok = r["status"] == "ok"
        factor = sim / cpu if ok and cpu else None
        target = ("100x" if "target 1" in r["label"] else "1x" if "target 2" in r["label"]
                  else "")
        met = ""
        if target and factor is not None:
            met = "met" if factor >= float(target[:-1]) else "NOT met"
        body.append([r["label"], r["status"], f"{cpu:.3f} s ({r['cpu_min_s']}-{r['cpu_max_s']})",
                     fmt(factor, "{:.1f}x"), r["rhs_evals"], r["rhs_evals_jac"] or "0",
                     r["steps"], fmt(num(r["us_per_eval"]), "{:.2f}"), target, met])
    return table(["case", "status", "CPU median (min-max)", "x real time", "rhs evals",
                  "Jacobian evals", "steps", "µs / eval", "target", ""], body)


def bench_block(outdir: str) -> str:
    path = os.path.join(outdir, "bench_wagon.json")
    if not os.path.exists(path):
        return missing("out/studies/bench_wagon.json")
    with open(path) as f:
        data = json.load(f)
    body = []
    for b in data.get("benchmarks", []):
        if b.get("run_type") == "aggregate" and b.get("aggregate_name") not in ("median", "cv"):
            continue
        if b.get("aggregate_name") == "cv":
            continue
        name = b.get("run_name", b["name"])
        if "us_per_eval" in b:  # bench_wagon's counter: CPU microseconds per evaluation
            body.append([name, f"{b['us_per_eval']:.2f}"])
        else:
            unit = b.get("time_unit", "ns")
            scale = {"ns": 1e-3, "us": 1.0, "ms": 1e3, "s": 1e6}[unit]
            body.append([name, f"{b['cpu_time'] * scale:.3f}"])
    ctx = data.get("context", {})
    return (f"Google Benchmark on {ctx.get('host_name', '?')}, {ctx.get('num_cpus', '?')} CPUs at "
            f"{ctx.get('mhz_per_cpu', '?')} MHz, {ctx.get('date', '')}:\n\n" +
            table(["benchmark (median of the repetitions)", "CPU µs per evaluation"], body))


def bench_integrators_block(outdir: str) -> str:
    """docs/integrators.md: bench/bench_integrators (the integrators' overhead per step)."""
    path = os.path.join(outdir, "bench_integrators.json")
    if not os.path.exists(path):
        return missing("out/studies/bench_integrators.json")
    with open(path) as f:
        data = json.load(f)
    body = []
    for b in data.get("benchmarks", []):
        if b.get("run_type") == "aggregate" and b.get("aggregate_name") != "median":
            continue
        name = b.get("run_name", b["name"])
        if "ns/step" in b:
            body.append([name, f"{b['ns/step']:.0f}", f"{b.get('rhs/step', 0):.2f}",
                         f"{b.get('overhead_ns', 0):.0f}", f"{b.get('steps', 0):.0f}"])
        else:  # BM_rhs: the cost of one right-hand side
            unit = b.get("time_unit", "ns")
            scale = {"ns": 1.0, "us": 1e3, "ms": 1e6, "s": 1e9}[unit]
            body.append([name, "–", "–", "–", f"rhs {b['cpu_time'] * scale:.0f} ns"])
    ctx = data.get("context", {})
    return (f"Google Benchmark on {ctx.get('host_name', '?')}, {ctx.get('num_cpus', '?')} CPUs at "
            f"{ctx.get('mhz_per_cpu', '?')} MHz, {ctx.get('date', '')} (median of the "
            f"repetitions):\n\n" +
            table(["benchmark", "ns / step", "rhs / step", "overhead ns / step",
                   "steps (or rhs cost)"], body))


# ---- hard cases --------------------------------------------------------------------------------

def hard_block(build: str) -> str:
    rows = read_csv(os.path.join(build, "hard", "hard_cases.csv"))
    if not rows:
        return missing(f"{build}/hard/hard_cases.csv (ctest -L hard)")
    body = []
    for r in rows:
        cpu = num(r["cpu_s"])
        evals = int(num(r["rhs_evals"], 0)) + int(num(r["rhs_evals_jac"], 0))
        reason = (r["message"] or "")[:90].replace("|", "/")
        body.append([r["case"], r["combination"], r["status"], r["verdict"],
                     f"{num(r['t_reached'], 0):.2f} / {num(r['t_end'], 0):.2f}",
                     fmt(cpu, "{:.2f}"), str(evals), fmt(num(r["max_abs_y_mm"]), "{:.2f}"),
                     fmt(num(r["max_abs_yq"]), "{:.2f}"), reason])
    return table(["case", "combination", "status", "test", "t reached / end [s]", "CPU [s]",
                  "rhs evals", "max abs y [mm]", "max abs Y/Q", "failure"], body)


def hard_rows(build: str) -> List[dict]:
    return read_csv(os.path.join(build, "hard", "hard_cases.csv"))


def failure_reason(msg: str) -> str:
    """The short reason of a failure message ("rk4: failed at t = 1.8: <reason>; details")."""
    if "left the table" in msg:
        return ("the LUT entry" if "LUT entry" in msg else "the contact") + " left the table"
    m = re.search(r"failed at t = [^:]+: (.*)", msg)
    reason = re.split(r"[:;(\[]", m.group(1) if m else msg)[0].strip()
    return reason[:60].replace("|", "/") or "?"


def hard_detail_block(build: str) -> str:
    """docs/hard_cases.md: every combination with steps, flange loads and the hunting measures,
    and the suite's verdict in one line."""
    rows = hard_rows(build)
    if not rows:
        return missing(f"{build}/hard/hard_cases.csv (ctest -L hard)")
    body = []
    for r in rows:
        status = r["status"] or "error"
        if status == "failed":
            status = "failed: " + failure_reason(r["message"] or "")
        extra = []
        if r["case"].startswith("hunting"):  # the hunting measures mean nothing elsewhere
            if r.get("ws1_y_pp_last_mm") not in (None, "", "nan"):
                extra.append(f"ws1 p-p last s {num(r['ws1_y_pp_last_mm']):.1f} mm")
            extra.append("onset " + ("none" if r.get("onset_speed") in (None, "", "nan")
                                     else f"{num(r['onset_speed']):.1f} m/s"))
        body.append([r["case"], r["combination"], status, r["verdict"],
                     fmt(num(r["t_reached"]), "{:.3f}"), fmt(num(r["cpu_s"]), "{:.2f}"),
                     f"{int(num(r['rhs_evals'], 0))} (+{int(num(r['rhs_evals_jac'], 0))})",
                     f"{int(num(r['steps'], 0))} ({int(num(r['rejected_steps'], 0))})",
                     fmt(num(r["max_abs_y_mm"]), "{:.2f}"),
                     f"{fmt(num(r.get('max_flange_kN')), '{:.0f}')} / "
                     f"{fmt(num(r.get('max_normal_flange_kN')), '{:.0f}')}",
                     fmt(num(r.get("flange_time_share")), "{:.2f}"),
                     fmt(num(r.get("max_indent_mm")), "{:.4f}"),
                     fmt(num(r["max_abs_yq"]), "{:.2f}"), ", ".join(extra)])
    n = len(rows)
    passed = sum(1 for r in rows if r["verdict"] == "pass")
    finished = sum(1 for r in rows if r["status"] == "ok")
    verdict = (f"{n} combinations: {passed} pass the suite's checks, {n - passed} fail them; "
               f"{finished} finished, {n - finished} stopped with the clean failure (exit 2) "
               f"or worse (see `test`).")
    return (verdict + "\n\n" +
            table(["case", "combination", "result", "test", "t reached [s]", "CPU [s]",
                   "rhs evals (+FD Jac)", "steps (rejected)", "max abs y [mm]",
                   "max flange N [kN] (LUT Hertz / flange patch)", "flange share",
                   "max indent [mm]", "max abs Y/Q", "hunting"], body))


# ---- validation (paper section 5.2, Tables 5 and 6; docs/validation.md) -----------------------

def paper_validation() -> List[dict]:
    here = os.path.dirname(os.path.abspath(__file__))
    return read_csv(os.path.join(here, "..", "docs", "data", "paper_validation.csv"))


def _y_psi(r: Optional[dict], key_y="y_mm", key_p="yaw_mrad") -> str:
    if r is None:
        return "–"
    cell = f"{num(r[key_y]):.3f} / {num(r[key_p]):.3f}"
    return cell + (" (failed run)" if r.get("status", "ok") != "ok" else "")


def validation_blocks(outdir: str) -> Dict[str, str]:
    d = os.path.join(outdir, "validation")
    steady = read_csv(os.path.join(d, "validation_steady.csv"))
    paper = paper_validation()
    out = {}

    def ours(case, radius, method, body):
        return next((r for r in steady if r["case"] == str(case) and r["radius_m"] == radius
                     and r["method"] == method and r["body"] == body), None)

    def theirs(case, radius, source, body):
        return next((p for p in paper if p["case"] == str(case) and p["radius_m"] == radius
                     and p["source"] == source and p["body"] == body), None)

    head = ["KEC (ours) y / psi", "LUT (ours) y / psi", "KEC (paper)", "LUT (paper)",
            "UM (paper)"]
    case1 = [r for r in steady if r["case"] == "1"]
    if case1:
        radii = sorted({r["radius_m"] for r in case1}, key=lambda x: num(x, 0))
        body = [[R] + [_y_psi(ours(1, R, m, "ws")) for m in ("kec", "lut")] +
                [_y_psi(theirs(1, R, src, "ws")) for src in ("KEC", "LUT", "UM")]
                for R in radii]
        out["validation_case1"] = (f"Mean over {case1[0]['window']} (y in mm, psi in mrad; "
                                   f"paper: Table 5):\n\n" + table(["R [m]"] + head, body))
    else:
        out["validation_case1"] = missing("out/studies/validation/validation_steady.csv")
    case2 = [r for r in steady if r["case"] == "2"]
    if case2:
        names = []
        for r in case2:
            if r["body"] not in names:
                names.append(r["body"])
        body = [[b] + [_y_psi(ours(2, "", m, b)) for m in ("kec", "lut")] +
                [_y_psi(theirs(2, "500", src, b)) for src in ("KEC", "LUT", "UM")]
                for b in names]
        out["validation_case2"] = (f"Mean over {case2[0]['window']} (y in mm, psi in mrad; "
                                   f"paper: Table 6):\n\n" + table(["body"] + head, body))
    else:
        out["validation_case2"] = missing("out/studies/validation/validation_steady.csv")

    c3 = read_csv(os.path.join(d, "validation_case3.csv"))
    if c3:
        body = []
        for r in c3:
            flag = "" if r["kec_status"] == "ok" and r["lut_status"] == "ok" else " (failed run)"
            body.append([r["solver"], r["wheelset"],
                         f"{num(r['eq33_max_percent']):.1f} %{flag}",
                         f"{num(r['eq33_mean_percent']):.1f} %",
                         f"{num(r['max_abs_y_lut_mm']):.2f}"])
        out["validation_case3"] = ("Eq. (33) difference of the wheelsets' lateral displacement, "
                                   "KEC against LUT with the same solver, relative to max "
                                   "|y_LUT|:\n\n" +
                                   table(["solver", "wheelset", "max", "mean",
                                          "max abs y_LUT [mm]"], body))
    else:
        out["validation_case3"] = missing("out/studies/validation/validation_case3.csv")

    cost = read_csv(os.path.join(d, "validation_cost.csv"))
    if cost:
        body = []
        for r in cost:
            case = "1, R = " + r["radius_m"] + " m" if r["radius_m"] else r["case"]
            ok = r["status"] == "ok"
            cpu = (f"{num(r['cpu_median_s']):.3f} ({num(r['cpu_min_s']):.3f}-"
                   f"{num(r['cpu_max_s']):.3f})" if ok else r["status"] or "error")
            body.append([case, r["method"].upper(), r["solver"], fmt(num(r["t_reached_s"]),
                                                                       "{:.2f}"),
                         cpu, fmt(num(r["real_time_factor"]), "{:.1f}x"),
                         f"{int(num(r['rhs_evals'], 0))} (+{int(num(r['rhs_evals_jac'], 0))})",
                         f"{int(num(r['steps'], 0))} ({int(num(r['rejected_steps'], 0))})"])
        out["validation_cost"] = ("CPU time of the integration (`/stats`, median (min-max) of "
                                  "the repeats, one case at a time), real-time factor = "
                                  "simulated / CPU time:\n\n" +
                                  table(["case", "method", "solver", "simulated [s]",
                                         "CPU [s]", "x real time", "rhs evals (+FD Jac)",
                                         "steps (rejected)"], body))
    else:
        out["validation_cost"] = missing("out/studies/validation/validation_cost.csv")
    return out


# ---- provenance ---------------------------------------------------------------------------------

# Where the runs behind each block were recorded: a study folder of OUT_DIR, a benchmark
# (BENCH_OUTPUTS) or "hard" (the hard-case record). A block not listed here is stamped from
# OUT_DIR/provenance.json (the `./wb studies` invocation).
BLOCK_SOURCES = {
    "efficiency": "efficiency_case3", "efficiency_paper": "efficiency_case3",
    "accuracy": "efficiency_case3", "flange": "flange_stiffness",
    "flange_paper": "flange_stiffness", "flange_accuracy": "flange_stiffness",
    "refinement": "refinement", "work_precision": "work_precision", "hard_cases": "hard",
    "hard_cases_detail": "hard", "effects": "effects", "speed": "speed", "bench": "bench",
    "bench_integrators": "bench_integrators",
    "validation_case1": "validation", "validation_case2": "validation",
    "validation_case3": "validation", "validation_cost": "validation",
    "coupling_convergence": "build",
}


# Benchmark sources: their JSON output (and provenance record) in OUT_DIR.
BENCH_OUTPUTS = {"bench": "bench_wagon", "bench_integrators": "bench_integrators"}


def block_provenance(name: str, outdir: str, build: str) -> List[dict]:
    src = BLOCK_SOURCES.get(name)
    if src == "build":  # written by the tests of the build tree now being documented
        return [provenance.current()]
    if src == "hard":
        seen = []
        for r in hard_rows(build):
            e = provenance.from_tag(r.get("commit") or "", r.get("run_date") or "")
            if not r.get("commit"):
                return []  # a record from before the suite wrote its commit: unknown
            if e not in seen:
                seen.append(e)
        return seen
    if src in BENCH_OUTPUTS:
        return provenance.read(os.path.join(outdir, BENCH_OUTPUTS[src] + ".provenance.json"))
    if src:
        return provenance.read(os.path.join(outdir, src, "provenance.json"))
    return provenance.read(os.path.join(outdir, "provenance.json"))


# ---- normal-force coupling (docs/contact_dynamics.md section 4.1) -------------------------------

COUPLING_CASES = (  # (csv under BUILD/dynamics, what it is, where it comes from)
    ("coupling_case3", "case 3 (wagon, 20 m/s, R = 500 m, ORE B176 low, KEC), first 9 s",
     "test_dynamics, Coupling.StepHalvingConvergesWithTheDefaultCoupling"),
)


def source_commit() -> str:
    """The commit of the source tree the numbers were generated in (with '+ uncommitted changes'
    when tracked files outside docs/ differ from it)."""
    import subprocess
    root = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
    try:
        head = subprocess.run(["git", "-C", root, "rev-parse", "--short", "HEAD"], check=True,
                              capture_output=True, text=True).stdout.strip()
        dirty = subprocess.run(["git", "-C", root, "status", "--porcelain", "--untracked-files=no",
                                "--", ".", ":!docs"],
                               check=True, capture_output=True, text=True).stdout.strip()
    except (OSError, subprocess.CalledProcessError):
        return "unknown commit"
    return f"commit {head}" + (" + uncommitted changes" if dirty else "")


def coupling_block(build: str) -> Optional[str]:
    """Step-halving differences of RK4 with both couplings and their cost per evaluation, from the
    CSVs the tests write; None when no CSV exists."""
    parts = []
    for name, what, src in COUPLING_CASES:
        path = os.path.join(build, "dynamics", name + ".csv")
        rows = read_csv(path)
        if not rows:
            continue
        body = []
        for r in rows:
            d = num(r["diff_to_half_step_mm"])
            it = num(r["iterations_per_solve"])
            body.append([r["coupling"], f"{num(r['step_ms']):g}",
                         fmt(d, "{:.2g}") if d is not None else "–",
                         f"{num(r['cpu_s']):.2f}", r["rhs_evals"], f"{num(r['us_per_rhs']):.1f}",
                         fmt(it, "{:.2f}") if it else "–"])
        parts.append(f"**{what}** ({src}):\n\n" + table(
            ["coupling", "RK4 step h [ms]", "d(h) [mm]", "CPU [s]", "rhs evals",
             "µs / rhs", "Phi evaluations per wheelset solve"], body))
    if not parts:
        return None
    return (f"From `{build}/dynamics/coupling_*.csv`:\n\n" + "\n\n".join(parts))


# ---- figures -----------------------------------------------------------------------------------

STUDIES = ("efficiency_case3", "flange_stiffness", "refinement", "work_precision", "effects",
           "speed", "validation")


def copy_figures(outdir: str, docs: str, pages) -> List[str]:
    """Copies the figures the pages show (`figures/<study>_<name>.png`, from
    OUT/<study>/study_<name>.png) and nothing else."""
    figdir = os.path.join(docs, "figures")
    os.makedirs(figdir, exist_ok=True)
    wanted = set()
    for md in pages:
        path = os.path.join(docs, md)
        if os.path.exists(path):
            with open(path) as f:
                wanted.update(re.findall(r"figures/([\w.+-]+\.png)", f.read()))
    copied = []
    for name in sorted(wanted):
        study = next((st for st in STUDIES if name.startswith(st + "_")), None)
        if study is None:
            continue
        src = os.path.join(outdir, study, "study_" + name[len(study) + 1:])
        if os.path.exists(src):
            dst = os.path.join(figdir, name)
            shutil.copyfile(src, dst)
            copied.append(dst)
        else:
            print(f"update_docs: {src} missing (figure {name} not updated)", file=sys.stderr)
    return copied


# ---- the pages ---------------------------------------------------------------------------------

def generate(outdir: str, build: str) -> Dict[str, Dict[str, str]]:
    """Every generated block of docs/: page -> block name -> content (without the stamp)."""
    blocks: Dict[str, Dict[str, str]] = {"studies.md": {}, "performance.md": {},
                                         "validation.md": {}, "hard_cases.md": {},
                                         "integrators.md": {}}
    blocks["studies.md"].update(efficiency_block(outdir))
    blocks["studies.md"]["accuracy"] = accuracy_block(outdir)
    blocks["studies.md"].update(efficiency_block(outdir, "flange_stiffness", "flange"))
    blocks["studies.md"]["flange_accuracy"] = accuracy_block(outdir, "flange_stiffness")
    blocks["studies.md"]["refinement"] = refinement_block(outdir)
    blocks["studies.md"]["work_precision"] = work_precision_block(outdir)
    blocks["studies.md"]["hard_cases"] = hard_block(build)
    blocks["performance.md"]["effects"] = effects_block(outdir)
    blocks["performance.md"]["speed"] = speed_block(outdir)
    blocks["performance.md"]["bench"] = bench_block(outdir)
    blocks["validation.md"].update(validation_blocks(outdir))
    blocks["hard_cases.md"]["hard_cases_detail"] = hard_detail_block(build)
    blocks["integrators.md"]["bench_integrators"] = bench_integrators_block(outdir)
    coupling = coupling_block(build)
    blocks["contact_dynamics.md"] = {"coupling_convergence": coupling if coupling is not None
                                     else missing(f"{build}/dynamics/coupling_*.csv "
                                                  "(ctest -R Coupling, test_dynamics)")}
    return blocks


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("outdir")
    ap.add_argument("--build", default="build")
    ap.add_argument("--docs", default=os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                                   "..", "docs"))
    ap.add_argument("--only", choices=("contact_dynamics",),
                    help="regenerate only the blocks of docs/NAME.md (inputs from --build, no "
                         "studies needed)")
    ap.add_argument("--pages", nargs="+", metavar="PAGE",
                    help="rewrite only these pages (e.g. validation.md hard_cases.md) after a "
                         "partial ./wb studies run; the other pages keep their blocks")
    a = ap.parse_args(argv)
    coupling = coupling_block(a.build)
    if a.only == "contact_dynamics":
        if coupling is None:
            print(f"update_docs: no {a.build}/dynamics/coupling_*.csv (run test_dynamics)",
                  file=sys.stderr)
            return 1
        path = os.path.join(a.docs, "contact_dynamics.md")
        with open(path) as f:
            text = replace_block(f.read(), "coupling_convergence", coupling,
                                 provenance.stamp([provenance.current()]))
        with open(path, "w") as f:
            f.write(text)
        print(f"updated {path}")
        return 0
    blocks = generate(a.outdir, a.build)
    if a.pages:
        unknown = [p for p in a.pages if p not in blocks]
        if unknown:
            print(f"update_docs: no generated page {unknown} (pages: {sorted(blocks)})",
                  file=sys.stderr)
            return 1
        blocks = {md: items for md, items in blocks.items() if md in a.pages}
    for md, items in blocks.items():
        path = os.path.join(a.docs, md)
        with open(path) as f:
            text = f.read()
        for name, body in items.items():
            stamp = provenance.stamp(block_provenance(name, a.outdir, a.build))
            try:
                text = replace_block(text, name, body, stamp)
            except KeyError as e:
                print(f"update_docs: {path}: {e}", file=sys.stderr)
                return 1
        with open(path, "w") as f:
            f.write(text)
        print(f"updated {path}")
    for p in copy_figures(a.outdir, a.docs, blocks):
        print(f"copied {p}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
