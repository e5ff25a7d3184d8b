#!/usr/bin/python3
"""The default scene of ./wb run against the validation case it is built on.

    default_scene.py --workbench BIN --out-dir DIR

./wb run's default scene (DEFAULT_SCENARIO in wb) is the validation case 3 KEC at a larger step,
chosen as the cheapest within 0.05 mm of a verified reference (the scene's header gives the
evidence). Here it runs into DIR/default_scene.h5 and is compared with the validation case's own
run, DIR/case3_kec.h5 (the ctest fixture validation_case3): every wheelset's lateral displacement
within 0.05 mm over the common output times, the assessment's summary values within 1 %, and fewer
rhs evaluations. Exit 0 on agreement, 1 otherwise (each failure named).
"""
import argparse
import os
import re
import subprocess
import sys

import h5py
import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
LIMIT_MM = 0.05
SUMMARY_REL = 0.01


def default_scenario() -> str:
    with open(os.path.join(ROOT, "wb")) as f:
        m = re.search(r'^DEFAULT_SCENARIO="([^"]+)"', f.read(), re.M)
    if not m:
        raise RuntimeError("wb: no DEFAULT_SCENARIO line")
    return m.group(1)


def _text(v) -> str:
    return v.decode() if isinstance(v, bytes) else str(v)


def summary(f) -> dict:
    """The assessment's summary value of every quantity (/assessment/summary attributes)."""
    attrs = f["/assessment/summary"].attrs
    names = _text(f["/assessment"].attrs["quantities"]).split("\n")
    return {q: float(attrs[q]) for q in names if q in attrs}


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--workbench", required=True)
    ap.add_argument("--out-dir", required=True)
    args = ap.parse_args(argv)
    failures = []
    scene = default_scenario()
    validation = os.path.join(args.out_dir, "case3_kec.h5")
    if not os.path.exists(validation):
        print(f"default_scene: {validation} missing (run validation_case3_kec first)")
        return 1
    out = os.path.join(args.out_dir, "default_scene.h5")
    if os.path.exists(out):
        os.remove(out)
    cmd = [args.workbench, "--root", ROOT, "run", os.path.join(ROOT, scene), "--out", out,
           "--quiet"]
    p = subprocess.run(cmd, cwd=ROOT, capture_output=True, text=True, timeout=600)
    if p.returncode != 0:
        print(f"default_scene: {' '.join(cmd)} exited {p.returncode}:\n{p.stderr[-2000:]}")
        return 1
    with h5py.File(out, "r") as a, h5py.File(validation, "r") as b:
        if a["/stats"].attrs["rhs_evals"] >= b["/stats"].attrs["rhs_evals"]:
            failures.append(f"{scene} is not cheaper than the validation case: "
                            f"{a['/stats'].attrs['rhs_evals']} rhs evaluations against "
                            f"{b['/stats'].attrs['rhs_evals']}")
        ta, tb = a["/time"][()], b["/time"][()]
        n = min(len(ta), len(tb))
        if n < 0.99 * len(tb) or not np.allclose(ta[:n], tb[:n], rtol=0, atol=1e-9):
            failures.append(f"output times differ: {len(ta)} against {len(tb)}")
        names = _text(a["/bodies"].attrs["names"]).split("\n")
        for ws in (w for w in names if _text(a[f"/bodies/{w}"].attrs["kind"]) == "wheelset"):
            d = np.max(np.abs(a[f"/bodies/{ws}/y"][:n] - b[f"/bodies/{ws}/y"][:n])) * 1e3
            print(f"  {ws}: max |y - y_validation| = {d:.4f} mm")
            if not d <= LIMIT_MM:
                failures.append(f"{ws}: y differs from the validation case by {d:.4f} mm "
                                f"> {LIMIT_MM} mm")
        sa, sb = summary(a), summary(b)
        if set(sa) != set(sb) or not sa:
            failures.append(f"assessment quantities differ: {sorted(sa)} against {sorted(sb)}")
        for k in sorted(set(sa) & set(sb)):
            if abs(sa[k] - sb[k]) > SUMMARY_REL * abs(sb[k]):
                failures.append(f"assessment {k}: {sa[k]:.6g} against {sb[k]:.6g} (more than "
                                f"{SUMMARY_REL:.0%})")
    for f in failures:
        print("FAIL:", f)
    print(f"default_scene: {scene}: " + ("ok" if not failures else f"{len(failures)} failures"))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
