#!/usr/bin/python3
"""Synthetic railbench result file for testing the plotting code (NOT engine output).

usage: /usr/bin/python3 tests/plots/make_fixture.py OUT.h5 [--no-irregularities] [--seed N]

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


def make_fixture(path, irregularities=True, seed=1, spectrum="ore_b176_low",
                 wavelength_min=3.0, wavelength_max=70.0, disabled=()):
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
    a = ap.parse_args(argv)
    make_fixture(a.out, irregularities=not a.no_irregularities, seed=a.seed, spectrum=a.spectrum)
    print(a.out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
