"""The checks of `workbench stress` on a train cover every vehicle (tests/stress/CMakeLists.txt):

    check_train_stress.py DIR WORKBENCH

For every result of the stress folder DIR, `workbench check-result` gives the largest wheel load,
the smallest and the largest |Y/Q| over the wheels of every vehicle of the train, as read here
from /vehicles/<name>/contact, and not those of the leading vehicle alone whenever another
vehicle's differ (in at least one run it must). Exit 0 when all hold.
"""
import csv
import json
import os
import subprocess
import sys

import h5py
import numpy as np


def wheels(f, vehicle, name):
    g = f["vehicles"][vehicle]["contact"]
    return np.concatenate([g[ws][side][name][:] for ws in g for side in ("left", "right")])


def main() -> int:
    folder, workbench = sys.argv[1], sys.argv[2]
    with open(os.path.join(folder, "stress.csv"), newline="") as fh:
        rows = [r for r in csv.DictReader(fh) if r["outcome"] == "ok"]
    problems = []
    others = 0  # runs where another vehicle than the leading one holds an extreme
    if not rows:
        problems.append("no ok run")
    for r in rows:
        p = subprocess.run([workbench, "check-result", r["file"], "--exit-code", "0", "--t-end",
                            r["t_end"]], capture_output=True, text=True)
        got = json.loads(p.stdout)
        with h5py.File(r["file"], "r") as f:
            names = f["vehicles"].attrs["names"]
            names = (names.decode() if isinstance(names, bytes) else names).split("\n")
            per = {v: (wheels(f, v, "normal_force"), np.abs(wheels(f, v, "y_over_q")))
                   for v in names}
        want = {"max_normal_kN": max(n.max() for n, _ in per.values()) / 1e3,
                "min_normal_kN": min(n.min() for n, _ in per.values()) / 1e3,
                "max_abs_yq": max(q.max() for _, q in per.values())}
        for key, value in want.items():
            if not np.isclose(got[key], value, rtol=1e-12):
                problems.append(f"{r['case']}: {key} = {got[key]}, every vehicle's {value}")
        lead_n, lead_q = per[names[0]]
        if want["max_normal_kN"] != lead_n.max() / 1e3 or want["max_abs_yq"] != lead_q.max():
            others += 1
    if rows and others == 0:
        problems.append("the leading vehicle holds every extreme in every run (nothing tested)")
    for p in problems:
        print(p)
    print(f"{len(rows)} results checked, {len(problems)} problems")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
