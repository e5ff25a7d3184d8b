"""Figures of a study's metrics (study.metrics, docs/studies.md "Metrics"): each metric column
metric_<name> of summary_cases.csv against the swept parameters.

    metric_sweeps(cases)                   the parameters that vary over the cases (in order of
                                           appearance in the overrides) and each case's values
    fig_metric_lines(cases, name, keys)    the metric against the first swept parameter, one line
                                           per value of the second (when there is one)
    fig_metric_map(cases, name, keys)      heat map of the metric over the first two parameters
    make_metric_outputs(outdir, written)   study_metric_<name>.png (+ _map.png for two parameters)

Axes are labelled from study_labels.csv, which the study runner writes from the scenario schema
(workbench/scenario/override_check.hpp: a --set path as words with its SI unit,
vehicle.groups.primary_longitudinal.stiffness -> "primary longitudinal stiffness [N/m]") and
from the metrics (unit of the signal or assessment quantity, and the standard's limit where the
metric has one, e.g. Y/Q 0.8 of EN 14363, drawn as a red line; map cells beyond it in red).

A case whose metric could not be computed (empty field) is left out of the lines and shown as a
blank cell of the map; summary_cases.csv's message column says why.
"""
from __future__ import annotations

import csv
import math
import os
from typing import Dict, List, Optional, Tuple

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from .common import save_figure  # noqa: E402
from .style import DPI  # noqa: E402


def _overrides(text: str) -> Dict[str, str]:
    out: Dict[str, str] = {}
    for item in text.split():
        k, _, v = item.partition("=")
        out[k] = v
    return out


def _number(v: str) -> Optional[float]:
    try:
        x = float(v)
    except ValueError:
        return None
    return x if math.isfinite(x) else None


Labels = Dict[Tuple[str, str], dict]


def load_labels(outdir: str) -> Labels:
    """{(kind, name): row} of study_labels.csv (empty when the runner wrote none)."""
    path = os.path.join(outdir, "study_labels.csv")
    if not os.path.exists(path):
        return {}
    with open(path, newline="") as f:
        return {(r["kind"], r["name"]): r for r in csv.DictReader(f)}


def axis_label(labels: Labels, kind: str, name: str) -> str:
    """'primary longitudinal stiffness [N/m]'; the raw name when nothing is known."""
    r = labels.get((kind, name))
    if not r:
        return name
    unit = r.get("unit", "")
    return f"{r.get('label') or name} [{unit}]" if unit else (r.get("label") or name)


def legend_value(labels: Labels, key: str, value: str) -> str:
    """'vehicle speed = 40 m/s' for one line of the second swept parameter."""
    r = labels.get(("parameter", key))
    if not r:
        return f"{key} = {value}"
    unit = r.get("unit", "")
    unit = "" if unit in ("", "-") else " " + unit
    return f"{r.get('label') or key} = {value}{unit}"


def limit_of(labels: Labels, name: str) -> Tuple[Optional[float], str]:
    """The standard's limit of a metric and where it comes from (None when there is none)."""
    r = labels.get(("metric", name), {})
    return _number(r.get("limit", "")), r.get("limit_source", "")


def load_cases(outdir: str) -> List[dict]:
    with open(os.path.join(outdir, "summary_cases.csv"), newline="") as f:
        return list(csv.DictReader(f))


def metric_names(cases: List[dict]) -> List[str]:
    cols = list(cases[0].keys()) if cases else []
    return [c[len("metric_"):] for c in cols if c.startswith("metric_")]


def metric_sweeps(cases: List[dict]) -> Tuple[List[str], List[Dict[str, str]]]:
    """The override keys whose value differs between cases, and each case's overrides."""
    per_case = [_overrides(c.get("overrides", "")) for c in cases]
    keys: List[str] = []
    for ov in per_case:
        for k in ov:
            if k not in keys and len({o.get(k, "") for o in per_case}) > 1:
                keys.append(k)
    return keys, per_case


def _axis_values(values: List[str]) -> Tuple[List[str], bool]:
    """Distinct values in numeric order when all are numbers, else in order of appearance."""
    distinct = list(dict.fromkeys(values))
    if all(_number(v) is not None for v in distinct):
        return sorted(distinct, key=lambda v: _number(v)), True
    return distinct, False


def _value(case: dict, name: str) -> Optional[float]:
    return _number(case.get("metric_" + name, ""))


def fig_metric_lines(cases: List[dict], name: str, keys: List[str], labels: Labels = None):
    labels = labels or {}
    if not keys:
        return None
    _, per_case = metric_sweeps(cases)
    xkey = keys[0]
    lkey = keys[1] if len(keys) > 1 else None
    xs, numeric = _axis_values([ov.get(xkey, "") for ov in per_case])
    lines = _axis_values([ov.get(lkey, "") for ov in per_case])[0] if lkey else [""]
    fig, ax = plt.subplots(figsize=(6.4, 4.2))
    drawn = False
    for lv in lines:
        pts = []
        for c, ov in zip(cases, per_case):
            if lkey and ov.get(lkey, "") != lv:
                continue
            y = _value(c, name)
            if y is None:
                continue
            xv = ov.get(xkey, "")
            pts.append((_number(xv) if numeric else xs.index(xv), y))
        pts.sort()
        if pts:
            drawn = True
            ax.plot([p[0] for p in pts], [p[1] for p in pts], "o-",
                    label=legend_value(labels, lkey, lv) if lkey else None)
    if not drawn:
        plt.close(fig)
        return None
    if not numeric:
        ax.set_xticks(range(len(xs)))
        ax.set_xticklabels(xs, rotation=20)
    limit, source = limit_of(labels, name)
    if limit is not None:
        ax.axhline(limit, color="#c0392b", ls="--", lw=1.2, label=f"limit {limit:g} ({source})")
    ax.set_xlabel(axis_label(labels, "parameter", xkey))
    ax.set_ylabel(axis_label(labels, "metric", name))
    ax.set_title(f"metric {name}")
    ax.grid(True, alpha=0.3)
    if lkey or limit is not None:
        ax.legend(fontsize=8)
    fig.tight_layout()
    return fig


def metric_grid(cases: List[dict], name: str, keys: List[str]):
    """(x values, y values, grid [len(y) x len(x)] with NaN where there is no value)."""
    _, per_case = metric_sweeps(cases)
    xs = _axis_values([ov.get(keys[0], "") for ov in per_case])[0]
    ys = _axis_values([ov.get(keys[1], "") for ov in per_case])[0]
    grid = np.full((len(ys), len(xs)), np.nan)
    for c, ov in zip(cases, per_case):
        v = _value(c, name)
        if v is not None:
            grid[ys.index(ov.get(keys[1], "")), xs.index(ov.get(keys[0], ""))] = v
    return xs, ys, grid


def fig_metric_map(cases: List[dict], name: str, keys: List[str], labels: Labels = None):
    labels = labels or {}
    if len(keys) < 2:
        return None
    xs, ys, grid = metric_grid(cases, name, keys)
    if np.all(np.isnan(grid)):
        return None
    fig, ax = plt.subplots(figsize=(6.4, 4.6))
    im = ax.imshow(np.ma.masked_invalid(grid), origin="lower", aspect="auto", cmap="viridis")
    ax.set_xticks(range(len(xs)))
    ax.set_xticklabels(xs, rotation=20)
    ax.set_yticks(range(len(ys)))
    ax.set_yticklabels(ys)
    ax.set_xlabel(axis_label(labels, "parameter", keys[0]))
    ax.set_ylabel(axis_label(labels, "parameter", keys[1]))
    limit, source = limit_of(labels, name)
    for (i, j), v in np.ndenumerate(grid):
        if np.isfinite(v):
            over = limit is not None and v > limit
            ax.text(j, i, f"{v:.3g}", ha="center", va="center",
                    color="#ff4d4d" if over else "w", fontsize=8,
                    fontweight="bold" if over else "normal")
    fig.colorbar(im, ax=ax, label=axis_label(labels, "metric", name))
    title = f"metric {name}"
    if limit is not None:
        title += f"\nlimit {limit:g} ({source}): values above it in red"
    ax.set_title(title, fontsize=9)
    fig.tight_layout()
    return fig


def _safe(name: str) -> str:
    return "".join(ch if ch.isalnum() or ch in "-_" else "_" for ch in name)


def make_metric_outputs(outdir: str, written: List[str], dpi: int = DPI) -> None:
    """Every metric's figures; nothing for a study without metrics or without a sweep."""
    cases = [c for c in load_cases(outdir) if not c.get("role")]
    names = metric_names(cases)
    if not names:
        return
    keys, _ = metric_sweeps(cases)
    labels = load_labels(outdir)
    for name in names:
        p = os.path.join(outdir, f"study_metric_{_safe(name)}")
        save_figure(fig_metric_lines(cases, name, keys, labels), p + ".png", written, dpi)
        save_figure(fig_metric_map(cases, name, keys, labels), p + "_map.png", written, dpi)
