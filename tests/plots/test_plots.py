#!/usr/bin/python3
"""Tests of plots/plot_run.py and plots/railbench_plots.py (plain script, no pytest).

usage: /usr/bin/python3 tests/plots/test_plots.py      -> exit 0 if all pass, 1 otherwise;
the last line is "N passed, M failed".  Work files go to a temp dir, removed on success
(kept on failure, or always with RB_KEEP_TMP=1).
"""
import os
import shutil
import subprocess
import sys
import tempfile
import time
import traceback

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.abspath(os.path.join(HERE, "..", ".."))
PLOTS = os.path.join(ROOT, "plots")
PLOT_RUN = os.path.join(PLOTS, "plot_run.py")
PY = "/usr/bin/python3"
sys.path[:0] = [PLOTS, HERE]

import railbench_plots as rp  # noqa: E402
import make_fixture as mf  # noqa: E402

FOUR = ["track_plan", "track_curvature_cant", "irregularities", "irregularity_psd"]
TMP = tempfile.mkdtemp(prefix="rb_plots_test_")
FIX = os.path.join(TMP, "run.h5")        # with irregularities, seed 1
FIX_PLAIN = os.path.join(TMP, "plain.h5")  # without

_tests = []


def test(fn):
    _tests.append(fn)
    return fn


def check(cond, msg):
    if not cond:
        raise AssertionError(msg)


def run_cli(*args):
    return subprocess.run([PY, PLOT_RUN, *args], capture_output=True, text=True, timeout=60)


def _is_png(path):
    with open(path, "rb") as f:
        return f.read(8) == b"\x89PNG\r\n\x1a\n"


# ---- (a) all four figures from a full fixture ------------------------------------------------
@test
def a_cli_writes_four_pngs_next_to_h5():
    r = run_cli(FIX)
    check(r.returncode == 0, f"exit {r.returncode}: {r.stderr.strip()}")
    listed = [ln for ln in r.stdout.splitlines() if ln.strip()]
    want = [os.path.join(TMP, f"run_{n}.png") for n in FOUR]
    check(sorted(listed) == sorted(want), f"printed {listed}, want {want}")
    for p in want:
        check(os.path.isfile(p), f"missing {p}")
        check(_is_png(p), f"not a PNG: {p}")
        sz = os.path.getsize(p)
        check(sz > 10_000, f"{os.path.basename(p)} only {sz} bytes")


@test
def a_cli_outdir_option():
    out = os.path.join(TMP, "figs", "sub")  # created on demand
    r = run_cli(FIX_PLAIN, "--outdir", out)
    check(r.returncode == 0, f"exit {r.returncode}: {r.stderr.strip()}")
    got = sorted(os.listdir(out))
    check(got == ["plain_track_curvature_cant.png", "plain_track_plan.png"], f"outdir holds {got}")


# ---- (b) Welch estimator scaling ---------------------------------------------------------------
@test
def b_welch_recovers_target_per_octave_on_fixture():
    """Mean of estimate/target per full octave inside 3-70 m within +-30 % (fixture seed 1).

    A 500 m record has real statistical scatter in its long-wavelength octaves; the fixture's
    Fourier-grid synthesis keeps it small (see make_fixture.py), so this checks the scaling
    (a factor 2 or 2*pi error would show as 0.5/2/0.16/6.3)."""
    res = rp.load_result(FIX)
    ir = res.irregularities
    lo, hi = ir.band()
    bad, rows = [], []
    for c in rp.CHANNELS:
        om, g = rp.welch_psd(ir.data[c], ir.step, wavelength_max=hi)
        bands = rp.octave_band_ratios(om, g, ir.target["omega"], ir.target[c], lo, hi)
        check(len(bands) == 4, f"{c}: expected 4 full octaves in 3-70 m, got {len(bands)}")
        rows.append(f"{c}: " + " ".join(f"{r:.2f}" for _, _, r in bands))
        bad += [f"{c} {2 * np.pi / b:.0f}-{2 * np.pi / a:.0f} m: {r:.2f}"
                for a, b, r in bands if not (0.7 <= r <= 1.3)]
    print("    ratios per octave (3-6, 6-12, 12-24, 24-48 m): " + "; ".join(rows))
    check(not bad, "outside +-30 %: " + ", ".join(bad))


@test
def b_welch_long_record_tight():
    """20 km realisation (IFFT method, reference doc section 4) of the ORE B176 low vertical
    spectrum: per-octave ratio within +-10 % (statistical scatter here is a few %)."""
    ds, n = 0.1, 200_000
    rng = np.random.default_rng(7)
    f = np.fft.rfftfreq(n, ds)
    gf = 2 * np.pi * mf.ore_psd("ore_b176_low", 2 * np.pi * f)["vertical"]  # m^2/(cycle/m)
    band = (f >= 1 / 70.0) & (f <= 1 / 3.0)
    mag = np.where(band, np.sqrt(n * gf / (2 * ds)), 0.0)
    spec = mag * np.exp(1j * rng.uniform(0, 2 * np.pi, f.size))
    spec[0] = 0.0
    spec[-1] = 0.0
    x = np.fft.irfft(spec, n)
    om, g = rp.welch_psd(x, ds, wavelength_max=70.0)
    ot = np.geomspace(1e-3, 30, 500)
    bands = rp.octave_band_ratios(om, g, ot, mf.ore_psd("ore_b176_low", ot)["vertical"], 3, 70)
    r = [b[2] for b in bands]
    print("    ratios: " + " ".join(f"{v:.3f}" for v in r))
    check(all(0.9 <= v <= 1.1 for v in r), f"ratios {r}")


@test
def b_welch_parseval_and_white_noise():
    # Parseval: sum(G) dOmega equals the mean of the windowed segment powers (exact identity).
    rng = np.random.default_rng(3)
    ds, n, m = 0.25, 3000, 512
    x = rng.standard_normal(n) * 2e-3
    om, g = rp.welch_psd(x, ds, nperseg=m)
    w = 0.5 - 0.5 * np.cos(2 * np.pi * np.arange(m) / m)
    st = rp.welch_segment_starts(n, m)
    check(np.all(np.diff(st) <= m // 2) and st[-1] == n - m and st[0] == 0,
          f"segments {st} do not cover the record with >= 50 % overlap")
    pw = np.mean([np.sum((w * (x[a:a + m] - x[a:a + m].mean())) ** 2) / np.sum(w ** 2)
                  for a in st])
    d_om = om[1] - om[0]
    check(abs(np.sum(g) * d_om - pw) < 1e-9 * pw, f"Parseval {np.sum(g) * d_om} vs {pw}")
    check(abs(d_om - 2 * np.pi / (m * ds)) < 1e-12, "omega spacing")
    # White noise of variance s2 and spacing ds: G(Omega) = s2 * ds / pi over (0, pi/ds).
    x = rng.standard_normal(400_000)
    om, g = rp.welch_psd(x, ds, nperseg=1024)
    lvl = np.mean(g[1:-1]) / (ds / np.pi)
    check(abs(lvl - 1) < 0.02, f"white-noise level {lvl:.4f} x expected")


@test
def b_default_nperseg_rule():
    check(rp.default_nperseg(5001, 0.1, 70.0) == 2048, "4*70/0.1=2800 -> 2048")
    check(rp.default_nperseg(1000, 0.1, 70.0) == 512, "capped by N=1000 -> 512")
    check(rp.default_nperseg(4096, 0.1, None) == 1024, "N/4 without lambda_max")
    check(rp.default_nperseg(10, 0.1, 70.0) == 10, "short record -> N")


# ---- (c) no irregularities -> only the track figures --------------------------------------------
@test
def c_without_irregularities_only_track_figures():
    r = run_cli(FIX_PLAIN)
    check(r.returncode == 0, f"exit {r.returncode}: {r.stderr.strip()}")
    names = sorted(os.path.basename(p) for p in r.stdout.split())
    check(names == ["plain_track_curvature_cant.png", "plain_track_plan.png"], f"wrote {names}")
    leftovers = [f for f in os.listdir(TMP) if f.startswith("plain_irreg")]
    check(not leftovers, f"unexpected {leftovers}")


@test
def c_disabled_channel_still_plots():
    p = os.path.join(TMP, "nogauge.h5")
    mf.make_fixture(p, seed=2, disabled=("gauge",))
    res = rp.load_result(p)
    check(not np.any(res.irregularities.target["gauge"]), "gauge target should be all zeros")
    fig = rp.fig_irregularity_psd(res)
    q = os.path.join(TMP, "nogauge_psd.png")
    fig.savefig(q)
    rp.plt.close(fig)
    check(os.path.getsize(q) > 10_000, f"{q} too small")


# ---- (d) bad input -> non-zero exit and one line ------------------------------------------------
def _one_line_error(r, needle):
    check(r.returncode != 0, "exit status 0")
    lines = [ln for ln in r.stderr.splitlines() if ln.strip()]
    check(len(lines) == 1, f"stderr has {len(lines)} lines: {r.stderr!r}")
    check(lines[0].startswith("plot_run: error:") and needle in lines[0], f"message {lines[0]!r}")
    check(r.stdout.strip() == "", f"stdout {r.stdout!r}")


@test
def d_missing_file():
    _one_line_error(run_cli(os.path.join(TMP, "does_not_exist.h5")), "no such file")


@test
def d_not_hdf5_and_not_railbench():
    bad = os.path.join(TMP, "garbage.h5")
    with open(bad, "w") as f:
        f.write("this is not HDF5\n")
    _one_line_error(run_cli(bad), "not a readable HDF5 file")
    import h5py
    other = os.path.join(TMP, "other.h5")
    with h5py.File(other, "w") as f:
        f.create_dataset("x", data=[1.0])
    _one_line_error(run_cli(other), "no /track group")


def main():
    t0 = time.time()
    mf.make_fixture(FIX, irregularities=True, seed=1)
    mf.make_fixture(FIX_PLAIN, irregularities=False)
    passed = failed = 0
    for fn in _tests:
        t = time.time()
        try:
            fn()
            passed += 1
            print(f"PASS {fn.__name__} ({time.time() - t:.1f} s)")
        except Exception as e:  # noqa: BLE001
            failed += 1
            print(f"FAIL {fn.__name__}: {e}")
            if not isinstance(e, AssertionError):
                traceback.print_exc()
    if failed == 0 and not os.environ.get("RB_KEEP_TMP"):
        shutil.rmtree(TMP, ignore_errors=True)
        print(f"({time.time() - t0:.1f} s)")
    else:
        print(f"(files kept in {TMP}, {time.time() - t0:.1f} s)")
    print(f"{passed} passed, {failed} failed")
    return 0 if failed == 0 else 1


if __name__ == "__main__":
    sys.exit(main())
