"""The work-precision figure of one model of `workbench precision` (docs/precision.md): integration
error (x, log) against CPU time and right-hand-side evaluations (y, log), one row per quantity;
the Pareto front bold, every other setting faint, failed settings as red crosses, errors below the
reference's bound greyed (not resolvable), the table error as a vertical line."""
from __future__ import annotations

import math
from typing import Dict, List, Optional

from .precision_errors import Quantity, pareto
from .style import A4_WIDTH_IN, FAIL_COLOR, plt, report_style
from .study_data import INTEGRATOR_COLORS


def _f(s) -> Optional[float]:
    try:
        v = float(s)
    except (TypeError, ValueError):
        return None
    return v


def _panel(ax, rows: List[dict], key: str, cost: str, bound, table, levels, chosen=()):
    pts = [(r, _f(r[key]), _f(r[cost])) for r in rows]
    ok = [(r, e, c) for r, e, c in pts if r["status"] == "ok" and e and c and e > 0 and c > 0]
    for integ in dict.fromkeys(r["integrator"] for r in rows):
        line = [(e, c) for r, e, c in ok if r["integrator"] == integ]
        if line:
            ax.plot([p[0] for p in line], [p[1] for p in line], "o-", color=INTEGRATOR_COLORS.get(
                integ, "#555555"), alpha=0.3, ms=3.5, lw=0.8, label=integ)
    front = pareto([(e, c) for _, e, c in ok])
    if front:
        fr = [ok[i] for i in front]
        ax.plot([p[1] for p in fr], [p[2] for p in fr], "-", color="black", lw=1.8, zorder=3,
                label="Pareto front")
        for r, e, c in fr:
            ax.plot(e, c, "o", color=INTEGRATOR_COLORS.get(r["integrator"], "#555555"), ms=5.5,
                    mec="black", zorder=4)
    for r, e, c in pts:
        if r["status"] not in ("ok", "skipped", "planned") and e and c and e > 0 and c > 0 \
                and math.isfinite(e):
            ax.plot(e, c, "x", color=FAIL_COLOR, ms=5)
    # The engine's recommendation (precision_recommendation.csv), drawn as it was computed.
    rec = [(e, c) for r, e, c in ok if r.get("case") in chosen]
    if rec:
        ax.plot([p[0] for p in rec], [p[1] for p in rec], "*", color="#1f5fa8", ms=11, mfc="none",
                mew=1.2, zorder=5, label="recommended (workbench precision)")
    xs = [e for _, e, _ in ok] + [v for v in (bound, table) if v and v > 0]
    if xs:
        lo, hi = min(xs) / 3, max(xs) * 3
        ax.set_xlim(lo, hi)
        if bound and bound > 0:
            ax.axvspan(lo, bound, color="#bbbbbb", alpha=0.4, lw=0,
                       label="below the reference bound (not resolvable)")
    if table and table > 0:
        ax.axvline(table, color="#444444", lw=1.0, ls="--",
                   label="table error (default vs refined tables)")
    for k, lv in enumerate(levels):
        ax.axvline(lv, color="#1f5fa8", lw=0.5, ls=":",
                   label="accuracy levels of the recommendation" if k == 0 else None)
    ax.set_xscale("log")
    ax.set_yscale("log")


def fig_model(model: str, rows: List[dict], ref: Dict, qs: List[Quantity], levels: List[float],
              refined: bool = False, recommended: List[dict] = ()):
    if not any(r["status"] == "ok" for r in rows):
        return None
    with report_style():
        fig, axes = plt.subplots(len(qs), 2, figsize=(A4_WIDTH_IN * 1.2, 2.9 * len(qs) + 1.2),
                                 squeeze=False)
        for i, q in enumerate(qs):
            key = f"{q.tag}_integration_max_{q.unit}"
            b = ref.get("bound", {}).get(q.tag)
            t = None if refined else ref.get("table", {}).get(q.tag)
            for j, (cost, label) in enumerate((("cpu_median_s", "CPU time [s] (median)"),
                                                ("rhs_evals", "rhs evaluations"))):
                ax = axes[i][j]
                _panel(ax, rows, key, cost, b[0] if b else None, t[0] if t else None,
                       levels if i == 0 else [],
                       {r.get("case") for r in recommended} if i == 0 else set())
                ax.set_xlabel(f"max |error| of {q.title} [{q.unit}]\n(integration error: "
                              f"against the reference on the same tables)", fontsize=7)
                ax.set_ylabel(label)
        h, lab = axes[0][0].get_legend_handles_labels()
        h.append(plt.Line2D([], [], marker="x", ls="none", color=FAIL_COLOR))
        lab.append("failed (error over the part it ran)")
        verified = ref.get("verified", False)
        title = f"Work-precision of {model}: what accuracy costs"
        if not verified:
            title += f" - REFERENCE UNVERIFIED ({ref.get('why', '')})"
        fig.suptitle(title, fontsize=9, color="black" if verified else FAIL_COLOR)
        rows_needed = (len(lab) + 2) // 3
        bottom = min(0.3, 0.02 + 0.02 * rows_needed)
        fig.tight_layout(rect=(0, bottom, 1, 0.96))
        fig.legend(h, lab, loc="lower center", ncol=3, fontsize=6, frameon=False)
    return fig
