"""Generated documentation block of docs/stress.md: the stability maps of the hard-case suite's
`workbench stress` runs (tests/hard/CMakeLists.txt: BUILD_DIR/hard/stress_*/stress.csv)."""
from __future__ import annotations

import glob
import os

from .docs_blocks import fmt, missing, num, read_csv, table


def stress_hard_block(build: str) -> str:
    """docs/stress.md block `stress_hard`: every run of every stress folder of the hard suite
    (`ctest -L hard`), with its outcome, error against its own reference, CPU and evaluations."""
    paths = sorted(glob.glob(os.path.join(build, "hard", "stress_*", "stress.csv")))
    if not paths:
        return missing(f"{build}/hard/stress_*/stress.csv (ctest -L hard)")
    body = []
    for p in paths:
        folder = os.path.basename(os.path.dirname(p))[len("stress_"):]
        for r in read_csv(p):
            body.append([folder, r["axis"], r["value_label"], r["integrator"], r["outcome"],
                         fmt(num(r["error_y_mm"]), "{:.3g}"),
                         fmt(num(r["t_reached"]), "{:.3f}"), fmt(num(r["cpu_s"]), "{:.2f}"),
                         r["rhs_evals"], (r["message"] or "")[:120].replace("|", "/")])
    return table(["scenario", "axis", "value", "integrator", "outcome",
                  "lateral error [mm]", "t reached [s]", "CPU [s]", "rhs evals", "message"], body)
