"""Instruction counts per right-hand-side evaluation of every case of an effects study
(scenarios/studies/effects.lua), for issue 7 item 5 ("disabled effects must cost nothing
measurable").

CPU times on a shared virtual machine scatter by 10-40 % between repeats, more than most effects
cost; valgrind's callgrind counts executed instructions, which are the same from run to run
whatever else the machine does. Each case of the study (its base and overrides, from
summary_cases.csv) is run again under callgrind for the first DURATION seconds, collecting only
inside the integration (rb::integ::integrate: right-hand sides, integrator, output callbacks;
not the set-up), less the result-file flushes (their number follows the wall clock, so the
machine's load), and the instructions are divided by the rhs evaluations of that run.

    plots/rbplot effects-instructions OUT/effects [--workbench BIN] [--root ROOT]
                                        [--duration 8] [--match REGEX] [--csv NAME] [--tag TAG]

Also used on the speed study (`./wb studies --only speed`: OUT/speed, --duration 3), and with
--workbench/--root of an earlier build and --tag naming it, for a before/after comparison.

Writes OUT/effects/study_effects_instructions.csv: case, label, method, instructions, rhs_evals,
instructions_per_eval, relative_to_baseline (the case of role "baseline" with the same method),
note, build, duration (the simulated seconds measured).
"""
import csv
import os
import re
import subprocess
import sys
import tempfile

import h5py

from .common import parser
from .provenance import ROOT


def callgrind_total(path: str) -> int:
    with open(path) as f:
        for line in f:
            m = re.match(r"^(summary|totals):\s+(\d+)", line)
            if m:
                return int(m.group(2))
    raise RuntimeError(f"{path}: no totals line")


# The result file is flushed to disk every second of wall time while a run goes
# (workbench/run/simulate.cpp): under callgrind the number of flushes follows the machine's load,
# not the model, so their instructions are taken out of the count to keep it repeatable.
FLUSH_FUNCTION = "rb::io::ResultFile::flush()"


def flush_instructions(cg: str) -> int:
    """Inclusive instructions of the result-file flushes inside the collected part of `cg`."""
    try:
        r = subprocess.run(["callgrind_annotate", "--inclusive=yes", "--threshold=100", cg],
                           stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True)
    except OSError:
        return 0
    for line in r.stdout.splitlines():
        if FLUSH_FUNCTION in line:
            head = line.strip().split()[0].replace(",", "")
            if head.isdigit():
                return int(head)
    return 0


def method_of(row: dict) -> str:
    m = re.search(r"contact\.method=(\w+)", row["overrides"])
    return m.group(1) if m else ""


def main(argv=None) -> int:
    root_default = ROOT
    ap = parser("effects-instructions", __doc__.split("\n\n")[0])
    ap.add_argument("study_dir")
    ap.add_argument("--workbench", default=os.path.join(root_default, "build", "workbench", "app",
                                                        "workbench"))
    ap.add_argument("--root", default=root_default)
    ap.add_argument("--duration", type=float, default=8.0,
                    help="simulated seconds per case (default 8: tangent, transition and the "
                         "curve entry of case 3)")
    ap.add_argument("--match", default="",
                    help="only the cases whose label matches this regular expression")
    ap.add_argument("--csv", default="study_effects_instructions.csv",
                    help="output file name in the study folder")
    ap.add_argument("--tag", default="",
                    help="name of the build measured (e.g. the commit of an earlier build given "
                         "by --workbench), written in the 'build' column")
    a = ap.parse_args(argv)
    cases_csv = os.path.join(a.study_dir, "summary_cases.csv")
    if not os.path.exists(cases_csv):
        print(f"railbench effects-instructions: {cases_csv} not found (run the study first)",
              file=sys.stderr)
        return 1
    with open(cases_csv, newline="") as f:
        cases = [c for c in csv.DictReader(f) if re.search(a.match, c["label"])]
    rows = []
    with tempfile.TemporaryDirectory(prefix="rb_effects_cg_") as tmp:
        for c in cases:
            out = os.path.join(tmp, c["case"] + ".h5")
            cg = os.path.join(tmp, c["case"] + ".cg")
            cmd = ["valgrind", "--tool=callgrind", f"--callgrind-out-file={cg}",
                   "--toggle-collect=rb::integ::integrate*", a.workbench, "--root", a.root,
                   "run", c["base"], "--out", out, "--quiet"]
            for ov in c["overrides"].split():
                cmd += ["--set", ov]
            cmd += ["--set", f"run.duration={a.duration:g}"]
            r = subprocess.run(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
            if r.returncode != 0 or not os.path.exists(out):
                print(f"railbench effects-instructions: {c['label']}: run failed (exit {r.returncode}): "
                      f"{r.stderr.strip()[-300:]}", file=sys.stderr)
                rows.append(dict(case=c["case"], label=c["label"], role=c["role"],
                                 method=method_of(c), instructions="", rhs_evals="",
                                 instructions_per_eval="", relative_to_baseline="",
                                 note="failed", build=a.tag, duration=f"{a.duration:g}"))
                continue
            with h5py.File(out, "r") as h:
                evals = int(h["stats"].attrs["rhs_evals"])
            total = callgrind_total(cg) - flush_instructions(cg)
            rows.append(dict(case=c["case"], label=c["label"], role=c["role"],
                             method=method_of(c), instructions=total, rhs_evals=evals,
                             instructions_per_eval=f"{total / evals:.1f}",
                             relative_to_baseline="", note="", build=a.tag,
                             duration=f"{a.duration:g}"))
            print(f"{c['label']:40s} {total / evals:10.1f} instructions / evaluation", flush=True)
    base = {r["method"]: float(r["instructions_per_eval"]) for r in rows
            if r["role"] == "baseline" and r["instructions_per_eval"]}
    for r in rows:
        if r["instructions_per_eval"] and r["method"] in base:
            r["relative_to_baseline"] = f"{float(r['instructions_per_eval']) / base[r['method']]:.4f}"
    if not rows:
        print("railbench effects-instructions: no case matches", file=sys.stderr)
        return 1
    path = os.path.join(a.study_dir, a.csv)
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)
    print(path)
    return 0

