"""Generated blocks of docs/three_asks.md: the three commands run on the paper's case 3 and on a
hard case by `./wb studies --only three_asks` into OUT_DIR/three_asks_{precision,stress,effects}.
"""
from __future__ import annotations

import os
from collections import Counter, OrderedDict
from typing import List

from .docs_blocks import fmt, missing, num, read_csv, table

PRECISION = "three_asks_precision"
STRESS = "three_asks_stress"
STRESS_KEC = "three_asks_stress_kec"
EFFECTS = "three_asks_effects"


def _folder(outdir: str, name: str) -> str:
    return os.path.join(outdir, name)


def precision_block(outdir: str) -> str:
    """The references (verified or not, bound, table error), the spread of the integration
    error, the recommendation table and the work-precision figures of case 3."""
    d = _folder(outdir, PRECISION)
    if not os.path.exists(os.path.join(d, "precision.csv")):
        return missing(f"{d}/precision.csv (./wb studies --only three_asks)")
    from .precision import block_from_folder  # heavy imports only when there is something to show
    body = block_from_folder(d)
    # The command names its figures precision_<model>.png; docs/figures holds them per folder.
    return body.replace("(figures/precision_", f"(figures/{PRECISION}_precision_")


def _pivot(rows: List[dict]) -> str:
    """Outcome per hardened case (axis, value) and integrator setting, references first."""
    settings = list(OrderedDict.fromkeys(
        r["integrator"] for r in sorted(rows, key=lambda r: r.get("role") != "reference")))
    cells = OrderedDict()
    for r in rows:
        key = (r["axis"], r["value_label"])
        cells.setdefault(key, {})[r["integrator"]] = r
    body = []
    for (axis, value), by in cells.items():
        line = [axis, value]
        for s in settings:
            r = by.get(s)
            if r is None:
                line.append("–")
                continue
            err = num(r.get("error_y_mm"))
            line.append(r["outcome"] + ("" if err is None or r.get("role") == "reference"
                                        else f" ({fmt(err, '{:.2g}')} mm)"))
        body.append(line)
    return table(["axis", "value"] + settings, body)


def stress_block(outdir: str, folder: str = STRESS) -> str:
    """The stability map of a hard case: counts per outcome, the map as a table (outcome and
    lateral error against the hardened case's own reference) and its figure."""
    d = _folder(outdir, folder)
    path = os.path.join(d, "stress.csv")
    if not os.path.exists(path):
        return missing(f"{path} (./wb studies --only three_asks)")
    rows = read_csv(path)
    counts = Counter(r["outcome"] for r in rows)
    cpu = sum(num(r.get("cpu_s")) or 0.0 for r in rows)
    out = [f"{len(rows)} runs ({sum(1 for r in rows if r.get('role') == 'reference')} of them "
           f"references), {cpu:.0f} s CPU in all: " +
           ", ".join(f"{counts.get(o, 0)} {o}" for o in
                     ("ok", "inaccurate", "failed cleanly", "failed badly")) + ".", "",
           _pivot(rows), "", f"![stability map](figures/{folder}_stress_map.png)", ""]
    notes = [r for r in rows if r["outcome"] in ("failed cleanly", "failed badly")
             and r.get("role") == "reference"]
    if notes:
        out.append("Where the reference itself stops, the model leaves its validity (the "
                   "message of the reference run):")
        out.append("")
        for r in notes:
            out.append(f"- {r['axis']} = {r['value_label']}: {(r['message'] or '')[:160]}")
        out.append("")
    return "\n".join(out)


def _stats_of(path: str):
    """(effects lines, [(stage, share)]) of a result file's /stats."""
    import h5py  # only when there is a result to read
    with h5py.File(path, "r") as f:
        st = f["stats"]
        eff = st.attrs.get("effects", b"")
        eff = eff.decode() if isinstance(eff, bytes) else str(eff)
        shares = []
        if "stage_names" in st and "stage_share" in st:
            names = [n.decode() if isinstance(n, bytes) else str(n) for n in st["stage_names"][()]]
            shares = list(zip(names, (float(v) for v in st["stage_share"][()])))
    return [e for e in eff.splitlines() if e.strip()], shares


def _cell(r: dict, key: str, spec: str) -> str:
    return fmt(num(r.get(key)), spec)


def effects_block(outdir: str) -> str:
    """Case 3: the effects and rhs stage shares its run records in /stats, and what each
    optional effect costs and changes (`workbench effects`)."""
    d = _folder(outdir, EFFECTS)
    path = os.path.join(d, "effects.csv")
    if not os.path.exists(path):
        return missing(f"{path} (./wb studies --only three_asks)")
    rows = read_csv(path)
    out = []
    base = next((r for r in rows if r.get("role") == "baseline"), None)
    base_file = None
    if base is not None:
        cases = {r["case"]: r for r in read_csv(os.path.join(d, "summary_cases.csv"))}
        base_file = (cases.get(base.get("case", "")) or {}).get("file")
    if base_file and not os.path.isabs(base_file):
        base_file = os.path.join(d, os.path.basename(base_file))
    if base_file and os.path.exists(base_file):
        effects, shares = _stats_of(base_file)
        out += ["What the full scene's result file records (`/stats`: the effects compiled into "
                "the run, and the share of the run's cost per stage of the right-hand side, "
                "timed on 1 evaluation in 64):", "",
                table(["effects (/stats@effects)"], [[e] for e in effects]), ""]
        if shares:
            out += [table(["stage", "share of the run's cost"],
                          [[n, f"{100 * v:.1f} %"] for n, v in
                           sorted(shares, key=lambda x: -x[1])]), ""]
    body = []
    for r in rows:
        if not r.get("case"):  # an effect the scene has but cannot switch off, or lacks
            body.append([r["effect"], r.get("role", ""), "", "", "", "", "", "",
                         (r.get("note") or "")[:100]])
            continue
        body.append([r["effect"], r.get("check", ""),
                     _cell(r, "instructions_per_eval", "{:.0f}"),
                     _cell(r, "d_instructions_pct", "{:.1f}"),
                     _cell(r, "cpu_us_per_eval", "{:.2f}"),
                     _cell(r, "d_cpu_pct", "{:.1f}"),
                     f"{_cell(r, 'max_dy', '{:.3g}')} / {_cell(r, 'rms_dy', '{:.3g}')}",
                     f"{_cell(r, 'max_dyaw', '{:.3g}')} / {_cell(r, 'rms_dyaw', '{:.3g}')}",
                     (r.get("note") or "")[:100]])
    out += ["Each optional effect switched off in turn (`run.effects.<name> = false`) against the "
            "full scene: instructions per rhs evaluation (callgrind, repeatable), CPU time per "
            "evaluation (median of the repeats, noisy), and the change of every wheelset's "
            "lateral displacement and yaw angle:", "",
            table(["effect off", "on/off check", "instructions / eval", "saved [%]",
                   "CPU [us/eval]", "CPU saved [%]", "max / rms dy [mm]",
                   "max / rms dyaw [mrad]", "note"], body), "",
            f"![effects](figures/{EFFECTS}_effects.png)", ""]
    return "\n".join(out)


def three_asks_blocks(outdir: str) -> dict:
    return {"three_asks_precision": precision_block(outdir),
            "three_asks_stress": stress_block(outdir),
            "three_asks_stress_kec": stress_block(outdir, STRESS_KEC),
            "three_asks_effects": effects_block(outdir)}
