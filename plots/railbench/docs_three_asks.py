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


def stress_block(outdir: str) -> str:
    """The stability map of the hard case: counts per outcome, the map as a table (outcome and
    lateral error against the hardened case's own reference) and its figure."""
    d = _folder(outdir, STRESS)
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
           _pivot(rows), "", f"![stability map](figures/{STRESS}_stress_map.png)", ""]
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


def effects_block(outdir: str) -> str:
    """What each effect of case 3 costs and changes (`workbench effects`)."""
    d = _folder(outdir, EFFECTS)
    path = os.path.join(d, "effects.md")
    if not os.path.exists(path):
        return missing(f"{path} (./wb studies --only three_asks)")
    with open(path) as f:
        body = f.read()
    return body.replace("(figures/effects", f"(figures/{EFFECTS}_effects")


def three_asks_blocks(outdir: str) -> dict:
    return {"three_asks_precision": precision_block(outdir),
            "three_asks_stress": stress_block(outdir),
            "three_asks_effects": effects_block(outdir)}
