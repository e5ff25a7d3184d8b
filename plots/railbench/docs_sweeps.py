"""Generated blocks of the study runner's own results: the physics sweep of docs/studies.md
(scenarios/studies/primary_yaw.lua, run by `./wb studies --only primary_yaw` into
OUT_DIR/primary_yaw) and the throughput of the ways of running a study in docs/performance.md
(bench/study_throughput.py, run by `./wb studies --only study_throughput` into
OUT_DIR/study_throughput/study_throughput.csv).
"""
from __future__ import annotations

import math
import os
from typing import Dict, List, Optional

from .docs_blocks import fmt, missing, num, read_csv, table

SWEEP = "primary_yaw"
THROUGHPUT = "study_throughput"
STIFFNESS = "vehicle.groups.primary_longitudinal.stiffness"
SPEED = "vehicle.speed"
# Hunting: a limit cycle whose half peak-to-peak over the last 2 s exceeds 1 mm, the amplitude
# criterion `workbench critical-speed --irregular` uses on irregular track (docs/stability.md):
# below it the forced response to the (scaled) irregularities stays at a few tenths of a mm.
HUNTING_M = 1e-3


def _overrides(r: dict) -> Dict[str, float]:
    out = {}
    for part in r.get("overrides", "").split():
        k, _, v = part.partition("=")
        x = num(v)
        if x is not None:
            out[k] = x
    return out


def _sweep_rows(outdir: str) -> Optional[List[dict]]:
    rows = read_csv(os.path.join(outdir, SWEEP, "summary_cases.csv"))
    if not rows:
        return None
    for r in rows:
        ov = _overrides(r)
        r["_k"], r["_v"] = ov.get(STIFFNESS), ov.get(SPEED)
    return [r for r in rows if r["_k"] is not None and r["_v"] is not None]


def _metric(r: dict, name: str) -> Optional[float]:
    x = num(r.get("metric_" + name))
    return None if x is None or math.isnan(x) else x


def _onset(cells: List[dict]) -> str:
    """The speed bracket in which the hunting amplitude first exceeds HUNTING_M."""
    below = None
    for r in cells:
        a = _metric(r, "hunting_amplitude")
        if r["status"] != "ok" or a is None:
            continue
        if a > HUNTING_M:
            return (f"{below:g}..{r['_v']:g}" if below is not None else f"<= {r['_v']:g}")
        below = r["_v"]
    return f"> {below:g}" if below is not None else "–"


def _cell(r: dict, name: str, scale: float, spec: str) -> str:
    x = _metric(r, name)
    if r["status"] != "ok":
        # The summary's failure record (workbench/study/summary.cpp), not the message's words.
        reason = "wheel lift" if r.get("failure_reason") == "wheel_lift" else r["status"]
        return f"{fmt(None if x is None else x * scale, spec)} ({reason})" if x is not None \
            else reason
    return fmt(None if x is None else x * scale, spec)


def _figure(outdir: str, by_k: Dict[float, List[dict]]) -> None:
    """study_hunting_onset.png: hunting amplitude against speed, one line per stiffness, the
    linear critical speed of each stiffness marked on its line's colour."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(7, 4.2), constrained_layout=True)
    for i, (k, cells) in enumerate(sorted(by_k.items())):
        colour = f"C{i}"
        pts = [(r["_v"], _metric(r, "hunting_amplitude")) for r in cells
               if r["status"] == "ok" and _metric(r, "hunting_amplitude") is not None]
        if pts:
            ax.plot([p[0] for p in pts], [1e3 * p[1] for p in pts], "o-", color=colour,
                    label=f"Kpx = {k / 1e6:g} MN/m")
        failed = [r["_v"] for r in cells if r["status"] != "ok"]
        for v in failed:
            ax.plot([v], [0.0], "x", color=colour, markersize=9)
        vc = next((_metric(r, "linear_critical_speed") for r in cells
                   if _metric(r, "linear_critical_speed") is not None), None)
        if vc is not None:
            ax.axvline(vc, color=colour, linestyle=":", linewidth=1.2)
    ax.axhline(1e3 * HUNTING_M, color="0.4", linestyle="--", linewidth=0.8)
    ax.set_xlabel("speed [m/s]")
    ax.set_ylabel("leading wheelset: half peak-to-peak of y, last 2 s [mm]")
    ax.set_title("Hunting against speed (dotted: linear critical speed; x: run failed)")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    fig.savefig(os.path.join(outdir, SWEEP, "study_hunting_onset.png"), dpi=110)
    plt.close(fig)


def sweep_block(outdir: str) -> str:
    rows = _sweep_rows(outdir)
    if not rows:
        return missing(f"{outdir}/{SWEEP}/summary_cases.csv (./wb studies --only {SWEEP})")
    by_k: Dict[float, List[dict]] = {}
    for r in rows:
        by_k.setdefault(r["_k"], []).append(r)
    for cells in by_k.values():
        cells.sort(key=lambda r: r["_v"])
    speeds = sorted({r["_v"] for r in rows})
    _figure(outdir, by_k)
    head = ["Kpx [MN/m]", "linear critical speed [m/s]", "hunting onset [m/s]"]
    amp, yq = [], []
    for k, cells in sorted(by_k.items()):
        vc = next((_metric(r, "linear_critical_speed") for r in cells
                   if _metric(r, "linear_critical_speed") is not None), None)
        amp.append([f"{k / 1e6:g}", fmt(vc, "{:.1f}"), _onset(cells)] +
                   [_cell(r, "hunting_amplitude", 1e3, "{:.2f}") for r in cells])
        yq.append([f"{k / 1e6:g}"] + [_cell(r, "y_over_q_max", 1.0, "{:.2f}") for r in cells] +
                  [_cell(r, "y_ws1_max", 1e3, "{:.1f}") for r in cells[-1:]])
    ok = [r for r in rows if r["status"] == "ok"]
    cpu = sum(num(r.get("median_cpu_time_s"), 0.0) for r in ok)
    failed = [r for r in rows if r["status"] != "ok"]
    parts = [
        f"{len(rows)} cases ({len(by_k)} stiffnesses x {len(speeds)} speeds), "
        f"{len(ok)} ok, {cpu:.1f} s CPU in the runs' loops in all"
        + (f"; compact case files {_case_size(outdir) / 1e6:.1f} MB each on average, the "
           f"track stored once ({(_track_size(outdir) or 0) / 1e6:.1f} MB in tracks/)"
           if _case_size(outdir) else "") + ".",
        "",
        "Hunting amplitude (half peak-to-peak of the leading wheelset's lateral displacement over "
        "the last 2 s) [mm] per speed [m/s]; onset = the speeds between which it first exceeds "
        f"{HUNTING_M * 1e3:g} mm:",
        "",
        table(head + [f"{v:g}" for v in speeds], amp),
        "",
        "Largest Y/Q of any wheel (EN 14363 sliding mean) per speed [m/s], and the largest "
        f"|y| of the leading wheelset at {speeds[-1]:g} m/s [mm]:",
        "",
        table(["Kpx [MN/m]"] + [f"{v:g}" for v in speeds] + [f"max abs y ws1 at {speeds[-1]:g}"],
              yq),
    ]
    if failed:
        parts += ["", "Cases that did not finish (their metrics up to the failure are in the "
                  "summary, the windows they no longer reach are reported):", ""]
        for r in failed:
            msg = r.get("message", "")
            lift = msg.find("wheel lift:")
            head = msg.split(";")[0]
            why = msg[lift:].split(" (a constraint")[0] if lift >= 0 else ""
            parts.append(f"- Kpx = {r['_k'] / 1e6:g} MN/m, {r['_v']:g} m/s: {head[:160]}"
                         + (f"; {why[:200]}" if why else ""))
    parts += ["", "![hunting onset](figures/primary_yaw_hunting_onset.png)",
              "![hunting amplitude map](figures/primary_yaw_metric_hunting_amplitude_map.png)",
              "![Y/Q map](figures/primary_yaw_metric_y_over_q_max_map.png)"]
    return "\n".join(parts)


def _case_size(outdir: str) -> Optional[float]:
    """Mean size [bytes] of the physics sweep's case files (compact results)."""
    folder = os.path.join(outdir, SWEEP)
    if not os.path.isdir(folder):
        return None
    sizes = [os.path.getsize(os.path.join(folder, f)) for f in os.listdir(folder)
             if f.startswith("case_") and f.endswith(".h5") and ".run-" not in f]
    return sum(sizes) / len(sizes) if sizes else None


def _track_size(outdir: str) -> Optional[float]:
    folder = os.path.join(outdir, SWEEP, "tracks")
    if not os.path.isdir(folder):
        return None
    sizes = [os.path.getsize(os.path.join(folder, f)) for f in os.listdir(folder)]
    return sum(sizes) if sizes else None


def throughput_block(outdir: str) -> str:
    rows = read_csv(os.path.join(outdir, THROUGHPUT, "study_throughput.csv"))
    if not rows:
        return missing(f"{outdir}/{THROUGHPUT}/study_throughput.csv "
                       f"(./wb studies --only {THROUGHPUT})")
    body = []
    for r in rows:
        body.append([r["runner"], r["slots"], r["cases"], fmt(num(r["wall_s"]), "{:.1f}"),
                     fmt(num(r["cases_per_hour"]), "{:.0f}"),
                     fmt(num(r.get("efficiency")), "{:.2f}"),
                     fmt(num(r["overhead_per_case_s"]), "{:.2f}"),
                     fmt(num(r["overhead_cpu_per_case_s"]), "{:.2f}"),
                     fmt(num(r.get("load_1min")), "{:.1f}")])
    base = next((r for r in rows if r["runner"] == "local jobs=1"), None)
    empty = next((r for r in rows if "near-empty" in r["runner"]), None)
    farm = [r for r in rows if r["runner"].startswith("mpi ranks=")
            and "dispatch" not in r["runner"]]
    parts = [table(["runner", "slots", "cases", "wall [s]", "cases/h", "efficiency",
                    "overhead/case, slot time [s]", "overhead/case, CPU [s]", "load (1 min)"],
                   body)]
    if base is not None:
        n = num(base["cases"], 1.0)
        run_cpu = num(base["sum_run_cpu_s"], 0.0) / n
        over = num(base["overhead_cpu_per_case_s"], 0.0)
        fixed = num(empty["overhead_cpu_per_case_s"]) if empty else None
        per_case = run_cpu + over
        # The farm filling this machine's cores: the loss a full node sees.
        full = [num(r.get("efficiency"), 0.0) for r in farm
                if num(r["slots"], 0) == num(base.get("cores"), 0)]
        eff = min(max(full), 1.0) if full else 1.0
        size = _case_size(outdir)
        nodes, cores = 100, 32
        rate = nodes * cores * 3600.0 / per_case * min(eff, 1.0)
        parts += [
            "",
            f"One case here costs {run_cpu:.2f} s CPU in its run's own loop and "
            f"{over:.2f} s CPU around it (process start, scenario load, track build, hashing, "
            "metrics, stamping"
            + (f"; {fixed:.2f} s for a near-empty case" if fixed is not None else "") + ").",
            "",
            f"**Projection** for a cluster of {nodes} nodes x {cores} cores running this case "
            f"(basis: {per_case:.2f} s CPU per case all-in as measured above, one case per "
            f"core, the efficiency of the farm filling this machine's {base.get('cores')} cores "
            f"({eff:.2f}) for the loss to dispatch and start-up): about "
            f"{rate:,.0f} cases per hour. "
            + (f"At the {size / 1e6:.1f} MB of a compact case of the physics sweep "
               f"(docs/studies.md section 6) that is {rate * size / 3600 / 1e9:.1f} GB/s into "
               "the shared file system, which a cluster's file system must take or the cases "
               "must write less (a longer output interval). " if size else "")
            + "Not included: node start-up and queue time. Rank 0 hands out one run per "
            "message pair with at most 2 ms polling latency, far from a limit at these case "
            "costs.",
        ]
    return "\n".join(parts)


TRAIN_SCALING = "train_scaling"


TRAIN_SCALING_COUPLED = "train_scaling_coupled"


def train_scaling_block(outdir: str, study: str = TRAIN_SCALING) -> str:
    """docs/trains.md "Cost": per number of wagons the rhs evaluations, CPU and instructions per
    evaluation per vehicle (bench/train_scaling.py; study train_scaling_coupled: --coupled)."""
    rows = read_csv(os.path.join(outdir, study, f"{study}.csv"))
    if not rows:
        return missing(f"{outdir}/{study}/{study}.csv (./wb studies --only {study})")
    body = [[r["vehicles"], r["rhs_evals"], fmt(num(r["us_per_eval"]), "{:.1f}"),
             fmt(num(r["us_per_eval_per_vehicle"]), "{:.1f}"),
             fmt(num(r["instructions_per_eval"]), "{:.0f}"),
             fmt(num(r["instructions_per_eval_per_vehicle"]), "{:.0f}"),
             fmt(num(r["relative_per_vehicle"]), "{:.3f}")] for r in rows]
    return table(["wagons", "rhs evaluations", "CPU per evaluation [us]",
                  "CPU per evaluation per wagon [us]", "instructions per evaluation",
                  "instructions per evaluation per wagon", "per wagon / one wagon's"], body)


TRAIN_BRAKING = "train_braking"


def train_braking_block(outdir: str) -> str:
    """docs/trains.md "Buffers, draw gear and braking": the braking train's in-train forces and
    their lateral effect against the evenly braked train, and the rake's hand calculation
    (bench/train_braking.py)."""
    rows = read_csv(os.path.join(outdir, TRAIN_BRAKING, "train_braking.csv"))
    if not rows:
        return missing(f"{outdir}/{TRAIN_BRAKING}/train_braking.csv "
                       f"(./wb studies --only {TRAIN_BRAKING})")
    body = [[r["quantity"], fmt(num(r["braking"]), "{:.5g}"), fmt(num(r["coasting"]), "{:.5g}"),
             r["unit"]] for r in rows]
    return table(["quantity", "leading vehicle brakes (the scene)",
                  "evenly braked / hand calculation", "unit"], body)


TURNOUT = "turnout"


def turnout_block(outdir: str) -> str:
    """docs/turnouts.md: the shipped turnout scene against the same track with a plain rail, and
    the sliced-rail validation scenes against their references (bench/turnout.py)."""
    rows = read_csv(os.path.join(outdir, TURNOUT, "turnout.csv"))
    if not rows:
        return missing(f"{outdir}/{TURNOUT}/turnout.csv (./wb studies --only {TURNOUT})")
    body = [[r["quantity"], fmt(num(r["value"]), "{:.5g}"), fmt(num(r["reference"]), "{:.5g}"),
             r["unit"]] for r in rows]
    return table(["quantity", "value", "reference", "unit"], body)


def sweep_blocks(outdir: str) -> Dict[str, Dict[str, str]]:
    return {"studies.md": {SWEEP: sweep_block(outdir)},
            "performance.md": {THROUGHPUT: throughput_block(outdir)},
            "trains.md": {TRAIN_SCALING: train_scaling_block(outdir),
                          TRAIN_SCALING_COUPLED: train_scaling_block(outdir, TRAIN_SCALING_COUPLED),
                          TRAIN_BRAKING: train_braking_block(outdir)},
            "turnouts.md": {TURNOUT: turnout_block(outdir)}}
