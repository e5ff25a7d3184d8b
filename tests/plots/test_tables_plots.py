"""Tests of `plots/rbplot tables` (railbench/tables*.py).

usage: /usr/bin/python3 -m pytest -q tests/plots/test_tables_plots.py   -> runs the tests
       PYTHONPATH=plots:tests/plots /usr/bin/python3 -c \
         'import test_tables_plots as t; t.make_tables_fixture("OUT.h5")'   -> writes the fixture

Work files go to a temp
dir, removed on success (kept on failure, or always with RB_KEEP_TMP=1).  A real file written by
`workbench tables` is tested too when RB_TABLES_H5 names one or /tmp/tables.h5 exists.

The synthetic fixture (make_tables_fixture) has the layout of `workbench tables` output
(workbench/app/tables.cpp) but is NOT engine output: a coned wheel (1:20) with a Gaussian-shaped
28 mm flange, r0 = 0.46 m, on a rail head h = -s^2/(2 * 0.3 m) - 14 mm (s/36 mm)^8 inclined 1:40
(Lw = 0.75 m, Lr = 0.753 m; y -12..12 mm, 121 nodes; xi_g -2..2 mm, 5 rows).  The rigid contact is
the smallest vertical gap of the wheel over the rail, sampled every 0.2 mm and refined by a
parabola: the LUT tread contact over the tread window (slope below 45 deg), the flange indentation
as the deepest vertical overlap of the flange window; the KEC maps follow the whole-profile contact
through the knife points (Eq. 22 with the solved z, phi) and bridge its jumps linearly over
[-d_hat, +d_bar] (flange side first); the conicity is a describing-function estimate.
"""
import os
import shutil
import tempfile
import time
import types

import numpy as np

from helpers import check, in_process, one_line_error, rbplot, work_folder
from railbench import tables as tables_command
from railbench.tables import FIGURES, summary_line
from railbench.tables_data import _rail_track, _wheel_track, knife_point, load_tables
from railbench.tables_figs import kec_solve
from railbench.tables_maps import conicity_at

FIGS = ["profiles_contact", "lut_z", "kec_map", "rolling_radius", "conicity"]

# ---------------------------------------------------------------------------------------------
# Synthetic fixture
# ---------------------------------------------------------------------------------------------
FX_R0 = 0.46
FX_LW = 0.75
FX_LR = 0.7530
FX_BETA = float(np.arctan(1.0 / 40.0))
FX_LAMBDA = 0.05          # tread cone
FX_DS = 2e-4              # profile sample step of the contact search [m]


def fx_wheel_h(s):
    """Left wheel radius [m] at s [m]: cone 1:20 and a smooth 28 mm flange at s < -30 mm."""
    s = np.asarray(s, float)
    u = np.maximum(0.0, -0.030 - s) / 0.010
    return FX_R0 - FX_LAMBDA * s + 0.028 * (1.0 - np.exp(-u * u))


def fx_rail_h(s):
    """Left rail head height [m] at s [m] (crown R 300 mm, steep sides from the 8th power)."""
    s = np.asarray(s, float)
    return -s * s / 0.6 - 0.014 * (s / 0.036) ** 8


FX_WHEEL_S = np.arange(-0.068, 0.060 + 1e-12, FX_DS)
FX_RAIL_S = np.arange(-0.036, 0.036 + 1e-12, FX_DS)


def _fx_boundary():
    """Tread/flange boundary: first s (from the tape circle toward the flange) with slope 45 deg."""
    s = FX_WHEEL_S
    d = np.gradient(fx_wheel_h(s), s)
    idx = np.where((s < 0) & (d <= -1.0))[0]
    return float(s[idx[-1]])


def _fx_rail_track(xi):
    """Left rail surface in the track frame: Y, Z, s_r (Y increasing)."""
    c, sn = np.cos(FX_BETA), np.sin(FX_BETA)
    s = FX_RAIL_S
    h = fx_rail_h(s)
    return FX_LR + xi / 2 + c * s - sn * h, sn * s + c * h, s


def _fx_gaps(y, z, phi, xi, s_w):
    """Vertical gaps of left-wheel points s_w ([n, m] or [m]) over the left rail, for arrays
    y, z, phi [n]; returns gaps and the points' Y."""
    ry, rz, rs = _fx_rail_track(xi)
    s_w = np.broadcast_to(s_w, (len(y),) + np.shape(s_w)[-1:])
    h = fx_wheel_h(s_w)
    wy = y[:, None] + FX_LW + s_w + phi[:, None] * h
    wz = z[:, None] + phi[:, None] * (FX_LW + s_w) - h
    # beyond the modelled head the rail sides continue downward at slope 20:1
    rzw = np.interp(wy, ry, rz) - 20.0 * (np.maximum(ry[0] - wy, 0) + np.maximum(wy - ry[-1], 0))
    return wz - rzw, wy


def _fx_contact(y, z, phi, xi, s_w):
    """Left contact on the samples s_w (uniform): min gap, s_w, s_r, contact angle gamma.
    The sampled minimum is refined by a parabola through it and its neighbours."""
    g, _ = _fx_gaps(y, z, phi, xi, s_w)
    rows = np.arange(len(y))
    k0 = np.argmin(g, axis=1)
    k = np.clip(k0, 1, len(s_w) - 2)
    gm, g0, gp = g[rows, k - 1], g[rows, k], g[rows, k + 1]
    den = gm - 2 * g0 + gp
    d = np.clip(np.where(den > 0, 0.5 * (gm - gp) / np.where(den > 0, den, 1), 0), -0.5, 0.5)
    sc = np.where(k0 == k, s_w[k] + d * (s_w[1] - s_w[0]), s_w[k0])   # window ends: no refinement
    gc, yc = _fx_gaps(y, z, phi, xi, sc[:, None])
    ry, rz, rs = _fx_rail_track(xi)
    yc = yc[:, 0]
    sr = np.interp(yc, ry, rs)
    slope = np.interp(yc, ry[1:-1], (rz[2:] - rz[:-2]) / (ry[2:] - ry[:-2]))
    return gc[:, 0], sc, sr, np.arctan(slope)


def _fx_solve(y, xi, s_w):
    """z, phi with both wheels just touching (min gap 0 on the samples s_w), for an array y."""
    z = np.full_like(y, FX_R0)
    phi = np.zeros_like(y)
    for _ in range(60):
        gl = _fx_contact(y, z, phi, xi, s_w)[0]
        gr = _fx_contact(-y, z, -phi, xi, s_w)[0]
        # gl(z - dz, ...) = 0 with dgl/dz = 1, dgl/dphi ~ Lw (right: -Lw)
        z = z - 0.5 * (gl + gr)
        phi = phi - 0.5 * (gl - gr) / FX_LW
        if max(np.max(np.abs(gl)), np.max(np.abs(gr))) < 1e-11:
            break
    return z, phi


def _fx_side(y, z, phi, xi, s_tread, s_flange):
    """Tread and flange channels of the left wheel (the right one: call with -y, -phi, negate s)."""
    _, sw, sr, gam = _fx_contact(y, z, phi, xi, s_tread)
    fg, fsw, fsr, fgam = _fx_contact(y, z, phi, xi, s_flange)
    return {"s_w": sw, "s_r": sr, "gamma": gam, "radius": fx_wheel_h(sw),
            "flange_delta": -fg, "flange_s_w": fsw, "flange_s_r": fsr, "flange_gamma": fgam,
            "flange_radius": fx_wheel_h(fsw)}


TREAD_NAMES = ("s_w", "s_r", "gamma", "radius", "k_w_trans", "k_w_long", "k_r_trans")
FLANGE_NAMES = ("delta", "s_w", "s_r", "gamma", "radius", "k_w_trans", "k_w_long", "k_r_trans",
                "n_y", "n_z", "ddelta_dphi")


def _fx_tan_gamma_e(y, dr, amp):
    """Describing-function conicity (fixture only; the engine uses EN 15302 Annex B)."""
    th = np.linspace(0.0, 2 * np.pi, 721)[:-1]
    out = []
    for a in amp:
        out.append(np.mean(np.interp(a * np.sin(th), y, dr) * np.sin(th)) / a)
    return np.array(out)


def make_tables_fixture(path, lut=True, kec=True, derived=True, profiles=True,
                        conicity=True, ny=121, ymax=0.012, ng=5):
    """Write a synthetic tables file (layout of `workbench tables`); returns the path."""
    import h5py

    t0 = time.time()
    sb = _fx_boundary()
    s_tread = FX_WHEEL_S[(FX_WHEEL_S >= sb) & (FX_WHEEL_S < 0.025)]   # contact windows
    s_flange = FX_WHEEL_S[(FX_WHEEL_S < sb) & (FX_WHEEL_S > -0.058)]
    y = np.linspace(-ymax, ymax, ny)
    xig = np.linspace(-0.002, 0.002, ng)
    ch = {}
    tp_y, tp_xi, tp_side = [], [], []
    for ig, xi in enumerate(xig):
        z, phi = _fx_solve(y, xi, s_tread)
        left = _fx_side(y, z, phi, xi, s_tread, s_flange)
        right = _fx_side(-y, z, -phi, xi, s_tread, s_flange)
        for k in ("s_w", "s_r", "flange_s_w", "flange_s_r"):
            right[k] = -right[k]
        row = {"z": z, "phi": phi}
        for side, d in (("left", left), ("right", right)):
            for q in TREAD_NAMES:
                row[f"{side}_{q}"] = d.get(q, np.zeros(ny))
            for q in FLANGE_NAMES:
                row[f"{side}_flange_{q}"] = d.get(f"flange_{q}", np.zeros(ny))
        for name, v in row.items():
            ch.setdefault(name, np.zeros((ng, ny)))[ig] = v
        for side, sgn in (("left", 1.0), ("right", -1.0)):
            d = row[f"{side}_flange_delta"]
            idx = np.where(sgn * y > 0)[0][:: int(sgn)]
            for a, b in zip(idx[:-1], idx[1:]):
                if d[a] < 0 <= d[b]:
                    tp_y.append(y[a] + (y[b] - y[a]) * (-d[a]) / (d[b] - d[a]))
                    tp_xi.append(xi)
                    tp_side.append(sgn)
                    break
    t_lut = time.time() - t0

    # KEC: knife points (Eq. 22 with y_ir = 0) of the whole-profile contact along a y sweep.
    t1 = time.time()
    i0 = int(np.argmin(np.abs(xig)))
    yk = np.linspace(-ymax, ymax, 301)
    s_all = FX_WHEEL_S[(FX_WHEEL_S > -0.058) & (FX_WHEEL_S < 0.025)]
    zk, pk = _fx_solve(yk, 0.0, s_all)
    kec_data = {}
    dhat, dbar = 0.5e-3, 1.0e-3
    sk_grid = np.arange(-0.0200, 0.0200 + 1e-9, 0.00005)
    for side, sgn in (("left", 1.0), ("right", -1.0)):
        yy, pp = sgn * yk, sgn * pk
        _, sw, sr, _ = _fx_contact(yy, zk, pp, 0.0, s_all)
        # s(1 + phi^2) = -y - phi r0 - phi (z - r0 + phi Lr), f = z - r0 + phi (Lr + s)
        sk = (-yy - pp * FX_R0 - pp * (zk - FX_R0 + pp * FX_LR)) / (1 + pp * pp)
        fk = zk - FX_R0 + pp * (FX_LR + sk)
        sk, sw, sr = sgn * sk, sgn * sw, sgn * sr    # right wheel: back from the mirror
        o = np.argsort(sk)
        sk, fk, sw, sr = sk[o], fk[o], sw[o], sr[o]
        jumps = np.where(np.abs(np.diff(sw)) > 1e-3)[0]
        t_s, t_lo, t_hi = [], [], []
        for j in jumps:
            sj = 0.5 * (sk[j] + sk[j + 1])
            lo, hi = (sj - dhat, sj + dbar) if sgn > 0 else (sj - dbar, sj + dhat)
            a, b = np.searchsorted(sk, lo), np.searchsorted(sk, hi) - 1
            tt = (sk[a:b + 1] - sk[a]) / (sk[b] - sk[a])
            for arr in (sw, sr):
                arr[a:b + 1] = arr[a] + (arr[b] - arr[a]) * tt
            sm = tt * tt * (3 - 2 * tt)
            fk[a:b + 1] = fk[a] + (fk[b] - fk[a]) * sm
            t_s.append(sj), t_lo.append(lo), t_hi.append(hi)
        for k, arr in (("f", fk), ("s_w", sw), ("s_r", sr)):
            kec_data[f"{side}_{k}"] = np.interp(sk_grid, sk, arr)
        wg = np.zeros_like(sk_grid)   # 0 at A (field side), 1 at B (flange side)
        for lo, hi in zip(t_lo, t_hi):
            m = (sk_grid >= lo) & (sk_grid <= hi)
            wg[m] = (hi - sk_grid[m]) / (hi - lo) if sgn > 0 else (sk_grid[m] - lo) / (hi - lo)
        kec_data[f"{side}_weight"] = wg
        kec_data[f"{side}_transition_s"] = np.array(t_s)
        kec_data[f"{side}_transition_lo"] = np.array(t_lo)
        kec_data[f"{side}_transition_hi"] = np.array(t_hi)
    t_kec = time.time() - t1

    with h5py.File(path, "w") as f:
        f.attrs["version"] = "fixture"
        f.attrs["scenario_file"] = "tests/plots/test_tables_plots.py (synthetic)"
        f.attrs["scenario_text"] = "-- synthetic fixture"
        f.attrs["overrides"] = ""
        t = f.create_group("tables")
        t.attrs["config_hash"] = "0123456789abcdef"
        t.attrs["lw"], t.attrs["lr"], t.attrs["beta"], t.attrs["r0"] = FX_LW, FX_LR, FX_BETA, FX_R0

        def ds(g, name, v, units):
            d = g.create_dataset(name, data=np.asarray(v, dtype=np.float64))
            d.attrs["units"] = units

        def stats(g, secs, nbytes, nodes, notes=""):
            g.attrs["build_time_s"] = secs
            g.attrs["bytes"] = np.int64(nbytes)
            g.attrs["nodes"] = np.int64(nodes)
            g.attrs["newton_iterations"] = np.int64(3 * nodes)
            g.attrs["failures"] = np.int64(0)
            g.attrs["warnings"] = ""
            g.attrs["notes"] = notes

        if profiles:
            for name, s, h, label in (("wheel_left", FX_WHEEL_S, fx_wheel_h(FX_WHEEL_S),
                                       "cone 1:20 + flange (fixture)"),
                                      ("rail_left", FX_RAIL_S, fx_rail_h(FX_RAIL_S),
                                       "R300 head (fixture)")):
                g = f.create_group(f"profiles/{name}")
                ds(g, "s", s, "m")
                ds(g, "h", h, "m")
                g.attrs["name"] = label
        if lut:
            g = t.create_group("lut")
            ds(g, "y", y, "m")
            ds(g, "xi_g", xig, "m")
            for name, v in ch.items():
                ds(g, name, v, "rad" if ("gamma" in name or name == "phi") else "m")
            tp = g.create_group("two_point")
            ds(tp, "y", tp_y, "m")
            ds(tp, "xi_g", tp_xi, "m")
            ds(tp, "side", tp_side, "-")
            stats(g, t_lut, 4 * 8 * ny * ng * len(ch), ny * ng)
        if kec:
            g = t.create_group("kec")
            ds(g, "s_k", sk_grid, "m")
            for name, v in kec_data.items():
                ds(g, name, v, "-" if name.endswith("weight") else "m")
            g.attrs["dhat"], g.attrs["dbar"] = dhat, dbar
            stats(g, t_kec, 8 * 12 * sk_grid.size, sk_grid.size, "synthetic")
        if derived:
            g = t.create_group("derived")
            r_l, r_r = ch["left_radius"][i0], ch["right_radius"][i0]
            dr = r_l - r_r
            ds(g, "y", y, "m")
            ds(g, "z", ch["z"][i0], "m")
            ds(g, "phi", ch["phi"][i0], "rad")
            ds(g, "r_left", r_l, "m")
            ds(g, "r_right", r_r, "m")
            ds(g, "delta_r", dr, "m")
            ds(g, "delta_gamma", ch["left_gamma"][i0] - ch["right_gamma"][i0], "rad")
            amp = np.arange(0.5e-3, 10e-3 + 1e-12, 0.25e-3)
            amp = amp[amp <= ymax] if conicity else amp[:0]
            ds(g, "conicity_amplitude", amp, "m")
            ds(g, "tan_gamma_e", _fx_tan_gamma_e(y, dr, amp), "-")
    return path


# ---------------------------------------------------------------------------------------------
# Tests
# ---------------------------------------------------------------------------------------------
TMP = tempfile.mkdtemp(prefix="rb_tables_test_")
FIX = os.path.join(TMP, "fx.h5")
REAL = os.environ.get("RB_TABLES_H5") or ("/tmp/tables.h5" if os.path.exists("/tmp/tables.h5")
                                          else None)

work_files = work_folder(TMP, lambda: make_tables_fixture(FIX))


def run_cli(*args):
    """`plots/rbplot tables` as a process: (exit code, stdout, stderr)."""
    r = rbplot("tables", *args)
    return r.returncode, r.stdout, r.stderr


def run_main(*args):
    """The tables command's main in this process (faster than a new interpreter)."""
    r = in_process(tables_command.main, *args)
    return r.returncode, r.stdout, r.stderr


def _variant(name, drop=(), edit=None):
    """Copy of the fixture with groups deleted and/or edited by edit(h5file)."""
    import h5py
    path = os.path.join(TMP, name + ".h5")
    shutil.copy(FIX, path)
    with h5py.File(path, "a") as f:
        for g in drop:
            del f[g]
        if edit:
            edit(f)
    return path


def _png_ok(path, min_ink=0.02, dpi=150):
    """A PNG of report width (6.5 in) with a fair amount of drawing on it."""
    import matplotlib.image as mpimg
    check(os.path.exists(path), f"{path} not written")
    with open(path, "rb") as fh:
        check(fh.read(8) == b"\x89PNG\r\n\x1a\n", f"{path} is not a PNG")
    check(os.path.getsize(path) > 20000 * (dpi / 150) ** 2, f"{path} only "
          f"{os.path.getsize(path)} bytes")
    im = mpimg.imread(path)[..., :3]
    check(abs(im.shape[1] - 6.5 * dpi) <= 2, f"{path} is {im.shape[1]} px wide, expected "
          f"{6.5 * dpi:.0f}")
    ink = float(np.mean(np.any(im < 0.9, axis=-1)))
    check(ink > min_ink, f"{path}: only {ink:.3f} of the pixels drawn")
    colours = np.unique((im[::3, ::3] * 8).astype(int).reshape(-1, 3), axis=0).shape[0]
    check(colours >= 12, f"{path}: only {colours} colours")
    return ink


def _written(stdout):
    return [ln for ln in stdout.splitlines() if ln.endswith(".png")]


def _suffixes(paths, stem):
    return sorted(os.path.basename(p)[len(stem) + 1:-4] for p in paths)


def _one_line_error(code, out, err, needle):
    one_line_error(types.SimpleNamespace(returncode=code, stdout=out, stderr=err), "tables",
                   needle)


# ---- (a) the full fixture through the CLI -------------------------------------------------------
def test_a_cli_writes_all_figures():
    outdir = os.path.join(TMP, "out_full")
    code, out, err = run_cli(FIX, "--outdir", outdir)
    check(code == 0, f"exit {code}: {err.strip()}")
    lines = out.splitlines()
    check(lines[0].startswith("tables: "), f"first line {lines[0]!r}")
    paths = _written(out)
    check(_suffixes(paths, "fx") == sorted(FIGS), f"written {paths}")
    check(all(os.path.dirname(p) == outdir for p in paths), f"not in --outdir: {paths}")
    for p in paths:
        _png_ok(p)
    check(err.strip() == "", f"stderr {err!r}")


def test_a_default_outdir_is_next_to_file():
    d = os.path.join(TMP, "beside")
    os.makedirs(d)
    src = os.path.join(d, "tab.h5")
    shutil.copy(FIX, src)
    code, out, err = run_main(src, "--dpi", "40")
    check(code == 0, f"exit {code}: {err}")
    check(sorted(os.listdir(d)) == sorted(["tab.h5"] + [f"tab_{s}.png" for s in FIGS]),
          f"folder has {sorted(os.listdir(d))}")


def test_a_summary_line():
    t = load_tables(FIX)
    s = summary_line(t)
    check("\n" not in s and s.startswith("tables: "), s)
    for part in ("LUT 121 x 5 (y x xi_g)", "KEC 801 points", "tan(gamma_e) at 3 mm = 0.05",
                 "two-point contact at y = -5.7", "+5.7", "config 0123456789abcdef", " MB", " kB"):
        check(part in s, f"{part!r} not in {s!r}")
    v = conicity_at(t, 3e-3)
    check(v is not None and abs(v - 0.0526) < 0.002, f"conicity at 3 mm {v}")


# ---- (b) reading and geometry on the fixture ----------------------------------------------------
def test_b_load_shapes_and_two_point():
    t = load_tables(FIX)
    check(t.lut.ch["z"].shape == (5, 121) and t.lut.y.size == 121, "LUT shape")
    check({"left_s_w", "right_flange_delta", "phi"} <= set(t.lut.ch), "channels missing")
    tp = t.lut.two_points(0.0)
    check(sorted(s for _, s in tp) == [-1, 1], f"two-point sides {tp}")
    check(all(abs(abs(y) - 5.749e-3) < 0.05e-3 for y, _ in tp), f"two-point y {tp}")
    check(t.kec.sides() == ["left", "right"] and len(t.kec.transitions("left")) == 1, "KEC")
    check(abs(t.g("beta") - np.arctan(1 / 40)) < 1e-15 and t.has_geometry, "geometry attrs")


def _contact_mismatch(t):
    """Largest distance [m] between the LUT's wheel and rail contact points, both placed in the
    track frame the way fig_profiles_contact places them (checks the frame conventions)."""
    worst = 0.0
    for row in range(t.lut.xi_g.size):
        y, z, phi = t.lut.y, t.lut.ch["z"][row], t.lut.ch["phi"][row]
        wy, wz = _wheel_track(t.wheel, y, z, phi, t.g("lw"), s=t.lut.ch["left_s_w"][row])
        ry, rz = _rail_track(t.rail, t.g("lr"), t.g("beta"), t.lut.xi_g[row],
                                s=t.lut.ch["left_s_r"][row])
        worst = max(worst, float(np.max(np.hypot(wy - ry, wz - rz))))
    return worst


def test_b_contact_points_coincide_in_track_frame():
    d = _contact_mismatch(load_tables(FIX))
    check(d < 2e-6, f"wheel and rail contact points {d * 1e3:.4f} mm apart")


def _kec_vs_lut(t, ys):
    """Largest |dz|, |dphi| between the KEC solve (Eq. 22) and the LUT at xi_g = 0."""
    row = t.lut.row(0.0)
    dz = dp = 0.0
    for yv in ys:
        i = int(np.argmin(np.abs(t.lut.y - yv)))
        sol = kec_solve(t.kec, float(t.lut.y[i]), t.g("r0"), t.g("lr"))
        check(sol is not None, f"KEC solve failed at y = {yv}")
        dz = max(dz, abs(sol[0] - t.lut.ch["z"][row, i]))
        dp = max(dp, abs(sol[1] - t.lut.ch["phi"][row, i]))
    return dz, dp


def test_b_kec_solve_matches_lut_before_two_point():
    t = load_tables(FIX)
    s, f = knife_point(0.0, load_tables(FIX).lut.ch["z"][2, 60], 0.0, FX_R0, FX_LR)
    check(abs(s) < 1e-15, f"knife point at y = 0: s_k = {s}")
    dz, dp = _kec_vs_lut(t, [-4e-3, -2e-3, 0.0, 1.5e-3, 3e-3, 4e-3])
    check(dz < 1e-7 and dp < 1e-7, f"|dz| {dz:.2e} m, |dphi| {dp:.2e}")


# ---- (c) missing groups: their figures are skipped ----------------------------------------------
def test_c_missing_groups_skip_figures():
    cases = [
        ("no_kec", ["tables/kec"], None, [f for f in FIGS if f != "kec_map"]),
        ("no_lut", ["tables/lut"], None, ["kec_map", "rolling_radius", "conicity"]),
        ("no_derived", ["tables/derived", "tables/lut/two_point"], None,
         ["profiles_contact", "lut_z", "kec_map"]),
        ("no_profiles", ["profiles"], None, ["lut_z", "kec_map", "rolling_radius", "conicity"]),
        ("empty_conicity", [], lambda f: [f["tables/derived"].__delitem__(k) or
                                          f["tables/derived"].create_dataset(k, data=np.zeros(0))
                                          for k in ("conicity_amplitude", "tan_gamma_e")],
         [f for f in FIGS if f != "conicity"]),
        ("only_profiles", ["tables/lut", "tables/kec", "tables/derived"], None, []),
    ]
    for name, drop, edit, expect in cases:
        path = _variant(name, drop, edit)
        outdir = os.path.join(TMP, "out_" + name)
        code, out, err = run_main(path, "--outdir", outdir, "--dpi", "50")
        check(code == 0, f"{name}: exit {code}: {err.strip()}")
        got = _suffixes(_written(out), name)
        check(got == sorted(expect), f"{name}: wrote {got}, expected {sorted(expect)}")
        check(out.startswith("tables: "), f"{name}: no summary line: {out!r}")
        for p in _written(out):
            _png_ok(p, dpi=50)
        if not expect:
            check("nothing to plot" in err, f"{name}: no note on stderr: {err!r}")
        else:
            check(err.strip() == "", f"{name}: stderr {err!r}")


def test_c_kec_with_left_wheel_only():
    def edit(f):
        for k in list(f["tables/kec"]):
            if k.startswith("right_"):
                del f["tables/kec"][k]
    path = _variant("kec_left", edit=edit)
    code, out, err = run_main(path, "--outdir", os.path.join(TMP, "out_kec_left"), "--dpi", "40")
    check(code == 0 and _suffixes(_written(out), "kec_left") == sorted(FIGS),
          f"exit {code}, {out!r} {err!r}")


# ---- (d) bad files: one line on stderr, exit 1 --------------------------------------------------
def test_d_missing_and_garbage_files_as_process():
    _one_line_error(*run_cli(os.path.join(TMP, "nope.h5")), "no such file")
    bad = os.path.join(TMP, "garbage.h5")
    with open(bad, "w") as fh:
        fh.write("not HDF5\n")
    _one_line_error(*run_cli(bad), "not a readable HDF5 file")


def test_d_not_a_tables_file_and_broken_groups():
    import h5py
    other = os.path.join(TMP, "other.h5")
    with h5py.File(other, "w") as f:
        f.create_dataset("x", data=[1.0])
    _one_line_error(*run_main(other), "no /tables group")
    _one_line_error(*run_main(TMP), "is a directory")
    _one_line_error(*run_main(_variant("no_z", ["tables/lut/z"])), "missing dataset /tables/lut/z")

    def short_phi(f):
        del f["tables/lut/phi"]
        f["tables/lut"].create_dataset("phi", data=np.zeros((5, 7)))
    _one_line_error(*run_main(_variant("bad_shape", edit=short_phi)), "/tables/lut/phi has shape")

    def short_dr(f):
        del f["tables/derived/delta_r"]
        f["tables/derived"].create_dataset("delta_r", data=np.zeros(3))
    _one_line_error(*run_main(_variant("bad_len", edit=short_dr)), "differ in length")
    _one_line_error(*run_main(_variant("no_s_w", ["tables/kec/left_s_w"])),
                    "missing dataset /tables/kec/left_s_w")
    _one_line_error(*run_main(_variant("no_wheel_h", ["profiles/wheel_left/h"])),
                    "missing dataset /profiles/wheel_left/h")

    def text_y(f):
        del f["tables/lut/y"]
        f["tables/lut"].create_dataset("y", data=np.array([b"a", b"b"]))
    _one_line_error(*run_main(_variant("text_y", edit=text_y)), "not numeric")


def test_d_unwritable_outdir():
    blocker = os.path.join(TMP, "a_file")
    with open(blocker, "w") as fh:
        fh.write("x")
    _one_line_error(*run_main(FIX, "--outdir", os.path.join(blocker, "sub")), "a_file")


# ---- (e) a real file from `workbench tables` ----------------------------------------------------
def test_e_real_file():
    if not REAL or not os.path.exists(REAL):
        import pytest
        pytest.skip("no /tmp/tables.h5 and RB_TABLES_H5 not set")
    t = load_tables(REAL)
    stem = os.path.splitext(os.path.basename(REAL))[0]
    outdir = os.path.join(TMP, "out_real")
    code, out, err = run_main(REAL, "--outdir", outdir)
    check(code == 0, f"exit {code}: {err}")
    paths = _written(out)
    expect = [spec.suffix for spec in FIGURES if spec.is_available(t)]
    check(_suffixes(paths, stem) == sorted(expect), f"written {paths}, expected {expect}")
    for p in paths:
        _png_ok(p)
    s = out.splitlines()[0]
    check(s == summary_line(t) and s.startswith("tables: LUT "), f"summary {s!r}")
    if t.lut is not None and t.wheel is not None and t.has_geometry:
        d = _contact_mismatch(t)
        check(d < 1e-7, f"real file: contact points {d * 1e3:.5f} mm apart in the track frame")
    if t.lut is not None and t.kec is not None and "right_f" in t.kec.data:
        dz, dp = _kec_vs_lut(t, [-3e-3, 2e-3, 3e-3])
        check(dz < 1e-6 and dp < 1e-6, f"real file: KEC vs LUT |dz| {dz:.2e}, |dphi| {dp:.2e}")
    print(f"  ({REAL}: {s})")

