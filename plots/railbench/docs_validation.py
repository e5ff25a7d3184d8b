"""Generated documentation blocks: hard cases and the validation tables (paper Tables 5, 6,
Eq. 33)."""
from __future__ import annotations

import os
from typing import Dict, List, Optional

from .provenance import ROOT
from .docs_blocks import fmt, missing, num, read_csv, table


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


def failure_reason(row: dict) -> str:
    """The reason of a failed run in words, from its failure record (hard_cases.csv's
    failure_text, written by `workbench check-result` from the engine's name tables; a record of
    an older suite: the reason's or kind's name)."""
    return row.get("failure_text") or row.get("failure_reason") or row.get("failure_kind") or "?"


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
            status = "failed: " + failure_reason(r)
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
    return read_csv(os.path.join(ROOT, "docs", "data", "paper_validation.csv"))


def _y_psi(r: Optional[dict], key_y="y_mm", key_p="yaw_mrad") -> str:
    if r is None:
        return "–"
    cell = f"{num(r[key_y]):.3f} / {num(r[key_p]):.3f}"
    return cell + (" (failed run)" if r.get("status", "ok") != "ok" else "")


def _car_offset_line(ours, theirs) -> str:
    """The car's lateral offset against the paper's (Table 6), per method and set-up."""
    parts = []
    for var, what in (("", "with the anti-roll bars"), ("table4", "Table 4 alone")):
        for m in ("kec", "lut"):
            r, p = ours(2, "", m, "car", var), theirs(2, "500", m.upper(), "car")
            if r is None or p is None or not num(p["y_mm"]):
                continue
            d = (num(r["y_mm"]) - num(p["y_mm"])) / num(p["y_mm"]) * 100
            parts.append(f"{m.upper()} {what} {d:+.1f} %")
    return ("\n\nCar body lateral offset against the paper's (same method): " +
            ", ".join(parts) + ".") if parts else ""


def validation_blocks(outdir: str) -> Dict[str, str]:
    d = os.path.join(outdir, "validation")
    steady = read_csv(os.path.join(d, "validation_steady.csv"))
    paper = paper_validation()
    out = {}

    def ours(case, radius, method, body, var=""):
        return next((r for r in steady if r["case"] == str(case) and r["radius_m"] == radius
                     and r["method"] == method and r["body"] == body
                     and r.get("variant", "") == var), None)

    def theirs(case, radius, source, body):
        return next((p for p in paper if p["case"] == str(case) and p["radius_m"] == radius
                     and p["source"] == source and p["body"] == body), None)

    head = ["KEC (ours) y / psi", "LUT (ours) y / psi", "KEC (paper)", "LUT (paper)",
            "UM (paper)"]
    case1 = [r for r in steady if r["case"] == "1"]
    if case1:
        radii = sorted({r["radius_m"] for r in case1}, key=lambda x: num(x, 0))
        body = []
        for var, label in (("", "{R}"), ("centred", "{R}, frame centred (variant)")):
            if not any(r.get("variant", "") == var for r in case1):
                continue
            body += [[label.format(R=R)] + [_y_psi(ours(1, R, m, "ws", var))
                                            for m in ("kec", "lut")] +
                     [_y_psi(theirs(1, R, src, "ws")) for src in ("KEC", "LUT", "UM")]
                     for R in radii]
        out["validation_case1"] = (f"Mean over {case1[0]['window']} (y in mm, psi in mrad; "
                                   f"paper: Table 5). Ours: the leading wheelset of a guided "
                                   f"bogie frame; variant rows: the frame centred at the "
                                   f"wheelset:\n\n" + table(["R [m]"] + head, body))
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
        if any(r.get("variant", "") == "table4" for r in case2):
            body += [[f"{b}, Table 4 alone (variant)"] +
                     [_y_psi(ours(2, "", m, b, "table4")) for m in ("kec", "lut")] +
                     [_y_psi(theirs(2, "500", src, b)) for src in ("KEC", "LUT", "UM")]
                     for b in names if b.startswith(("bogie", "car"))]
        out["validation_case2"] = (f"Mean over {case2[0]['window']} (y in mm, psi in mrad; "
                                   f"paper: Table 6). Ours: the wagon with the anti-roll bars "
                                   f"of the benchmark data; variant rows: the paper's Table 4 "
                                   f"elements alone:\n\n" + table(["body"] + head, body) +
                                   _car_offset_line(ours, theirs))
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
