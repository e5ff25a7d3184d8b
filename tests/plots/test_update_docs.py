#!/usr/bin/python3
"""Tests of plots/update_docs.py (the generator of the run-derived blocks of docs/) on synthetic
study outputs: blocks are replaced between their markers, the hand-written text around them is
kept, a missing input gives a "Not generated" line instead of stale numbers, a missing marker is
an error, and the speed table judges the targets. Stamping: every generated block names the
commit and date of its runs (plots/provenance.py records, the hard-case record's commit column),
a dirty tree and an unrecorded commit are said so. The repository's own docs: every generated
block has a generator and starts with a stamp or a "Not generated" line. The validation tables
(plots/validation_tables.py) on synthetic result files.

usage: /usr/bin/python3 tests/plots/test_update_docs.py   -> exit 0 if all pass
"""
import csv
import json
import os
import shutil
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "plots"))
import provenance  # noqa: E402
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
    blocks_v = ["validation_case1", "validation_case2", "validation_case3", "validation_cost"]
    blocks_h = ["hard_cases_detail"]
    for md, names in (("studies.md", blocks_s), ("performance.md", blocks_p),
                      ("validation.md", blocks_v), ("hard_cases.md", blocks_h),
                      ("integrators.md", ["bench_integrators"]),
                      ("contact_dynamics.md", ["coupling_convergence"])):
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
    check(ud.main([out, "--docs", docs]) == 0, "update_docs returns 0 (second run)")
    # --pages: a partial regeneration leaves the other pages as they are.
    with open(os.path.join(docs, "studies.md")) as f:
        before = f.read()
    with open(os.path.join(docs, "studies.md"), "w") as f:
        f.write(before.replace("(49x)", "(KEPT)"))
    check(ud.main([out, "--build", os.path.join(TMP, "nobuild"), "--docs", docs, "--pages",
                   "performance.md"]) == 0, "--pages performance.md returns 0")
    check("(KEPT)" in open(os.path.join(docs, "studies.md")).read(),
          "--pages leaves the pages not named alone")
    check(ud.main([out, "--docs", docs, "--pages", "nosuch.md"]) == 1,
          "--pages with an unknown page is an error")
    with open(os.path.join(docs, "studies.md"), "w") as f:
        f.write(before)
    stamps(docs, out)
    git_state()
    repository_docs()
    validation_tables()
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
    write_csv(os.path.join(build, "dynamics", "coupling_case3.csv"), rows)
    rc = ud.main(["-", "--build", build, "--docs", docs, "--only", "contact_dynamics"])
    text = open(md).read()
    block = text.split("generated: coupling_convergence")[1].split("end: coupling_convergence")[0]
    check(rc == 0 and "OLD NUMBERS" not in text, "--only contact_dynamics replaces the block")
    check(text.startswith("hand before") and "hand after" in text, "... keeps the hand text")
    check("| consistent | 0.125 | 0.0022 | 0.62 | 41600 | 14.9 | 3.92 |" in block,
          "... with the consistent row")
    check("| lagged | 0.0625 | – |" in block, "... and the finest step without a difference")
    check("commit" in block, "... stamped with the commit")


def block(text, name):
    return ud.doc_blocks(text)[name]


def stamps(docs, out):
    """Provenance: a clean study, a dirty one, one without a record, the hard-case record."""
    build = os.path.join(TMP, "build")
    provenance.record(os.path.join(out, "speed", "provenance.json"),
                      entry={"commit": "abc1234", "dirty": False, "date": "2026-12-01"})
    provenance.record(os.path.join(out, "efficiency_case3", "provenance.json"),
                      entry={"commit": "def5678", "dirty": True, "date": "2026-12-02"})
    # A study resumed at another commit lists both; recording the same state again does not.
    pv = os.path.join(out, "refinement", "provenance.json")
    provenance.record(pv, entry={"commit": "1111111", "dirty": False, "date": "2026-11-30"})
    provenance.record(pv, entry={"commit": "2222222", "dirty": False, "date": "2026-12-01"})
    provenance.record(pv, entry={"commit": "2222222", "dirty": False, "date": "2026-12-03"})
    check(len(provenance.read(pv)) == 2, "one provenance entry per tree state")
    write_csv(os.path.join(out, "refinement", "study_cost.csv"), [
        cost("a", "kec", "abm", "0.5", 50006, step="0.001"),
        cost("a", "kec", "abm", "0.5", 50006, step="0.001", refined="true")])
    hard = dict(case="lut_stiff_flange", combination="rk4 1 ms", expect="any", rc="2",
                status="failed", verdict="pass", t_reached="1.869", t_end="2", cpu_s="0.05",
                wall_s="0.1", rhs_evals="7493", rhs_evals_jac="0", steps="1870",
                rejected_steps="6", jacobian_evals="0", max_abs_y_mm="11.3",
                max_normal_kN="900", min_normal_kN="-300", max_flange_kN="3321",
                max_normal_flange_kN="3321", flange_time_share="0.01", max_indent_mm="0.02",
                max_abs_yq="5.8", ws1_y_pp_last_mm="12", onset_t="1", onset_speed="15",
                problems="", notes="", commit="abc1234+dirty", run_date="2026-12-01",
                message="rk4: failed at t = 1.869: the right-hand side kept failing; the LUT "
                        "entry (y = -50 mm) left the table [-18, 18] x [-5, 5] mm")
    write_csv(os.path.join(build, "hard", "hard_cases.csv"), [
        hard, dict(hard, case="hunting", combination="dopri5 1e-06 V=80", status="ok",
                   message="", ws1_y_pp_last_mm="7.8", onset_speed="nan")])
    bench = {"context": {"host_name": "h", "num_cpus": 2, "mhz_per_cpu": 2000, "date": "d"},
             "benchmarks": [
                 {"name": "BM_rhs_median", "run_name": "BM_rhs", "run_type": "aggregate",
                  "aggregate_name": "median", "cpu_time": 37.0, "time_unit": "ns"},
                 {"name": "runMethod/abm_mean", "run_name": "runMethod/abm",
                  "run_type": "aggregate", "aggregate_name": "mean", "ns/step": 9e9},
                 {"name": "runMethod/abm_median", "run_name": "runMethod/abm",
                  "run_type": "aggregate", "aggregate_name": "median", "ns/step": 864.0,
                  "rhs/step": 2.006, "overhead_ns": 481.0, "steps": 1000.0}]}
    with open(os.path.join(out, "bench_integrators.json"), "w") as f:
        json.dump(bench, f)
    provenance.record(os.path.join(out, "bench_integrators.provenance.json"),
                      entry={"commit": "0badc0d", "dirty": False, "date": "2026-12-04"})
    check(ud.main([out, "--build", build, "--docs", docs]) == 0, "update_docs with provenance")
    s = open(os.path.join(docs, "studies.md")).read()
    p = open(os.path.join(docs, "performance.md")).read()
    h = open(os.path.join(docs, "hard_cases.md")).read()
    check(block(p, "speed").startswith("*Generated by `plots/update_docs.py` from runs of commit "
                                       "`abc1234` (2026-12-01).*"),
          "a clean tree's block is stamped with its commit and date")
    eff = block(s, "efficiency")
    check("`def5678`" in eff.split("\n")[0] and "dirty tree" in eff.split("\n")[0],
          "a dirty tree's block says so in its stamp")
    check("`def5678`" in block(s, "efficiency_paper").split("\n")[0] and
          "`def5678`" in block(s, "accuracy").split("\n")[0] or
          block(s, "accuracy").startswith(ud.NOT_GENERATED),
          "blocks from the same study carry its stamp")
    ref = block(s, "refinement").split("\n")[0]
    check("`1111111` (2026-11-30)" in ref and "`2222222` (2026-12-03)" in ref and
          "several trees" in ref, "a study resumed across commits lists every commit")
    check("unrecorded commit" in block(p, "bench").split("\n")[0] or
          block(p, "bench").startswith(ud.NOT_GENERATED), "no record: an unrecorded commit")
    hd = block(h, "hard_cases_detail")
    check(hd.split("\n")[0].count("`abc1234`") == 1 and "dirty tree" in hd.split("\n")[0],
          "the hard-case blocks are stamped from the record's commit column")
    check("`abc1234`" in block(s, "hard_cases").split("\n")[0],
          "the hard-case table of studies.md is stamped too")
    check("the LUT entry left the table" in hd and "1870 (6)" in hd,
          "hard-case detail: failure reason, steps (rejected)")
    check("onset none" in hd and "ws1 p-p last s 7.8 mm" in hd and "onset 15" not in hd,
          "hunting measures only for the hunting cases")
    check("2 combinations: 2 pass" in hd, "hard-case detail: the suite's verdict")
    bi = block(open(os.path.join(docs, "integrators.md")).read(), "bench_integrators")
    check(bi.startswith("*Generated by `plots/update_docs.py` from runs of commit `0badc0d` "
                        "(2026-12-04).*") and "| runMethod/abm | 864 | 2.01 | 481 | 1000 |" in bi
          and "rhs 37 ns" in bi and "9000000000" not in bi,
          "bench_integrators: medians only, stamped from its own record")
    # Every block of every page: a stamp first, or the "Not generated" line.
    for md in ("studies.md", "performance.md", "validation.md", "hard_cases.md",
               "integrators.md"):
        text = open(os.path.join(docs, md)).read()
        bad = [n for n, b in ud.doc_blocks(text).items()
               if not (b.startswith("*Generated by `plots/update_docs.py` from runs of ") or
                       b.startswith(ud.NOT_GENERATED))]
        check(not bad, f"{md}: every block starts with a stamp or 'Not generated' {bad}")
    # A record from before the commit column: unknown, not silently the current commit.
    rows = ud.read_csv(os.path.join(build, "hard", "hard_cases.csv"))
    for r in rows:
        r["commit"] = ""
    write_csv(os.path.join(build, "hard", "hard_cases.csv"), rows)
    check(ud.block_provenance("hard_cases", out, build) == [],
          "a hard-case record without commits has an unrecorded provenance")


def git_state():
    """provenance.current on a scratch repository: the short commit, clean, a change under docs/
    (update_docs.py's own output) keeps it clean, a change elsewhere makes it dirty; no git
    repository gives "unknown"."""
    import subprocess
    repo = os.path.join(TMP, "repo")
    os.makedirs(os.path.join(repo, "docs"))
    for name in ("a.txt", "docs/p.md"):
        with open(os.path.join(repo, name), "w") as f:
            f.write("1\n")
    git = ["git", "-C", repo, "-c", "user.email=t@t", "-c", "user.name=t"]
    try:
        subprocess.run(git + ["init", "-q"], check=True)
        subprocess.run(git + ["add", "."], check=True)
        subprocess.run(git + ["commit", "-qm", "x"], check=True)
        head = subprocess.run(git + ["rev-parse", "--short", "HEAD"], check=True,
                              capture_output=True, text=True).stdout.strip()
    except (OSError, subprocess.CalledProcessError) as e:
        print(f"skip git_state: no usable git ({e})")
        return
    e = provenance.current(repo)
    check(e["commit"] == head and not e["dirty"], "provenance: commit of a clean tree")
    with open(os.path.join(repo, "docs", "p.md"), "w") as f:
        f.write("2\n")
    check(not provenance.current(repo)["dirty"], "provenance: a change under docs/ is not dirty")
    with open(os.path.join(repo, "a.txt"), "w") as f:
        f.write("2\n")
    check(provenance.current(repo)["dirty"], "provenance: a changed tracked file is dirty")
    check(provenance.tag(provenance.current(repo)) == head + "+dirty",
          "provenance: the record tag of a dirty tree")
    nogit = os.path.join(TMP, "nogit")
    os.makedirs(nogit)
    check(provenance.current(nogit)["commit"] == "unknown", "provenance: no git -> unknown")


def repository_docs():
    """The repository's docs: every generated block has a generator (a name update_docs.py
    writes, on the page it writes it to) and starts with a stamp or a "Not generated" line."""
    empty = os.path.join(TMP, "empty")
    generated = ud.generate(empty, empty)
    here_docs = os.path.join(HERE, "..", "..", "docs")
    pages = sorted(f for f in os.listdir(here_docs) if f.endswith(".md"))
    found = {}
    for md in pages:
        text = open(os.path.join(here_docs, md)).read()
        starts = text.count("<!-- generated: ")
        blocks = ud.doc_blocks(text)
        check(starts == len(blocks), f"docs/{md}: every generated marker has its end marker")
        for name, body in blocks.items():
            found.setdefault(md, set()).add(name)
            check(name in generated.get(md, {}),
                  f"docs/{md}: block '{name}' has a generator in update_docs.py")
            check(body.startswith("*Generated by `plots/update_docs.py` from runs of ") or
                  body.startswith(ud.NOT_GENERATED),
                  f"docs/{md}: block '{name}' starts with a stamp or 'Not generated'")
    for md, names in generated.items():
        missing_here = set(names) - found.get(md, set())
        check(not missing_here, f"docs/{md}: every generator has its block {sorted(missing_here)}")
    # A block without a source of its own is stamped from the `./wb studies` invocation.
    os.makedirs(os.path.join(empty, "x"), exist_ok=True)
    provenance.record(os.path.join(empty, "provenance.json"),
                      entry={"commit": "feedbee", "dirty": False, "date": "2026-12-01"})
    check(ud.block_provenance("some_new_block", empty, empty)[0]["commit"] == "feedbee",
          "a block without a listed source is stamped from OUT_DIR/provenance.json")


def validation_tables():
    """plots/validation_tables.py on a synthetic study folder of h5 results."""
    import h5py
    import numpy as np
    import validation_tables as vt
    d = os.path.join(TMP, "out", "validation")
    os.makedirs(d, exist_ok=True)

    def result(name, bodies, t, status="ok"):
        path = os.path.join(d, name)
        with h5py.File(path, "w") as f:
            f["/time"] = t
            f.create_group("/stats").attrs["status"] = status
            for b, kind, y, yaw in bodies:
                g = f.create_group("/bodies/" + b)
                g.attrs["kind"] = kind
                g["s"] = 10.0 * t
                g["y"] = y
                g["yaw"] = yaw
        return path

    t = np.arange(0, 12.005, 0.01)
    w = lambda y: np.full_like(t, y)  # noqa: E731
    rows = []
    for m, y in (("kec", -0.4e-3), ("lut", -0.3e-3)):
        f = result(f"c1_{m}.h5", [("frame", "frame", w(0), w(0)),
                                  ("ws", "wheelset", w(y), w(-0.25e-3))], t)
        rows.append(dict(case="c1" + m, label="", role="", base=f"scenarios/validation/"
                         f"case1_R300_{m}.lua", overrides="", runs=3, runs_ok=3, status="ok",
                         median_cpu_time_s="0.3", min_cpu_time_s="0.29", max_cpu_time_s="0.31",
                         rhs_evals="120006", rhs_evals_jac="0", steps="60000",
                         rejected_steps="0", t_reached="12", message="", file=f))
    t2 = np.arange(0, 24.465, 0.01)
    for case in (2, 3):
        for m, y1 in (("kec", -5.0e-3), ("lut", -6.0e-3)):
            y = np.where(t2 > 19.5, y1, 0.5 * y1) if case == 2 else y1 * np.sin(t2)
            body = [("car", "car", w(0)[:1].repeat(len(t2)) + 0.028, 0 * t2),
                    ("ws1", "wheelset", y, 0 * t2 - 4.6e-3), ("bogie1", "bogie", y / 2, 0 * t2)]
            f = result(f"c{case}_{m}.h5", body, t2)
            rows.append(dict(rows[0], case=f"c{case}{m}", base=f"../validation/case{case}_"
                             f"{m}.lua", steps="97844", t_reached="24.461",
                             rhs_evals="195694", file=f))
    rows.append(dict(rows[-1], case="c3dp", overrides="solver.method=dopri5 solver.rtol=1e-06",
                     status="failed", file=os.path.join(d, "absent.h5")))
    write_csv(os.path.join(d, "summary_cases.csv"), rows)
    vt.make(d)
    steady = ud.read_csv(os.path.join(d, "validation_steady.csv"))
    c1 = [r for r in steady if r["case"] == "1"]
    check(len(c1) == 2 and {r["body"] for r in c1} == {"ws"},
          "validation: case 1 steady values of the wheelset, not the kinematic frame")
    check(abs(float(c1[0]["y_mm"]) + 0.4) < 1e-9 and "s = 110..120 m" == c1[0]["window"],
          "validation: case 1 mean over s = 110..120 m in mm")
    c2 = [r for r in steady if r["case"] == "2" and r["method"] == "kec"]
    check([r["body"] for r in c2] == ["ws1", "bogie1", "car"],
          "validation: case 2 bodies in the paper's order (wheelsets, bogies, car)")
    check(abs(float(c2[0]["y_mm"]) + 5.0) < 1e-9, "validation: case 2 mean over t = 20..24 s")
    c3 = ud.read_csv(os.path.join(d, "validation_case3.csv"))
    check(len(c3) == 1 and c3[0]["solver"] == "scenario ABM 0.25 ms" and
          abs(float(c3[0]["max_abs_y_lut_mm"]) - 6.0) < 1e-3 and
          abs(float(c3[0]["eq33_max_percent"]) - 100 / 6) < 0.1,
          "validation: Eq. (33) difference KEC vs LUT on case 3, solver from the run")
    cost_rows = ud.read_csv(os.path.join(d, "validation_cost.csv"))
    check(len(cost_rows) == 7 and cost_rows[-1]["solver"] == "dopri5 1e-06" and
          cost_rows[-1]["cpu_median_s"] == "", "validation: cost rows, a failed case has no CPU")
    blocks = ud.validation_blocks(os.path.join(TMP, "out"))
    check("| 300 | -0.400 / -0.250 | -0.300 / -0.250 | -8.857 / -4.557 |" in
          blocks["validation_case1"], "validation block: ours beside the paper's Table 5")
    check("| ws1 | -5.000 / -4.600 | -6.000 / -4.600 | -8.829 / -4.782 |" in
          blocks["validation_case2"], "validation block: ours beside the paper's Table 6")
    check("failed" in blocks["validation_cost"] and "81.5x" in blocks["validation_cost"],
          "validation cost block: real-time factor and failed case")


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
