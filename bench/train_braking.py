#!/usr/bin/env python3
"""In-train forces of the shipped braking train and their lateral effect (docs/trains.md,
"Buffers, draw gear and braking").

usage: bench/train_braking.py [CSV] [--workbench BIN]

Runs scenarios/train/loco_braking_r500.lua (a locomotive-like leading vehicle braking with
120 kN, three unbraked wagons, R = 500 m) and the same train with the 120 kN shared among the
vehicles in proportion to their masses (a copy of the scene with that one change): the same
deceleration and speed history, no in-train forces beyond the resistances'. It reads per
connection the steady and peak compressive force and the lateral force on the car bodies, and per
vehicle the quasi-static (mean over the last 2 s, in the curve) outer-wheel Y of its leading
wheelset and car-body lateral displacement, in both runs (columns "braking" and "coasting": the
latter is the evenly braked train). Then the braking rake of tests/run/data/
train_braking_rake.lua against its hand calculation, and the CPU time and rhs evaluations of
every run.

Rows of the CSV (default out/studies/train_braking.csv): quantity, braking, coasting, unit, commit.
"""
import os
import re
import sys
import tempfile

import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "plots"))
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import scene_runs  # noqa: E402

SCENE = "scenarios/train/loco_braking_r500.lua"
RAKE = "tests/run/data/train_braking_rake.lua"


def last(f, path, seconds=2.0):
    t = f["/time"][:]
    return float(np.mean(f[path][:][t >= t[-1] - seconds]))


def peak_after(f, path, t0=1.0):
    t = f["/time"][:]
    return float(np.max(np.abs(f[path][:][t >= t0])))


def main(argv=None) -> int:
    a = scene_runs.arguments(__doc__, "train_braking.csv", argv)
    commit = scene_runs.commit()
    rows = []

    def row(q, braking, coasting, unit):
        rows.append(dict(quantity=q, braking=f"{braking:.6g}",
                         coasting="" if coasting is None else f"{coasting:.6g}", unit=unit,
                         commit=commit))

    with tempfile.TemporaryDirectory(prefix="rb_train_braking_") as tmp:
        text = open(os.path.join(ROOT, SCENE)).read()
        # Masses of the longitudinal equations: bodies plus the wheelsets' I_yy / r0^2 (the
        # scene's locomotive has a 60 t car body instead of the wagon's 32 t).
        wheelsets = 2 * 2615 + 4 * (1813 + 112 / 0.46 ** 2)
        m_loco, m_wagon = 60000 + wheelsets, 32000 + wheelsets
        total = m_loco + 3 * m_wagon
        coast_text, n = re.subn(r"\{ 3, -120e3 \}", f"{{ 3, {-120e3 * m_loco / total:.1f} }}",
                                text)
        coast_text, n2 = re.subn(
            r"(start = [\d.]+ \}, resistance = resistance) \}",
            lambda m: m.group(1) + f", traction = {{ {{ 0, 0 }}, {{ 1, 0 }}, "
            f"{{ 3, {-120e3 * m_wagon / total:.1f} }} }} }}", coast_text)
        if n != 1 or n2 != 3:
            raise RuntimeError(f"{SCENE}: the braking force or the wagons' entries are not where "
                               "this study expects them")
        coast_lua = os.path.join(ROOT, "scenarios", "train", ".coasting_tmp.lua")
        try:
            with open(coast_lua, "w") as f:
                f.write(coast_text)
            b = scene_runs.run(a.workbench, SCENE, os.path.join(tmp, "braking.h5"))
            c = scene_runs.run(a.workbench, coast_lua, os.path.join(tmp, "coasting.h5"))
        finally:
            os.remove(coast_lua)
        for name in ("loco-wagon1", "wagon1-wagon2", "wagon2-wagon3"):
            g = f"/train/connections/{name}"
            row(f"{name}: force, last 2 s", last(b, g + "/force"), last(c, g + "/force"), "N")
            row(f"{name}: most compressive force", float(b[g + "/force"][:].min()),
                float(c[g + "/force"][:].min()), "N")
            row(f"{name}: lateral force on the rear car body, last 2 s",
                last(b, g + "/lateral_rear"), last(c, g + "/lateral_rear"), "N")
        for v in ("loco", "wagon1", "wagon2", "wagon3"):
            p = f"/vehicles/{v}"
            row(f"{v}: ws1 outer (right) wheel Y, last 2 s",
                last(b, p + "/contact/ws1/right/Y"), last(c, p + "/contact/ws1/right/Y"), "N")
            row(f"{v}: car body lateral displacement, last 2 s", last(b, p + "/bodies/car/y"),
                last(c, p + "/bodies/car/y"), "m")
            row(f"{v}: speed at the end", float(b[p + "/motion/speed"][-1]),
                float(c[p + "/motion/speed"][-1]), "m/s")
            # After the first second: the start transient on irregular rails (docs/trains.md)
            # is out of the 1 s window by then.
            jerk = p + "/motion/jerk_1s"
            row(f"{v}: largest jerk over 1 s (absolute), t >= 1 s", peak_after(b, jerk),
                peak_after(c, jerk), "m/s^3")
        for label, f in (("braking", b), ("evenly braked", c)):
            st = f["stats"].attrs
            row(f"{label} run: CPU time ({f['/time'][-1]:.0f} s simulated)",
                float(st["cpu_time_s"]), None, "s")
            row(f"{label} run: rhs evaluations", float(st["rhs_evals"]), None, "-")
        r = scene_runs.run(a.workbench, RAKE, os.path.join(tmp, "rake.h5"))
        # The hand calculation: 60 kN decelerate three equal wagons (bodies plus the wheelsets'
        # rotating mass I_yy / r0^2 = 112 / 0.46^2 kg each, scenarios/vehicles/
        # manchester_wagon1.lua).
        mv = 32000 + 2 * 2615 + 4 * (1813 + 112 / 0.46 ** 2)
        acc = -60e3 / (3 * mv)
        t = r["/time"][:]
        steady = t >= 2.0
        row("rake: deceleration, t >= 2 s (hand: -60 kN / 3 m)",
            float(np.mean(r["/vehicles/w2/motion/acceleration"][:][steady])), acc, "m/s^2")
        row("rake: w1-w2 force, t >= 2 s (hand: 2 m a)",
            float(np.mean(r["/train/connections/w1-w2/force"][:][steady])), 2 * mv * acc, "N")
        row("rake: w2-w3 force, t >= 2 s (hand: m a)",
            float(np.mean(r["/train/connections/w2-w3/force"][:][steady])), mv * acc, "N")
        # The braking ramp (0.2 s to 0.7 s) takes the rake from 0 to acc: the jerk over the 1 s
        # centred in it (0 to 0.95 s, shortened at the start) is acc / 0.95 s.
        mid = int(np.argmin(np.abs(t - 0.45)))
        row("rake: w2 jerk over 1 s at t = 0.45 s (hand: a / 0.95 s)",
            float(r["/vehicles/w2/motion/jerk_1s"][mid]), acc / 0.95, "m/s^3")
        row("rake: w1-w2 most compressive force (the run-in)",
            float(r["/train/connections/w1-w2/force"][:].min()), 2 * mv * acc, "N")
    scene_runs.write_rows(a.csv, rows, ("quantity", "braking", "coasting", "unit"))
    return 0


if __name__ == "__main__":
    sys.exit(main())
