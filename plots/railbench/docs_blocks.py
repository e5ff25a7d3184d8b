"""Generated documentation blocks: efficiency, accuracy, refinement, work precision,
effects, speed and benchmark tables."""
from __future__ import annotations

import csv
import json
import os
import re
from typing import Dict, List, Optional

from .provenance import GENERATOR, ROOT


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


BLOCK_RE = re.compile(r"<!-- generated: ([\w.-]+) \(" + re.escape(GENERATOR) +
                      r"\) -->\n(.*?)<!-- end: \1 -->", re.S)
NOT_GENERATED = "*Not generated: "


def replace_block(text: str, name: str, body: str, stamp: str = "") -> str:
    """Replaces the block NAME by body, with the stamp line first (not for a "Not generated"
    line: nothing was run)."""
    start = f"<!-- generated: {name} ({GENERATOR}) -->"
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

def solver_setting(r: dict) -> str:
    """"dopri5 1e-6" (no largest step), "dopri5 1e-6, 1 ms cap", "abm 1 ms"."""
    if r.get("tol"):
        cap = num(r.get("max_step_s"))
        if cap is None:  # a study summary without the column: the solver label says it
            m = re.search(r"hmax=([0-9.e+-]+)ms", r.get("solver") or "")
            cap = float(m.group(1)) * 1e-3 if m else 0.0
        return f"{r['integrator']} {r['tol']}" + (f", {cap * 1e3:g} ms cap" if cap else "")
    if r.get("step_s"):
        return f"{r['integrator']} {num(r['step_s']) * 1e3:g} ms"
    return r.get("integrator", "")


def paper_rows() -> List[dict]:
    return read_csv(os.path.join(ROOT, "docs", "data", "paper_efficiency.csv"))


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
        return {name: missing(f"out/studies/{study}/study_cost.csv")}
    sim = max(num(r["t_reached_s"], 0) for r in rows)
    models = [("kec", "")] + [("lut", k) for k in sorted({r["K"] for r in rows if r["K"]},
                                                         key=lambda k: num(k))]
    settings = []
    for r in rows:
        s = solver_setting(r)
        if s not in settings:
            settings.append(s)
    order = {"rk4": 0, "abm": 1, "dopri5": 2, "bdf": 3, "ida": 4}
    settings.sort(key=lambda s: (order.get(s.split()[0], 9), "cap" in s,
                                 -num(s.split()[1].rstrip(","), 0)))

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

    return {name: eff}


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
        # The largest step in words: "hmax=0ms" is none (the paper's section 5.3 settings),
        # "hmax=1ms" the 1 ms of the paper's Table 8.
        line = [s.replace(" hmax=0ms", ", no cap").replace(" hmax=1ms", ", 1 ms cap")]
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
    """Default against refined tables per model (method, K, table interpolation) and solver
    setting; and the tables' build or load time and size as the result files record them."""
    rows = read_csv(os.path.join(outdir, "refinement", "study_cost.csv"))
    if not rows:
        return missing("out/studies/refinement/study_cost.csv")
    sim = max(num(r["t_reached_s"], 0) for r in rows)
    interp = lambda r: r.get("interpolation") or "cubic"  # noqa: E731
    several = len({interp(r) for r in rows}) > 1

    def key(r):
        return r["method"], r["K"], interp(r), solver_setting(r)

    keys = []
    for r in rows:
        if key(r) not in keys:
            keys.append(key(r))
    body = []
    for k in keys:
        d = next((r for r in rows if key(r) == k and r["refined_tables"] == "false"), None)
        f = next((r for r in rows if key(r) == k and r["refined_tables"] == "true"), None)
        ratio = (num(f["cpu_median_s"]) / num(d["cpu_median_s"])
                 if d and f and d["status"] == "ok" and f["status"] == "ok" else None)
        method, K, kind, s = k
        model = method.upper() + (f" K={K}" if K else "") + (f", {kind}" if several else "")
        body.append([model, s, cost_cell(d, sim), cost_cell(f, sim), fmt(ratio, "{:.2f}")])
    builds = []
    for method in ("kec", "lut"):
        for kind in sorted({interp(r) for r in rows}):
            for ref in ("false", "true"):
                r = next((x for x in rows if x["method"] == method and x["refined_tables"] == ref
                          and interp(x) == kind and x["table_build_time_s"]), None)
                if r:
                    builds.append([method.upper(), kind, "refined" if ref == "true" else "default",
                                   f"{num(r['table_build_time_s']):.3f} s",
                                   f"{num(r['table_bytes']) / 1e6:.2f} MB"])
    return (table(["model", "solver", "default tables", "refined tables", "CPU refined/default"],
                  body) + "\n\nContact tables (as recorded in the result files; a run that "
                  "loaded them from the disk cache records the load time):\n\n" +
            table(["method", "interpolation", "tables", "build or load time", "size"], builds))


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

    def cell(source, key, text, method, lab):
        """The variant's value of `key` for one contact method: "failed" when empty, "–" when
        the variant is not in `source`."""
        r = next((r for r in source if r["method"] == method and strip(r["label"]) == lab), None)
        if r is None:
            return "–"
        return text(r) if r[key] else "failed"

    def time_cell(method, lab):
        return cell(rows, "us_per_eval", lambda r: (
            f"{num(r['us_per_eval']):.2f} µs ({num(r['relative_to_baseline']):.2f}, "
            f"±{r['spread_percent'] or '?'} %)"), method, lab)

    def instr_cell(method, lab):
        return cell(instr, "instructions_per_eval", lambda r: (
            f"{num(r['instructions_per_eval']) / 1e3:.1f}k "
            f"({num(r['relative_to_baseline']):.3f})"), method, lab)

    head = ["variant", "KEC instructions / eval (rel.)", "LUT instructions / eval (rel.)",
            "KEC CPU / eval (rel., spread)", "LUT CPU / eval (rel., spread)"]
    body = [[lab, instr_cell("kec", lab), instr_cell("lut", lab), time_cell("kec", lab),
             time_cell("lut", lab)] for lab in labels]
    note = ("" if instr else "\n\n" + missing("out/studies/effects/study_effects_instructions.csv "
                                               "(plots/rbplot effects-instructions)"))
    return ("Per right-hand-side evaluation, each variant relative to the full model: callgrind "
            "instructions (repeatable; first 8 s of the run, integration only, "
            "`plots/rbplot effects-instructions`) and CPU time (median of 5 repeats over the whole "
            "run, ABM 0.25 ms, free spin; spread = (max - min) / median):\n\n" +
            table(head, body) + note)


# ---- the paper's settings: KEC against LUT per integrator -------------------------------------

def paper_settings_block(outdir: str, study: str) -> str:
    """KEC against LUT (K = 7.075e13) per solver setting of lib.paper_settings_cases, from
    OUT/<study>/study_cost.csv: CPU time, evaluations (rhs incl. Jacobian columns), x real time,
    and the LUT/KEC ratios of CPU time and of evaluations."""
    rows = read_csv(os.path.join(outdir, study, "study_cost.csv"))
    if not rows:
        return missing(f"out/studies/{study}/study_cost.csv")
    by = {}
    order: List[str] = []
    for r in rows:
        model, _, setting = r["label"].partition(" | ")
        if setting not in by:
            by[setting] = {}
            order.append(setting)
        by[setting]["kec" if model.startswith("KEC") else "lut"] = r

    def cell(r: Optional[dict]) -> str:
        if r is None:
            return "–"
        cpu, sim = num(r["cpu_median_s"]), num(r["t_reached_s"], 0)
        cost = f"{cpu:.2f} s / {total_evals(r)} ({sim / cpu:.0f}x)" if cpu else "–"
        # A failed run's cost up to where it stopped, e.g. the LUT's wheel lift at the first
        # hard flange impact (docs/hard_cases.md).
        if r["status"] == "ok":
            return cost
        evals = total_evals(r)
        return (f"failed at {sim:.2f} s" + (f": {cost}" if cost != "–" else
                                             f" after {evals} evaluations" if evals else ""))

    def ratio(k: Optional[dict], l: Optional[dict], what) -> str:
        if not k or not l or k["status"] != "ok" or l["status"] != "ok":
            return "–"
        a, b = what(k), what(l)
        return f"{b / a:.2f}" if a else "–"

    body = []
    for setting in order:
        k, l = by[setting].get("kec"), by[setting].get("lut")
        body.append([setting, cell(k), cell(l),
                     ratio(k, l, lambda r: num(r["cpu_median_s"], 0)),
                     ratio(k, l, lambda r: float(total_evals(r)))])
    return ("CPU time (median of the repeats) / rhs evaluations incl. finite-difference Jacobian "
            "columns (x real time):\n\n" +
            table(["solver", "KEC", "LUT K=7.075e13", "CPU LUT/KEC", "evaluations LUT/KEC"],
                  body))


# ---- speed targets -----------------------------------------------------------------------------

def _instructions_by_label(path: str) -> Dict[str, dict]:
    return {r["label"]: r for r in read_csv(path) if r.get("instructions_per_eval")}


def _wheelset_paths(path: str) -> Optional[Dict[str, "object"]]:
    """Lateral displacement y [m] of every wheelset of a result file, by wheelset name, with
    "/time"; None when the file cannot be read."""
    try:
        import h5py
        with h5py.File(path, "r") as f:
            out = {"/time": f["time"][()]}
            names = f["bodies"].attrs["names"]
            names = names.decode() if isinstance(names, bytes) else str(names)
            for name in names.split("\n"):
                if name.startswith("ws") and "y" in f["bodies"][name]:
                    out[name] = f["bodies"][name]["y"][()]
            return out
    except (OSError, KeyError, ValueError):
        return None


def _max_dy_mm(ref: Optional[dict], path: str) -> Optional[float]:
    """Largest |y - y_ref| over every wheelset and output time [mm] (the output times of both
    runs: one interval; the shorter run's times)."""
    if ref is None:
        return None
    run = _wheelset_paths(path)
    if run is None:
        return None
    import numpy as np
    worst = 0.0
    for name, y in run.items():
        if name == "/time" or name not in ref:
            continue
        yr = np.interp(run["/time"], ref["/time"], ref[name])
        worst = max(worst, float(np.max(np.abs(y - yr))))
    return worst * 1e3


def _observer_share(path: str) -> Optional[float]:
    """Share of a run's CPU spent on its outputs and assessment: the integration's observer (output
    evaluations, assessment samples, writing; timed by the wall clock, its descheduled part taken
    out in the integration's CPU / wall proportion as in the run's own cost summary) plus the
    assessment computed after the run, over the integration's CPU plus that assessment."""
    try:
        import h5py
        with h5py.File(path, "r") as f:
            a = f["stats"].attrs
            cpu, wall = float(a["cpu_time_s"]), float(a["wall_time_s"])
            callbacks = float(a.get("callback_wall_time_s", 0.0))
            after = float(a.get("assessment_cpu_s", 0.0))
            shared = float(a.get("shared_evaluations", 0.0))
            evals = float(a.get("rhs_evals", 0.0)) + float(a.get("rhs_evals_jac", 0.0))
    except (OSError, KeyError, ValueError):
        return None
    if not (cpu > 0 and wall > 0):
        return None
    observer = callbacks * min(1.0, cpu / wall)
    # The observer's evaluations that are the integrator's next right-hand sides
    # (/stats/shared_evaluations) are integration, at the cost of the integrator's own ones.
    if shared > 0 and evals > shared:
        observer = max(0.0, observer - shared * (cpu - observer) / (evals - shared))
    return (observer + after) / (cpu + after)


def speed_block(outdir: str, study: str = "speed") -> str:
    """The speed table of a study folder: CPU, x real time, evaluations, instructions per
    evaluation and the accuracy against the study's reference case; the "default_scene" study
    (the shipped scenes as a user runs them) also shows what its outputs and assessment cost."""
    rows = read_csv(os.path.join(outdir, study, "study_cost.csv"))
    if not rows:
        return missing(f"out/studies/{study}/study_cost.csv")
    shares = study != "speed"
    # Accuracy of the cases of the reference's model (same overrides but the solver's: contact
    # method, spin, coupling) against the reference case.
    ref_row = next((r for r in rows if r.get("role") == "reference" and r["status"] == "ok"),
                   None)
    ref = _wheelset_paths(ref_row["file"]) if ref_row else None
    # A case's model: its overrides other than the solver's (summary_cases.csv).
    model_of = {c["case"]: frozenset(o for o in c["overrides"].split()
                                     if not o.startswith("solver."))
                for c in read_csv(os.path.join(outdir, study, "summary_cases.csv"))}
    # Callgrind instructions per evaluation (`plots/rbplot effects-instructions`), of this build
    # and, when measured, of an earlier one (its --tag names it).
    now = _instructions_by_label(os.path.join(outdir, study, f"study_{study}_instructions.csv"))
    before = _instructions_by_label(os.path.join(outdir, study,
                                                 f"study_{study}_instructions_before.csv"))
    tag = next((r.get("build") for r in before.values() if r.get("build")), "earlier build")
    body = []
    for r in rows:
        sim = num(r["t_reached_s"], 0)
        cpu = num(r["cpu_median_s"])
        ok = r["status"] == "ok"
        factor = sim / cpu if ok and cpu else None
        # The case's speed target, as its label states it: "... (target 100x)".
        m = re.search(r"target (\d+(?:\.\d+)?)x", r["label"])
        target = m.group(1) + "x" if m else ""
        met = ""
        if target and factor is not None:
            met = "met" if factor >= float(target[:-1]) else "NOT met"
        instr = [fmt(num((d.get(r["label"]) or {}).get("instructions_per_eval")),
                     "{:,.0f}") for d in (now, before)]
        same_model = (ref_row is not None and r is not ref_row and
                      model_of.get(r.get("case")) is not None and
                      model_of.get(r.get("case")) == model_of.get(ref_row.get("case")))
        dy = fmt(_max_dy_mm(ref, r.get("file", "")) if same_model and ok else None, "{:.3f}")
        share = _observer_share(r.get("file", "")) if shares and ok else None
        body.append([r["label"], r["status"], f"{cpu:.3f} s ({r['cpu_min_s']}-{r['cpu_max_s']})",
                     fmt(factor, "{:.1f}x"), r["rhs_evals"], r["rhs_evals_jac"] or "0",
                     r["steps"], fmt(num(r["us_per_eval"]), "{:.2f}"), instr[0], instr[1],
                     dy, fmt(share * 100 if share is not None else None, "{:.0f} %"), target,
                     met])
    head = ["case", "status", "CPU median (min-max)", "x real time", "rhs evals",
            "Jacobian evals", "steps", "µs / eval", "instructions / eval",
            f"instructions / eval ({tag})", "max \\|dy\\| vs reference [mm]",
            "outputs + assessment [% of CPU]", "target", ""]
    keep = [i for i in range(len(head))  # columns without data left out
            if (now or i != 8) and (before or i != 9) and (shares or i != 11)]
    head = [head[i] for i in keep]
    body = [[row[i] for i in keep] for row in body]
    note = (("Instructions per rhs evaluation: callgrind over the first 3 s of each case, "
             "integration only (integrator and output callbacks included; "
             "`plots/rbplot effects-instructions`)" +
             (f", also of the build `{tag}`. " if before else ". ") if now else "") +
            "max |dy|: the largest difference of any wheelset's lateral displacement from the "
            "reference case over the whole run, for the cases of the reference's model." +
            (" Outputs + assessment: the integration's output callbacks (output evaluations, "
             "assessment samples, writing; less the evaluations that are the integrator's next "
             "right-hand sides, `/stats/shared_evaluations`, at the integrator's cost per "
             "evaluation) plus the assessment computed after the run, as a share of the run's "
             "CPU (from each case's /stats)." if shares else "") + "\n\n")
    return note + table(head, body)


def _bench_json(outdir: str, name: str) -> Optional[dict]:
    """OUT_DIR/NAME.json, the Google Benchmark output (None when missing)."""
    path = os.path.join(outdir, name + ".json")
    if not os.path.exists(path):
        return None
    with open(path) as f:
        return json.load(f)


def _bench_machine(data: dict) -> str:
    ctx = data.get("context", {})
    return (f"Google Benchmark on {ctx.get('host_name', '?')}, {ctx.get('num_cpus', '?')} CPUs at "
            f"{ctx.get('mhz_per_cpu', '?')} MHz, {ctx.get('date', '')}")


def bench_block(outdir: str) -> str:
    data = _bench_json(outdir, "bench_wagon")
    if data is None:
        return missing("out/studies/bench_wagon.json")
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
    return (_bench_machine(data) + ":\n\n" +
            table(["benchmark (median of the repetitions)", "CPU µs per evaluation"], body))


def bench_integrators_block(outdir: str) -> str:
    """docs/integrators.md: bench/bench_integrators (the integrators' overhead per step)."""
    data = _bench_json(outdir, "bench_integrators")
    if data is None:
        return missing("out/studies/bench_integrators.json")
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
    return (_bench_machine(data) + " (median of the repetitions):\n\n" +
            table(["benchmark", "ns / step", "rhs / step", "overhead ns / step",
                   "steps (or rhs cost)"], body))


# ---- assessment of validation cases 2 and 3 (docs/assessment.md) -----------------------------

# (case, contact method) of the validation study (scenarios/studies/validation.lua), each run
# with its scenario's own solver.
ASSESSMENT_CASES = ((2, "kec"), (2, "lut"), (3, "kec"), (3, "lut"))
# Row label of each /assessment/summary quantity shown.
ASSESSMENT_ROWS = (("y_over_q", "max (Y/Q)_2m [-]"), ("sum_y", "max (ΣY)_2m [kN]"),
                   ("dq_over_q", "max ΔQ/Q0 [-]"), ("stability_rms", "stability rms [m/s²]"),
                   ("n_mv", "N_MV [-] (target)"), ("wz_lateral", "Wz lateral [-] (target)"),
                   ("wz_vertical", "Wz vertical [-] (target)"), ("t_gamma_max", "max T-gamma [N]"))
# The figure of case 3 KEC: drawn to OUT/validation/study_<name>.png, which copy_figures (docs.py)
# copies to docs/figures/validation_<name>.png.
ASSESSMENT_FIGURE = "case3_kec_assessment"


def _validation_case_files(d: str) -> Dict[tuple, tuple]:
    """(case, method) -> (result file or None, its name in summary_cases.csv) of the validation
    study's runs with the scenario's own solver (no overrides)."""
    from .validation import _file, parse_case
    out: Dict[tuple, tuple] = {}
    for r in read_csv(os.path.join(d, "summary_cases.csv")):
        parsed = parse_case(r.get("base", ""))
        if parsed is None or (r.get("overrides") or "").strip():
            continue
        key = (parsed[0], parsed[2])
        if key in ASSESSMENT_CASES and key not in out:
            out[key] = (_file(d, r), os.path.basename(r.get("file") or "") or "?")
    return out


def _assessment_column(path: Optional[str]) -> Optional[Dict[str, str]]:
    """Quantity -> cell of one result file's /assessment/summary; None without /assessment."""
    from .assessment import locate, read_assessment, summary_items
    try:
        a = read_assessment(path) if path else None
    except OSError:
        a = None
    if a is None or not a.summary:
        return None
    cells = {}
    for it in summary_items(a.summary):
        where = it.where
        at_s = None if "s =" in where else locate(a, it.quantity.key, it)
        if at_s is not None:
            where = (where + ", " if where else "") + f"s = {at_s:.1f} m"
        cells[it.quantity.key] = it.against() + (f" ({where})" if where else "")
    return cells


def _assessment_figure(path: str, d: str) -> Optional[str]:
    """Draws the assessment figure of `path` to d/study_<ASSESSMENT_FIGURE>.png; its docs name."""
    from .common import save_figure
    from .h5 import ResultFileError
    from .result import load_result
    from .run import FIGURES, build_figure
    try:
        result = load_result(path)
    except ResultFileError:
        return None
    spec = next(f for f in FIGURES if f.suffix == "assessment")
    if not spec.is_available(result):
        return None
    save_figure(build_figure(result, spec), os.path.join(d, f"study_{ASSESSMENT_FIGURE}.png"))
    return f"figures/validation_{ASSESSMENT_FIGURE}.png"


def assessment_cases_block(outdir: str) -> str:
    """docs/assessment.md: the /assessment/summary of validation cases 2 and 3, KEC and LUT
    (value against limit, ok / EXCEEDED, where), and the assessment figure of case 3 KEC."""
    d = os.path.join(outdir, "validation")
    files = _validation_case_files(d)
    if not files:
        return missing("out/studies/validation/summary_cases.csv")
    columns, notes = [], []
    for case, method in ASSESSMENT_CASES:
        path, name = files.get((case, method), (None, "no run in summary_cases.csv"))
        cells = _assessment_column(path)
        columns.append(cells)
        if cells is None:
            notes.append(f"case {case} {method.upper()} ({name})")
    if all(c is None for c in columns):
        return missing("/assessment/summary in the case 2 and case 3 result files of "
                       "out/studies/validation")
    body = [[label] + ["not generated" if c is None else c.get(key, "–") for c in columns]
            for key, label in ASSESSMENT_ROWS]
    out = ("/assessment/summary of the validation study's runs with the scenario's own solver "
           "(out/studies/validation): the assessed value against its limit (ok / EXCEEDED) and "
           "where it occurs (wheel, wheelset, bogie position or floor position; s where the "
           "2 m or 100 m window ends). N_MV and Wz are checked against comfort targets, not "
           "normative limits; T-gamma has none.\n\n" +
           table(["quantity"] + [f"case {c} {m.upper()}" for c, m in ASSESSMENT_CASES], body))
    if notes:
        out += "\n\n" + missing("/assessment in the result file of " + ", ".join(notes))
    kec3 = files.get((3, "kec"), (None, ""))[0]
    fig = _assessment_figure(kec3, d) if columns[2] is not None else None
    if fig:
        out += f"\n\n![Assessment of case 3 KEC]({fig})"
    return out


# ---- hard cases --------------------------------------------------------------------------------


# ---- a route, section by section (docs/assessment.md) ------------------------------------------

ROUTE = "route_assessment"          # OUT/route_assessment/route.h5 (./wb studies --only route_assessment)
ROUTE_FIGURE = "route_assessment_route_assessment.png"  # OUT/route_assessment/route_assessment.png


def _cell(sec, key: str, scale: float, digits: int) -> str:
    v = sec.get(key)
    if v is None:
        return "–"
    ok = sec.attrs.get(key + "_ok")
    lim = sec.get(key + "_limit")
    text = f"{v * scale:.{digits}f}"
    if ok is not None and not bool(ok):
        text += f" > {lim * scale:.{digits}f} EXCEEDED"
    where = str(sec.attrs.get(key + "_where", "")).strip()
    return text + (f" ({where})" if where else "")


def route_sections_block(outdir: str) -> str:
    """docs/assessment.md: the route scenario's /assessment section by section (EN 14363 per track
    section and test zone), its static wheel loads Q0 and where each wheel unloads most, in its
    own distance along the track."""
    from .assessment import read_assessment
    from .layout import _num
    path = os.path.join(outdir, ROUTE, "route.h5")
    try:
        a = read_assessment(path) if os.path.exists(path) else None
    except OSError:
        a = None
    if a is None or not a.sections:
        return missing(f"out/studies/{ROUTE}/route.h5 (./wb studies --only {ROUTE})")
    rows = []
    for sec in a.sections:
        r = sec.get("radius")
        lo, hi = sec.get("from"), sec.get("to")
        rows.append([sec.name, str(sec.attrs.get("kind", "")), str(sec.attrs.get("zone", "")),
                     "∞" if sec.attrs.get("kind") == "tangent" else ("–" if r is None else f"{r:.0f}"),
                     "–" if sec.get("cant") is None else f"{sec.get('cant') * 1e3:.0f}",
                     f"{lo:.0f}–{hi:.0f}", fmt(sec.get("covered"), "{:.0f}"),
                     _cell(sec, "y_over_q", 1.0, 3), _cell(sec, "sum_y", 1e-3, 1),
                     _cell(sec, "dq_over_q", 1.0, 3), _cell(sec, "y_qst", 1e-3, 1),
                     _cell(sec, "q_qst", 1e-3, 1), _cell(sec, "q_max", 1e-3, 1)])
    out = ("`scenarios/assessment/route.lua` (Manchester wagon 1 at 25 m/s over tangents, "
           "transitions, a left R = 600 m and a right R = 350 m curve, ORE B176 low): "
           "/assessment/sections of its run, each quantity the worst wheel (or wheelset, ΣY) of "
           "its section, with the wheel that gives it. Forces in kN; `run` is the length of the "
           "section the leading wheelset ran; Y_qst and Q_qst are evaluated in the curve "
           "sections only. Limits: (Y/Q)_2m 0.8, ΣY alpha (10 kN + 2 Q0/3), ΔQ/Q0 0.6, "
           "Y_qst 60 kN, Q_qst 145 kN, Q_max 90 kN + Q0.\n\n" +
           table(["section", "kind", "test zone", "R [m]", "cant [mm]", "s [m]", "run [m]",
                  "(Y/Q)_2m", "(ΣY)_2m", "ΔQ/Q0", "Y_qst", "Q_qst", "Q_max"], rows))
    q0 = sorted({round(_num(q.attrs.get("q0")) or 0.0, 1)
                 for q in a.dq_over_q.values() if q.attrs.get("q0") is not None})
    src = str(a.attrs.get("q0_source", "")).strip()
    if q0:
        out += ("\n\nQ0 of the eight wheels: " + ", ".join(f"{v / 1e3:.3f} kN" for v in q0) +
                (f" ({src})." if src else "."))
    wheel_rows = []
    for (ws, side), q in a.dq_over_q.items():
        off = a.s_offset.get((ws, side))
        at = _num(q.attrs.get("at_s"))
        v = _num(q.attrs.get("value"))
        wheel_rows.append([f"{ws} {side}", fmt(off, "{:.2f}"), fmt(v, "{:.3f}"),
                           fmt(at, "{:.1f}")])
    if wheel_rows:
        out += ("\n\nThe largest ΔQ/Q0 of each wheel over the run and where it occurs, in that "
                "wheel's own distance along the track (its offset behind the leading wheelset "
                "is `s_offset`): the wheels of one bogie meet the same track defects a "
                "wheelbase apart, so their positions agree where the same defect unloads them."
                "\n\n" + table(["wheel", "s_offset [m]", "max ΔQ/Q0", "at s [m]"], wheel_rows))
    fig = os.path.join(outdir, ROUTE, "route_assessment.png")
    if os.path.exists(fig):
        out += f"\n\n![Assessment of the route](figures/{ROUTE_FIGURE})"
    return out



# ---- ./wb run on a built tree ------------------------------------------------------------------

def default_run_block(outdir: str) -> str:
    """Wall time of `./wb run` (the default scene) on a built tree, with and without its figures
    (`./wb studies --only default_run`: 3 repeats each), and from a fresh clone (`--only
    cold_run`: one repeat)."""
    rows = read_csv(os.path.join(outdir, "default_run", "default_run.csv"))
    if not rows:
        return missing("out/studies/default_run/default_run.csv")
    rows += read_csv(os.path.join(outdir, "default_run", "cold_run.csv"))
    labels = {"figures": "`./wb run` (build check, simulation, result file, figures)",
              "no_figures": "`./wb run --no-plots` (build check, simulation, result file)",
              "cold_no_figures": "fresh clone, packages installed, no compiler cache: "
                                 "`./wb run --no-plots` (configure, build the program, run)",
              "cold_no_pch": "the same without precompiled headers (configured with "
                             "`-DRB_PCH=OFF` first)"}
    targets = {"figures": 8.0, "cold_no_figures": 240.0}
    body = []
    for what, label in labels.items():
        mine = [r for r in rows if r["what"] == what]
        walls = sorted(num(r["wall_s"], 0.0) for r in mine)
        if not walls:
            continue
        failed = sum(1 for r in mine if r["rc"] != "0")
        median = walls[len(walls) // 2]
        target = targets.get(what)
        verdict = "" if target is None else ("met" if median <= target and not failed
                                             else "NOT met")
        cpus = sorted(num(r.get("cpu_s"), float("nan")) for r in mine if r.get("cpu_s"))
        body.append([label, str(len(walls)) + (f" ({failed} failed)" if failed else ""),
                     f"{median:.2f} s ({walls[0]:.2f}-{walls[-1]:.2f})",
                     f"{cpus[len(cpus) // 2]:.0f} s" if cpus else "–",
                     fmt(target, "<= {:.0f} s"), verdict])
    return ("Wall time of the default scene as a user starts it (median and min-max of the "
            "repeats; CPU: user and system time of every process of the fresh clone's run, "
            "the compiler's mostly):\n\n" +
            table(["command", "repeats", "wall median (min-max)", "CPU", "target", ""], body))


# ---- the instruction set -----------------------------------------------------------------------

def march_block(outdir: str) -> str:
    """The default scene from the portable build and from a build for this machine's instruction
    set (`./wb studies --only march`, bench/march.py): CPU, instructions, and how far the two
    results drift apart."""
    rows = read_csv(os.path.join(outdir, "march", "march.csv"))
    if not rows:
        return missing("out/studies/march/march.csv")
    body = []
    medians = {}
    for build in ("portable", "native"):
        mine = [r for r in rows if r["build"] == build and r["repeat"] != "callgrind"]
        if not mine:
            continue
        cpus = sorted(num(r["cpu_s"], float("nan")) for r in mine)
        failed = [r for r in mine if r["status"] != "ok"]
        cg = [r for r in rows if r["build"] == build and r["repeat"] == "callgrind"]
        instr = num(cg[0]["instructions"]) if cg else None
        median = cpus[len(cpus) // 2]
        medians[build] = (median, instr)
        t_end = num(mine[0]["t_end_s"], float("nan"))
        march = mine[0]["march"] or "compiler default (x86-64)"
        body.append([build, f"`{march}`",
                     f"{median:.3f} s ({cpus[0]:.3f}-{cpus[-1]:.3f})" +
                     (f" ({len(failed)} failed)" if failed else ""),
                     f"{t_end / median:.1f}x", mine[0]["evaluations"],
                     fmt(instr / 1e9 if instr else None, "{:.2f} G"),
                     fmt(num(mine[0].get("max_dy_mm")), "{:.2g}")])
    out = ("The default scene (`scenarios/default/case3_kec_fast.lua`, every output and the "
           "assessment) from the portable build and from a build for this machine "
           f"({rows[0].get('cpu_model', 'unknown')}); CPU of the integration, median and min-max "
           "of 5 runs one at a time; instructions of the whole program (start to written file, "
           "contact tables cached) from one callgrind run; max |dy|: the largest difference of any "
           "wheelset's lateral displacement from the portable build's result over the run.\n\n" +
           table(["build", "-march", "CPU median (min-max)", "x real time", "evaluations",
                  "instructions", "max \\|dy\\| vs portable [mm]"], body))
    if "portable" in medians and "native" in medians:
        (cp, ip), (cn, inn) = medians["portable"], medians["native"]
        out += f"\n\nNative against portable: CPU x {cn / cp:.2f}"
        if ip and inn:
            out += f", instructions x {inn / ip:.2f}"
        out += "."
    return out
