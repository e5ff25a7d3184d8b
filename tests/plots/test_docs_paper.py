"""Tests of the blocks of docs/studies.md that put our studies beside the paper's tables
(railbench/docs_paper.py), on small synthetic study_cost.csv files: the paper's rows and ours
column by column, the KEC/LUT ratios (ours and the paper's), the adaptive cases with the 1 ms
cap kept out of the paper's efficiency tables, linear and cubic tables side by side, the
refined/default ratio, Tables 9-10 and the flange-loaded ratios; and the typed-in paper data
(docs/data/paper_efficiency.csv) complete.

usage: /usr/bin/python3 -m pytest -q tests/plots/test_docs_paper.py
"""
import csv
import os
import tempfile

from helpers import work_folder

from railbench import docs_paper as dp
from railbench.docs_blocks import paper_rows, solver_setting

TMP = tempfile.mkdtemp(prefix="rb_docs_paper_")
work_files = work_folder(TMP)


def write_cost(study, rows):
    path = os.path.join(TMP, study, "study_cost.csv")
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)


def cost(method, integ, cpu, evals, K="", tol="", step="", cap="", refined="false",
         interp="cubic", status="ok", jac=0, nbytes="", build=""):
    return dict(case=f"{method}{K}{integ}{tol}{cap}{refined}{interp}", label="", method=method,
                integrator=integ, tol=tol, step_s=step, max_step_s=cap, K=K,
                refined_tables=refined, interpolation=interp, status=status, cpu_median_s=cpu,
                rhs_evals=evals, rhs_evals_jac=jac, t_reached_s="24.4610" if status == "ok"
                else "1.0400", table_build_time_s=build, table_bytes=nbytes,
                solver=f"{integ} tol={tol} hmax={float(cap or 0) * 1e3:g}ms" if tol else
                f"{integ} h=1ms")


def line(block, start):
    """The table line of a block that starts with `start`."""
    found = [ln for ln in block.splitlines() if ln.startswith(start)]
    assert len(found) == 1, (start, block)
    return [c.strip() for c in found[0].strip("|").split("|")]


def test_paper_data_complete():
    rows = paper_rows()
    per = {}
    for r in rows:
        per.setdefault(r["table"], []).append(r)
    for no in ("12", "13", "14", "15", "16", "17", "18"):
        assert len(per[no]) == 8, f"Table {no}: 8 rows (ode15s, ode45 x 3 tolerances, RK4, ABM)"
    assert len(per["7"]) == 4 and len(per["11"]) == 4
    t18 = {(r["integrator"], r["tol"]): r for r in per["18"]}
    assert t18[("ode45", "1e-6")]["evaluations"] == "77323"
    assert t18[("ode45", "1e-6")]["cpu_median_s"] == "537.56"
    assert t18[("ABM", "")]["evaluations"] == "50011"
    t7 = {(r["integrator"], r["tol"]): r for r in per["7"]}
    assert t7[("RK4", "")]["status"] == "failed"
    assert dp.paper_cpu(t7[("ode45", "1e-8")]) == 16909.05, "Table 7: the one time it gives"


def test_efficiency_tables_beside_the_paper():
    write_cost("efficiency_case3", [
        cost("kec", "bdf", "1.00", 40000, tol="1e-6", cap="0", jac=2000),
        cost("lut", "bdf", "2.00", 80000, K="1e10", tol="1e-6", cap="0", jac=4000),
        # the accuracy setting (1 ms cap): not one of the paper's efficiency rows
        cost("kec", "bdf", "9.00", 90000, tol="1e-6", cap="0.001"),
        cost("lut", "bdf", "9.00", 90000, K="1e10", tol="1e-6", cap="0.001"),
        cost("kec", "abm", "0.50", 48928, step="0.001"),
        cost("lut", "abm", "0.40", 48928, K="1e10", step="0.001"),
        cost("kec", "abm", "5.00", 489280, step="0.0001"),  # Fig. 25's step: not a paper row
        cost("lut", "abm", "0.10", 2000, K="7.075e13", step="0.001", status="failed"),
        cost("lut", "dopri5", "3.00", 300000, K="7.075e13", tol="1e-8", cap="0"),
        cost("kec", "dopri5", "2.00", 200000, tol="1e-8", cap="0"),
    ])
    b = dp.paper_table_blocks(TMP)
    t13 = b["paper_table13"]
    assert "Paper Table 13 (LUT, K = 1e10 N/m^1.5)" in t13
    assert line(t13, "| integrator") == [
        "integrator", "tol", "CPU [s] ours", "CPU [s] paper", "evals ours", "evals paper",
        "KEC/LUT CPU ours", "KEC/LUT CPU paper", "KEC/LUT evals ours", "KEC/LUT evals paper"]
    # ours: 2.00 s, 84000 evaluations incl. Jacobian columns; KEC/LUT 0.50 and 42000/84000;
    # the paper: 653.89 s / 85968, KEC 757.94 / 123172.
    assert line(t13, "| ode15s (bdf) | 1e-6") == [
        "ode15s (bdf)", "1e-6", "2.00", "653.89", "84000", "85968", "0.50", "1.16", "0.50",
        "1.43"]
    assert line(t13, "| ABM (abm)") == [
        "ABM (abm)", "1 ms step", "0.40", "398.92", "48928", "50011", "1.25", "0.66", "1.00",
        "1.00"]
    assert "9.00" not in t13, "the capped accuracy cases stay out of the paper's Table 13"
    # ours missing: the paper's row with dashes
    assert line(t13, "| ode45 (dopri5) | 1e-5")[2:5] == ["–", "410.13", "–"]
    t16 = b["paper_table16"]
    assert "KEC/LUT K=1e10 CPU ours" in t16
    assert line(t16, "| ABM (abm)")[2:] == ["0.50", "262.63", "48928", "50011", "1.25", "0.66",
                                            "1.00", "1.00"]
    assert "489280" not in t16, "ABM at 0.1 ms is not the paper's 1 ms row"
    t7 = b["paper_table7"]
    assert line(t7, "| ABM (abm)")[2:6] == ["failed at 1.04 s", "failed", "failed", "failed"]
    assert line(t7, "| ode45 (dopri5) | 1e-8") == [
        "ode45 (dopri5)", "1e-8", "3.00", "16909.05", "300000", "2171100", "0.67", "–", "0.67",
        "–"]
    assert "the one time it gives" in t7


def test_refinement_tables_linear_and_cubic():
    rows = []
    for interp, f in (("linear", 1.0), ("cubic", 2.0)):
        for refined, g in (("false", 1.0), ("true", 0.5)):
            rows += [cost("kec", "dopri5", f"{1.0 * f * g:.2f}", 10000, tol="1e-4", cap="0",
                          refined=refined, interp=interp, nbytes="200000", build="0.05"),
                     cost("lut", "dopri5", f"{2.0 * f * g:.2f}", 20000, K="1e10", tol="1e-4",
                          cap="0", refined=refined, interp=interp,
                          nbytes="4000000" if refined == "false" else "8000000", build="0.2")]
    write_cost("refinement", rows)
    b = dp.paper_table_blocks(TMP)
    t18 = b["paper_table18"]
    head = line(t18, "| integrator")
    assert head[2:5] == ["CPU [s] ours (linear)", "CPU [s] ours (cubic)", "CPU [s] paper"]
    assert head[-3:] == ["refined/default CPU ours (linear)", "refined/default CPU ours (cubic)",
                         "refined/default CPU paper"]
    r = line(t18, "| ode45 (dopri5) | 1e-4")
    assert r[2:5] == ["1.00", "2.00", "265.75"], "refined LUT: linear, cubic, the paper's"
    assert r[8:11] == ["0.50", "0.50", f"{196.09 / 265.75:.2f}"], "KEC/LUT CPU with Table 17"
    assert r[-3:] == ["0.50", "0.50", f"{265.75 / 271.93:.2f}"], "refined/default: Table 13"
    assert "interpolated linearly (the paper's, section 5.5)" in t18
    t910 = dp.tables_9_10_block(TMP)
    assert line(t910, "| LUT refined | linear") == [
        "LUT refined", "linear", "8000 kB", "0.200 s",
        "gauge -5 to 5 mm step 1 mm; y -18 to 18 mm step 0.05 mm", "721 x 11", "46 kB"]
    assert line(t910, "| KEC default | cubic")[5:] == ["465 x 1", "4 kB"]


def test_flange_ratios_and_settings():
    write_cost("flange_stiffness", [
        cost("kec", "dopri5", "1.00", 30000, tol="1e-6", cap="0"),
        cost("lut", "dopri5", "2.00", 60000, K="1e12", tol="1e-6", cap="0"),
        cost("lut", "dopri5", "0.20", 6000, K="7.075e13", tol="1e-6", cap="0", status="failed"),
        cost("kec", "dopri5", "5.00", 50000, tol="1e-6", cap="0.001"),
    ])
    b = dp.flange_paper_block(TMP)
    assert line(b, "| ode45 (dopri5) | 1e-6 | 1e12") == [
        "ode45 (dopri5)", "1e-6", "1e12", "0.50", f"{568.18 / 3315.77:.2f}", "0.50",
        f"{112201 / 370171:.2f}", "60000"]
    assert line(b, "| ode45 (dopri5) | 1e-6 | 7.075e13")[3:] == ["–", "–", "–", "–", "failed"]
    assert line(b, "| ode45 (dopri5) | 1e-6 | 1e12")[3] == "0.50", \
        "the KEC of the ratio is the case without the cap"
    # the settings' names: the cap from the column, else from the solver label
    assert solver_setting(dict(integrator="bdf", tol="1e-6", max_step_s="0.001")) == \
        "bdf 1e-6, 1 ms cap"
    assert solver_setting(dict(integrator="bdf", tol="1e-6", max_step_s="0")) == "bdf 1e-6"
    assert solver_setting(dict(integrator="bdf", tol="1e-6",
                               solver="bdf tol=1e-6 hmax=1ms")) == "bdf 1e-6, 1 ms cap"
    assert dp.max_step(dict(solver="dopri5 tol=1e-6 hmax=0ms")) == 0.0
    assert dp.tol_text("0.0001") == "1e-4" and dp.tol_text("2.5e-05") == "2.5e-5"
    assert dp.tol_text("") == "1 ms step"


def test_missing_inputs():
    empty = os.path.join(TMP, "empty")
    os.makedirs(empty, exist_ok=True)
    b = dp.paper_table_blocks(empty)
    assert set(b) == {f"paper_table{n}" for n in ("7", "11", "12", "13", "14", "15", "16", "17",
                                                   "18")}
    assert all(v.startswith("*Not generated: ") for v in b.values())
    assert dp.tables_9_10_block(empty).startswith("*Not generated: ")
    assert dp.flange_paper_block(empty).startswith("*Not generated: ")
