#!/usr/bin/python3
"""A minimal scene pays at most 1 % of its integration's instructions for the effects it does not
use (architecture.md: "effects are compiled in, not branched on"; docs/run_stats.md).

    unused_effects_callgrind.py WORKBENCH ROOT

Runs scenarios/studies/bases/minimal.lua (case 3 without irregularities, bump stops and series
dampers; default outputs; no assessment) for a short distance under callgrind, collecting only
inside the integration (rb::integ::integrate*), and sums the inclusive instructions of the
functions that implement the effects the scene does not use: irregularity evaluation, bump stop
forces, series damper forces, element and body-acceleration outputs, assessment sampling, and the
sampled stage timing itself (which every run has). The sum must be <= 1 % of the integration's
instructions. Every pattern must name a function of the binary (nm), so a renamed function
cannot make the test pass by matching nothing.
"""
import os
import re
import subprocess
import sys
import tempfile

LIMIT = 0.01
# What the minimal scene does not use -> the functions (demangled names) that implement it.
UNUSED = {
    "irregularities": r"rb::track::Irregularities::",
    "bump stops": r"rb::suspension::BumpstopLaw::",
    "series dampers": r"rb::suspension::seriesDamper",
    "element outputs": r"::elementOutputs\(",
    "body accelerations": r"::bodyAccelerations\(",
    "assessment sampling": r"rb::run::sampleAssessment\(",
    "stage timing": r"rb::vehicle::StageClock::",
}
OVERRIDES = ["run.distance=10"]


def fail(msg: str) -> None:
    print("FAIL: " + msg)
    sys.exit(1)


def defined_functions(binary: str) -> list:
    r = subprocess.run(["nm", "-C", "--defined-only", binary], capture_output=True, text=True,
                       check=True)
    return [line.split(" ", 2)[2] for line in r.stdout.splitlines()
            if len(line.split(" ", 2)) == 3 and line.split(" ", 2)[1] in "tTwW"]


def inclusive_costs(cg: str) -> dict:
    """{function: inclusive instructions} from callgrind_annotate (every function listed)."""
    r = subprocess.run(["callgrind_annotate", "--inclusive=yes", "--threshold=100", cg],
                       capture_output=True, text=True, check=True)
    costs = {}
    for line in r.stdout.splitlines():
        m = re.match(r"^\s*([\d,]+)\s+(?:\(\s*[\d.]+%\)\s+)?(\S.*)$", line)
        if not m or ":" not in m.group(2):
            continue
        name = m.group(2)
        name = re.sub(r"\s+\[[^\]]*\]$", "", name)   # the object file
        name = name.split(":", 1)[1] if re.match(r"^[^:(]*:", name) else name  # the source file
        costs[name] = costs.get(name, 0) + int(m.group(1).replace(",", ""))
    return costs


def total_instructions(cg: str) -> int:
    with open(cg) as f:
        for line in f:
            m = re.match(r"^(summary|totals):\s+(\d+)", line)
            if m:
                return int(m.group(2))
    fail(f"{cg}: no totals line")
    return 0


def main() -> int:
    binary, root = sys.argv[1], sys.argv[2]
    scenario = os.path.join(root, "scenarios", "studies", "bases", "minimal.lua")
    functions = defined_functions(binary)
    for what, pattern in UNUSED.items():
        if not any(re.search(pattern, f) for f in functions):
            fail(f"pattern of '{what}' ({pattern}) names no function of {binary}")
    with tempfile.TemporaryDirectory(prefix="rb_stages_cg_") as tmp:
        env = dict(os.environ, RAILBENCH_TABLE_CACHE=os.path.join(tmp, "tables"))
        sets = [a for o in OVERRIDES for a in ("--set", o)]
        # The tables are built natively first (check compiles everything a run does).
        r = subprocess.run([binary, "--root", root, "check", scenario] + sets, env=env,
                           capture_output=True, text=True)
        if r.returncode != 0:
            fail(f"check failed: {r.stderr.strip()[-500:]}")
        cg = os.path.join(tmp, "minimal.cg")
        out = os.path.join(tmp, "minimal.h5")
        r = subprocess.run(["valgrind", "--tool=callgrind", f"--callgrind-out-file={cg}",
                            "--toggle-collect=rb::integ::integrate*", binary, "--root", root,
                            "run", scenario, "--out", out, "--quiet"] + sets, env=env,
                           capture_output=True, text=True)
        if r.returncode != 0:
            fail(f"run failed (exit {r.returncode}): {r.stderr.strip()[-500:]}")
        print(r.stdout.strip())
        total = total_instructions(cg)
        costs = inclusive_costs(cg)
    if total <= 0 or not costs:
        fail("no instructions collected inside the integration")
    unused = 0
    for what, pattern in UNUSED.items():
        n = sum(c for f, c in costs.items() if re.search(pattern, f))
        unused += n
        print(f"{what:22s} {n:14,d} instructions ({100.0 * n / total:.4f} %)")
    print(f"{'integration':22s} {total:14,d} instructions")
    share = unused / total
    print(f"unused effects: {100.0 * share:.4f} % of the integration (limit {100.0 * LIMIT:g} %)")
    if share > LIMIT:
        fail(f"the minimal scene pays {100.0 * share:.3f} % for effects it does not use")
    print("PASS")
    return 0


if __name__ == "__main__":
    sys.exit(main())
