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


# ---- (e) vehicle results: /time, /bodies, /contact, /stats ---------------------------------------
VEH = os.path.join(TMP, "veh.h5")            # KEC, contact, ok
VEH_LUT = os.path.join(TMP, "veh_lut.h5")    # LUT, contact, ok
VEH_FAIL = os.path.join(TMP, "veh_fail.h5")  # KEC, failed at t = 12.345 s, one ragged series
VEH_BODIES = os.path.join(TMP, "veh_bodies.h5")  # no /contact
VEHICLE_FIGS = ["wheelsets", "bogies_car", "contact_forces", "creep"]
COMPARE = os.path.join(PLOTS, "compare_runs.py")


def _ink(path):
    """Fraction of non-white pixels of a PNG (a blank or nearly empty figure is ~0)."""
    import matplotlib.image as mpimg
    im = mpimg.imread(path)[..., :3]
    return float(np.mean(np.any(im < 0.9, axis=-1)))


def _vehicle_fixtures():
    if not os.path.exists(VEH):
        mf.make_fixture(VEH, irregularities=False, vehicle=True, method="kec")
        mf.make_fixture(VEH_LUT, irregularities=False, vehicle=True, method="lut")
        mf.make_fixture(VEH_FAIL, irregularities=False, vehicle=True, failed=True, ragged=True)
        mf.make_fixture(VEH_BODIES, irregularities=False, vehicle=True, contact=False)


@test
def e_vehicle_figures_and_stats_line():
    _vehicle_fixtures()
    out = os.path.join(TMP, "veh_figs")
    r = run_cli(VEH, "--outdir", out)
    check(r.returncode == 0, f"exit {r.returncode}: {r.stderr.strip()}")
    lines = [ln for ln in r.stdout.splitlines() if ln.strip()]
    check(lines and lines[0].startswith("stats: ok, solver bdf"), f"first line {lines[:1]}")
    rtf = 23.91 / 9.87
    for part in ("contact KEC", "CPU 9.87 s", f"{rtf:.3g}x real time", "48213 rhs evaluations",
                 "20417 steps"):
        check(part in lines[0], f"'{part}' not in stats line {lines[0]!r}")
    want = [os.path.join(out, f"veh_{n}.png") for n in
            ["track_plan", "track_curvature_cant"] + VEHICLE_FIGS]
    check(sorted(lines[1:]) == sorted(want), f"printed {lines[1:]}, want {want}")
    import matplotlib.image as mpimg
    for p in want[2:]:
        check(_is_png(p), f"not a PNG: {p}")
        h, w = mpimg.imread(p).shape[:2]
        check(w == round(rp.A4_WIDTH_IN * rp.DPI), f"{os.path.basename(p)} is {w} px wide")
        ink = _ink(p)
        check(os.path.getsize(p) > 40_000 and ink > 0.15,
              f"{os.path.basename(p)}: {os.path.getsize(p)} bytes, {ink:.0%} ink")
    # one panel per wheelset and quantity, each with data
    res = rp.load_result(VEH)
    fig = rp.fig_wheelsets(res)
    data_axes = [ax for ax in fig.axes if any(len(ln.get_xdata()) > 1000 for ln in ax.lines)]
    rp.plt.close(fig)
    check(len(data_axes) == 8, f"wheelset figure: {len(data_axes)} axes with data, want 2 x 4")
    fig = rp.fig_contact_forces(res)
    ylabels = " ".join(ax.get_ylabel() for ax in fig.axes)
    rp.plt.close(fig)
    for q in ("Q [kN]", "flange force", "indent", "Y/Q"):
        check(q in ylabels, f"contact figure lacks a '{q}' row ({ylabels!r})")


@test
def e_steady_state_matches_synthetic_input():
    _vehicle_fixtures()
    rows = {row["body"]: row for row in rp.steady_state(rp.load_result(VEH))}
    check(sorted(rows) == sorted(mf.STEADY["kec"]), f"bodies {sorted(rows)}")
    bad = [f"{n}: {rows[n]['y_mm']:.3f}/{rows[n]['yaw_mrad']:.3f} vs {y}/{p}"
           for n, (y, p) in mf.STEADY["kec"].items()
           if abs(rows[n]["y_mm"] - y) > 0.1 or abs(rows[n]["yaw_mrad"] - p) > 0.1]
    check(not bad, "; ".join(bad))


@test
def e_failed_run_still_plots_with_banner():
    """In-process (one CLI run less): every available figure is drawn from the partial
    results, with the red banner above the axes."""
    import contextlib
    import io
    from matplotlib.colors import to_rgb
    _vehicle_fixtures()
    err = io.StringIO()
    with contextlib.redirect_stderr(err):
        res = rp.load_result(VEH_FAIL)
    check("differ in length" in err.getvalue(), f"no ragged-series warning: {err.getvalue()!r}")
    check(res.failed, "result not flagged as failed")
    line = rp.stats_summary(res)
    check(line.startswith("stats: FAILED") and mf.FAIL_MESSAGE in line, f"stats line {line!r}")
    out = os.path.join(TMP, "fail_figs")
    os.makedirs(out)
    done = []
    for spec in rp.FIGURES:
        if not spec.is_available(res):
            continue
        fig = rp.build_figure(res, spec)
        p = os.path.join(out, f"{spec.suffix}.png")
        fig.savefig(p)
        banner = [t for t in fig.texts if t.get_text().startswith("FAILED at t = 12.345 s: CVODE")]
        top = max((ax.get_tightbbox().y1 for ax in fig.axes if ax.get_visible()), default=0)
        b_y0 = banner[0].get_window_extent().y0 if banner else 0
        rp.plt.close(fig)
        check(banner, f"{spec.suffix}: no FAILED banner")
        rgb = to_rgb(banner[0].get_color())
        check(rgb[0] > 0.7 and rgb[1] < 0.2, f"{spec.suffix}: banner colour {rgb}")
        check(b_y0 >= top - 1, f"{spec.suffix}: banner overlaps the axes ({b_y0:.0f} < {top:.0f})")
        check(os.path.getsize(p) > 30_000, f"{spec.suffix}: {os.path.getsize(p)} bytes")
        done.append(spec.suffix)
    for n in VEHICLE_FIGS:
        check(n in done, f"{n} not drawn for the failed run ({done})")


@test
def e_bodies_only_no_contact_figures():
    _vehicle_fixtures()
    res = rp.load_result(VEH_BODIES)
    got = [spec.suffix for spec in rp.FIGURES if spec.is_available(res)]
    want = ["track_plan", "track_curvature_cant", "wheelsets", "bogies_car"]
    check(got == want, f"available {got}, want {want}")
    check(res.contact is None and len(res.bodies) == 7, "bodies-only fixture content")


def _run_compare(*args):
    return subprocess.run([PY, COMPARE, *args], capture_output=True, text=True, timeout=60)


@test
def e_compare_runs_figures_and_steady_csv():
    import csv
    _vehicle_fixtures()
    out = os.path.join(TMP, "cmp")
    r = _run_compare(VEH, VEH_LUT, "--outdir", out, "--prefix", "r500")
    check(r.returncode == 0, f"exit {r.returncode}: {r.stderr.strip()}")
    names = ["r500_compare_wheelsets.png", "r500_compare_bogies_car.png", "r500_steady_state.csv"]
    for n in names:
        check(os.path.join(out, n) in r.stdout.splitlines(), f"{n} not printed")
    for n in names[:2]:
        p = os.path.join(out, n)
        check(_is_png(p) and os.path.getsize(p) > 40_000 and _ink(p) > 0.15, f"{n} trivial")
    check("Steady curving" in r.stdout and "KEC" in r.stdout and "LUT" in r.stdout,
          f"no table in {r.stdout!r}")
    with open(os.path.join(out, names[2]), newline="") as f:
        rows = list(csv.DictReader(f))
    check(len(rows) == 14, f"{len(rows)} CSV rows, want 2 runs x 7 bodies")
    bad = []
    for row in rows:
        y, p = mf.STEADY[row["label"].lower()][row["body"]]
        if abs(float(row["y_mm"]) - y) > 0.1 or abs(float(row["yaw_mrad"]) - p) > 0.1:
            bad.append(f"{row['label']} {row['body']}: {row['y_mm']}/{row['yaw_mrad']} vs {y}/{p}")
    check(not bad, "; ".join(bad))


@test
def e_compare_runs_partial_and_no_common_bodies():
    """compare_runs.main in-process: a body missing in one run, none in common, bad --labels."""
    import contextlib
    import h5py
    import io
    import compare_runs as cr
    _vehicle_fixtures()
    part = os.path.join(TMP, "veh_no_ws4.h5")
    other = os.path.join(TMP, "veh_renamed.h5")
    shutil.copy(VEH_LUT, part)
    shutil.copy(VEH_LUT, other)
    with h5py.File(part, "a") as f:
        del f["bodies/ws4"]
        f["bodies"].attrs["names"] = np.bytes_("car\nbogie1\nbogie2\nws1\nws2\nws3")
    with h5py.File(other, "a") as f:
        for n in list(f["bodies"].keys()):
            f.move(f"bodies/{n}", f"bodies/x_{n}")
        f["bodies"].attrs["names"] = np.bytes_("")

    def run(*args):
        o, e = io.StringIO(), io.StringIO()
        with contextlib.redirect_stdout(o), contextlib.redirect_stderr(e):
            code = cr.main(list(args))
        return code, o.getvalue(), e.getvalue()

    out = os.path.join(TMP, "cmp2")
    code, so, se = run(VEH, part, "--labels", "A,B", "--outdir", out)
    check(code == 0, f"exit {code}: {se.strip()}")
    check("ws4" in se and "not compared" in se, f"stderr {se!r}")
    with open(os.path.join(out, "veh_vs_veh_no_ws4_steady_state.csv")) as f:
        n = len(f.read().splitlines())
    check(n == 1 + 2 * 6, f"CSV has {n} lines, want header + 2 x 6")
    code, so, se = run(VEH, other, "--outdir", out)
    lines = [ln for ln in se.splitlines() if ln.strip()]
    check(code == 1 and len(lines) == 1 and lines[0].startswith("compare_runs: error:")
          and "no bodies in common" in lines[0], f"exit {code}, stderr {se!r}")
    code, so, se = run(VEH, VEH_LUT, "--labels", "only-one")
    check(code == 1 and "--labels" in se, f"labels mismatch: exit {code}, {se!r}")

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
