#!/usr/bin/env python3
"""Cost of a train against its number of vehicles (docs/trains.md, "Cost").

usage: bench/train_scaling.py [CSV] [--workbench BIN] [--vehicles 1,2,4,10] [--duration 0.5]
                              [--no-callgrind] [--coupled]

Trains of N Manchester wagons 1 (KEC, the default scene's set-up: case 3 track with ORE B176 low
irregularities, ABM 1.25 ms with exponential stiff components, every output and the assessment)
run for `duration` simulated seconds, the leading wagon's reference point at 260 m and one every
25 m behind it (N = 1: the same wagon in a vehicle{} block). Without connections the vehicles are
independent, so the cost per rhs evaluation should grow as N: instructions per evaluation per
vehicle equal to one vehicle's.

--coupled: the wagons joined by buffers and draw gear (scenarios/train/couplings.lua, 50 mm
between the buffer faces and 60 mm slack, so that no connection is loaded at the start), with
their motion along the track as states and the leading wagon braking with 30 kN at its
wheelsets, on a track whose first 300 m are tangent (the leading wagon at 280 m): the cost of the
connections, the longitudinal states and the brake torques on top of the vehicles'.

Per N the run is made twice: plainly (CPU time from /stats) and under valgrind's callgrind,
collecting inside rb::integ::integrate only (the right-hand sides, the integrator and the output
callbacks, not the set-up), so that its count is the same from run to run whatever the machine
does; less the result-file flushes, whose number follows the wall clock.

Columns of the CSV (default out/studies/train_scaling.csv): vehicles, rhs_evals, cpu_s,
us_per_eval, us_per_eval_per_vehicle, instructions, instructions_per_eval,
instructions_per_eval_per_vehicle, relative_per_vehicle (to N = 1), commit.
"""
import argparse
import csv
import os
import subprocess
import sys
import tempfile

import h5py

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "plots"))
from railbench.effects import callgrind_total, flush_instructions  # noqa: E402
from railbench import provenance  # noqa: E402

HEAD = """-- bench/train_scaling.py: {n} Manchester wagon(s) on the default scene's track.
local c = require "validation.common"
local lib = require "tracks.lib"
local wagon = require "vehicles.manchester_wagon1"
track {{ segments = lib.manchester_r500(), step = 0.5,
        irregularities = psd {{ spectrum = "ore_b176_low", seed = 42, wavelengths = {{ 3, 70 }},
                               step = 0.1, fade_in = 0 }} }}
c.profiles()
c.contact("kec")
"""
TAIL = """c.abm(20, 1.25e-3)
run {{ output = {{ every = 0.01 }}, duration = {duration},
      assessment = {{ safety = true, stability = true, comfort = true, wear = true }} }}
"""


COUPLED_TRACK = """track { segments = { tangent { length = 300 },
  transition { length = 50, radius = 500, side = "left" },
  curve { length = 300, radius = 500, side = "left" } }, step = 0.5,
  irregularities = psd { spectrum = "ore_b176_low", seed = 42, wavelengths = { 3, 70 },
                         step = 0.1, fade_in = 0 } }
"""


def coupled(n: int, duration: float) -> str:
    head = HEAD.format(n=n)
    text = (head[:head.index("track {")] + "local couplings = require \"train.couplings\"\n" +
            COUPLED_TRACK + head[head.index("c.profiles()"):])
    if n == 1:
        text += "vehicle (wagon { speed = 20, start = 280 })\n"
        return text + TAIL.format(duration=duration)
    entries = []
    for k in range(n):
        brake = ", traction = { { 0, 0 }, { 0.1, -30e3 } }" if k == 0 else ""
        entries.append(f'  {{ name = "w{k + 1}", vehicle = wagon {{ speed = 20, '
                       f'start = {280 - 25.05 * k:.2f} }}{brake} }}')
    links = ",\n".join(f'  couplings.screw("w{k + 1}", "w{k + 2}", {{ slack = 0.06 }})'
                        for k in range(n - 1))
    text += ("train { vehicles = {\n" + ",\n".join(entries) + "\n},\nconnections = {\n" + links +
             "\n},\nlongitudinal = {} }\n")
    return text + TAIL.format(duration=duration)


def scenario(n: int, duration: float) -> str:
    text = HEAD.format(n=n)
    if n == 1:
        text += "vehicle (wagon { speed = 20, start = 260 })\n"
    else:
        entries = ",\n".join(f'  {{ name = "w{k + 1}", vehicle = wagon {{ speed = 20, '
                             f'start = {260 - 25 * k} }} }}' for k in range(n))
        text += "train { vehicles = {\n" + entries + "\n} }\n"
    return text + TAIL.format(duration=duration)


def run(cmd, out):
    r = subprocess.run(cmd, cwd=ROOT, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE,
                       text=True)
    if r.returncode != 0:
        raise RuntimeError(f"{' '.join(cmd)}: exit {r.returncode}: {r.stderr[-500:]}")
    with h5py.File(out, "r") as f:
        st = f["stats"].attrs
        return int(st["rhs_evals"]), float(st["cpu_time_s"])


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("csv", nargs="?", default=os.path.join(ROOT, "out", "studies",
                                                          "train_scaling.csv"))
    ap.add_argument("--workbench", default=os.path.join(ROOT, "build", "workbench", "app",
                                                        "workbench"))
    ap.add_argument("--vehicles", default="1,2,4,10")
    ap.add_argument("--duration", type=float, default=0.5)
    ap.add_argument("--no-callgrind", action="store_true")
    ap.add_argument("--coupled", action="store_true")
    a = ap.parse_args(argv)
    counts = [int(v) for v in a.vehicles.split(",")]
    if not counts or min(counts) < 1 or max(counts) > 10:
        print("train_scaling: --vehicles: numbers from 1 to 10", file=sys.stderr)
        return 1
    rows = []
    commit = provenance.tag(provenance.current())
    with tempfile.TemporaryDirectory(prefix="rb_train_scaling_") as tmp:
        for n in counts:
            lua = os.path.join(tmp, f"train_{n}.lua")
            with open(lua, "w") as f:
                f.write(coupled(n, a.duration) if a.coupled else scenario(n, a.duration))
            out = os.path.join(tmp, f"train_{n}.h5")
            evals, cpu = run([a.workbench, "run", lua, "--out", out, "--quiet"], out)
            row = dict(vehicles=n, rhs_evals=evals, cpu_s=f"{cpu:.4f}",
                       us_per_eval=f"{cpu / evals * 1e6:.2f}",
                       us_per_eval_per_vehicle=f"{cpu / evals / n * 1e6:.2f}", instructions="",
                       instructions_per_eval="", instructions_per_eval_per_vehicle="",
                       relative_per_vehicle="", commit=commit)
            if not a.no_callgrind:
                cg = os.path.join(tmp, f"callgrind_{n}.out")
                cg_out = os.path.join(tmp, f"train_{n}_cg.h5")
                evals_cg, _ = run(["valgrind", "--tool=callgrind", f"--callgrind-out-file={cg}",
                                   "--toggle-collect=rb::integ::integrate*", a.workbench, "run",
                                   lua, "--out", cg_out, "--quiet"], cg_out)
                ins = callgrind_total(cg) - flush_instructions(cg)
                row.update(instructions=ins, instructions_per_eval=f"{ins / evals_cg:.0f}",
                           instructions_per_eval_per_vehicle=f"{ins / evals_cg / n:.0f}")
            rows.append(row)
            print(" ".join(f"{k}={v}" for k, v in row.items()), flush=True)
    base = next((r for r in rows if r["vehicles"] == 1 and r["instructions"] != ""), None)
    for r in rows:
        if base and r["instructions"] != "":
            ratio = (float(r["instructions_per_eval_per_vehicle"]) /
                     float(base["instructions_per_eval_per_vehicle"]))
            r["relative_per_vehicle"] = f"{ratio:.3f}"
    os.makedirs(os.path.dirname(os.path.abspath(a.csv)), exist_ok=True)
    with open(a.csv, "w", newline="") as f:
        w = csv.DictWriter(f, list(rows[0].keys()))
        w.writeheader()
        w.writerows(rows)
    print(a.csv)
    return 0


if __name__ == "__main__":
    sys.exit(main())
