#!/usr/bin/python3
"""Synthetic railbench result file for testing the plotting code (NOT engine output).

usage: /usr/bin/python3 tests/plots/make_fixture.py OUT.h5 [--no-irregularities] [--seed N]
           [--vehicle [--method kec|lut] [--no-contact] [--failed]]

Track (paper section 5.2, Fig. 18): 100 m tangent, 50 m clothoid (curvature and cant ramp
linearly), 350 m left curve R = 500 m with 100 mm cant.  Centreline sampled every 0.5 m.

Irregularities: ORE B176 "low" spectra (reference doc section 1), one-sided G(Omega) over
Omega > 0, synthesised by a sum of cosines (section 4) with independent uniform random phases
per channel and amplitudes A_k = sqrt(2 G(Omega_k) dOmega), sampled every 0.1 m over the track.
The components sit on the Fourier frequencies of the record, Omega_k = 2*pi*k/L
(dOmega = 2*pi/L, L = track length) inside [2*pi/lambda_max, 2*pi/lambda_min]; this is the
deterministic-amplitude form of the IFFT method of section 4.  It is chosen because its
periodogram reproduces the target up to window leakage, so a 500 m record can test the PSD
*scaling* of the Welch estimator to +-30 % per octave; with randomised frequencies (the engine's
way) the statistical scatter of a 500 m record alone is ~25-35 % rms in the 24-48 m octave.

Cross level is stored as a height difference h = 2b * angle (b = 0.75 m), so its target is
G_h = (2b)^2 * (A_v/b^2) * ... = 4 A_v Omega_c^2 Omega^2 / ((..)(..)(..)) [m^2/(rad/m)].
Rail deviations: left/right_y = alignment +- gauge/2, left/right_z = vertical +- cross_level/2,
delta = cross_level / (2 Lr) (as workbench/track/irregularities.cpp).

Vehicle (--vehicle): seven bodies of a Manchester-wagon-like vehicle at 20 m/s with a
steady-curving-LIKE response (see BODIES/STEADY below; not dynamics), contact quantities per
wheel (normal force ~45 kN, flange contact of the front wheelsets in the curve), two suspension
elements and /stats.  --failed stops at t = 12.345 s with /stats status "failed".
"""
import argparse
import sys

import numpy as np
import h5py

# ORE B176 (reference doc section 1)
OC, OR, OS = 0.8246, 0.0206, 0.4380
B = 0.75
ORE = {
    "ore_b176_low": dict(Aa=2.119e-7, Av=4.032e-7, Ag=5.32e-8),
    "ore_b176_high": dict(Aa=6.125e-7, Av=1.080e-6, Ag=1.032e-7),
}


def ore_psd(spectrum, omega):
    """One-sided G(Omega) [m^2/(rad/m)] for the four channels (cross level as height)."""
    p = ORE[spectrum]
    o2 = np.asarray(omega, float) ** 2
    d = (o2 + OR ** 2) * (o2 + OC ** 2)
    return {
        "alignment": p["Aa"] * OC ** 2 / d,
        "vertical": p["Av"] * OC ** 2 / d,
        "gauge": p["Ag"] * OC ** 2 * o2 / (d * (o2 + OS ** 2)),
        "cross_level": 4.0 * p["Av"] * OC ** 2 * o2 / (d * (o2 + OS ** 2)),
    }


SEGMENTS = [  # kind (0 tangent, 1 transition, 2 curve), length, end radius, side, end cant
    (0, 100.0, 0.0, 1.0, 0.0),
    (1, 50.0, 500.0, 1.0, 0.100),
    (2, 350.0, 500.0, 1.0, 0.100),
]
CANT_BASE = 1.5
RAIL_LR = 0.7555
RAIL_INCL = 1.0 / 40.0


def _profiles(s):
    """Curvature and cant at arc length s (linear ramps in transitions)."""
    kap = np.zeros_like(s)
    cant = np.zeros_like(s)
    a = 0.0
    k0 = c0 = 0.0
    for kind, ln, r, side, c in SEGMENTS:
        k1 = side / r if r > 0 else 0.0
        sel = (s >= a) & (s <= a + ln)
        if kind == 0:
            k1, c = 0.0, 0.0
            kap[sel], cant[sel] = 0.0, 0.0
        elif kind == 1:
            t = (s[sel] - a) / ln
            kap[sel] = k0 + (k1 - k0) * t
            cant[sel] = c0 + (c - c0) * t
        else:
            kap[sel], cant[sel] = k1, c
        a += ln
        k0, c0 = k1, c
    return kap, cant


def _attr_str(obj, name, value):
    obj.attrs[name] = np.bytes_(value)  # fixed-length string, like the engine


def _ds(group, name, data, units):
    d = group.create_dataset(name, data=np.asarray(data, dtype=np.float64))
    _attr_str(d, "units", units)


# ---- synthetic vehicle results (Manchester wagon-like, paper section 5.2 case 2) -------------
# Body positions ahead of the car body centre [m] (bogie semi-spacing 9.5 m, semi wheelbase
# 1.28 m) and steady-curving values y [mm], yaw [mrad] taken from the paper's Table 6 (KEC and
# LUT rows).  The synthetic response is NOT dynamics: y and yaw follow the transition curvature
# ramp (0 on the tangent, linear in the transition, constant in the curve) plus a small hunting
# oscillation (decaying in the curve, plus a 0.04 mm / 0.02 mrad persistent ripple) so that the
# mean over the last 20 % of the distance equals the steady value to ~0.01 mm.
BODIES = [  # name, kind, offset ahead of the car centre [m]
    ("car", "car", 0.0), ("bogie1", "bogie", 9.5), ("bogie2", "bogie", -9.5),
    ("ws1", "wheelset", 10.78), ("ws2", "wheelset", 8.22),
    ("ws3", "wheelset", -8.22), ("ws4", "wheelset", -10.78),
]
STEADY = {  # method -> body -> (y [mm], yaw [mrad])
    "kec": {"ws1": (-8.8291, -4.7822), "ws2": (-4.6144, 0.2586), "ws3": (-8.8294, -4.7911),
            "ws4": (-4.6242, 0.2495), "bogie1": (-6.3153, -2.1481), "bogie2": (-6.3191, -2.1570),
            "car": (41.8464, -0.1997)},
    "lut": {"ws1": (-9.0966, -4.7474), "ws2": (-4.5718, 0.3042), "ws3": (-9.0970, -4.7752),
            "ws4": (-4.5469, 0.2799), "bogie1": (-6.4958, -2.1474), "bogie2": (-6.4676, -2.1730),
            "car": (41.0944, -0.1200)},
}
SPEED = 20.0          # m/s
CAR_S0 = 11.0         # m, so that the rear wheelset starts at s = 0.22 m
DT_OUT = 0.01         # s
Q_STATIC = 45e3       # N per wheel
K_HERTZ = 1e10        # N/m^1.5 (flange), as a low stiffness of paper Fig. 25
FAIL_T = 12.345       # s, failed variant
FAIL_MESSAGE = ("CVODE: at t = 12.345 s the error test failed repeatedly or with |h| = hmin "
                "(distance 257.9 m at the last output)")


def _curve_ramp(s):
    """0 before the transition, linear over it, 1 in the curve (matches SEGMENTS)."""
    a = SEGMENTS[0][1]
    return np.clip((s - a) / SEGMENTS[1][1], 0.0, 1.0)


def vehicle_response(method="kec", t_end=None):
    """Time, and per body s, y, yaw, ... [SI] of the synthetic run (no file)."""
    length = sum(seg[1] for seg in SEGMENTS)
    front = max(off for _, _, off in BODIES)
    if t_end is None:
        t_end = (length - front - CAR_S0) / SPEED
    t = np.arange(0.0, t_end + 0.5 * DT_OUT, DT_OUT)
    t = t[t <= t_end + 1e-9]
    s_car = CAR_S0 + SPEED * t
    out = {}
    for k, (name, kind, off) in enumerate(BODIES):
        y_ss, psi_ss = STEADY[method][name]
        s = s_car + off
        r = _curve_ramp(s)
        after = np.clip(s - SEGMENTS[0][1], 0.0, None)
        env = np.where(s < SEGMENTS[0][1], 1.0, np.exp(-after / 40.0))
        ph = 2 * np.pi * s / 17.0 + 0.7 * k
        y = y_ss * 1e-3 * r + (0.6e-3 * env + 0.04e-3) * np.sin(ph)
        yaw = psi_ss * 1e-3 * r + (0.25e-3 * env + 0.02e-3) * np.cos(ph)
        _, cant = _profiles(s)
        roll = {"car": 0.3, "bogie": 0.05}.get(kind, 0.0) * np.arcsin(cant / CANT_BASE)
        z = np.full_like(s, 0.0 if kind == "wheelset" else -0.002)
        out[name] = dict(kind=kind, s=s, y=y, z=z, roll=roll, pitch=np.zeros_like(s), yaw=yaw,
                         y_dot=np.gradient(y, t) if t.size > 1 else np.zeros_like(y))
    return t, out


def _contact_response(name, s, y, r):
    """Plausible contact quantities for wheelset `name` (front wheelsets flange on the right,
    the outer rail of the left curve)."""
    flanging = name in ("ws1", "ws3")
    rng = np.random.default_rng(sum(map(ord, name)))  # reproducible (no hash())
    wob = np.sin(2 * np.pi * s / 23.0 + rng.uniform(0, 6))
    dq = 4.5e3 * r
    d = {}
    for side, sg in (("left", -1.0), ("right", 1.0)):
        q = Q_STATIC + sg * dq + 0.8e3 * wob
        fl = np.zeros_like(s)
        if flanging and side == "right":
            fl = 22e3 * np.clip((r - 0.7) / 0.3, 0.0, 1.0) * (1 + 0.08 * wob)
        cx = sg * (0.9e-3 if flanging else -0.3e-3) * r + 0.05e-3 * wob
        cy = (-0.8e-3 if flanging else 0.25e-3) * r + 0.04e-3 * wob
        spin = sg * 0.03 * r + (1.2 * (fl > 0) * np.clip((r - 0.7) / 0.3, 0, 1))
        d[side] = dict(
            normal_force=(q, "N"),
            creep_force_x=(-8.5e6 * cx, "N"), creep_force_y=(-7.9e6 * cy, "N"),
            creepage_x=(cx, "-"), creepage_y=(cy, "-"), spin=(spin, "1/m"),
            wheel_s=(-sg * y, "m"), rail_s=(np.zeros_like(s), "m"),
            flange_indentation=((fl / K_HERTZ) ** (2.0 / 3.0), "m"), flange_force=(fl, "N"),
            regime=(np.where(fl > 0, 2.0, 0.0), "-"),
        )
    yq_r = (0.42 if flanging else 0.12) * r + 0.02 * wob
    yq_l = (-0.18 if flanging else 0.08) * r + 0.02 * wob
    return d, yq_l, yq_r


def add_vehicle(f, method="kec", contact=True, failed=False, ragged=False):
    """Write /time, /bodies, /contact (optional), /elements, /stats and the root attributes of a
    synthetic vehicle run into the open h5py file `f`."""
    t, bodies = vehicle_response(method, t_end=FAIL_T if failed else None)
    if failed:  # diverging just before the failure
        grow = np.exp(np.clip((t - t[-1]) / 0.05, -50, 0))
        for b in bodies.values():
            b["y"] = b["y"] + 6e-3 * grow * np.sin(40 * t)
            b["yaw"] = b["yaw"] + 8e-3 * grow * np.cos(40 * t)
    _attr_str(f, "contact_method", method)
    _attr_str(f, "solver", "bdf")
    _attr_str(f, "effects", "track_geometry\nvehicle" + ("\ncontact" if contact else ""))
    _ds(f, "time", t, "s")
    bg = f.create_group("bodies")
    _attr_str(bg, "names", "\n".join(name for name, _, _ in BODIES))
    for name, b in bodies.items():
        g = bg.create_group(name)
        _attr_str(g, "kind", b["kind"])
        for k in ("s", "y", "z", "roll", "pitch", "yaw"):
            _ds(g, k, b[k], "m" if k in ("s", "y", "z") else "rad")
        if name == "ws1":
            _ds(g, "y_dot", b["y_dot"], "m/s")  # a rate: read, not plotted
    if contact:
        cg = f.create_group("contact")
        _attr_str(cg, "method", method)
        for name, b in bodies.items():
            if b["kind"] != "wheelset":
                continue
            r = _curve_ramp(b["s"])
            d, yq_l, yq_r = _contact_response(name, b["s"], b["y"], r)
            wg = cg.create_group(name)
            for side, items in d.items():
                sg = wg.create_group(side)
                for k, (v, u) in items.items():
                    v = np.array(v, dtype=float)
                    if failed and k == "normal_force":
                        v[-1] = np.nan  # the last output of a failing run may be NaN
                    if ragged and k == "normal_force" and name == "ws1":
                        v = v[:-1]      # interrupted while writing: one sample short
                    _ds(sg, k, v, u)
            _ds(wg, "y_over_q_left", yq_l, "-")
            _ds(wg, "y_over_q_right", yq_r, "-")
    eg = f.create_group("elements")
    for name, ws in (("primary_lateral_ws1", "ws1"), ("secondary_yaw_bogie1", "bogie1")):
        g = eg.create_group(name)
        rot = "yaw" in name
        q, other = ("yaw", "car") if rot else ("y", "bogie1")
        dfl = bodies[ws][q] - bodies[other][q]
        _ds(g, "deflection", dfl, "rad" if rot else "m")
        _ds(g, "force", -(2e5 if rot else 1.2e6) * dfl, "N m" if rot else "N")
    st = f.create_group("stats")
    _attr_str(st, "status", "failed" if failed else "ok")
    _attr_str(st, "message", FAIL_MESSAGE if failed else "")
    _attr_str(st, "method", "bdf")
    st.attrs["t_reached"] = FAIL_T if failed else float(t[-1])  # integrator time, not output
    st.attrs["cpu_time_s"] = 9.87 if not failed else 5.43
    st.attrs["wall_time_s"] = 10.02 if not failed else 5.50
    st.attrs["rhs_evals"] = np.int64(48213)
    st.attrs["rhs_evals_jac"] = np.int64(3120)
    st.attrs["steps"] = np.int64(20417)
    st.attrs["rejected_steps"] = np.int64(311)
    st.attrs["jacobian_evals"] = np.int64(208)


def make_fixture(path, irregularities=True, seed=1, spectrum="ore_b176_low",
                 wavelength_min=3.0, wavelength_max=70.0, disabled=(), vehicle=False,
                 method="kec", contact=True, failed=False, ragged=False):
    length = sum(seg[1] for seg in SEGMENTS)
    step = 0.5
    # Fine integration of heading and position, then sample every `step`.
    sf = np.linspace(0.0, length, int(round(length / 0.01)) + 1)
    kf, cf = _profiles(sf)
    hf = np.concatenate([[0.0], np.cumsum(0.5 * (kf[1:] + kf[:-1]) * np.diff(sf))])
    xf = np.concatenate([[0.0], np.cumsum(0.5 * (np.cos(hf[1:]) + np.cos(hf[:-1])) * np.diff(sf))])
    yf = np.concatenate([[0.0], np.cumsum(0.5 * (np.sin(hf[1:]) + np.sin(hf[:-1])) * np.diff(sf))])
    s = np.linspace(0.0, length, int(round(length / step)) + 1)
    kap, cant = _profiles(s)

    with h5py.File(path, "w") as f:
        _attr_str(f, "version", "0.1.0-fixture")
        _attr_str(f, "scenario_file", "tests/plots/make_fixture.py")
        _attr_str(f, "scenario_text", "-- synthetic fixture, see make_fixture.py")
        _attr_str(f, "overrides", "")
        _attr_str(f, "created", "1970-01-01T00:00:00Z")
        t = f.create_group("track")
        t.attrs["length"] = length
        t.attrs["step"] = step
        t.attrs["cant_base"] = CANT_BASE
        t.attrs["rail_lr"] = RAIL_LR
        t.attrs["rail_inclination"] = RAIL_INCL
        c = t.create_group("centreline")
        _ds(c, "s", s, "m")
        _ds(c, "x", np.interp(s, sf, xf), "m")
        _ds(c, "y", np.interp(s, sf, yf), "m")
        _ds(c, "z", np.zeros_like(s), "m")
        _ds(c, "heading", np.interp(s, sf, hf), "rad")
        _ds(c, "slope", np.zeros_like(s), "rad")
        _ds(c, "cant_angle", np.arcsin(cant / CANT_BASE), "rad")
        _ds(c, "curvature", kap, "1/m")
        _ds(c, "cant", cant, "m")
        g = t.create_group("segments")
        starts = np.cumsum([0.0] + [seg[1] for seg in SEGMENTS[:-1]])
        _ds(g, "start", starts, "m")
        _ds(g, "length", [seg[1] for seg in SEGMENTS], "m")
        _ds(g, "kind", [seg[0] for seg in SEGMENTS], "-")
        _attr_str(g["kind"], "codes", "0=tangent,1=transition,2=curve")
        _ds(g, "radius", [seg[2] for seg in SEGMENTS], "m")
        _ds(g, "side", [seg[3] for seg in SEGMENTS], "-")
        _ds(g, "cant", [seg[4] for seg in SEGMENTS], "m")

        if vehicle:
            add_vehicle(f, method=method, contact=contact, failed=failed, ragged=ragged)
        if not irregularities:
            return path
        ds_i = 0.1
        si = np.linspace(0.0, length, int(round(length / ds_i)) + 1)
        d_om = 2.0 * np.pi / length
        o_lo, o_hi = 2 * np.pi / wavelength_max, 2 * np.pi / wavelength_min
        ok = np.arange(int(np.ceil(o_lo / d_om)), int(np.floor(o_hi / d_om)) + 1) * d_om
        g_k = ore_psd(spectrum, ok)
        rng = np.random.default_rng(seed)
        sig = {}
        for ch in ("alignment", "vertical", "gauge", "cross_level"):
            phase = rng.uniform(0.0, 2 * np.pi, ok.size)
            if ch in disabled:
                sig[ch] = np.zeros_like(si)
                continue
            amp = np.sqrt(2.0 * g_k[ch] * d_om)
            acc = np.zeros_like(si)
            for a, o, p in zip(amp, ok, phase):
                acc += a * np.cos(o * si + p)
            sig[ch] = acc
        ir = t.create_group("irregularities")
        _attr_str(ir, "source", "psd")
        _attr_str(ir, "spectrum", spectrum)
        ir.attrs["seed"] = np.int64(seed)
        ir.attrs["wavelength_min"] = float(wavelength_min)
        ir.attrs["wavelength_max"] = float(wavelength_max)
        ir.attrs["components"] = np.int64(ok.size)
        ir.attrs["scale"] = 1.0
        _ds(ir, "s", si, "m")
        for ch in ("alignment", "vertical", "gauge", "cross_level"):
            _ds(ir, ch, sig[ch], "m")
        _ds(ir, "left_y", sig["alignment"] + 0.5 * sig["gauge"], "m")
        _ds(ir, "right_y", sig["alignment"] - 0.5 * sig["gauge"], "m")
        _ds(ir, "left_z", sig["vertical"] + 0.5 * sig["cross_level"], "m")
        _ds(ir, "right_z", sig["vertical"] - 0.5 * sig["cross_level"], "m")
        _ds(ir, "delta", sig["cross_level"] / (2.0 * RAIL_LR), "rad")  # as the engine: dz/(2 Lr)
        tp = ir.create_group("target_psd")
        om = np.logspace(np.log10(2 * np.pi / 1000.0), np.log10(2 * np.pi / 0.5), 400)
        gt = ore_psd(spectrum, om)
        _ds(tp, "omega", om, "rad/m")
        for ch in ("alignment", "vertical", "gauge", "cross_level"):
            _ds(tp, ch, np.zeros_like(om) if ch in disabled else gt[ch], "m^2/(rad/m)")
    return path


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("out")
    ap.add_argument("--no-irregularities", action="store_true")
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--spectrum", default="ore_b176_low", choices=sorted(ORE))
    ap.add_argument("--vehicle", action="store_true",
                    help="add synthetic vehicle results (/time, /bodies, /contact, /stats)")
    ap.add_argument("--method", default="kec", choices=sorted(STEADY),
                    help="steady-curving values of this method (paper Table 6)")
    ap.add_argument("--no-contact", action="store_true", help="vehicle without /contact")
    ap.add_argument("--failed", action="store_true",
                    help=f"vehicle run that failed at t = {FAIL_T} s (partial results)")
    a = ap.parse_args(argv)
    make_fixture(a.out, irregularities=not a.no_irregularities, seed=a.seed, spectrum=a.spectrum,
                 vehicle=a.vehicle or a.failed or a.no_contact, method=a.method,
                 contact=not a.no_contact, failed=a.failed)
    print(a.out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
