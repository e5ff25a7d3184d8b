"""`workbench stress`: the stability map as a figure (stress_map.png) from the verdict the
engine wrote (stress.csv: one row per run with its outcome and its lateral error against the
reference of its hardened case; workbench/stress/verdict.hpp, docs/stress.md).

    plots/rbplot stress DIR [--tolerance MM] [--dpi N]

Exit status: 0 the figure was drawn, 1 bad input (no stress.csv), 4 the figure failed.
"""
from __future__ import annotations

import os
import sys
from typing import Dict, List, Optional, Tuple

from .common import error, parser, read_csv, save_figure

OUTCOMES = ("ok", "inaccurate", "failed cleanly", "failed badly")
COLORS = {"ok": "#4dac26", "inaccurate": "#f1c232", "failed cleanly": "#e08214",
          "failed badly": "#b2182b"}
SHORT = {"ok": "ok", "inaccurate": "inacc", "failed cleanly": "clean-fail",
         "failed badly": "BAD"}


# ---- the map -----------------------------------------------------------------------------------

def _axes(rows: List[dict]) -> List[str]:
    out = []
    for r in rows:
        if r["axis"] not in out:
            out.append(r["axis"])
    return out


def _grid(rows: List[dict], axis: str) -> Tuple[List[str], List[str], Dict[Tuple[str, str], dict]]:
    values, integrators, cells = [], [], {}
    for r in rows:
        if r["axis"] != axis:
            continue
        if r["value_label"] not in values:
            values.append(r["value_label"])
        if r["integrator"] not in integrators:
            integrators.append(r["integrator"])
        cells[(r["value_label"], r["integrator"])] = r
    return values, integrators, cells


def _cell_text(r: Optional[dict]) -> str:
    if r is None:
        return "-"
    t = SHORT[r["outcome"]]
    if r["error_y_mm"] != "" and r["outcome"] in ("ok", "inaccurate") and \
            not r["integrator"].startswith("reference"):
        t += " %.2g" % float(r["error_y_mm"])
    return t


def figure(rows: List[dict], tol: float):
    from matplotlib.patches import Patch

    from .style import plt
    axes_names = _axes(rows)
    n = len(axes_names)
    ncol = min(n, 3)
    nrow = (n + ncol - 1) // ncol
    fig, axs = plt.subplots(nrow, ncol, figsize=(4.2 * ncol, 0.9 + 1.9 * nrow), squeeze=False)
    for k, axis in enumerate(axes_names):
        ax = axs[k // ncol][k % ncol]
        values, integrators, cells = _grid(rows, axis)
        for yi, v in enumerate(values):
            for xi, i in enumerate(integrators):
                r = cells.get((v, i))
                color = COLORS[r["outcome"]] if r else "#ffffff"
                ax.add_patch(plt.Rectangle((xi, yi), 1, 1, facecolor=color, edgecolor="white"))
                ax.text(xi + 0.5, yi + 0.5, _cell_text(r), ha="center", va="center", fontsize=6)
        ax.set_xlim(0, len(integrators))
        ax.set_ylim(0, len(values))
        ax.set_xticks([x + 0.5 for x in range(len(integrators))])
        ax.set_xticklabels([i.replace("reference ", "ref ") for i in integrators], rotation=30,
                           ha="right", fontsize=6)
        ax.set_yticks([y + 0.5 for y in range(len(values))])
        ax.set_yticklabels(values, fontsize=6)
        ax.set_title(axis, fontsize=8)
    for k in range(n, nrow * ncol):
        axs[k // ncol][k % ncol].axis("off")
    fig.legend(handles=[Patch(color=COLORS[o], label=o) for o in OUTCOMES], loc="lower center",
               ncol=4, fontsize=7, frameon=False)
    fig.suptitle(f"Stability map: outcome per axis value and integrator setting (ok: lateral "
                 f"error <= {tol:g} mm vs the case's own reference)", fontsize=8)
    fig.tight_layout(rect=(0, 0.06, 1, 0.95))
    return fig


def main(argv=None) -> int:
    ap = parser("stress", "the stability map of a `workbench stress` folder (from stress.csv)")
    ap.add_argument("dir", help="output folder of workbench stress")
    ap.add_argument("--tolerance", type=float, default=1.0,
                    help="largest wheelset lateral error [mm] of an ok run (the title; default 1)")
    ap.add_argument("--dpi", type=int, default=150)
    args = ap.parse_args(argv)
    path = os.path.join(args.dir, "stress.csv")
    if not os.path.exists(path):
        return error("stress", f"{args.dir}: no stress.csv (written by `workbench stress`)")
    rows = read_csv(path)
    unknown = sorted({r.get("outcome", "") for r in rows} - set(OUTCOMES))
    if unknown:
        return error("stress", f"{path}: unknown outcome {unknown[0]!r}")
    if not rows:
        return 0
    try:
        png = os.path.join(args.dir, "stress_map.png")
        save_figure(figure(rows, args.tolerance), png, dpi=args.dpi)
        print(png)
    except Exception as e:  # the verdict stands without its figure
        print(f"railbench stress: the figure failed: {e}", file=sys.stderr)
        return 4
    return 0
