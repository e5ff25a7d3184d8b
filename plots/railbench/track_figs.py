"""Track figures: plan view, curvature and cant, irregularities and their PSD."""
from __future__ import annotations

import math
from typing import Optional

from matplotlib.patches import Patch
from matplotlib.ticker import NullLocator
import numpy as np

from .style import A4_WIDTH_IN, CHANNEL_COLORS, CHANNEL_TITLES, SEGMENT_FILL, SEGMENT_LINE, plt, report_style
from .result import Result, Track
from .psd import default_nperseg, fractional_octave_average, interp_loglog, welch_psd, welch_segment_starts


# Figure helpers
# --------------------------------------------------------------------------------------------
def _shade_segments(ax, track: Track, alpha: float = 1.0):
    st, ln, kd = track.segments["start"], track.segments["length"], track.segments["kind"]
    for a, l, k in zip(st, ln, kd):
        name = track.kind_name(k)
        if name != "tangent":  # tangent stays white
            ax.axvspan(a, a + l, color=SEGMENT_FILL.get(name, "#eeeeee"), alpha=alpha, lw=0,
                       zorder=0)
    for b in track.segment_bounds():
        ax.axvline(b, color="#9a9a9a", lw=0.5, zorder=0.5)


def _segment_legend_handles(track: Track):
    kinds = sorted({int(round(k)) for k in track.segments["kind"]})
    return [Patch(facecolor=SEGMENT_FILL.get(track.kind_name(k), "#eee"), edgecolor="#9a9a9a",
                  lw=0.5, label=track.kind_name(k)) for k in kinds]


def _segment_label(track: Track, i: int) -> str:
    sg = track.segments
    name = track.kind_name(sg["kind"][i])
    txt = f"{name}, {sg['length'][i]:g} m"
    r = sg["radius"][i]
    side = track.side_name(sg["side"][i])
    if name == "curve" and r > 0:
        txt += f"\nR = {r:g} m {side}"
    elif name == "transition":
        txt += f"\nto R = {r:g} m {side}" if r > 0 else "\nto straight"
    if name in ("transition", "curve") and sg["cant"][i] != 0:
        txt += f", cant {sg['cant'][i] * 1e3:g} mm"
    return txt


def _interp_pose(track: Track, s_q: np.ndarray):
    cl = track.centreline
    s = cl["s"]
    hd = np.unwrap(cl["heading"])
    return np.interp(s_q, s, cl["x"]), np.interp(s_q, s, cl["y"]), np.interp(s_q, s, hd)


# --------------------------------------------------------------------------------------------
# Figures
# --------------------------------------------------------------------------------------------
def fig_track_plan(result: Result):
    """Plan view x-y (equal aspect), coloured by segment kind, with short lines perpendicular
    to the track at the segment transition points (paper Fig. 16/18).  Boundary ticks carry
    their arc length; segments are numbered on the outside of the curve and described in the
    legend (by kind only when there are more than 12 segments)."""
    from matplotlib.lines import Line2D

    tr = result.track
    cl = tr.centreline
    s, x, y = cl["s"], cl["x"], cl["y"]
    with report_style():
        fig, ax = plt.subplots(figsize=(A4_WIDTH_IN, 3.7), layout="constrained")
        ext = max(np.ptp(x), np.ptp(y), 1.0)
        tick = 0.05 * ext
        bounds = tr.segment_bounds()
        nseg = tr.n_segments
        detailed = nseg <= 12
        handles = []
        seen = set()
        ax.plot(x, y, color="#bbbbbb", lw=0.8, zorder=1)
        for i in range(nseg):
            a, b = bounds[i], bounds[i + 1]
            k = tr.kind_name(tr.segments["kind"][i])
            sel = (s > a) & (s < b)
            xa, ya, _ = _interp_pose(tr, np.array([a, b]))
            xs = np.concatenate([[xa[0]], x[sel], [xa[1]]])
            ys = np.concatenate([[ya[0]], y[sel], [ya[1]]])
            col = SEGMENT_LINE.get(k, "k")
            ax.plot(xs, ys, color=col, lw=2.0, solid_capstyle="butt", zorder=2)
            if detailed:
                handles.append(Line2D([], [], color=col, lw=2.0,
                                      label=f"{i + 1}: " + _segment_label(tr, i).replace("\n", ", ")))
            elif k not in seen:
                handles.append(Line2D([], [], color=col, lw=2.0, label=k))
                seen.add(k)
        # Outside of the curve = opposite to the net turning direction.
        turn = np.unwrap(cl["heading"])[-1] - np.unwrap(cl["heading"])[0]
        out_global = -1.0 if turn >= 0 else 1.0   # multiplies the left normal

        def out_side(a, b):
            """Outside of the curve over [a, b]: -sign(mean curvature), global if straight."""
            sel = (s >= a) & (s <= b)
            k = float(np.mean(cl["curvature"][sel])) if sel.any() else 0.0
            return -float(np.sign(k)) if abs(k) > 1e-9 else out_global

        bx, by, bh = _interp_pose(tr, bounds)
        span = 0.25 * (bounds[-1] - bounds[0]) / max(nseg, 1)
        for px, py, h, sb in zip(bx, by, bh, bounds):
            nx, ny = -np.sin(h), np.cos(h)
            out = out_side(sb - span, sb + span)
            ax.plot([px - nx * tick / 2, px + nx * tick / 2],
                    [py - ny * tick / 2, py + ny * tick / 2], color="k", lw=1.1, zorder=3)
            # arc-length label continues the tick on the inside of the curve
            ux, uy = -out * nx, -out * ny
            ang = math.degrees(math.atan2(uy, ux))
            ha = "left"
            if ang > 100 or ang <= -80:  # keep text readable (a little past vertical is fine)
                ang += 180 if ang <= -80 else -180
                ha = "right"
            lx, ly = px + ux * tick * 0.6, py + uy * tick * 0.6
            # invisible points along the label so that legend loc="best" avoids it
            ax.plot(lx + ux * tick * np.linspace(0, 1.6, 5), ly + uy * tick * np.linspace(0, 1.6, 5),
                    ls="none", marker="", alpha=0)
            ax.text(lx, ly, f"s = {sb:g} m", rotation=ang,
                    rotation_mode="anchor", ha=ha, va="center", fontsize=6.5, color="#333333",
                    zorder=4)
        if detailed:
            mids = 0.5 * (bounds[:-1] + bounds[1:])
            mx, my, mh = _interp_pose(tr, mids)
            for i, (px, py, h) in enumerate(zip(mx, my, mh)):
                nx, ny = -np.sin(h), np.cos(h)
                out = out_side(bounds[i], bounds[i + 1])
                ax.plot([px + out * nx * tick * 0.75], [py + out * ny * tick * 0.75], ls="none",
                        marker="", alpha=0)
                ax.text(px + out * nx * tick * 0.75, py + out * ny * tick * 0.75, str(i + 1),
                        ha="center", va="center", fontsize=7, zorder=5,
                        bbox=dict(boxstyle="circle,pad=0.2", fc="white",
                                  ec=SEGMENT_LINE.get(tr.kind_name(tr.segments["kind"][i]), "k"),
                                  lw=0.8))
        ax.plot(x[0], y[0], "o", ms=4.5, color="k", zorder=4)
        handles.append(Line2D([], [], ls="none", marker="o", ms=4.5, color="k",
                              label=f"start, s = {s[0]:g} m"))
        ax.set_aspect("equal", adjustable="datalim")
        pad = 0.1 * ext
        ax.set_xlim(x.min() - pad, x.max() + pad)
        ax.set_ylim(y.min() - pad, y.max() + pad)
        ax.set_xlabel("x [m]")
        ax.set_ylabel("y [m]")
        L = tr.attrs.get("length", s[-1] - s[0])
        ax.set_title(f"Track geometry, plan view: {float(L):g} m, {nseg} segment"
                     f"{'s' if nseg != 1 else ''} (ticks at segment transition points)")
        ax.legend(handles=handles, loc="best", handlelength=1.5, fontsize=7)
    return fig


def fig_curvature_cant(result: Result):
    """Curvature [1/km] and cant [mm] (+ cant angle [mrad]) versus s, segments shaded."""
    tr = result.track
    cl = tr.centreline
    s = cl["s"]
    with report_style():
        fig, (a1, a2) = plt.subplots(2, 1, figsize=(A4_WIDTH_IN, 4.6), sharex=True,
                                     layout="constrained")
        for ax in (a1, a2):
            _shade_segments(ax, tr)
        a1.plot(s, cl["curvature"] * 1e3, color="#1f5fa8", lw=1.3, label="curvature")
        a1.set_ylabel("curvature [1/km]\n(+ left)")
        a1.set_title("Track curvature and cant", loc="left")
        a1.axhline(0, color="k", lw=0.5)
        # Annotate radius of constant-curvature curves.
        for i in range(tr.n_segments):
            if int(round(tr.segments["kind"][i])) == 2 and tr.segments["radius"][i] > 0:
                a, l = tr.segments["start"][i], tr.segments["length"][i]
                kap = np.interp(a + 0.5 * l, s, cl["curvature"]) * 1e3
                a1.annotate(f"R = {tr.segments['radius'][i]:g} m", (a + 0.5 * l, kap),
                            xytext=(0, -11 if kap >= 0 else 4), textcoords="offset points",
                            ha="center", fontsize=7, color="#1f5fa8")
        h_seg = _segment_legend_handles(tr)
        a1.legend(handles=h_seg, loc="lower right", bbox_to_anchor=(1.0, 1.0), ncol=len(h_seg),
                  frameon=False, borderaxespad=0.2, handlelength=1.4, fontsize=7)
        lo, hi = a1.get_ylim()
        span = max(hi - lo, 1e-9)
        a1.set_ylim(lo - 0.08 * span, hi + 0.15 * span)

        c_mm = cl["cant"] * 1e3
        l1, = a2.plot(s, c_mm, color="#b2182b", lw=1.3, label="cant [mm] (left axis)")
        a2.set_ylabel("cant [mm]")
        a2.set_xlabel("s [m]")
        a2.axhline(0, color="k", lw=0.5)
        lo, hi = min(c_mm.min(), 0.0), max(c_mm.max(), 0.0)
        span = max(hi - lo, 1.0)
        a2.set_ylim(lo - 0.08 * span, hi + 0.2 * span)
        # Cant angle on a twin axis, scaled so that angle = asin(cant/cant_base) overlays the
        # cant line exactly when the file is consistent (a visual check).
        at = a2.twinx()
        at.grid(False)
        ang = cl["cant_angle"] * 1e3
        l2, = at.plot(s, ang, color="#333333", lw=1.0, ls=(0, (4, 3)), label="cant angle [mrad] (right axis)")
        base = tr.attrs.get("cant_base")
        y0, y1 = a2.get_ylim()
        if isinstance(base, (int, float)) and base > 0 and max(abs(y0), abs(y1)) < base * 1e3:
            at.set_ylim(np.arcsin(y0 / 1e3 / base) * 1e3, np.arcsin(y1 / 1e3 / base) * 1e3)
            note = f"cant base {base:g} m"
        else:
            note = None
        at.set_ylabel("cant angle [mrad]")
        # legend on the twin axes so that it is drawn above both lines
        at.legend(handles=[l1, l2], loc="best", title=note, title_fontsize=7, alignment="left")
        a2.set_xlim(s[0], s[-1])
    return fig


def fig_irregularities(result: Result):
    """Four stacked panels: alignment, vertical profile, gauge variation, cross level [mm]."""
    ir = result.irregularities
    s = ir.data["s"]
    with report_style():
        fig, axes = plt.subplots(4, 1, figsize=(A4_WIDTH_IN, 7.2), sharex=True,
                                 layout="constrained")
        for ax, c in zip(axes, ir.channels):
            v = ir.data[c] * 1e3
            ax.plot(s, v, color=CHANNEL_COLORS[c], lw=0.7)
            ax.axhline(0, color="k", lw=0.4)
            ax.set_ylabel(f"{CHANNEL_TITLES[c].lower()}\n[mm]")
            peak = float(np.max(np.abs(v))) if v.size else 0.0
            if peak == 0.0:
                note = "channel disabled (all zeros)"
                ax.set_ylim(-1.0, 1.0)
            else:
                rms = float(np.sqrt(np.mean(v ** 2)))
                note = f"RMS {rms:.2f} mm, max |·| {peak:.2f} mm"
                ax.set_ylim(-1.3 * peak, 1.3 * peak)
            ax.text(0.995, 0.95, note, transform=ax.transAxes, ha="right", va="top", fontsize=7,
                    bbox=dict(boxstyle="round,pad=0.2", fc="white", ec="#cccccc", lw=0.5,
                              alpha=0.9))
        axes[-1].set_xlabel("s [m]")
        axes[-1].set_xlim(s[0], s[-1])
        fig.suptitle(f"Track irregularities — {ir.describe()}", fontsize=9.5)
    return fig


def _band_rms(omega_t, g_t, o_lo, o_hi) -> float:
    """sqrt(integral of G over [o_lo, o_hi]) with log-log interpolation of the target."""
    o = np.geomspace(o_lo, o_hi, 4000)
    gi = interp_loglog(o, omega_t, g_t)
    gi = np.where(np.isfinite(gi), gi, 0.0)
    return float(np.sqrt(np.sum(0.5 * (gi[1:] + gi[:-1]) * np.diff(o))))


def fig_irregularity_psd(result: Result, nperseg: Optional[int] = None):
    """Welch estimate vs target one-sided PSD G(Omega), one log-log panel per channel.

    x range: a factor 4 beyond the synthesis band on both sides (capped at the Nyquist
    wavenumber), or the target grid when no band is recorded.  The estimate falls by many
    decades outside the band (nothing was synthesised there); the y range follows the target
    and the in-band estimate so that this roll-off does not squash the plot.
    """
    from matplotlib.lines import Line2D

    ir = result.irregularities
    s = ir.data["s"]
    ds = ir.step
    lam_min, lam_max = ir.band()
    m = int(nperseg or default_nperseg(s.size, ds, lam_max))
    m = max(2, min(m, s.size))
    nseg = len(welch_segment_starts(s.size, m))
    o_nyq = np.pi / ds
    with report_style():
        fig, axes = plt.subplots(2, 2, figsize=(A4_WIDTH_IN, 5.8), layout="constrained")
        any_target = False
        for ax, c in zip(axes.flat, ir.channels):
            x = ir.data[c]
            om, g = welch_psd(x, ds, nperseg=m)
            om, g = om[1:], g[1:]
            tgt = None
            if ir.target is not None and c in ir.target:
                ot, gt = ir.target["omega"], ir.target[c]
                if np.any(gt > 0):
                    tgt = (ot[ot > 0], gt[ot > 0])
            have_signal = bool(np.any(x != 0))
            if lam_min and lam_max:
                xl = (0.25 * 2 * np.pi / lam_max, min(4 * 2 * np.pi / lam_min, o_nyq))
            elif tgt is not None:
                xl = (max(tgt[0].min(), om[0] * 0.5), min(tgt[0].max(), o_nyq))
            else:
                xl = (om[0], om[-1])
            if lam_min and lam_max:
                ax.axvspan(2 * np.pi / lam_max, 2 * np.pi / lam_min, color="#f0f0f0", lw=0,
                           zorder=0)
                for lam in (lam_max, lam_min):
                    ax.axvline(2 * np.pi / lam, color="#555555", lw=0.8, ls="--", zorder=1)
            ys = []
            if tgt is not None:
                any_target = True
                ax.loglog(tgt[0], tgt[1], color="k", lw=1.3, zorder=3)
                sel = (tgt[0] >= xl[0]) & (tgt[0] <= xl[1])
                ys.append(tgt[1][sel])
            if have_signal:
                col = CHANNEL_COLORS[c]
                ax.loglog(om, g, color=col, lw=0.7, alpha=0.45, zorder=2)
                # 1/3-octave band means of the estimate: readable even with few segments
                bo_lo = 2 * np.pi / lam_max if lam_max else None
                bo_hi = 2 * np.pi / lam_min if lam_min else None
                oc3, g3 = fractional_octave_average(om, g, 3, bo_lo, bo_hi)
                ok = g3 > 0
                ax.loglog(oc3[ok], g3[ok], color=col, lw=1.0, marker="o", ms=2.8, zorder=4)
                inb = (om >= xl[0]) & (om <= xl[1])
                if lam_min and lam_max:
                    inb &= (om >= 2 * np.pi / lam_max) & (om <= 2 * np.pi / lam_min)
                ys.append(g[inb])
            ax.set_xscale("log")
            ax.set_yscale("log")
            ax.set_xlim(*xl)
            yy = np.concatenate(ys) if ys else np.array([])
            yy = yy[np.isfinite(yy) & (yy > 0)]
            if yy.size:
                top = yy.max() * 5.0
                ax.set_ylim(max(yy.min() * 0.2, top * 1e-9), top)
            rms = float(np.sqrt(np.mean((x - x.mean()) ** 2))) * 1e3
            ttl = f"{CHANNEL_TITLES[c]}: RMS {rms:.2f} mm"
            if not have_signal:
                ax.text(0.5, 0.5, "channel disabled (all zeros)", transform=ax.transAxes,
                        ha="center", va="center", fontsize=8, color="#555555",
                        bbox=dict(boxstyle="round,pad=0.3", fc="white", ec="#cccccc", lw=0.5))
                ttl = f"{CHANNEL_TITLES[c]}: disabled"
                if tgt is None:
                    ax.set_ylim(1e-12, 1e-4)
            elif tgt is not None and lam_min and lam_max:
                ttl += f" (target {_band_rms(tgt[0], tgt[1], 2 * np.pi / lam_max, 2 * np.pi / lam_min) * 1e3:.2f})"
            # Above the wavelength axis on top (the report style does not move titles by itself:
            # that search costs a third of drawing a figure).
            ax.set_title(ttl, fontsize=8, pad=22)
            ax.set_xlabel("Ω [rad/m]")
            ax.set_ylabel("G(Ω) [m²/(rad/m)]")
            ax.grid(True, which="major", lw=0.4)
            ax.grid(True, which="minor", lw=0.25, alpha=0.35)
            # The y range spans up to 9 decades: a line per decade reads as well as the 8 minor
            # lines between, which cost 0.6 s of the figure's 1.9 s.
            ax.yaxis.set_minor_locator(NullLocator())
            sec = ax.secondary_xaxis("top", functions=(_om2lam, _om2lam))
            sec.set_xlabel("λ [m]", fontsize=7, labelpad=1)
            sec.tick_params(labelsize=6.5, direction="in")
            sec.xaxis.set_minor_locator(NullLocator())  # minor ticks here cost ~1 s per figure
        handles = [Line2D([], [], color="k", lw=1.3, label="target")] if any_target else []
        handles.append(Line2D([], [], color="#777777", lw=0.7, alpha=0.6,
                              label=f"Welch estimate (Hann, {nseg} × {m * ds:g} m)"))
        handles.append(Line2D([], [], color="#777777", lw=1.0, marker="o", ms=2.8,
                              label="1/3-octave means"))
        if lam_min and lam_max:
            handles.append(Patch(facecolor="#f0f0f0", edgecolor="#555555", ls="--", lw=0.8,
                                 label=f"band {lam_min:g}–{lam_max:g} m"))
        # (loc="outside ..." needs matplotlib >= 3.7; Debian 12 has 3.6: reserve a strip instead)
        fig.get_layout_engine().set(rect=(0.0, 0.045, 1.0, 0.955))
        fig.legend(handles=handles, loc="lower center", bbox_to_anchor=(0.5, 0.0),
                   ncol=len(handles), fontsize=7, frameon=False, handlelength=1.8)
        fig.suptitle(f"Irregularity PSD, one-sided in Ω: {ir.describe()}", fontsize=9.5)
    return fig


def _om2lam(v):
    v = np.asarray(v, dtype=float)
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.where(v > 0, 2 * np.pi / np.where(v > 0, v, 1.0), np.inf)


# --------------------------------------------------------------------------------------------
