"""The numbers of docs/validation.md from the validation study (scenarios/studies/validation.lua):

    plots/rbplot validation-tables OUT_DIR    (OUT_DIR = out/studies/validation)

reads OUT_DIR/summary_cases.csv and the result file of each case and writes, beside them,

    validation_steady.csv   steady-curving mean y [mm] and yaw [mrad] of every body (paper
                            Tables 5 and 6): case 1 over s = 110..120 m of the wheelset (the last
                            10 m of the 40 m curve), case 2 over t = 20..24 s (the whole wagon in
                            the curve); scenario solver (ABM) runs only, column `variant` the
                            set-up variant (scenarios/validation/variants/; "" = shipped)
    validation_case3.csv    Eq. (33) difference of the wheelsets' y between the KEC and the LUT
                            run of case 3 (same solver): max and mean of |y_KEC - y_LUT| /
                            max |y_LUT| [%], and max |y_LUT| [mm]
    validation_cost.csv     per case: status, CPU time (median, min, max over the repeats), real
                            time factor, rhs evaluations, steps
    study_fig*.png          the paper's Fig. 17, 19-22 and 27 (railbench/validation_figs.py),
                            which docs/validation.md shows as figures/validation_fig*.png; Fig. 27
                            runs the workbench ($RAILBENCH_WORKBENCH, else this checkout's
                            build/workbench/app/workbench) on a bump-stop rig
                            (OUT_DIR/bumpstop_law.lua, .h5)

`plots/rbplot docs` turns them into the generated tables of docs/validation.md. The case is
read from its base scenario's name (case1_R300_kec.lua, case2_lut.lua, ...), the solver from the
result file and the overrides.
"""
import csv
import os
import re
import sys
from typing import Dict, List, Optional, Tuple

import h5py
import numpy as np

from . import validation_figs

CASE1_S = (110.0, 120.0)   # m: the last 10 m of case 1's 40 m curve (Table 5)
CASE2_T = (20.0, 24.0)     # s: the whole wagon in the curve (front past s = 172 m), Table 6
KIND_ORDER = {"wheelset": 0, "bogie": 1, "car": 2}


CASE_RE = r"case(\d)(?:_R(\d+))?_(kec|lut)(?:_(centred|table4))?\.lua$"


def parse_case(base: str) -> Optional[Tuple[int, str, str]]:
    """(case number, radius or "", method) from the base scenario's file name (a set-up variant
    of scenarios/validation/variants/ parses as its case; `variant` tells them apart)."""
    m = re.search(CASE_RE, base or "")
    if not m:
        return None
    return int(m.group(1)), m.group(2) or "", m.group(3)


def variant(base: str) -> str:
    """The set-up variant of a validation scenario: "" for the shipped set-up, "centred" (case 1,
    the frame at the wheelset itself), "table4" (case 2, the paper's Table 4 elements alone)."""
    m = re.search(CASE_RE, base or "")
    return (m.group(4) or "") if m else ""


def solver_label(overrides: str, row: dict) -> str:
    ov = dict(o.split("=", 1) for o in (overrides or "").split() if "=" in o)
    method = ov.get("solver.method")
    if method:
        tol = ov.get("solver.rtol")
        return f"{method} {tol}" if tol else method
    # The scenario's own fixed-step solver: the step from the run (t reached / steps).
    try:
        h = float(row["t_reached"]) / float(row["steps"])
        return f"scenario ABM {h * 1e3:.4g} ms"
    except (KeyError, ValueError, ZeroDivisionError):
        return "scenario solver"


def _text(v) -> str:
    return v.decode() if isinstance(v, bytes) else str(v)


def bodies(f: h5py.File) -> List[str]:
    """Moving bodies (not the kinematic frame of case 1) in the paper's order: wheelsets,
    bogies, car body."""
    names = [n for n in f["/bodies"] if "y" in f["/bodies"][n]]
    kinds = {n: _text(f["/bodies"][n].attrs.get("kind", "")) for n in names}
    names = [n for n in names if kinds[n] != "frame"]
    return sorted(names, key=lambda n: (KIND_ORDER.get(kinds[n], 9), n))


def steady(path: str, case: int) -> List[dict]:
    out = []
    with h5py.File(path, "r") as f:
        t = f["/time"][:]
        for name in bodies(f):
            g = f["/bodies"][name]
            if case == 1:
                s = g["s"][:]
                sel = (s >= CASE1_S[0]) & (s <= CASE1_S[1])
                window = f"s = {CASE1_S[0]:g}..{CASE1_S[1]:g} m"
            else:
                sel = (t >= CASE2_T[0] - 1e-9) & (t <= CASE2_T[1] + 1e-9)
                window = f"t = {CASE2_T[0]:g}..{CASE2_T[1]:g} s"
            if not np.any(sel):
                continue
            out.append({"body": name, "y_mm": float(np.mean(g["y"][:][sel])) * 1e3,
                        "yaw_mrad": float(np.mean(g["yaw"][:][sel])) * 1e3,
                        "window": window, "samples": int(np.sum(sel))})
    return out


def eq33(kec_path: str, lut_path: str) -> List[dict]:
    out = []
    with h5py.File(kec_path, "r") as fk, h5py.File(lut_path, "r") as fl:
        tk, tl = fk["/time"][:], fl["/time"][:]
        n = min(len(tk), len(tl))
        for name in bodies(fk):
            if _text(fk["/bodies"][name].attrs.get("kind", "")) != "wheelset" or \
                    name not in fl["/bodies"]:
                continue
            yk = fk["/bodies"][name]["y"][:n]
            yl = fl["/bodies"][name]["y"][:n]
            ymax = float(np.max(np.abs(yl))) if n else 0.0
            if not ymax:
                continue
            e = np.abs(yk - yl) / ymax
            out.append({"wheelset": name, "eq33_max_percent": float(np.max(e)) * 100,
                        "eq33_mean_percent": float(np.mean(e)) * 100,
                        "max_abs_y_lut_mm": ymax * 1e3})
    return out


def _file(outdir: str, row: dict) -> Optional[str]:
    f = row.get("file") or ""
    for p in (f, os.path.join(outdir, os.path.basename(f))):
        if p and os.path.exists(p):
            return p
    return None


def write_csv(path: str, rows: List[dict], fields: List[str]):
    with open(path, "w", newline="") as fh:
        w = csv.DictWriter(fh, fields, extrasaction="ignore")
        w.writeheader()
        w.writerows(rows)


def make(outdir: str, workbench: Optional[str] = None) -> List[str]:
    sc = os.path.join(outdir, "summary_cases.csv")
    if not os.path.exists(sc):
        raise SystemExit(f"railbench validation-tables: {sc} missing (run ./wb studies --only validation)")
    with open(sc, newline="") as fh:
        cases = list(csv.DictReader(fh))
    steady_rows, cost_rows = [], []
    by_key: Dict[Tuple[int, str, str, str], dict] = {}
    scenario_files: Dict[Tuple[int, str, str], str] = {}  # the figures' runs
    for r in cases:
        parsed = parse_case(r.get("base", ""))
        if parsed is None:
            continue
        case, radius, method = parsed
        solver = solver_label(r.get("overrides", ""), r)
        var = variant(r.get("base", ""))
        if var:
            # Set-up variants: their steady-curving values only, beside the shipped set-up.
            path = _file(outdir, r)
            if case in (1, 2) and path:
                for b in steady(path, case):
                    steady_rows.append(dict(b, case=case, radius_m=radius, method=method,
                                            variant=var, status=r.get("status", "")))
            continue
        by_key[(case, radius, method, solver)] = r
        cpu = float(r.get("median_cpu_time_s") or 0)
        t = float(r.get("t_reached") or 0)
        ok = r.get("status") == "ok"
        cost_rows.append({"case": case, "radius_m": radius, "method": method, "solver": solver,
                          "status": r.get("status", ""), "cpu_median_s": cpu if ok else "",
                          "cpu_min_s": r.get("min_cpu_time_s", "") if ok else "",
                          "cpu_max_s": r.get("max_cpu_time_s", "") if ok else "",
                          "t_reached_s": t, "real_time_factor": t / cpu if ok and cpu else "",
                          "rhs_evals": r.get("rhs_evals", ""),
                          "rhs_evals_jac": r.get("rhs_evals_jac", ""),
                          "steps": r.get("steps", ""), "rejected_steps": r.get("rejected_steps", ""),
                          "message": r.get("message", "")})
        path = _file(outdir, r)
        if solver.startswith("scenario") and path:
            scenario_files[(case, radius, method)] = path
        if case in (1, 2) and solver.startswith("scenario") and path:
            for b in steady(path, case):
                steady_rows.append(dict(b, case=case, radius_m=radius, method=method,
                                        variant="", status=r.get("status", "")))
    c3 = []
    for (case, radius, method, solver), r in sorted(by_key.items()):
        if case != 3 or method != "kec":
            continue
        lut = by_key.get((3, radius, "lut", solver))
        kp, lp = _file(outdir, r), _file(outdir, lut) if lut else None
        if kp and lp:
            for row in eq33(kp, lp):
                c3.append(dict(row, solver=solver, kec_status=r.get("status", ""),
                               lut_status=lut.get("status", "")))
    written = []
    for name, rows, fields in (
            ("validation_steady.csv", steady_rows,
             ["case", "radius_m", "method", "variant", "body", "y_mm", "yaw_mrad", "window",
              "samples", "status"]),
            ("validation_case3.csv", c3,
             ["solver", "wheelset", "eq33_max_percent", "eq33_mean_percent", "max_abs_y_lut_mm",
              "kec_status", "lut_status"]),
            ("validation_cost.csv", cost_rows,
             ["case", "radius_m", "method", "solver", "status", "cpu_median_s", "cpu_min_s",
              "cpu_max_s", "t_reached_s", "real_time_factor", "rhs_evals", "rhs_evals_jac",
              "steps", "rejected_steps", "message"])):
        p = os.path.join(outdir, name)
        write_csv(p, rows, fields)
        written.append(p)
    written += validation_figs.make_figures(outdir, scenario_files, workbench or
                                            validation_figs.WORKBENCH)
    return written


def main(argv=None) -> int:
    argv = sys.argv[1:] if argv is None else argv
    if len(argv) != 1:
        print("usage: railbench validation-tables OUT_DIR", file=sys.stderr)
        return 1
    for p in make(argv[0]):
        print(f"wrote {p}")
    return 0

