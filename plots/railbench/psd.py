"""Welch power spectral density estimate and octave-band helpers (irregularity PSD)."""
from __future__ import annotations

import math
from typing import List, Optional, Sequence, Tuple

import numpy as np


# PSD estimation
# --------------------------------------------------------------------------------------------
def default_nperseg(n: int, ds: float, wavelength_max: Optional[float] = None,
                    cycles: float = 4.0) -> int:
    """Welch segment length (samples).

    A segment must hold several periods of the longest wavelength of interest so that its
    frequency resolution df = 1/(nperseg*ds) puts Omega_min = 2*pi/lambda_max a few bins above
    DC (the Hann main lobe is +-2 bins wide).  We ask for `cycles` = 4 periods, i.e.
    4*lambda_max/ds samples, then take the largest power of two <= min(n, that); a power of two
    below the request trades a little resolution (>= 2 periods still) for more averaged
    segments.  Without lambda_max (e.g. measured irregularities from a csv file), a quarter of
    the record is used (7 half-overlapping segments).  Never below 16 samples (or n if
    shorter).
    """
    n = int(n)
    if n < 2:
        return max(n, 1)
    want = cycles * wavelength_max / ds if (wavelength_max and ds > 0) else n / 4.0
    cap = max(min(float(n), want), 16.0)
    m = 1 << int(math.floor(math.log2(cap)))
    return int(min(m, n))


def welch_segment_starts(n: int, nperseg: int, overlap: float = 0.5) -> np.ndarray:
    """Start indices of Welch segments: K = ceil((n-M)/hop)+1 segments, hop = M*(1-overlap),
    spread evenly over [0, n-M] so the whole record is used (actual overlap >= `overlap`)."""
    m = max(1, min(int(nperseg), int(n)))
    if n <= m:
        return np.array([0])
    hop = max(1, int(round(m * (1.0 - overlap))))
    k = int(math.ceil((n - m) / hop)) + 1
    return np.round(np.linspace(0, n - m, k)).astype(int)


def welch_psd(x: Sequence[float], ds: float, nperseg: Optional[int] = None,
              overlap: float = 0.5, detrend: Optional[str] = "constant",
              wavelength_max: Optional[float] = None) -> Tuple[np.ndarray, np.ndarray]:
    """One-sided PSD of a spatial signal by Welch's method, in units^2/(rad/m) over Omega.

    x       samples at constant spacing ds [m]
    nperseg segment length; default_nperseg(len(x), ds, wavelength_max) if None
    overlap minimum fractional overlap of consecutive segments (0.5).  The number of segments
            K = ceil((N - M)/(M*(1-overlap))) + 1 and their starts are spread evenly over
            [0, N-M], so no sample is dropped (the actual overlap is >= `overlap`).
    detrend "constant" (remove segment mean), "linear", or None

    Window: periodic Hann.  Scaling: per segment P_f = |FFT(w*x)|^2 * ds / sum(w^2) is the
    two-sided density in units^2/(cycle/m); bins 1..M/2-1 are doubled for the one-sided G_f,
    and G_Omega = G_f/(2*pi) at Omega = 2*pi*f.  Then sum(G_Omega)*dOmega equals the mean
    windowed segment variance (Parseval), i.e. variance = integral G dOmega.

    Returns (omega [rad/m], G [units^2/(rad/m)]), omega[0] = 0.
    """
    x = np.asarray(x, dtype=float).reshape(-1)
    n = x.size
    if n < 2 or not (ds > 0):
        raise ValueError("welch_psd needs at least 2 samples and ds > 0")
    m = int(nperseg) if nperseg else default_nperseg(n, ds, wavelength_max)
    m = max(2, min(m, n))
    starts = welch_segment_starts(n, m, overlap)
    w = 0.5 - 0.5 * np.cos(2.0 * np.pi * np.arange(m) / m)  # periodic Hann
    t = np.arange(m, dtype=float)
    acc = np.zeros(m // 2 + 1)
    for st in starts:
        seg = x[st:st + m]
        if detrend == "constant":
            seg = seg - seg.mean()
        elif detrend == "linear":
            seg = seg - np.polyval(np.polyfit(t, seg, 1), t)
        acc += np.abs(np.fft.rfft(w * seg)) ** 2
    p = acc / len(starts) * ds / np.sum(w ** 2)  # two-sided, per cycle/m
    p[1:] *= 2.0
    if m % 2 == 0:
        p[-1] /= 2.0  # Nyquist bin is not mirrored
    f = np.fft.rfftfreq(m, ds)
    return 2.0 * np.pi * f, p / (2.0 * np.pi)


def interp_loglog(x_new: np.ndarray, x: np.ndarray, y: np.ndarray) -> np.ndarray:
    """Interpolate y(x) linearly in log-log; zeros/negatives stay 0; NaN outside [x0, x-1]."""
    x_new = np.asarray(x_new, float)
    x, y = np.asarray(x, float), np.asarray(y, float)
    ok = (x > 0) & (y > 0)
    out = np.full(x_new.shape, np.nan)
    if ok.sum() < 2:
        if np.all(y == 0):
            out[(x_new >= x.min()) & (x_new <= x.max())] = 0.0
        return out
    inside = (x_new >= x[ok].min()) & (x_new <= x[ok].max()) & (x_new > 0)
    out[inside] = np.exp(np.interp(np.log(x_new[inside]), np.log(x[ok]), np.log(y[ok])))
    return out


def octave_band_ratios(omega: np.ndarray, g_est: np.ndarray, omega_t: np.ndarray,
                       g_target: np.ndarray, wavelength_min: float, wavelength_max: float
                       ) -> List[Tuple[float, float, float]]:
    """Mean of G_est/G_target over each full octave inside [2pi/lambda_max, 2pi/lambda_min].

    Octaves are stacked downwards from Omega_max = 2*pi/lambda_min; a remaining partial octave
    at the long-wavelength end is not used.  Returns [(Omega_lo, Omega_hi, ratio), ...] from
    short to long wavelengths; ratio is NaN if an octave holds no estimate bin.
    """
    o_lo, o_hi = 2 * np.pi / wavelength_max, 2 * np.pi / wavelength_min
    tgt = interp_loglog(omega, omega_t, g_target)
    out = []
    hi = o_hi
    while hi / 2.0 >= o_lo * (1 - 1e-12):
        lo = hi / 2.0
        sel = (omega >= lo) & (omega < hi) & np.isfinite(tgt) & (tgt > 0)
        r = float(np.mean(g_est[sel] / tgt[sel])) if sel.any() else float("nan")
        out.append((lo, hi, r))
        hi = lo
    return out


def fractional_octave_average(omega: np.ndarray, g: np.ndarray, fraction: int = 3,
                              omega_min: Optional[float] = None,
                              omega_max: Optional[float] = None
                              ) -> Tuple[np.ndarray, np.ndarray]:
    """Mean of g over 1/`fraction`-octave bands (for display of a noisy estimate).

    Band centres are 2**(k/fraction) rad/m (k integer) within [omega_min, omega_max]
    (default: the positive range of omega); bands holding no bin are dropped.
    Returns (band centre [rad/m], band mean)."""
    omega, g = np.asarray(omega, float), np.asarray(g, float)
    pos = omega > 0
    lo = omega_min if omega_min else omega[pos].min()
    hi = omega_max if omega_max else omega[pos].max()
    k = np.arange(math.floor(math.log2(lo) * fraction), math.ceil(math.log2(hi) * fraction) + 1)
    centres = 2.0 ** (k / fraction)
    half = 2.0 ** (0.5 / fraction)
    oc, gm = [], []
    for c in centres:
        sel = pos & (omega >= c / half) & (omega < c * half)
        if sel.any() and lo <= c <= hi:
            oc.append(c)
            gm.append(float(np.mean(g[sel])))
    return np.array(oc), np.array(gm)


# --------------------------------------------------------------------------------------------
