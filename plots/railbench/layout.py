"""Figure layout shared by the vehicle figures: failure banner, panel grid, legends."""
from __future__ import annotations

import math
from typing import Dict, List, Optional, Sequence, Tuple

import numpy as np

from .style import A4_WIDTH_IN, FAIL_COLOR, RUN_COLORS, RUN_STYLES, plt
from .result import Result, Track


# Vehicle results: helpers
# --------------------------------------------------------------------------------------------
def _pair(x: np.ndarray, v: np.ndarray) -> Tuple[np.ndarray, np.ndarray]:
    """x and v cut to their common length (a failed run may leave ragged series)."""
    n = min(x.size, v.size)
    return x[:n], v[:n]


def _last_finite(x: np.ndarray, v: np.ndarray) -> Optional[Tuple[float, float]]:
    ok = np.flatnonzero(np.isfinite(x) & np.isfinite(v))
    return (float(x[ok[-1]]), float(v[ok[-1]])) if ok.size else None


def _num(v) -> Optional[float]:
    if isinstance(v, (bool, np.bool_)):
        return None
    if isinstance(v, (int, float, np.integer, np.floating)) and math.isfinite(float(v)):
        return float(v)
    return None


def failure_text(result: Result) -> Optional[str]:
    """'FAILED at t = 12.345 s: <message>' for a failed run (/stats status), else None."""
    if not result.failed:
        return None
    t = result.t_reached()
    head = f"FAILED at t = {t:.6g} s" if t is not None else "FAILED"
    msg = " ".join(str(result.stats.get("message", "")).split())
    return f"{head}: {msg}" if msg else head


def add_failure_banner(fig, text: str, max_chars: Optional[int] = None, max_lines: int = 3):
    """Red line(s) `text` at the very top of `fig`, above its suptitle (or axes title).

    For constrained-layout figures the layout rectangle is lowered by the banner height and
    an existing suptitle is moved just below the banner (its height reserved explicitly, since
    constrained layout only reserves room for a suptitle at its automatic position)."""
    import textwrap
    fs = 8.5
    if max_chars is None:  # bold DejaVu Sans: ~0.63 em per character on average
        max_chars = max(20, int(fig.get_size_inches()[0] * 72 * 0.95 / (0.63 * fs)))
    lines = textwrap.wrap(text, max_chars) or [text]
    if len(lines) > max_lines:
        lines = lines[:max_lines]
        lines[-1] = lines[-1][:max_chars - 1].rstrip() + "…"
    pad_in = 3.0 / 72
    line_in = fs * 1.25 / 72
    fig_h = fig.get_size_inches()[1]
    banner_in = len(lines) * line_in + pad_in
    reserve_in = banner_in + pad_in
    sup = getattr(fig, "_suptitle", None)
    if sup is not None and not sup.get_text():
        sup = None
    if sup is not None:
        sup_in = (sup.get_text().count("\n") + 1) * sup.get_fontsize() * 1.25 / 72
        reserve_in += sup_in + pad_in
    eng = fig.get_layout_engine()
    params = eng.get() if eng is not None else {}
    if "rect" in params:
        left, bottom, width, height = params["rect"]
        top = bottom + height
        eng.set(rect=(left, bottom, width, height - reserve_in / fig_h))
    else:  # not constrained layout: plain subplots
        top = 1.0
        fig.subplots_adjust(top=min(fig.subplotpars.top, 1.0 - reserve_in / fig_h))
    if sup is not None:
        fig.suptitle(sup.get_text(), y=top - (banner_in + pad_in) / fig_h, va="top",
                     fontsize=sup.get_fontsize(), fontweight=sup.get_fontweight(),
                     color=sup.get_color())
    fig.text(0.5, top - pad_in / fig_h, "\n".join(lines), ha="center", va="top", fontsize=fs,
             color=FAIL_COLOR, fontweight="bold", linespacing=1.1)
    return fig


def _run_info(result: Result) -> str:
    parts = [result.stem + (f" {result.vehicle}" if result.vehicle else "")]
    m = result.contact_method
    if m:
        parts.append(f"{m.upper()} contact")
    elif result.guided:
        parts.append("guided wheelsets")
    sv = result.attrs.get("solver") or (result.stats or {}).get("method")
    if sv:
        parts.append(f"solver {sv}")
    return ", ".join(parts)


def _grid(n_items: int, n_quant: int, row_h: float, extra_h: float, max_cols: int = 4):
    """Axes for n_items columns (bodies / wheelsets) x n_quant rows (quantities).

    More than max_cols items wrap into further bands of n_quant rows.  The axes of one item
    share x (bodies of a vehicle are at different distances: in a short run a common x range
    would squeeze every column into a corner); only the bottom row of each item has x tick
    labels.  Returns (fig, cells, ncol), cells[i][q]."""
    nb = max(1, math.ceil(n_items / max_cols))
    ncol = max(1, math.ceil(n_items / nb))
    nrows = nb * n_quant
    fig_h = min(nrows * row_h + extra_h, 9.4)
    fig, axes = plt.subplots(nrows, ncol, figsize=(A4_WIDTH_IN, fig_h), squeeze=False,
                             layout="constrained")
    cells = []
    for i in range(nb * ncol):
        b, c = divmod(i, ncol)
        col = [axes[b * n_quant + q, c] for q in range(n_quant)]
        if i >= n_items:
            for ax in col:
                ax.set_visible(False)
            continue
        for ax in col[1:]:
            ax.sharex(col[0])
        for ax in col[:-1]:
            ax.xaxis.set_tick_params(labelbottom=False)
        cells.append(col)
    return fig, cells, ncol


def _share_rows(cells: List[List], keys: Sequence[str], ncol: int, labels: Sequence[str]):
    """Share y within each quantity row between items with the same key (e.g. body kind); y
    tick labels are dropped where the left neighbour already shows the same scale.  The first
    column of every band gets the row labels `labels`."""
    for q in range(len(cells[0]) if cells else 0):
        first: Dict[str, object] = {}
        for i, col in enumerate(cells):
            ax = col[q]
            if i % ncol == 0:
                ax.set_ylabel(labels[q])
            ref = first.get(keys[i])
            if ref is None:
                first[keys[i]] = ax
                continue
            ax.sharey(ref)
            if i % ncol != 0 and keys[i - 1] == keys[i]:
                ax.tick_params(labelleft=False)


def _min_span(ax, span: float):
    lo, hi = ax.get_ylim()
    if hi - lo < span:
        c = 0.5 * (lo + hi)
        ax.set_ylim(c - span / 2, c + span / 2)


def _bottom_legend(fig, groups: Sequence[Sequence], fig_h: float, max_per_row: int = 6):
    """Legend in a strip below the axes (matplotlib 3.6: no loc="outside ...").

    groups: lists of handles (e.g. runs, then segment kinds and markers).  They share one row
    when they fit in `max_per_row` entries, else each group gets a row of its own (split if
    longer), filled left to right."""
    from matplotlib.lines import Line2D

    groups = [list(g) for g in groups if g]
    if not groups:
        return
    flat = [h for g in groups for h in g]
    if len(flat) <= max_per_row:
        rows = [flat]
    else:
        rows = []
        for g in groups:
            rows += [g[i:i + max_per_row] for i in range(0, len(g), max_per_row)]
    ncol = max(len(r) for r in rows)
    blank = lambda: Line2D([], [], ls="none", label=" ")  # noqa: E731
    rows = [r + [blank() for _ in range(ncol - len(r))] for r in rows]
    handles = [rows[r][c] for c in range(ncol) for r in range(len(rows))]  # column-major
    strip = (0.1 + 0.17 * len(rows)) / fig_h
    eng = fig.get_layout_engine()
    left, bottom, width, height = eng.get()["rect"]
    eng.set(rect=(left, bottom + strip, width, height - strip))
    fig.legend(handles=handles, loc="lower center", bbox_to_anchor=(0.5, 0.0), ncol=ncol,
               fontsize=7, frameon=False, handlelength=2.2, columnspacing=1.4)


def _set_distance_range(ax, xmin: float, xmax: float, track: Optional[Track], to_end: bool):
    """x limits from the data; ends within 5 % of the track length snap to the track ends, and
    `to_end` (failed run) extends the range to the track end to show what is missing."""
    if track is not None:
        bounds = track.segment_bounds()
        b0, b1 = float(bounds[0]), float(bounds[-1])
        tol = 0.05 * (b1 - b0)
        if to_end:
            xmax = max(xmax, b1)
        if np.isfinite(xmin) and abs(xmin - b0) < tol:
            xmin = min(xmin, b0)
        if np.isfinite(xmax) and abs(xmax - b1) < tol:
            xmax = max(xmax, b1)
    if np.isfinite(xmin) and np.isfinite(xmax) and xmax > xmin:
        ax.set_xlim(xmin, xmax)


def _fail_marker(ax, x, v):
    p = _last_finite(x, v)
    if p is not None:
        ax.plot([p[0]], [p[1]], ls="none", marker="x", ms=5, mew=1.3, color=FAIL_COLOR, zorder=6)


def _fail_handle(label="last output of a failed run"):
    from matplotlib.lines import Line2D
    return Line2D([], [], ls="none", marker="x", ms=5, mew=1.3, color=FAIL_COLOR, label=label)


def _run_style(k: int) -> Dict[str, object]:
    """Colour, dash pattern and width of run k (dotted lines a little wider to stay visible)."""
    ls = RUN_STYLES[k % len(RUN_STYLES)]
    dotted = isinstance(ls, tuple) and ls[1][0] < 2
    return dict(color=RUN_COLORS[k % len(RUN_COLORS)], ls=ls, lw=1.3 if dotted else 1.0)


def _x_range(x: np.ndarray, xmin: float, xmax: float) -> Tuple[float, float]:
    """(xmin, xmax) widened to the finite values of x."""
    fin = x[np.isfinite(x)]
    return (min(xmin, fin.min()), max(xmax, fin.max())) if fin.size else (xmin, xmax)


def _label_cell(ax, q: int, n_rows: int, title: str, xlabel: str):
    """Body name above the first row of a column, the x label below its last row."""
    if q == 0:
        ax.set_title(title, fontsize=8.5)
    if q == n_rows - 1:
        ax.set_xlabel(xlabel)
