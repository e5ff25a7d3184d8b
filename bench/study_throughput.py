#!/usr/bin/env python3
"""Throughput of the ways of running a study: cases per hour, parallel efficiency, overhead.

usage: bench/study_throughput.py [CSV] [--workbench BIN] [--cases 12] [--distance 400]
                                 [--ranks 1,2,3] [--jobs 1,2] [--mpirun mpirun]

One study of N equal-ish cases (the paper's case 3, case3_base.lua, over `distance` metres plus
5 m per case, so every case is its own run of about the same cost) is run from scratch into a
fresh folder by each runner: the local pool with --jobs 1 and 2, and the MPI farm
(`mpirun --oversubscribe -np R ... --mpi`) with R = 1, 2, 3 ranks (rank 0 runs runs too), and
with 3 ranks and rank 0 as a pure dispatcher (RAILBENCH_MPI_RANK0_RUNS=0). Then a study of N
near-empty cases (0.5 m) with --jobs 1 gives the fixed cost of a case (process start, scenario
load, track build, hashing, result writing, stamping) directly. Figures are off
(RAILBENCH_STUDY_PLOTS=0): they are a cost per study, not per case.

Columns of the CSV (default out/studies/study_throughput.csv):
  runner, slots       local jobs=J or mpi ranks=R, and the runs at once (J, or R; R - 1 with a
                      pure dispatcher)
  cases, wall_s       the study's wall time (from the command's start to its exit)
  cases_per_hour      3600 * cases / wall_s
  efficiency          cases_per_hour / (slots * cases_per_hour of local jobs=1): 1 is perfect
                      scaling; on a machine with C cores it cannot exceed C / slots
  sum_run_wall_s      the runs' own wall time (/stats/wall_time_s: the integration and output)
  sum_run_cpu_s       the runs' CPU time (/stats/cpu_time_s)
  overhead_per_case_s (wall_s * slots - sum_run_wall_s) / cases: slot time per case spent outside
                      the runs' own loops (process start, load, track, hash, stamp, dispatch);
                      on a loaded machine it includes the time the runs waited for a core
  cpu_s               CPU time of the whole command and every process under it (RUSAGE_CHILDREN:
                      runner, mpirun, ranks, runs)
  overhead_cpu_per_case_s (cpu_s - sum_run_cpu_s) / cases: the CPU a case costs outside the
                      run's own loop, which a loaded machine does not inflate
  cores, load_1min    the machine's cores and its load average when the runner started
"""
import argparse
import csv
import os
import resource
import shutil
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)


def study_file(folder, name, distances):
    path = os.path.join(folder, name + ".lua")
    values = ", ".join(f"{d:g}" for d in distances)
    with open(path, "w") as f:
        f.write(f'study {{ base = "{ROOT}/scenarios/studies/case3_base.lua",\n'
                f'        matrix = {{ ["run.distance"] = {{ {values} }} }} }}\n')
    return path


def run_totals(folder):
    with open(os.path.join(folder, "summary.csv"), newline="") as f:
        rows = list(csv.DictReader(f))
    bad = [r["case"] for r in rows if r["status"] != "ok"]
    if bad:
        raise SystemExit(f"{folder}: runs not ok: {bad}")
    return (len(rows), sum(float(r["wall_time_s"]) for r in rows),
            sum(float(r["cpu_time_s"]) for r in rows))


def measure(label, slots, command, folder, env):
    shutil.rmtree(folder, ignore_errors=True)
    load = os.getloadavg()[0]
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.monotonic()
    done = subprocess.run(command, env=env, stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL,
                          stderr=subprocess.PIPE, text=True)
    wall = time.monotonic() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    if done.returncode != 0:
        raise SystemExit(f"{label}: exit {done.returncode}\n{done.stderr}")
    cases, run_wall, run_cpu = run_totals(folder)
    row = {"runner": label, "slots": slots, "cases": cases, "wall_s": round(wall, 3),
           "cases_per_hour": round(3600.0 * cases / wall, 1),
           "sum_run_wall_s": round(run_wall, 3), "sum_run_cpu_s": round(run_cpu, 3),
           "overhead_per_case_s": round((wall * slots - run_wall) / cases, 3),
           "cpu_s": round(cpu, 3), "overhead_cpu_per_case_s": round((cpu - run_cpu) / cases, 3),
           "cores": os.cpu_count(), "load_1min": round(load, 2)}
    print(f"{label:32s} {cases} cases in {wall:7.2f} s: {row['cases_per_hour']:8.0f} cases/h, "
          f"overhead {row['overhead_per_case_s']:.3f} s/case, "
          f"{row['overhead_cpu_per_case_s']:.3f} s CPU/case (load {load:.1f})", flush=True)
    return row


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("csv", nargs="?", default=os.path.join(ROOT, "out", "studies",
                                                           "study_throughput.csv"))
    ap.add_argument("--workbench", default=os.path.join(ROOT, "build", "workbench", "app",
                                                        "workbench"))
    ap.add_argument("--cases", type=int, default=12)
    ap.add_argument("--distance", type=float, default=400.0)
    ap.add_argument("--jobs", default="1,2")
    ap.add_argument("--ranks", default="1,2,3")
    ap.add_argument("--mpirun", default="mpirun")
    a = ap.parse_args()
    wb = [os.path.abspath(a.workbench), "--root", ROOT, "study"]
    mpi = [a.mpirun, "--oversubscribe"] + (["--allow-run-as-root"] if os.getuid() == 0 else [])
    env = dict(os.environ, RAILBENCH_STUDY_PLOTS="0")
    tmp = tempfile.mkdtemp(prefix="study_throughput.")
    try:
        full = study_file(tmp, "cases", [a.distance + 5 * i for i in range(a.cases)])
        empty = study_file(tmp, "empty", [0.5 + 0.01 * i for i in range(a.cases)])
        out = os.path.join(tmp, "out")
        rows = []
        for j in [int(x) for x in a.jobs.split(",")]:
            rows.append(measure(f"local jobs={j}", j, wb + [full, "--out", out, "--jobs", str(j)],
                                out, env))
        if shutil.which(a.mpirun):
            for r in [int(x) for x in a.ranks.split(",")]:
                rows.append(measure(f"mpi ranks={r}", r,
                                    mpi + ["-np", str(r)] + wb + [full, "--out", out, "--mpi"],
                                    out, env))
            r = max(int(x) for x in a.ranks.split(","))
            if r > 1:
                rows.append(measure(f"mpi ranks={r} rank 0 dispatches only", r - 1,
                                    mpi + ["-np", str(r)] + wb + [full, "--out", out, "--mpi"],
                                    out, dict(env, RAILBENCH_MPI_RANK0_RUNS="0")))
        else:
            print(f"{a.mpirun} not found: no MPI rows", file=sys.stderr)
        rows.append(measure("local jobs=1 near-empty cases", 1,
                            wb + [empty, "--out", out, "--jobs", "1"], out, env))
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    base = rows[0]["cases_per_hour"]
    for row in rows:  # the near-empty study is a different study: no efficiency
        if "near-empty" not in row["runner"]:
            row["efficiency"] = round(row["cases_per_hour"] / (row["slots"] * base), 3)
    os.makedirs(os.path.dirname(os.path.abspath(a.csv)), exist_ok=True)
    fields = ["runner", "slots", "cases", "wall_s", "cases_per_hour", "efficiency",
              "sum_run_wall_s", "sum_run_cpu_s", "overhead_per_case_s", "cpu_s",
              "overhead_cpu_per_case_s", "cores", "load_1min"]
    with open(a.csv, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=fields)
        w.writeheader()
        w.writerows(rows)
    print(f"wrote {a.csv}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
