#!/usr/bin/python3
"""`workbench stress --quick` on every shipped vehicle scenario (docs/stress.md): each must
produce its stability map (exit 0) with no run that fails badly (expect_stable.csv; the crossing:
expect_crossing.csv); the wheel-lift reproducer must stop cleanly in every run of its nominal case
(expect_wheel_lift.csv).

usage: stress_all.py --workbench BIN --out-dir DIR [--only SUBSTRING]
"""
import argparse
import glob
import os
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
HERE = os.path.dirname(os.path.abspath(__file__))
WHEEL_LIFT = "tests/app/data/wheel_lift/my_wheelset.lua"


def scenarios():
    out = []
    for pattern in ("scenarios/validation/case*.lua", "scenarios/validation/variants/*.lua",
                    "scenarios/hard/*.lua", "scenarios/vehicle/*.lua"):
        out += sorted(os.path.relpath(p, ROOT) for p in glob.glob(os.path.join(ROOT, pattern)))
    out = [p for p in out if not p.endswith("/lib.lua")]
    return out + ["scenarios/studies/case3_base.lua", "scenarios/train/three_wagons.lua",
                  "scenarios/train/loco_braking_r500.lua", "scenarios/turnout/diverging_r190.lua",
                  "scenarios/turnout/crossing_through.lua", WHEEL_LIFT]


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--workbench", required=True)
    ap.add_argument("--out-dir", required=True)
    ap.add_argument("--only", default="")
    ap.add_argument("--jobs", default="2")
    args = ap.parse_args()
    failed = []
    for scen in scenarios():
        if args.only not in scen:
            continue
        stem = os.path.splitext(scen)[0].replace("/", "_")
        expect = ("expect_wheel_lift.csv" if scen == WHEEL_LIFT else
                  "expect_crossing.csv" if scen.endswith("crossing_through.lua") else
                  "expect_stable.csv")
        cmd = [args.workbench, "stress", scen, "--quick", "--jobs", args.jobs,
               "--out", os.path.join(args.out_dir, stem), "--expect", os.path.join(HERE, expect)]
        t0 = time.monotonic()
        p = subprocess.run(cmd, cwd=ROOT, capture_output=True, text=True)
        wall = time.monotonic() - t0
        print("%-60s exit %d  %.0f s" % (scen, p.returncode, wall))
        if p.returncode != 0:
            failed.append(scen)
            print(p.stdout[-4000:])
            print(p.stderr[-2000:])
        sys.stdout.flush()
    if failed:
        print("\nFAILED: " + ", ".join(failed))
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
