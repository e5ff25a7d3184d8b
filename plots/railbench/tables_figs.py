"""Contact-table figures: profiles with contact points (paper Fig. 1) and the LUT z table
(Fig. 7)."""
from __future__ import annotations

import math
from typing import List, Optional, Tuple

from matplotlib.lines import Line2D
from matplotlib.patches import Patch
import numpy as np

from .style import A4_WIDTH_IN, plt, report_style
from .tables_data import FLANGE_NEAR, RAIL_EDGE, RAIL_FILL, Kec, TRANS_FILL, Tables, Y_COLORS, _contact_nodes, _fmt_mm, _mm, _rail_track, _wheel_track, knife_point


# Figures
# --------------------------------------------------------------------------------------------
def _short(name: str) -> str:
    """'S1002 left wheel' -> 'S1002', '60E1 left rail' -> '60E1'."""
    words = [w for w in name.split() if w.lower() not in ("left", "right", "wheel", "rail")]
    return " ".join(words) or name


def _title(t: Tables) -> str:
    """'<stem> (<wheel> on <rail>)' for the figure titles."""
    if t.wheel is not None and t.rail is not None:
        return f"{t.stem} ({_short(t.wheel.name)} on {_short(t.rail.name)})"
    return t.stem


def _suptitle(fig, text: str, fontsize: float = 9.5):
    """Figure title, split after its ' — ' when it would not fit on one line."""
    max_chars = int(fig.get_size_inches()[0] * 72 / (0.56 * fontsize))
    if len(text) > max_chars and " — " in text:
        head, tail = text.split(" — ", 1)
        text = f"{head} —\n{tail}"
    fig.suptitle(text, fontsize=fontsize)


def _knife_marker():
    """Upward wedge with its tip at the data point (the knife edge of the KEC)."""
    return [(0.0, 0.0), (-0.28, -1.0), (0.28, -1.0), (0.0, 0.0)]


def kec_solve(kec: Kec, y: float, r0: float, lr: float, guess=(None, 0.0, None, None),
              tol: float = 1e-11, max_iter: int = 60
              ) -> Optional[Tuple[float, float, float, float]]:
    """KEC pose (z, phi, s_lk, s_rk) at lateral displacement y, zero irregularity: Newton on the
    four rows of Eq. 22 (docs' form) with f_l, f_r interpolated linearly in the table (slopes
    from the node differences).  None when it does not converge or the table has no right wheel.
    """
    sk = kec.s_k
    fl, fr = kec.get("left", "f"), kec.get("right", "f")
    if fl is None or fr is None:
        return None
    dfl, dfr = np.gradient(fl, sk), np.gradient(fr, sk)
    z0, phi, sl, sr = guess
    if sl is None:
        sl = -y
    if sr is None:
        sr = -y
    z = r0 + float(np.interp(sl, sk, fl)) if z0 is None else z0
    x = np.array([z, phi, sl, sr], float)
    step_max = np.array([1e-3, 5e-3, 1e-3, 1e-3])
    for _ in range(max_iter):
        z, phi, sl, sr = x
        f1, f2 = np.interp(sl, sk, fl), np.interp(sr, sk, fr)
        d1, d2 = np.interp(sl, sk, dfl), np.interp(sr, sk, dfr)
        r = np.array([y + sl + phi * (r0 + f1),
                      y + sr + phi * (r0 + f2),
                      z + phi * (lr + sl) - r0 - f1,
                      z + phi * (-lr + sr) - r0 - f2])
        if np.max(np.abs(r)) < tol:
            return float(z), float(phi), float(sl), float(sr)
        J = np.array([[0.0, r0 + f1, 1 + phi * d1, 0.0],
                      [0.0, r0 + f2, 0.0, 1 + phi * d2],
                      [1.0, lr + sl, phi - d1, 0.0],
                      [1.0, -lr + sr, 0.0, phi - d2]])
        try:
            dx = np.linalg.solve(J, -r)
        except np.linalg.LinAlgError:
            return None
        scale = np.max(np.abs(dx) / step_max)
        x = x + (dx / scale if scale > 1 else dx)
    return None


def fig_profiles_contact(t: Tables):
    """Paper Fig. 1: (a) the left wheel on the left rail in the wheelset track frame at a few
    lateral displacements (LUT nodes at xi_g nearest 0: tread contact, flange point when its gap
    is below 0.1 mm); (b) the KEC at the same y (Eq. 22): knife edge on the equivalent profile
    f_k(s_k) and the mapped contact s_w(s_k) on the real wheel profile."""
    lut, wh, rl = t.lut, t.wheel, t.rail
    lw, lr, beta = t.g("lw"), t.g("lr"), t.g("beta")
    row = lut.row(0.0)
    xi = float(lut.xi_g[row])
    nodes = _contact_nodes(lut, row)
    kec_ok = t.kec is not None and "left_f" in t.kec.data

    # --- data of (a), to size the figure for an equal aspect ratio
    ry, rz = _rail_track(rl, lr, beta, xi)
    x_r, z_r = _mm(ry - lr), _mm(rz)
    wheels = []
    for k, (i, tag) in enumerate(nodes):
        y, z, phi = (float(lut.y[i]), float(lut.ch["z"][row, i]), float(lut.ch["phi"][row, i]))
        wy, wz = _wheel_track(wh, y, z, phi, lw)
        wheels.append((i, tag, y, z, phi, _mm(wy - lr), _mm(wz)))
    # x: the rail head with the whole flange (to 45 mm beyond the gauge side) and 12 mm field side
    x_flange = min([float(w[5].min()) for w in wheels] + [float(x_r.min()) - 25.0])
    x0 = max(x_flange - 3.0, float(x_r.min()) - 45.0)
    x1 = float(x_r.max()) + 12.0
    z_lo, z_hi = float(z_r.min()), 0.0
    for w in wheels:
        vis = (w[5] > x0) & (w[5] < x1)
        if vis.any():
            z_lo, z_hi = min(z_lo, float(w[6][vis].min())), max(z_hi, float(w[6][vis].max()))
    z0, z1 = z_lo - 2.0, z_hi + 2.0
    ax_w_in = A4_WIDTH_IN - 0.62
    ax_h_in = ax_w_in * (z1 - z0) / (x1 - x0)
    n_leg = math.ceil((len(nodes) + 2) / 2)
    h_a = ax_h_in + 0.45 + 0.13 * n_leg
    h_b = 2.9
    with report_style():
        fig = plt.figure(figsize=(A4_WIDTH_IN, h_a + (h_b if kec_ok else 0.0) + 0.3),
                         layout="constrained")
        gs = fig.add_gridspec(2 if kec_ok else 1, 1, height_ratios=[h_a, h_b] if kec_ok else [1])
        ax = fig.add_subplot(gs[0])
        # rail head, fixed in the track frame; its sides continue below the axes
        zb = z0 - 10.0
        xs = np.concatenate([[x_r[0]], x_r, [x_r[-1]]])
        zs = np.concatenate([[zb], z_r, [zb]])
        ax.fill(xs, zs, color=RAIL_FILL, lw=0, zorder=1)
        ax.plot(xs, zs, color=RAIL_EDGE, lw=1.0, zorder=2)
        ax.text(0.5 * (x_r.min() + x_r.max()), z0 + 1.0, rl.name, ha="center",
                va="bottom", fontsize=7, color="#333333", zorder=3)
        handles = []
        sw, fd, fs = (lut.get(n, row) for n in ("left_s_w", "left_flange_delta",
                                                "left_flange_s_w"))
        for k, (i, tag, y, z, phi, xw, zw) in enumerate(wheels):
            col = Y_COLORS[k % len(Y_COLORS)]
            ax.plot(xw, zw, color=col, lw=1.0, zorder=4)
            lab = f"y = {_fmt_mm(y)} mm"
            if tag:
                lab += f" ({tag})"
            if sw is not None:
                cy, cz = _wheel_track(wh, y, z, phi, lw, s=sw[i])
                ax.plot(_mm(cy - lr), _mm(cz), "o", ms=4.5, color=col, mec="white", mew=0.6,
                        zorder=6)
            if fd is not None and fs is not None and fd[i] > -FLANGE_NEAR:
                cy, cz = _wheel_track(wh, y, z, phi, lw, s=fs[i])
                ax.plot(_mm(cy - lr), _mm(cz), "D", ms=4.5, mfc="white", mec=col, mew=1.2,
                        zorder=6)
                lab += (f", flange {'gap' if fd[i] < 0 else 'indentation'} "
                        f"{abs(fd[i]) * 1e3:.2g} mm")
            handles.append(Line2D([], [], color=col, lw=1.0, label=lab))
        handles.append(Line2D([], [], ls="none", marker="o", ms=4.5, color="#555555",
                              mec="white", label="tread contact (LUT)"))
        if any("flange" in h.get_label() for h in handles):
            handles.append(Line2D([], [], ls="none", marker="D", ms=4.5, mfc="white",
                                  mec="#555555", mew=1.2, label="flange point (LUT, elastic)"))
        ax.set_xlim(x0, x1)
        ax.set_ylim(z0, z1)
        ax.set_aspect("equal", adjustable="datalim")
        ax.set_xlabel("Y − $L_r$ [mm]  (track frame, left rail profile origin at 0)")
        ax.set_ylabel("Z [mm]")
        ax.set_title(f"(a) left wheel on left rail in the wheelset track frame, LUT at "
                     f"$\\xi_g$ = {_fmt_mm(xi)} mm", loc="left")
        from matplotlib.transforms import offset_copy
        ax.legend(handles=handles, loc="upper center", bbox_to_anchor=(0.5, 0.0),
                  bbox_transform=offset_copy(ax.transAxes, fig=fig, y=-25, units="points"),
                  ncol=2, fontsize=6.5, handlelength=1.8, columnspacing=1.2, frameon=False)
        if kec_ok:
            _panel_kec_profile(fig.add_subplot(gs[1]), t, wheels)
        _suptitle(fig, f"Wheel/rail profiles and contact points — {_title(t)}")
        # equal aspect: resize (a) until its box matches the data range (no stretched limits)
        for _ in range(3):
            fig.canvas.draw()
            ax.set_xlim(x0, x1)
            ax.set_ylim(z0, z1)
            W, H = fig.get_size_inches()
            pos = ax.get_position(original=True)
            w_in, h_in = pos.width * W, pos.height * H
            delta = w_in * (z1 - z0) / (x1 - x0) - h_in
            if abs(delta) < 0.02:
                break
            h_a = max(h_a + delta, 0.8)
            fig.set_size_inches(W, H + delta)
            if kec_ok:
                gs.set_height_ratios([h_a, h_b])
    return fig


def _panel_kec_profile(ax, t: Tables, wheels):
    wh, kec = t.wheel, t.kec
    lr, r0 = t.g("lr"), t.g("r0")
    sk, fk, swk = kec.s_k, kec.get("left", "f"), kec.get("left", "s_w")
    ax.plot(_mm(wh.s), -_mm(wh.h - r0), color="#777777", lw=0.9, ls=(0, (6, 2, 1.2, 2)),
            label="real wheel $-(h_w(s_w) - r_0)$ vs $s_w$", zorder=2)
    ax.plot(_mm(sk), -_mm(fk), color="black", lw=1.2,
            label="KEC-equivalent $-f_k(s_k)$ vs $s_k$", zorder=3)
    for _, lo, hi in kec.transitions("left"):
        ax.axvspan(_mm(lo), _mm(hi), color=TRANS_FILL, lw=0, alpha=0.8, zorder=0)
    failed = []
    for k, (i, tag, y, z, phi, _, _) in enumerate(wheels):
        col = Y_COLORS[k % len(Y_COLORS)]
        s_l, _ = knife_point(y, z, phi, r0, lr)
        s_r, _ = knife_point(-y, z, -phi, r0, lr)
        sol = kec_solve(kec, y, r0, lr, guess=(z, phi, float(s_l), -float(s_r)))
        if sol is None:
            failed.append(_fmt_mm(y))
            continue
        s_k = sol[2]
        f_k = float(np.interp(s_k, sk, fk))
        ax.plot(_mm(s_k), -_mm(f_k), marker=_knife_marker(), ms=11, color=col, mec="black",
                mew=0.4, ls="none", zorder=5)
        if swk is not None:
            s_w = float(np.interp(s_k, sk, swk))
            h = float(np.interp(s_w, wh.s, wh.h))
            ax.plot(_mm(s_w), -_mm(h - r0), "o", ms=4.5, color=col, mec="white", mew=0.6,
                    zorder=5)
            ax.annotate("", xy=(_mm(s_w), -_mm(h - r0)), xytext=(_mm(s_k), -_mm(f_k)),
                        arrowprops=dict(arrowstyle="-", color=col, lw=0.7, ls=":",
                                        shrinkA=2, shrinkB=2), zorder=4)
    lo = min(float(sk.min()), float(wh.s.min()))
    hi = max(float(sk.max()), float(wh.s.max()))
    ax.set_xlim(_mm(lo) - 2, _mm(hi) + 2)
    handles, _ = ax.get_legend_handles_labels()
    handles += [Line2D([], [], ls="none", marker=_knife_marker(), ms=9, color="#555555",
                       mec="black", mew=0.4, label="knife edge at $s_k$ (KEC, Eq. 22)"),
                Line2D([], [], ls="none", marker="o", ms=4.5, color="#555555", mec="white",
                       label="real contact $s_w(s_k)$ (KEC map)")]
    if kec.transitions("left"):
        handles.append(Patch(color=TRANS_FILL, label="regularised transitions"))
    ax.legend(handles=handles, loc="lower right", fontsize=6.5, ncol=1, handlelength=2.2)
    if failed:
        ax.text(0.01, 0.03, f"KEC solve failed at y = {', '.join(failed)} mm",
                transform=ax.transAxes, fontsize=6.5, color="#d00000")
    ax.set_xlabel("profile parameter $s_w$, $s_k$ [mm]  (left wheel, + field side)")
    ax.set_ylabel("$-(h_w - r_0)$, $-f_k$ [mm]")
    ax.set_title("(b) KEC (Eq. 22) at the same y: equivalent and real contact points",
                 loc="left")


def _xi_colors(xi: np.ndarray):
    import matplotlib.colors as mcolors
    n = xi.size
    cmap = plt.get_cmap("coolwarm")
    if n == 1:
        return ["black"], None, None
    edges = np.concatenate([[xi[0] - 0.5 * (xi[1] - xi[0])], 0.5 * (xi[1:] + xi[:-1]),
                            [xi[-1] + 0.5 * (xi[-1] - xi[-2])]]) * 1e3
    norm = mcolors.BoundaryNorm(edges, cmap.N)
    cols = [cmap(norm(v * 1e3)) for v in xi]
    return cols, cmap, norm


def fig_lut_z(t: Tables):
    """Paper Fig. 7: (a) z(y, xi_g) - z(0, 0) and (b) phi(y, xi_g) for every gauge variation,
    (c) the z table over (y, xi_g) with the two-point contact positions."""
    lut = t.lut
    y = _mm(lut.y)
    xi = lut.xi_g
    r0 = lut.row(0.0)
    i0 = int(np.argmin(np.abs(lut.y)))
    z0 = float(lut.ch["z"][r0, i0])
    cols, cmap, norm = _xi_colors(xi)
    tp = lut.two_point if lut.two_point and lut.two_point["y"].size else None
    table = xi.size > 1
    with report_style():
        if table:
            fig, axes = plt.subplots(3, 1, figsize=(A4_WIDTH_IN, 7.4), sharex=True,
                                     layout="constrained", height_ratios=[1, 1, 1.05])
            a1, a2, a3 = axes
        else:
            fig, axes = plt.subplots(2, 1, figsize=(A4_WIDTH_IN, 5.0), sharex=True,
                                     layout="constrained")
            a1, a2 = axes
        for k in range(xi.size):
            main = k == r0
            kw = dict(color="black" if main else cols[k], lw=1.5 if main else 0.9,
                      zorder=3 if main else 2)
            a1.plot(y, _mm(lut.ch["z"][k] - z0), **kw)
            a2.plot(y, lut.ch["phi"][k] * 1e3, **kw)
        if tp is not None:
            for ty, tx in zip(tp["y"], tp["xi_g"]):
                k = lut.row(tx)
                if abs(xi[k] - tx) > 1e-9:   # not one of the stored gauge rows
                    continue
                a1.plot(ty * 1e3, np.interp(ty, lut.y, lut.ch["z"][k] - z0) * 1e3, "o", ms=4,
                        mfc="white", mec="black", mew=0.9, zorder=5)
                a2.plot(ty * 1e3, np.interp(ty, lut.y, lut.ch["phi"][k]) * 1e3, "o", ms=4,
                        mfc="white", mec="black", mew=0.9, zorder=5)
        a1.set_ylabel("$z - z(0)$ [mm]")
        a1.set_title(f"(a) wheelset vertical displacement, $z(0)$ = z at y = 0, "
                     f"$\\xi_g$ = {_fmt_mm(xi[r0])} mm: $z(0) - r_0$ = "
                     f"{(z0 - (t.g('r0') or z0)) * 1e3:+.4f} mm" if t.g("r0") is not None
                     else "(a) wheelset vertical displacement", loc="left")
        a2.set_ylabel("$\\phi$ [mrad]")
        a2.set_title("(b) wheelset roll angle (+ lifts the left wheel)", loc="left")
        hl = [Line2D([], [], color="black", lw=1.5, label=f"$\\xi_g$ = {_fmt_mm(xi[r0])} mm")]
        if xi.size > 1:
            hl.append(Line2D([], [], color=cols[0], lw=0.9, label="other $\\xi_g$ (colour bar)"))
        if tp is not None:
            hl.append(Line2D([], [], ls="none", marker="o", ms=4, mfc="white", mec="black",
                             label="two-point contact"))
        a1.legend(handles=hl, loc="upper center", fontsize=7)
        # (c) the table itself
        Z = _mm(lut.ch["z"] - z0)
        if table:
            xe = np.concatenate([[y[0]], 0.5 * (y[1:] + y[:-1]), [y[-1]]])
            ge = np.concatenate([[xi[0] - 0.5 * (xi[1] - xi[0])], 0.5 * (xi[1:] + xi[:-1]),
                                 [xi[-1] + 0.5 * (xi[-1] - xi[-2])]]) * 1e3
            pm = a3.pcolormesh(xe, ge, Z, cmap="viridis", shading="flat", rasterized=True)
            cb = fig.colorbar(pm, ax=a3, pad=0.01, fraction=0.04)
            cb.set_label("$z - z(0)$ [mm]")
            if np.ptp(Z) > 0:
                cs = a3.contour(y, xi * 1e3, Z, levels=8, colors="white", linewidths=0.4,
                                alpha=0.8)
                a3.clabel(cs, fontsize=6, fmt="%.2g")
            if tp is not None:
                for side, mk in ((1, ">"), (-1, "<")):
                    sel = np.round(tp["side"]) == side
                    if sel.any():
                        o = np.argsort(tp["xi_g"][sel])
                        a3.plot(tp["y"][sel][o] * 1e3, tp["xi_g"][sel][o] * 1e3, color="#d00000",
                                lw=1.0, marker=mk, ms=3.5,
                                label=f"two-point contact ({'left' if side > 0 else 'right'} "
                                      "wheel)")
            a3.set_ylabel("$\\xi_g$ [mm]")
            a3.grid(False)
            # discrete colour bar of the gauge variations, shared by (a) and (b)
            sm = plt.cm.ScalarMappable(norm=norm, cmap=cmap)
            cb2 = fig.colorbar(sm, ax=[a1, a2], pad=0.01, fraction=0.04, ticks=xi * 1e3)
            cb2.set_label("gauge variation $\\xi_g$ [mm]")
            cb2.ax.set_yticklabels([_fmt_mm(v) for v in xi])
            a3.set_title("(c) contact lookup table $z(y, \\xi_g) - z(0)$"
                         + (", two-point contact in red (▶ left, ◀ right wheel)"
                            if tp is not None else ""), loc="left")
        axes[-1].set_xlabel("lateral displacement y [mm]  (+ left)")
        axes[-1].set_xlim(y[0], y[-1])
        _suptitle(fig, f"Contact lookup table (LUT), {lut.y.size} × {xi.size} nodes — "
                       f"{_title(t)}")
    return fig


def _kec_real_points(t: Tables, side: str):
    """(s_k, s_w) of the real LUT contact at xi_g nearest 0, from the centre up to the two-point
    contact of this side's flange (the LUT keeps the tread contact beyond it)."""
    lut = t.lut
    if lut is None or t.g("r0") is None or t.g("lr") is None:
        return None
    row = lut.row(0.0)
    sw = lut.get(f"{side}_s_w", row)
    if sw is None:
        return None
    sgn = 1.0 if side == "left" else -1.0
    y, z, phi = lut.y, lut.ch["z"][row], lut.ch["phi"][row]
    xi = float(lut.xi_g[row])
    # mirror: the right wheel's knife point is the left one of the mirrored pose, negated
    s_k, _ = knife_point(sgn * y, z, sgn * phi, t.g("r0"), t.g("lr"), y_ir=xi / 2)
    s_k = sgn * s_k
    keep = np.ones_like(y, bool)
    for ty, ts in lut.two_points(xi):
        if ts > 0:
            keep &= y < ty
        else:
            keep &= y > ty
    return s_k[keep], sw[keep]


def _main_cluster(kec: Kec, side: str) -> List[Tuple[float, float, float]]:
    """The transitions of `side` whose intervals touch each other, grouped; returns the group
    with the largest change of s_w across it (the tread-flange transition), [] if none."""
    sw = kec.get(side, "s_w")
    trs = sorted(kec.transitions(side), key=lambda tr: tr[1])
    groups: List[List[Tuple[float, float, float]]] = []
    for tr in trs:
        if groups and tr[1] <= groups[-1][-1][2] + 1e-7:
            groups[-1].append(tr)
        else:
            groups.append([tr])
    best, jump = [], -1.0
    for g in groups:
        lo, hi = g[0][1], max(tr[2] for tr in g)
        d = abs(float(np.interp(hi, kec.s_k, sw) - np.interp(lo, kec.s_k, sw)))
        if d > jump:
            best, jump = g, d
    return best
