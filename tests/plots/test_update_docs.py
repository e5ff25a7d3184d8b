#!/usr/bin/python3
"""Tests of plots/update_docs.py (the generator of the measured blocks of docs/studies.md and
docs/performance.md) on synthetic study outputs: blocks are replaced between their markers, the
hand-written text around them is kept, a missing input gives a "Not generated" line instead of
stale numbers, a missing marker is an error, and the speed table judges the targets.

usage: /usr/bin/python3 tests/plots/test_update_docs.py   -> exit 0 if all pass
"""
import csv
import os
import shutil
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "plots"))
import update_docs as ud  # noqa: E402

TMP = tempfile.mkdtemp(prefix="rb_update_docs_")
failures = []


def check(cond, what):
    print(("ok   " if cond else "FAIL ") + what)
    if not cond:
        failures.append(what)


def write_csv(path, rows):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)


def cost(label, method, integ, cpu, evals, status="ok", K="", tol="", step="", refined="false"):
    return dict(case=label, label=label, role="", method=method, integrator=integ, tol=tol,
                step_s=step, K=K, refined_tables=refined, status=status, cpu_median_s=cpu,
                cpu_min_s=cpu, cpu_max_s=cpu, rhs_evals=evals, rhs_evals_jac=0, steps=evals // 2,
                us_per_eval=f"{float(cpu) / evals * 1e6:.3f}", t_reached_s="24.46",
                table_build_time_s="0.1", table_bytes="1000000", message="")


def main():
    docs = os.path.join(TMP, "docs")
    out = os.path.join(TMP, "out")
    os.makedirs(docs)
    blocks_s = ["efficiency", "efficiency_paper", "accuracy", "flange", "flange_paper",
                "flange_accuracy", "refinement", "work_precision", "hard_cases"]
    blocks_p = ["speed", "bench", "effects"]
    for md, names in (("studies.md", blocks_s), ("performance.md", blocks_p)):
        with open(os.path.join(docs, md), "w") as f:
            f.write("# hand text before\n")
            for n in names:
                f.write(f"<!-- generated: {n} (plots/update_docs.py) -->\nOLD NUMBERS\n"
                        f"<!-- end: {n} -->\nhand text after {n}\n")
    write_csv(os.path.join(out, "speed", "study_cost.csv"), [
        cost("KEC ABM 1 ms (target 1)", "kec", "abm", "0.2", 50006, step="0.001"),
        cost("LUT BDF (target 2)", "lut", "bdf", "30.0", 150000, K="7.075e13", tol="1e-06")])
    write_csv(os.path.join(out, "efficiency_case3", "study_cost.csv"), [
        cost("a", "kec", "abm", "0.5", 50006, step="0.001"),
        cost("b", "lut", "abm", "0.4", 50006, K="1e10", step="0.001"),
        cost("c", "lut", "abm", "0", 1000, K="7.075e13", step="0.001", status="failed")])
    rc = ud.main([out, "--build", os.path.join(TMP, "nobuild"), "--docs", docs])
    check(rc == 0, "update_docs returns 0")
    s = open(os.path.join(docs, "studies.md")).read()
    p = open(os.path.join(docs, "performance.md")).read()
    check("OLD NUMBERS" not in s and "OLD NUMBERS" not in p, "every old block is replaced")
    check(all(f"hand text after {n}" in s for n in blocks_s) and "# hand text before" in s,
          "hand-written text is kept")
    check("Not generated" in s.split("generated: accuracy")[1].split("end: accuracy")[0],
          "a missing input gives a 'Not generated' line")
    speed = p.split("generated: speed")[1].split("end: speed")[0]
    check("122.3x" in speed and "| met" in speed, "target 1 at 122x real time is met")
    check("0.8x" in speed and "NOT met" in speed, "target 2 at 0.8x real time is not met")
    eff = s.split("generated: efficiency ")[1].split("end: efficiency ")[0]
    check("failed" in eff and "(49x)" in eff, "efficiency table: failed case and real-time factor")
    paper = s.split("generated: efficiency_paper")[1].split("end: efficiency_paper")[0]
    check("50011" in paper, "the paper's ABM evaluation count is put beside ours")
    # Idempotent: a second run gives the same text.
    ud.main([out, "--build", os.path.join(TMP, "nobuild"), "--docs", docs])
    check(open(os.path.join(docs, "studies.md")).read() == s, "a second run changes nothing")
    with open(os.path.join(docs, "performance.md"), "w") as f:
        f.write("no markers here\n")
    check(ud.main([out, "--docs", docs]) == 1, "a missing marker is an error")
    coupling_only()


def coupling_only():
    """--only contact_dynamics: the coupling block from BUILD/dynamics/coupling_*.csv alone."""
    docs = os.path.join(TMP, "docs_cd")
    build = os.path.join(TMP, "build_cd")
    os.makedirs(docs)
    md = os.path.join(docs, "contact_dynamics.md")
    with open(md, "w") as f:
        f.write("hand before\n<!-- generated: coupling_convergence (plots/update_docs.py) -->\n"
                "OLD NUMBERS\n<!-- end: coupling_convergence -->\nhand after\n")
    check(ud.main(["-", "--build", build, "--docs", docs, "--only", "contact_dynamics"]) == 1,
          "--only contact_dynamics without its CSVs is an error")
    check("OLD NUMBERS" in open(md).read(), "... and leaves the block alone")
    rows = [dict(coupling="consistent", step_ms="0.125", diff_to_half_step_mm="0.002226",
                 cpu_s="0.62", rhs_evals="41600", us_per_rhs="14.9", iterations_per_solve="3.92"),
            dict(coupling="lagged", step_ms="0.0625", diff_to_half_step_mm="", cpu_s="0.70",
                 rhs_evals="83200", us_per_rhs="8.4", iterations_per_solve="0")]
    write_csv(os.path.join(build, "dynamics", "coupling_flange_curve.csv"), rows)
    rc = ud.main(["-", "--build", build, "--docs", docs, "--only", "contact_dynamics"])
    text = open(md).read()
    block = text.split("generated: coupling_convergence")[1].split("end: coupling_convergence")[0]
    check(rc == 0 and "OLD NUMBERS" not in text, "--only contact_dynamics replaces the block")
    check(text.startswith("hand before") and "hand after" in text, "... keeps the hand text")
    check("| consistent | 0.125 | 0.0022 | 0.62 | 41600 | 14.9 | 3.92 |" in block,
          "... with the consistent row")
    check("| lagged | 0.0625 | – |" in block, "... and the finest step without a difference")
    check("commit" in block, "... stamped with the commit")


if __name__ == "__main__":
    try:
        main()
    except Exception as e:  # a crash is a failure, reported as such
        import traceback
        traceback.print_exc()
        failures.append(repr(e))
    print(f"{'FAILED' if failures else 'passed'}: {len(failures)} failure(s)")
    if failures:
        print(f"work files kept in {TMP}")
        sys.exit(1)
    shutil.rmtree(TMP, ignore_errors=True)
