#!/usr/bin/env python3
"""What the instruction set costs or gains: the default scene with the portable build against a
build for this machine's own instruction set (CMake -DRB_MARCH=native: its vector units and
fused multiply-add).

usage: bench/march.py CSV --portable BIN --native BIN [--repeats 5] [--callgrind]

Each build runs `./wb run`'s default scene (scenarios/default/case3_kec_fast.lua, every output
and the whole assessment) `repeats` times, one run at a time; the CPU of the integration and its
evaluations come from the result's /stats. With --callgrind each build also runs once under
`valgrind --tool=callgrind` (instructions of the whole program, start to written file, the
contact-table cache warm), which a shared machine does not disturb. The results of the two
builds are compared: the largest difference of any wheelset's lateral displacement over the
run (fused multiply-add rounds once where the portable code rounds twice, so the two agree to
round-off at the start and drift apart by what the round-off excites).

Columns of the CSV:
  build            portable or native
  march            the -march the build was configured with (empty: the compiler's default)
  repeat           1..repeats, or "callgrind"
  cpu_s            /stats/cpu_time_s (the integration with its outputs)
  t_end_s          simulated time
  x_real_time      t_end_s / cpu_s
  evaluations      /stats/model_evaluations
  instructions     callgrind's total (callgrind rows only)
  max_dy_mm        largest |y_native - y_portable| of any wheelset over the run [mm] (native rows)
  status           /stats/status
  cpu_model        the processor (/proc/cpuinfo)
"""
import argparse
import csv
import os
import re
import shutil
import subprocess
import sys
import tempfile

import h5py
import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
SCENE = os.path.join(ROOT, "scenarios", "default", "case3_kec_fast.lua")


def cpu_model() -> str:
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return "unknown"


def march_of(binary: str) -> str:
    """The RB_MARCH the binary's build folder was configured with (CMakeCache.txt)."""
    folder = os.path.dirname(binary)
    while folder and folder != "/":
        cache = os.path.join(folder, "CMakeCache.txt")
        if os.path.exists(cache):
            with open(cache) as f:
                for line in f:
                    if line.startswith("RB_MARCH:"):
                        return line.split("=", 1)[1].strip()
            return ""
        folder = os.path.dirname(folder)
    return ""


def run(binary: str, out: str, env: dict, prefix=()) -> subprocess.CompletedProcess:
    return subprocess.run([*prefix, binary, "--root", ROOT, "run", SCENE, "--out", out, "--quiet"],
                          env=env, cwd=os.path.dirname(out), stdout=subprocess.PIPE,
                          stderr=subprocess.STDOUT, text=True, check=False)


def stats(path: str) -> dict:
    with h5py.File(path, "r") as f:
        a = f["/stats"].attrs
        status = a["status"]
        return {"cpu_s": float(a["cpu_time_s"]), "t_end_s": float(a["t_reached"]),
                "evaluations": int(a["model_evaluations"]),
                "status": status.decode() if isinstance(status, bytes) else str(status)}


def wheelset_y(path: str) -> dict:
    with h5py.File(path, "r") as f:
        out = {}
        for name, g in f["/bodies"].items():
            if isinstance(g, h5py.Group) and g.attrs.get("kind", b"") in (b"wheelset", "wheelset"):
                out[name] = np.asarray(g["y"][()])
        return out


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("csv")
    ap.add_argument("--portable", required=True)
    ap.add_argument("--native", required=True)
    ap.add_argument("--repeats", type=int, default=5)
    ap.add_argument("--callgrind", action="store_true")
    a = ap.parse_args()
    a.portable, a.native = os.path.abspath(a.portable), os.path.abspath(a.native)
    model = cpu_model()
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        # One contact-table cache for both builds: the tables are built once, before the runs
        # that are measured (the cache key is the configuration, not the build).
        env = dict(os.environ, RAILBENCH_TABLE_CACHE=os.path.join(tmp, "tables"))
        last = {}
        for build, binary in (("portable", a.portable), ("native", a.native)):
            march = march_of(binary)
            warm = os.path.join(tmp, f"{build}_warm.h5")
            p = run(binary, warm, env)
            if p.returncode != 0:
                sys.stderr.write(p.stdout)
                return 1
            for i in range(1, a.repeats + 1):
                out = os.path.join(tmp, f"{build}_{i}.h5")
                p = run(binary, out, env)
                s = stats(out) if os.path.exists(out) else {"status": f"exit {p.returncode}"}
                rows.append({"build": build, "march": march, "repeat": i, **s})
                last[build] = out
            if a.callgrind and shutil.which("valgrind"):
                cg = os.path.join(tmp, f"{build}.callgrind")
                out = os.path.join(tmp, f"{build}_cg.h5")
                p = run(binary, out, env,
                        ("valgrind", "--tool=callgrind", f"--callgrind-out-file={cg}"))
                m = re.search(r"Collected\s*:\s*(\d+)", p.stdout)
                rows.append({"build": build, "march": march, "repeat": "callgrind",
                             "instructions": int(m.group(1)) if m else "",
                             "status": stats(out)["status"] if os.path.exists(out) else "failed"})
        if "portable" in last and "native" in last:
            yp, yn = wheelset_y(last["portable"]), wheelset_y(last["native"])
            dy = max((float(np.max(np.abs(yn[k] - yp[k]))) for k in yp if k in yn
                      and len(yn[k]) == len(yp[k])), default=float("nan"))
            for r in rows:
                if r["build"] == "native":
                    r["max_dy_mm"] = 1e3 * dy
    cols = ["build", "march", "repeat", "cpu_s", "t_end_s", "x_real_time", "evaluations",
            "instructions", "max_dy_mm", "status", "cpu_model"]
    for r in rows:
        if r.get("cpu_s"):
            r["x_real_time"] = r["t_end_s"] / r["cpu_s"]
        r["cpu_model"] = model
    os.makedirs(os.path.dirname(os.path.abspath(a.csv)), exist_ok=True)
    with open(a.csv, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=cols)
        w.writeheader()
        for r in rows:
            w.writerow({c: r.get(c, "") for c in cols})
    return 0


if __name__ == "__main__":
    sys.exit(main())
