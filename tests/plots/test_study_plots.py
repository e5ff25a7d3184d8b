"""Tests of `plots/rbplot study` (railbench/study*.py) on a synthetic study folder, and of the
figures `workbench study` draws itself on a real (tiny) study.

usage: /usr/bin/python3 -m pytest -q tests/plots/test_study_plots.py
    The real study needs the workbench program: $RAILBENCH_WORKBENCH, else
    build/workbench/app/workbench.  Work files go to a temp dir, removed on success (kept on
    failure, or always with RB_KEEP_TMP=1).
"""
import csv
import os
import subprocess
import tempfile

import h5py
import numpy as np
import pytest

from helpers import RBPLOT, ROOT, work_folder

from railbench.study_cost import accuracy_rows
from railbench.study_data import compact, load_study, parse_overrides
from railbench.study_precision import effect_rows, work_precision_rows

TMP = tempfile.mkdtemp(prefix="rb_study_test_")
WS = ["ws1", "ws2", "ws3", "ws4"]
work_files = work_folder(TMP)


def write_case(path, t, y, flange=0.0, status="ok", method="kec"):
    """A result file with the groups the study figures read; y(t) for every wheelset."""
    with h5py.File(path, "w") as f:
        f.attrs["solver"] = "abm"
        f["time"] = t
        g = f.create_group("bodies")
        g.attrs["names"] = "car\n" + "\n".join(WS)
        c = f.create_group("contact")
        c.attrs["method"] = method
        c.attrs["table_build_time_s"] = 0.1
        c.attrs["table_bytes"] = 1000
        for k, ws in enumerate(WS):
            b = g.create_group(ws)
            b.attrs["kind"] = "wheelset"
            b["y"] = y * (k + 1)
            b["yaw"] = 0.1 * y
            for side in ("left", "right"):
                w = c.create_group(f"{ws}/{side}")
                w["normal_force"] = 5e4 + 1e6 * y
                w["creep_force_y"] = 1e5 * y
                w["flange_indentation"] = flange * np.maximum(y, 0)
                w["flange_force"] = flange * 1e9 * np.maximum(y, 0)
        s = f.create_group("stats")
        s.attrs["status"] = status
        s.attrs["cpu_time_s"] = 1.0


# case id, label, role, overrides, solver (as workbench study writes it), status, cpu, evals,
# y offset [m], t_end
CASES = [
    ("case_a", "KEC abm", "baseline", "contact.method=kec solver.method=abm solver.step=0.00025",
     "abm h=0.25ms", "ok", 2.0, 1000, 0.0, 1.0),
    ("case_b", "LUT K=1e10 abm", "",
     "contact.flange_stiffness=1e10 contact.method=lut solver.method=abm solver.step=0.00025",
     "abm h=0.25ms", "ok", 3.0, 1000, 1e-3, 1.0),
    ("case_c", "LUT K=1e12 abm", "",
     "contact.flange_stiffness=1e12 contact.method=lut solver.method=abm solver.step=0.00025",
     "abm h=0.25ms", "failed", 0.0, 500, 2e-3, 0.5),
    ("case_d", "KEC bdf tol=1e-6", "",
     "contact.method=kec solver.atol=1e-06 solver.method=bdf solver.rtol=1e-06", "bdf tol=1e-6",
     "ok", 4.0, 800, 1e-4, 1.0),
    ("case_r", "KEC ref", "reference",
     "contact.method=kec profiles.refined_tables=true solver.atol=1e-10 solver.method=bdf "
     "solver.rtol=1e-09", "bdf rtol=1e-9 atol=1e-10", "ok", 9.0, 5000, 0.0, 1.0),
    ("case_q", "KEC ref check", "reference_check",
     "contact.method=kec profiles.refined_tables=true solver.atol=1e-11 solver.method=bdf "
     "solver.rtol=1e-10", "bdf rtol=1e-10 atol=1e-11", "ok", 12.0, 9000, 1e-6, 1.0),
]


def make_study(d):
    os.makedirs(d, exist_ok=True)
    t_full = np.linspace(0, 1, 101)
    base_y = 1e-3 * np.sin(2 * np.pi * t_full)
    with open(os.path.join(d, "summary.csv"), "w", newline="") as fr, \
            open(os.path.join(d, "summary_cases.csv"), "w", newline="") as fc:
        wr, wc = csv.writer(fr), csv.writer(fc)
        wr.writerow(["case", "repeat", "label", "role", "base", "overrides", "status",
                     "cpu_time_s", "rhs_evals", "t_reached", "message", "file"])
        wc.writerow(["case", "label", "role", "base", "overrides", "solver", "runs", "runs_ok",
                     "status",
                     "median_cpu_time_s", "min_cpu_time_s", "max_cpu_time_s", "rhs_evals",
                     "rhs_evals_jac", "steps", "rejected_steps", "jacobian_evals",
                     "nonlinear_iters", "t_reached", "model_evaluations", "message", "file"])
        for cid, lab, role, ov, solver, st, cpu, ev, dy, tend in CASES:
            n = int(round(tend * 100)) + 1
            h5 = os.path.join(d, f"{cid}_r0.h5")
            write_case(h5, t_full[:n], base_y[:n] + dy, flange=1.0 if "lut" in ov else 0.0,
                       status=st, method="lut" if "lut" in ov else "kec")
            msg = "step size too small at t = 0.5" if st != "ok" else ""
            wr.writerow([cid, 0, lab, role, "b.lua", ov, st, cpu, ev, tend, msg, h5])
            wc.writerow([cid, lab, role, "b.lua", ov, solver, 1, int(st == "ok"), st, cpu, cpu,
                         cpu, ev, 0, ev, 0, 0, 0, tend, ev, msg, h5])
    # The engine's errors (workbench/study/reference_errors.hpp; their values are its unit
    # test's): case_d 0.1 mm off on ws1 .. 0.4 mm on ws4, case_q 1e-6 m per wheelset number.
    with open(os.path.join(d, "summary_errors.csv"), "w", newline="") as fe:
        we = csv.writer(fe)
        we.writerow(["case", "against", "reference", "quantity", "unit", "max", "rms"])
        we.writerow(["case_d", "reference", "case_r", "y", "mm", 0.4, 0.1 * np.sqrt(7.5)])
        we.writerow(["case_d", "reference", "case_r", "yaw", "mrad", 0.04, ""])
        we.writerow(["case_q", "reference", "case_r", "y", "mm", 0.004, 0.0025])
        we.writerow(["case_b", "baseline", "case_a", "y", "mm", "inf", "inf"])


DIR = os.path.join(TMP, "study")
make_study(DIR)


def test_labels_and_keys():
    assert compact(1e-06) == "1e-6" and compact(7.075e13) == "7.075e13"
    ov = parse_overrides("solver.method=bdf solver.rtol=1e-06 solver.atol=1e-06 "
                            "solver.max_step=0.001")
    assert ov == {"solver.method": "bdf", "solver.rtol": "1e-06", "solver.atol": "1e-06",
                  "solver.max_step": "0.001"}
    st = load_study(DIR)
    c = {x.id: x for x in st.cases}
    assert c["case_b"].method == "lut" and c["case_b"].K == 1e10 and c["case_a"].K is None
    assert c["case_b"].solver_key == "abm h=0.25ms"
    assert c["case_b"].model_key == "LUT K=1e10"


def test_accuracy_pairs_eq33():
    st = load_study(DIR)
    rows = accuracy_rows(st)
    by = {(r["lut_case"], r["wheelset"]): r for r in rows}
    # LUT K=1e10 = KEC + 1 mm on every wheelset (times k for wheelset k: y scales, offset too).
    r = by[("case_b", "ws1")]
    assert abs(float(r["max_abs_mm"]) - 1.0) < 1e-9 and abs(float(r["mean_abs_mm"]) - 1.0) < 1e-9
    assert abs(float(by[("case_b", "ws4")]["max_abs_mm"]) - 4.0) < 1e-9
    assert float(r["eq33_max"]) == float(r["eq33_mean"]) > 0
    assert abs(float(by[("case_b", "all")]["max_abs_mm"]) - 4.0) < 1e-9
    # The failed LUT run is compared up to where it stopped.
    f = by[("case_c", "ws1")]
    assert f["samples"] == 51 and "failed" in f["note"], f
    assert ("case_d", "ws1") not in by  # BDF has no LUT partner


def test_work_precision_against_reference():
    st = load_study(DIR)
    rows = {r["case"]: r for r in work_precision_rows(st)}
    assert abs(float(rows["case_d"]["y_max_mm"]) - 0.4) < 1e-6, rows["case_d"]  # 0.1 mm x ws4
    assert abs(float(rows["case_d"]["y_rms_mm"]) - 0.1 * np.sqrt(7.5)) < 1e-3
    assert rows["case_q"]["note"].startswith("reference_check")
    assert abs(float(rows["case_q"]["y_max_mm"]) - 0.004) < 1e-9
    assert rows["case_b"]["note"] == "no reference case with the same model"
    # A diverged run is infinitely wrong; a quantity the engine could not compare stays empty.
    assert st.errors_of(st.case("case_b"), "baseline")[1]["lateral displacement y"][0] == np.inf
    assert rows["case_d"]["Q_max_kN"] == ""


def test_effects_relative():
    st = load_study(DIR)
    rows = {r["case"]: r for r in effect_rows(st)}
    assert float(rows["case_a"]["us_per_eval"]) == 2000.0
    assert float(rows["case_b"]["relative_to_baseline"]) == 1.5
    assert rows["case_c"]["us_per_eval"] == ""  # failed


def test_plot_study_writes_everything():
    out = subprocess.run([RBPLOT, "study", DIR], capture_output=True, text=True)
    assert out.returncode == 0, out.stderr
    names = {os.path.basename(p) for p in out.stdout.split()}
    for n in ("study_cost.png", "study_cost.csv", "study_failures.csv",
              "study_accuracy_lut_vs_kec.csv", "study_accuracy_lut_vs_kec.png",
              "study_work_precision.csv", "study_work_precision.png", "study_effects.csv",
              "study_effects.png", "study_lut_stiffness_abm_h_0.25ms.png"):
        assert n in names and os.path.getsize(os.path.join(DIR, n)) > 0, (n, names)
    fails = list(csv.DictReader(open(os.path.join(DIR, "study_failures.csv"))))
    assert len(fails) == 1 and fails[0]["reason"].startswith("step size too small"), fails
    cost = {r["case"]: r for r in csv.DictReader(open(os.path.join(DIR, "study_cost.csv")))}
    assert cost["case_b"]["K"] == "1e10" and cost["case_b"]["us_per_eval"] == "3000.000"


def test_not_a_study_folder():
    out = subprocess.run([RBPLOT, "study", TMP], capture_output=True, text=True)
    assert out.returncode == 1 and out.stderr.startswith("railbench study: error: "), out.stderr



def test_workbench_study_writes_the_solver_labels_and_draws_the_figures():
    """A real study (tests/scenarios/data/study_plots.lua: 7 cases of 2 m): `workbench study`
    writes each case's solver label into summary_cases.csv and runs `python3 -m railbench study`,
    whose cost table groups the cases by that label."""
    wb = os.environ.get("RAILBENCH_WORKBENCH") or \
        os.path.join(ROOT, "build", "workbench", "app", "workbench")
    if not os.access(wb, os.X_OK):
        pytest.fail(f"no workbench program at {wb} (set RAILBENCH_WORKBENCH)")
    out = os.path.join(TMP, "real_study")
    env = dict(os.environ, RAILBENCH_ROOT=ROOT)
    env.pop("RAILBENCH_STUDY_PLOTS", None)
    r = subprocess.run([wb, "study", "tests/scenarios/data/study_plots.lua", "--out", out],
                       cwd=ROOT, env=env, capture_output=True, text=True, timeout=280,
                       stdin=subprocess.DEVNULL)
    assert r.returncode == 0, r.stdout + r.stderr
    with open(os.path.join(out, "summary_cases.csv"), newline="") as f:
        rows = list(csv.DictReader(f))
    assert sorted({row["solver"] for row in rows}) == ["", "dopri5 tol=1e-7", "dopri5 tol=1e-8",
                                                      "rk4 h=0.5ms"], rows
    for row in rows:  # the label holds the solver label the figures group by
        assert row["solver"] in row["label"], row
    with open(os.path.join(out, "study_cost.csv"), newline="") as f:
        cost = {row["case"]: row for row in csv.DictReader(f)}
    by_case = {row["case"]: row for row in rows}
    for cid, row in cost.items():
        assert row["solver"] == (by_case[cid]["solver"] or row["integrator"]), row
    for name in ("study_cost.png", "study_accuracy_lut_vs_kec.png", "study_work_precision.png",
                 "study_effects.png"):
        assert os.path.getsize(os.path.join(out, name)) > 10000, name
