"""Contact-table figures: KEC parameter map (paper Fig. 9, 10), rolling radius difference,
equivalent conicity."""
from __future__ import annotations

from typing import Dict, List, Optional

from matplotlib.patches import Patch
import numpy as np

from .style import A4_WIDTH_IN, SIDE_STYLE, plt, report_style
from .layout import _bottom_legend
from .tables_data import TRANS_FILL, Tables, _fmt_mm, _mm, delta_r_with_jumps
from .tables_figs import _kec_real_points, _main_cluster, _suptitle, _title


def fig_kec_map(t: Tables):
    """Paper Fig. 9/10: s_w(s_k) of each wheel with the regularised transitions, the weight w of
    the flange-side point B, and a zoom on the largest transition with A (tread end) and B."""
    kec = t.kec
    sides = kec.sides()
    sk = kec.s_k
    zoom = any(_main_cluster(kec, sd) for sd in sides)
    weight = any(kec.get(sd, "weight") is not None for sd in sides)
    any_tr = any(kec.transitions(sd) for sd in sides)
    rows = ["map"] + (["weight"] if weight else []) + (["zoom"] if zoom else [])
    hr = {"map": 1.5, "weight": 0.7, "zoom": 1.4}
    with report_style():
        fig, axes = plt.subplots(len(rows), len(sides),
                                 figsize=(A4_WIDTH_IN, 0.8 + sum(1.45 * hr[r] for r in rows)),
                                 squeeze=False, layout="constrained",
                                 height_ratios=[hr[r] for r in rows])
        for c, sd in enumerate(sides):
            col = SIDE_STYLE[sd]["color"]
            sw = kec.get(sd, "s_w")
            w = kec.get(sd, "weight")
            trs = kec.transitions(sd)
            a1 = axes[0, c]
            a2 = axes[1, c] if weight else None
            if a2 is not None:
                a2.sharex(a1)
            for _, lo, hi in trs:
                for a in (a1, a2):
                    if a is not None:
                        a.axvspan(_mm(lo), _mm(hi), color=TRANS_FILL, lw=0, alpha=0.8, zorder=0)
            real = _kec_real_points(t, sd)
            if real is not None and real[0].size:
                a1.plot(_mm(real[0]), _mm(real[1]), ".", ms=2.2, color="#888888", zorder=2,
                        label="real contact (LUT, $\\xi_g$ = 0)")
            a1.plot(_mm(sk), _mm(sw), color=col, lw=1.1, zorder=3, label="KEC table $s_w(s_k)$")
            a1.set_title(f"{sd} wheel", loc="left")
            a1.set_ylabel("$s_w$ [mm]")
            a1.legend(loc="upper left", fontsize=6.5)
            a1.set_xlim(_mm(sk[0]), _mm(sk[-1]))
            if a2 is not None:
                if w is not None:
                    a2.plot(_mm(sk), w, color=col, lw=1.0)
                else:
                    a2.text(0.5, 0.5, "no weight dataset", transform=a2.transAxes, ha="center",
                            va="center", fontsize=7, color="#777777")
                a2.set_ylim(-0.08, 1.12)
                a2.set_ylabel("weight w of B")
            (a2 or a1).set_xlabel("equivalent parameter $s_k$ [mm]")
            if zoom:
                _kec_zoom(axes[-1, c], t, sd, col, real)
        if any_tr:
            hl = [Patch(color=TRANS_FILL, label="regularised transition [lo, hi]: $\\hat d$ = "
                        f"{_fmt_mm(kec.attrs.get('dhat', np.nan))} mm (flange side), $\\bar d$ = "
                        f"{_fmt_mm(kec.attrs.get('dbar', np.nan))} mm")]
            _bottom_legend(fig, [hl], fig.get_size_inches()[1])
        _suptitle(fig, f"KEC lookup table: real versus equivalent wheel parameter — {_title(t)}")
    return fig


def _kec_zoom(ax, t: Tables, sd: str, col, real):
    """Zoom on the main group of transitions: s_w(s_k), the real LUT contact, the end points A
    (field-side end, w = 0) and B (flange-side end, w = 1) of every transition, w dashed."""
    kec = t.kec
    sk, sw, w = kec.s_k, kec.get(sd, "s_w"), kec.get(sd, "weight")
    group = _main_cluster(kec, sd)
    if not group:
        ax.text(0.5, 0.5, "no transition", transform=ax.transAxes, ha="center", va="center")
        ax.set_axis_off()
        return
    lo, hi = group[0][1], max(tr[2] for tr in group)
    width = hi - lo
    x0, x1 = lo - 0.6 * width, hi + 0.6 * width
    # shading and the dashed weight on a twin axis drawn below the s_w axis
    tw = ax.twinx()
    tw.grid(False)
    tw.set_zorder(ax.get_zorder() - 1)
    ax.patch.set_visible(False)
    for _, a, b in kec.transitions(sd):
        if b > x0 and a < x1:
            tw.axvspan(_mm(a), _mm(b), color=TRANS_FILL, lw=0, alpha=0.8, zorder=0)
    sel = (sk >= x0) & (sk <= x1)
    if real is not None:
        rs = (real[0] >= x0) & (real[0] <= x1)
        ax.plot(_mm(real[0][rs]), _mm(real[1][rs]), ".", ms=3, color="#888888", zorder=2)
    ax.plot(_mm(sk[sel]), _mm(sw[sel]), color=col, lw=1.2, marker=".", ms=2.5, zorder=3)
    # A: field-side end (w = 0), B: flange-side end (w = 1); left flange side = smaller s_k
    ends: Dict[float, List[str]] = {}
    n = len(group)
    order = group if sd == "right" else group[::-1]   # numbered from the field side
    for k, (sj, a, b) in enumerate(order):
        ax.axvline(_mm(sj), color="#555555", lw=0.6, ls=":", zorder=1)
        sub = f"$_{k + 1}$" if n > 1 else ""
        pa, pb = (b, a) if sd == "left" else (a, b)
        for key, name in ((pa, "A"), (pb, "B")):
            match = next((e for e in ends if abs(e - key) < 1e-7), key)
            ends.setdefault(match, []).append(name + sub)
    rising = float(np.interp(hi, sk, sw)) >= float(np.interp(lo, sk, sw))
    for at, names in ends.items():
        v = float(np.interp(at, sk, sw))
        ax.plot(_mm(at), _mm(v), "o", ms=5, mfc="white", mec="black", mew=1.0, zorder=5)
        ax.annotate(f"{' = '.join(names)}: {v * 1e3:.1f} mm", (_mm(at), _mm(v)),
                    xytext=(-5 if rising else 5, 5), textcoords="offset points",
                    ha="right" if rising else "left", va="bottom", fontsize=6.5,
                    bbox=dict(boxstyle="round,pad=0.15", fc="white", ec="none", alpha=0.8),
                    zorder=6)
    ax.set_xlim(_mm(x0), _mm(x1))
    lo_y, hi_y = ax.get_ylim()
    pad = 0.12 * (hi_y - lo_y)
    ax.set_ylim(lo_y - pad, hi_y + pad)
    ax.set_ylabel("$s_w$ [mm]")
    ax.set_xlabel("$s_k$ [mm]")
    js = ", ".join(f"{tr[0] * 1e3:.2f}" for tr in group)
    ax.set_title(f"zoom: jump{'s' if n > 1 else ''} at $s_k$ = {js} mm", loc="left", fontsize=8)
    tw.set_ylim(-0.08, 1.12)
    if w is not None:
        tw.plot(_mm(sk[sel]), w[sel], color="#333333", lw=0.9, ls=(0, (4, 2.5)))
        tw.set_ylabel("weight w (dashed)", fontsize=7)
    else:
        tw.set_yticks([])


def fig_rolling_radius(t: Tables):
    """delta r(y) = r_l - r_r [mm] (with r_l - r0, r_r - r0) and delta gamma(y) [deg] at
    xi_g = 0, two-point contact positions marked."""
    d = t.derived
    y = _mm(d["y"])
    has_g = "delta_gamma" in d
    tps = t.lut.two_points(float(t.lut.xi_g[t.lut.row(0.0)])) if t.lut is not None else []
    with report_style():
        fig, axes = plt.subplots(2 if has_g else 1, 1, figsize=(A4_WIDTH_IN, 4.9 if has_g else 2.9),
                                 sharex=True, squeeze=False, layout="constrained")
        a1 = axes[0, 0]
        yj, drj = delta_r_with_jumps(d)
        a1.plot(_mm(yj), _mm(drj), color="black", lw=1.4, label="$\\Delta r = r_l - r_r$",
                zorder=3)
        r0 = t.g("r0")
        if r0 is not None:
            for sd in ("left", "right"):
                if f"r_{sd}" in d:
                    a1.plot(y, _mm(d[f"r_{sd}"] - r0), lw=0.8, label=f"$r_{sd[0]} - r_0$",
                            **SIDE_STYLE[sd])
        a1.axhline(0, color="k", lw=0.5)
        a1.set_ylabel("rolling radius [mm]")
        a1.set_title("(a) rolling radius difference ($\\xi_g$ = 0)", loc="left")
        axs = [a1]
        if has_g:
            a2 = axes[1, 0]
            a2.plot(y, np.degrees(d["delta_gamma"]), color="black", lw=1.4,
                    label="$\\Delta\\gamma = \\gamma_l - \\gamma_r$")
            a2.axhline(0, color="k", lw=0.5)
            a2.set_ylabel("$\\Delta\\gamma$ [deg]")
            a2.set_title("(b) contact angle difference", loc="left")
            axs.append(a2)
        for ty, side in tps:
            for a in axs:
                a.axvline(ty * 1e3, color="#d00000", lw=0.8, ls=(0, (4, 2)), zorder=1)
        if tps:
            # The title above the two-line labels of the top axis (the report style does not move
            # titles by itself).
            a1.set_title(a1.get_title(loc="left"), loc="left", pad=26)
            top = a1.secondary_xaxis("top")
            top.set_xticks([ty * 1e3 for ty, _ in tps])
            top.set_xticklabels([f"two-point ({'left' if s > 0 else 'right'} wheel)\n"
                                 f"y = {ty * 1e3:+.2f} mm" for ty, s in tps], fontsize=6.5,
                                color="#d00000")
            top.tick_params(direction="out", length=3, color="#d00000")
        a1.legend(loc="lower right", fontsize=7)
        axs[-1].set_xlabel("lateral displacement y [mm]  (+ left)")
        axs[-1].set_xlim(y[0], y[-1])
        _suptitle(fig, f"Rolling radius and contact angle difference — {_title(t)}")
    return fig


def conicity_at(t: Tables, amplitude: float) -> Optional[float]:
    c = t.conicity
    if c is None:
        return None
    a, g = c
    if amplitude < a.min() - 1e-12 or amplitude > a.max() + 1e-12:
        return None
    return float(np.interp(amplitude, a, g))


def fig_conicity(t: Tables):
    """EN 15302 equivalent conicity tan(gamma_e) versus amplitude, with delta r / (2 y)."""
    a, g = t.conicity
    with report_style():
        fig, ax = plt.subplots(figsize=(A4_WIDTH_IN, 3.4), layout="constrained")
        ax.plot(_mm(a), g, color="#1f5fa8", lw=1.5, marker="o", ms=2.5,
                label="tan $\\gamma_e$ (EN 15302, Annex B method)", zorder=3)
        d = t.derived
        if d is not None:
            y, dr = d["y"], d["delta_r"]
            sel = (y > 0.25e-3) & (y <= a.max() * 1.05)
            if sel.any():
                ax.plot(_mm(y[sel]), dr[sel] / (2 * y[sel]), color="#777777", lw=0.9,
                        ls=(0, (4, 2.5)), label="$\\Delta r(y) / (2y)$ (local, for comparison)",
                        zorder=2)
        v3 = conicity_at(t, 3e-3)
        if v3 is not None:
            ax.plot([3.0, 3.0], [0, v3], color="#b2182b", lw=0.7, ls=":")
            ax.plot([0, 3.0], [v3, v3], color="#b2182b", lw=0.7, ls=":")
            ax.plot(3.0, v3, "o", ms=6, mfc="white", mec="#b2182b", mew=1.4, zorder=4)
            ax.annotate(f"tan $\\gamma_e$ = {v3:.3f} at $\\hat y$ = 3 mm", (3.0, v3),
                        xytext=(0.5, v3 * 0.45), textcoords="data", fontsize=8, color="#b2182b",
                        ha="left", va="center",
                        bbox=dict(boxstyle="round,pad=0.25", fc="white", ec="#b2182b", lw=0.5),
                        arrowprops=dict(arrowstyle="-", color="#b2182b", lw=0.6,
                                        shrinkA=0, shrinkB=4), zorder=5)
        ax.set_xlim(0, max(_mm(a.max()) * 1.03, 3.5))
        hi = float(np.nanmax(g))
        ax.set_ylim(0, hi * 1.25 if hi > 0 else 1)
        ax.set_xlabel("amplitude $\\hat y$ [mm]")
        ax.set_ylabel("equivalent conicity tan $\\gamma_e$ [-]")
        ax.legend(loc="upper right", fontsize=7)
        ax.set_title("from the rolling radius difference $\\Delta r(y)$ at $\\xi_g$ = 0",
                     loc="left")
        _suptitle(fig, f"Equivalent conicity (EN 15302) — {_title(t)}")
    return fig


# --------------------------------------------------------------------------------------------
