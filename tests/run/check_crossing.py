#!/usr/bin/python3
"""Checks the shipped crossing scene's result (scenarios/turnout/crossing_through.lua,
docs/turnouts.md, "The crossing"): every right wheel dips as the wing rail diverges from under
it, moves from the wing rail to the nose while the nose is 10 to 40 mm wide (from its tip to where
its top is level), hits the nose with a force of a few static loads, bounces, and runs on on the
nose alone; no wheel derails, and the rails figure is drawn.

usage: check_crossing.py RESULT.h5
"""
import sys

import h5py
import numpy as np
from rails_figure import verdict

TP = 60.0  # [m] the crossing's theoretical point (the scene)


def crossing(s, a, b):
    d = a - b
    i = np.nonzero((d[:-1] > 0) & (d[1:] <= 0))[0]
    if len(i) == 0:
        return np.nan
    k = i[0]
    return float(s[k] + (s[k + 1] - s[k]) * d[k] / (d[k] - d[k + 1]))


def main(path):
    problems, lines = [], []
    with h5py.File(path, "r") as f:
        if f["stats"].attrs["status"] not in (b"ok", "ok"):
            problems.append(f"run status {f['stats'].attrs['status']}")
        q0 = float(f["/contact"].attrs["elastic_static_load_N"])
        for ws in ("ws1", "ws2", "ws3", "ws4"):
            s = f[f"/bodies/{ws}/s"][:]
            z = f[f"/bodies/{ws}/z"][:]
            g = f[f"/contact/{ws}/right/rails/"]
            wing, nose = g["rail/normal_force"][:], g["nose/normal_force"][:]
            x = crossing(s, wing, nose) - TP
            width = x / 9 * 1e3  # [mm] the nose's width there (1:9)
            if not 10.0 <= width <= 40.0:
                problems.append(f"{ws}: wing to nose at x = {x:.3f} m (nose {width:.1f} mm wide)")
            # The dip: the wheelset lower at the transfer than before the knuckle (0.37 m before
            # the theoretical point), by a fraction of a millimetre to a few.
            before = z[s < TP - 1.0][-1]
            dip = before - z[(s > TP - 0.4) & (s < TP + x + 0.01)].min()
            if not 0.3e-3 < dip < 3e-3:
                problems.append(f"{ws}: dip before the nose {dip * 1e3:.2f} mm")
            peak = nose.max()
            if not 2.0 * q0 < peak < 10.0 * q0:
                problems.append(f"{ws}: the nose's peak force {peak / 1e3:.0f} kN "
                                f"({peak / q0:.1f} static loads)")
            # Settled: 2 m past the full-width nose the wheel is on the nose alone, its load within
            # 25 % of the static one (the wagon's own bounce after the impact, about 12 %, decays
            # over several metres).
            late = s > TP + 0.65 + 2.0
            if not late.any() or np.any(wing[late] > 0) or \
                    np.any(np.abs(nose[late] - q0) > 0.25 * q0):
                problems.append(f"{ws}: not settled on the nose 2 m after it")
            lines.append(f"{ws}: nose from x = {x:.3f} m ({width:.1f} mm), dip {dip * 1e3:.2f} mm, "
                         f"peak {peak / 1e3:.0f} kN")
    return verdict(path, "crossing_figures", problems, "; ".join(lines))


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
