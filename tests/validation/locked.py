"""Locked validation values: the seed paper's validation cases (Yu et al., section 5.2) as shipped
in scenarios/validation/, run through the real command line, reduced to the numbers of
docs/validation.md and compared with tests/validation/expected_values.csv.

Shared by check.py (one ctest test per case, label "validation") and lock.py (regenerates the
expected file). The reductions are those of `plots/rbplot validation-tables`
(plots/railbench/validation.py: steady() for Tables 5 and 6, eq33() for Eq. (33) of case 3),
imported, so the locked numbers are the documented ones by construction.
"""
import csv
import datetime
import io
import os
import subprocess
import sys
from typing import Dict, List, Optional, Tuple

import h5py

HERE = os.path.dirname(os.path.abspath(__file__))
# tests/validation/locked.py -> the repository root, two levels up.
ROOT = os.path.dirname(os.path.dirname(HERE))
if os.path.join(ROOT, "plots") not in sys.path:
    sys.path.insert(0, os.path.join(ROOT, "plots"))
from railbench import provenance, validation  # noqa: E402  (read-only use of the docs' reductions)

EXPECTED = os.path.join(HERE, "expected_values.csv")
CASE1 = [f"case1_R{r}_{m}" for r in (300, 500, 700, 900) for m in ("kec", "lut")]
CASE2 = ["case2_kec", "case2_lut"]
CASE3 = ["case3_kec", "case3_lut"]
# The Eq. (33) comparison is one locked "case": it needs both case-3 result files.
EQ33 = "case3_eq33"
FIELDS = ["case", "body", "quantity", "unit", "expected", "tolerance"]

# Absolute tolerance of each locked quantity and why (tests/validation/README.md, "Tolerances").
# Measured noise: a rerun is bit-identical, and a 1e-12 relative change of the friction
# coefficient (a stand-in for round-off differences between compilers, optimisation levels and
# libm versions; it also flips the iteration counts of the KEC and normal-force solves) moves the
# steady means by < 1e-12 mm or mrad and the Eq. (33) values by < 1e-9 % and < 1e-10 mm. A 1 %
# change of the friction coefficient, a small model change, moves the steady means of case 1 at
# R = 900 m by only 0.3 um and 0.25 urad and the Eq. (33) values by 0.02 % (max) to 0.1 %
# (mean). The tolerances sit between the two: about 1e7 times the noise, and small enough that
# that 1 % change fails in every group of cases.
TOLERANCES: Dict[str, Tuple[float, str]] = {
    "y_mm": (1e-4, "steady mean lateral displacement: 0.1 um; noise < 1e-12 mm, a 1 % friction "
             "change moves the least sensitive case (R = 900 m LUT) by 0.3 um"),
    "yaw_mrad": (1e-4, "steady mean yaw: 0.1 urad; noise < 1e-12 mrad, a 1 % friction change "
                 "moves the least sensitive case (R = 900 m) by 0.25 urad"),
    "eq33_max_percent": (1e-3, "Eq. (33) max: 0.001 percentage points; noise < 1e-9, a 1 % "
                         "friction change moves it by up to 0.02"),
    "eq33_mean_percent": (1e-3, "Eq. (33) mean: 0.001 percentage points; noise < 1e-10, a 1 % "
                          "friction change moves it by up to 0.11"),
    "max_abs_y_lut_mm": (1e-4, "max|y_LUT| on the irregular track: 0.1 um as the steady means; "
                         "noise < 1e-10 mm, a 1 % friction change moves it by up to 15 um"),
}
UNITS = {"y_mm": "mm", "yaw_mrad": "mrad", "eq33_max_percent": "%", "eq33_mean_percent": "%",
         "max_abs_y_lut_mm": "mm"}


def scenario(case: str) -> str:
    return os.path.join(ROOT, "scenarios", "validation", case + ".lua")


def result_path(out_dir: str, case: str) -> str:
    return os.path.join(out_dir, case + ".h5")


def run_case(workbench: str, case: str, out_dir: str, timeout: float = 600.0) -> str:
    """Run one shipped validation scenario unchanged into out_dir/<case>.h5; raise RuntimeError
    unless the run finished (exit 0, /stats/status ok)."""
    os.makedirs(out_dir, exist_ok=True)
    out = result_path(out_dir, case)
    if os.path.exists(out):
        os.remove(out)
    cmd = [workbench, "--root", ROOT, "run", scenario(case), "--out", out, "--quiet"]
    env = dict(os.environ, RAILBENCH_ROOT=ROOT)
    p = subprocess.run(cmd, cwd=ROOT, env=env, capture_output=True, text=True, timeout=timeout)
    if p.returncode != 0:
        raise RuntimeError(f"{case}: `{' '.join(cmd)}` exited {p.returncode}:\n"
                           f"{(p.stderr or p.stdout).strip()[-2000:]}")
    with h5py.File(out, "r") as f:
        status = f["/stats"].attrs.get("status", b"?") if "/stats" in f else b"?"
    status = status.decode() if isinstance(status, bytes) else str(status)
    if status != "ok":
        raise RuntimeError(f"{case}: run status '{status}' (expected ok), file {out}")
    return out


def case_number(case: str) -> int:
    return int(case[4])


def steady_values(case: str, path: str) -> List[dict]:
    """Tables 5 and 6: the steady mean y and yaw of every body (validation.steady)."""
    rows = []
    for b in validation.steady(path, case_number(case)):
        for q in ("y_mm", "yaw_mrad"):
            rows.append({"case": case, "body": b["body"], "quantity": q, "value": b[q]})
    return rows


def eq33_values(kec_path: str, lut_path: str) -> List[dict]:
    """Eq. (33) of case 3, KEC against LUT with the scenario's solver (validation.eq33)."""
    rows = []
    for w in validation.eq33(kec_path, lut_path):
        for q in ("eq33_max_percent", "eq33_mean_percent", "max_abs_y_lut_mm"):
            rows.append({"case": EQ33, "body": w["wheelset"], "quantity": q, "value": w[q]})
    return rows


def key(row: dict) -> Tuple[str, str, str]:
    return row["case"], row["body"], row["quantity"]


# ---------------------------------------------------------------- the expected file


def build_type(workbench: str) -> str:
    """CMAKE_BUILD_TYPE (and the sanitizer option) of the build tree holding the binary."""
    d = os.path.dirname(os.path.abspath(workbench))
    while d != os.path.dirname(d):
        cache = os.path.join(d, "CMakeCache.txt")
        if os.path.exists(cache):
            vals = {}
            with open(cache) as fh:
                for line in fh:
                    name, _, value = line.strip().partition("=")
                    vals[name.split(":")[0]] = value
            kind = vals.get("CMAKE_BUILD_TYPE") or "unknown"
            return kind + (" +ASan/UBSan" if vals.get("RB_SANITIZE") in ("ON", "TRUE", "1") else "")
        d = os.path.dirname(d)
    return "unknown"


def version(workbench: str) -> str:
    p = subprocess.run([workbench, "--version"], capture_output=True, text=True, timeout=60)
    return (p.stdout or p.stderr).strip() or "unknown"


def provenance_lines(workbench: str, command: str) -> List[str]:
    tree = provenance.current(ROOT)
    now = datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M UTC")
    return [f"commit: {provenance.tag(tree)}", f"date: {now}",
            f"build_type: {build_type(workbench)}", f"workbench: {version(workbench)}",
            f"command: {command}"]


def write_expected(path: str, rows: List[dict], prov: List[str]) -> None:
    header = [
        "Locked validation values (ctest label 'validation', tests/validation/README.md):",
        "paper Table 5 (case 1, mean over s = 110..120 m), Table 6 (case 2, mean over",
        "t = 20..24 s) and Eq. (33) of case 3 (KEC against LUT, scenario solver), each case the",
        "shipped scenarios/validation/<case>.lua run unchanged.",
        "Regenerate (one command, from the repository root, after building):",
        "  /usr/bin/python3 tests/validation/lock.py --workbench build/workbench/app/workbench",
        "Provenance of the values below:",
    ] + ["  " + p for p in prov] + ["Tolerances (absolute, per quantity):"] + [
        f"  {q} [{UNITS[q]}] {tol:g}: {why}" for q, (tol, why) in TOLERANCES.items()]
    tmp = path + ".tmp"
    with open(tmp, "w", newline="") as fh:
        for line in header:
            fh.write("# " + line + "\n")
        w = csv.DictWriter(fh, FIELDS, lineterminator="\n")
        w.writeheader()
        for r in rows:
            q = r["quantity"]
            w.writerow({"case": r["case"], "body": r["body"], "quantity": q, "unit": UNITS[q],
                        "expected": f"{r['value']:.9g}", "tolerance": f"{TOLERANCES[q][0]:g}"})
    os.replace(tmp, path)


def read_expected(path: str) -> Tuple[List[dict], str]:
    """(rows, provenance text) of an expected file; '#' lines are its header."""
    with open(path) as fh:
        lines = fh.read().splitlines()
    prov = [ln[2:].strip() for ln in lines if ln.startswith("#  ")]
    keep = ("commit:", "date:", "build_type:", "workbench:", "command:")
    text = "; ".join(p for p in prov if p.startswith(keep))
    body = "\n".join(ln for ln in lines if not ln.startswith("#"))
    rows = []
    for r in csv.DictReader(io.StringIO(body)):
        rows.append(dict(r, expected=float(r["expected"]), tolerance=float(r["tolerance"])))
    return rows, text


# ---------------------------------------------------------------- the comparison


def compare(case: str, got: List[dict], expected: List[dict], prov: str) -> List[str]:
    """Failure messages for one case: each locked quantity of `case` against its expected value
    and tolerance; a quantity produced but not locked, or locked but not produced, fails too."""
    exp = {key(r): r for r in expected if r["case"] == case}
    have = {key(r): r for r in got}
    failures = []
    for k in sorted(set(exp) | set(have)):
        e, g = exp.get(k), have.get(k)
        name = "/".join(k)
        if e is None:
            failures.append(f"{name}: got {g['value']:.9g} but no expected value is locked "
                            f"(expected file from {prov})")
        elif g is None:
            failures.append(f"{name}: expected {e['expected']:.9g} {e['unit']} but the run "
                            f"did not produce it (expected file from {prov})")
        elif not abs(g["value"] - e["expected"]) <= e["tolerance"]:
            failures.append(f"{name}: expected {e['expected']:.9g} {e['unit']}, got "
                            f"{g['value']:.9g}, difference {g['value'] - e['expected']:+.3g}, "
                            f"tolerance {e['tolerance']:g} (expected value from {prov})")
    return failures


def report(case: str, got: List[dict], expected: List[dict]) -> str:
    exp = {key(r): r for r in expected}
    lines = [f"{case}: {len(got)} locked quantities"]
    for g in got:
        e: Optional[dict] = exp.get(key(g))
        ref = f"{e['expected']:.9g} +- {e['tolerance']:g}" if e else "(not locked)"
        lines.append(f"  {g['body']:8s} {g['quantity']:18s} {g['value']:14.9g}   expected {ref}")
    return "\n".join(lines)
