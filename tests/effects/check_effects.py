"""Checks the output folder of `workbench effects` (tests/effects/CMakeLists.txt):

    check_effects.py DIR [--expect EFFECT ...] [--callgrind]

effects.csv exists with the full scene, one row per expected effect and every check column "ok"
(the effect on in the full scene's result and off in its case's), no NaN anywhere, and with
--callgrind a positive instruction count per evaluation for every ok case. Exit 0 when all hold.
"""
import argparse
import csv
import math
import os
import sys


def main() -> int:
    ap = argparse.ArgumentParser()
    ap.add_argument("dir")
    ap.add_argument("--expect", nargs="*", default=[])
    ap.add_argument("--callgrind", action="store_true")
    ap.add_argument("--allow-failed", action="store_true",
                    help="failed cases are results (a scene that ends in a clean failure)")
    a = ap.parse_args()
    path = os.path.join(a.dir, "effects.csv")
    if not os.path.exists(path):
        print(f"{path}: missing")
        return 1
    with open(path, newline="") as f:
        text = f.read()
    if "nan" in text.lower().replace("nance", ""):
        print(f"{path}: NaN in the table")
        return 1
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    problems = []
    effects = {r["effect"]: r for r in rows}
    if "(full scene)" not in effects:
        problems.append("no full-scene row")
    for e in a.expect:
        if e not in effects:
            problems.append(f"no row for {e}")
    for r in rows:
        if r["role"] not in ("baseline", "effect_off", "minimal"):
            continue
        if r["status"] != "ok":
            if not a.allow_failed:
                problems.append(f"{r['effect']}: status {r['status']}")
            continue
        if r["check"] != "ok":
            problems.append(f"{r['effect']}: check {r['check']}")
        if r["role"] != "baseline" and r.get("max_dy", "x") == "" and "unit_y" in r:
            problems.append(f"{r['effect']}: no change in answer")
        if a.callgrind:
            v = r.get("instructions_per_eval", "")
            if not v or not float(v) > 0 or not math.isfinite(float(v)):
                problems.append(f"{r['effect']}: no instructions per evaluation ({r['note']})")
    for p in problems:
        print(f"{path}: {p}")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
