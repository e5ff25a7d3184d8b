"""The numbers and figures of docs/three_way.md from the three-way study
(scenarios/studies/three_way.lua): every scenario with KEC, LUT and elastic contact.

    plots/rbplot three-way OUT_DIR    (OUT_DIR = out/studies/three_way)

reads OUT_DIR/summary_cases.csv (case labels "<scenario> | <method>") and each case's result
file and writes, beside them,

    three_way_steady.csv    per scenario and method, over the scenario's steady window (WINDOWS):
                            mean y [mm] and yaw [mrad] of the leading wheelset, and of its outer
                            (right: every curve is a left curve) wheel the mean and std of Y, Q
                            and Y/Q, the share of output samples in two-point contact (regime 1:
                            a tread and a flange patch) and with a flange patch (regime 1 or 2),
                            the flange patches' share of the normal force, the mean number of
                            patches and the contact angle of the strongest patch
    three_way_extremes.csv  per case over the whole run: status, t reached, max |y| of the
                            leading wheelset, max Y, Q, Y/Q and flange force of its outer wheel,
                            max wheel lift of any wheel
    three_way_dynamic.csv   KEC and LUT against elastic on the same output times: rms and max
                            difference of the leading wheelset's y [mm] and of its outer wheel's
                            Y and Q [kN] (whole run, scenarios with irregularities), and
                            the rms of the y difference before the curve (tangent and
                            transition) and in the curve
    three_way_cost.csv      per case: CPU [s] (one run), rhs evaluations, us per evaluation, the
                            contact stage's share of the rhs cost (/stats stage_share)
    three_way_trial.csv     the trial scenario: the outer wheel of the leading wheelset over
                            s >= 110 m, at the run's 2 ms output and every 5th sample (the trial's
                            10 ms): Y mean/std/min/max, regime switches per second and mean run
                            length, the std above 15 Hz of the wheelset's y and of Y, the largest
                            peaks above 15 Hz of the Y and Q spectra (Welch, 1 s segments) and the
                            share of the Q variance above 15 Hz
    three_way_constants.csv the elastic method's constants per scenario (/contact elastic_*
                            attributes) and the tread's Hertz constant N0 / delta0^1.5
    study_trial.png, study_case3.png, study_climb.png   figures

`plots/rbplot docs` turns them into the generated blocks of docs/three_way.md.
"""
from __future__ import annotations

import csv
import os
import sys
from typing import Dict, List, Optional, Tuple

import h5py
import numpy as np

from .result import parse_codes

METHODS = ("kec", "lut", "elastic")
# Steady windows: (signal, lo, hi): "s" the leading wheelset's arc length [m], "t" time [s].
WINDOWS = {
    "case1": ("s", 110.0, 120.0),        # the last 10 m of case 1's 40 m curve (Table 5)
    "case2": ("s", 300.0, 450.0),        # the whole wagon in the R = 500 m curve
    "case3": ("s", 300.0, 450.0),
    "sharp_curve": ("t", 3.0, 4.0),      # the last second: leading wheelset 16-32 m into the curve
    "stiff_flange": ("t", 0.5, 1.0),     # curve entry before the first impact (t ~ 1.0 s)
    "wheel_climb": ("t", 5.0, 6.0),      # the last second: leading wheelset on its flange
    "trial_r300": ("s", 110.0, 400.0),   # the whole wagon in the full 100 mm cant curve
}
TRIAL = "trial_r300"
TRIAL_DECIMATE = 5  # 2 ms output -> the trial's 10 ms


def _text(v) -> str:
    return v.decode() if isinstance(v, bytes) else str(v)


def split_label(label: str) -> Tuple[str, str]:
    scen, _, method = label.partition(" | ")
    return scen.strip(), method.strip()


def scenario_kind(scen: str) -> str:
    if scen.startswith("case1"):
        return "case1"
    return scen.split(" ")[0]  # "case3 dopri5 1e-6": the window of case3


def leading_wheelset(f: h5py.File) -> str:
    names = [n for n in f["/bodies"] if _text(f["/bodies"][n].attrs.get("kind", "")) == "wheelset"]
    return sorted(names)[0]


def window(f: h5py.File, ws: str, scen: str) -> np.ndarray:
    sig, lo, hi = WINDOWS[scenario_kind(scen)]
    x = f["/bodies"][ws]["s"][:] if sig == "s" else f["/time"][:]
    return (x >= lo - 1e-9) & (x <= hi + 1e-9)


def _mean(x):
    return float(np.mean(x)) if len(x) else float("nan")


def regime_code(f: h5py.File, name: str) -> int:
    """The code of the contact regime `name` in the file (/schema/enums/contact_regime)."""
    g = f.get("schema/enums")
    codes = parse_codes(g.attrs["contact_regime"]) if g is not None and \
        "contact_regime" in g.attrs else {}
    for code, n in codes.items():
        if n == name:
            return code
    raise ValueError(f"{f.filename}: no contact regime '{name}' in /schema/enums")


def steady_row(f: h5py.File, scen: str) -> Optional[dict]:
    ws = leading_wheelset(f)
    sel = window(f, ws, scen)
    if not np.any(sel):
        return None
    b = f["/bodies"][ws]
    w = f["/contact"][ws]["right"]
    Y = w["Y"][:][sel]
    Q = w["Q"][:][sel]
    reg = w["regime"][:][sel].astype(int)
    N = w["normal_force"][:][sel]
    Nf = w["normal_flange"][:][sel] if "normal_flange" in w else np.zeros_like(N)
    cnt = w["contact_count"][:][sel] if "contact_count" in w else np.full_like(N, np.nan)
    # Contact angle of the strongest patch per sample.
    ang = np.full(N.shape, np.nan)
    best = np.zeros(N.shape)
    for p in ("patch0", "patch1"):
        if p in w:
            n = w[p]["normal_force"][:][sel]
            a = w[p]["contact_angle"][:][sel]
            take = n > best
            ang[take] = a[take]
            best = np.maximum(best, n)
    sig, lo, hi = WINDOWS[scenario_kind(scen)]
    return dict(
        window=f"{'s' if sig == 's' else 't'} = {lo:g}..{hi:g} {'m' if sig == 's' else 's'}",
        samples=int(np.sum(sel)), wheelset=ws,
        y_mm=_mean(b["y"][:][sel]) * 1e3, yaw_mrad=_mean(b["yaw"][:][sel]) * 1e3,
        Y_kN=_mean(Y) / 1e3, Y_std_kN=float(np.std(Y)) / 1e3, Q_kN=_mean(Q) / 1e3,
        Q_std_kN=float(np.std(Q)) / 1e3, YQ=_mean(Y / np.where(Q > 1, Q, np.nan)),
        two_point=_mean(reg == regime_code(f, "two_point")),
        flange_any=_mean(reg != regime_code(f, "tread")),
        flange_N_share=float(np.sum(Nf) / np.sum(N)) if np.sum(N) > 0 else float("nan"),
        patches=_mean(cnt), angle_rad=float(np.nanmean(ang)))


def extremes_row(f: h5py.File) -> dict:
    ws = leading_wheelset(f)
    w = f["/contact"][ws]["right"]
    st = f["/stats"].attrs
    # Loss of contact: output samples in which some wheel has no patch (elastic only; a
    # constraint method keeps every wheel on its rail). The wheel_lift channel is not used: it is
    # the rise of the tape circle, which also grows when the contact climbs the flange root.
    lost = None
    for name in f["/contact"]:
        for side in ("left", "right"):
            g = f["/contact"][name].get(side)
            if g is not None and "contact_count" in g and len(g["contact_count"]):
                z = g["contact_count"][:] == 0
                lost = z if lost is None else (lost | z)
    Q = w["Q"][:]
    yq = w["Y"][:] / np.where(Q > 1, Q, np.nan)
    nf = w["normal_flange"][:] if "normal_flange" in w else np.zeros(1)
    return dict(status=_text(st.get("status", "")), t_reached=float(st.get("t_reached", 0.0)),
                message=_text(st.get("message", ""))[:120],
                y_max_mm=float(np.max(np.abs(f["/bodies"][ws]["y"][:]))) * 1e3,
                Y_max_kN=float(np.max(w["Y"][:])) / 1e3, Q_max_kN=float(np.max(Q)) / 1e3,
                YQ_max=float(np.nanmax(yq)) if np.any(np.isfinite(yq)) else float("nan"),
                flange_N_max_kN=float(np.max(nf)) / 1e3,
                no_contact_samples=int(np.sum(lost)) if lost is not None else 0,
                no_contact_first_t=float(f["/time"][:][np.argmax(lost)])
                if lost is not None and np.any(lost) else float("nan"),
                Q_min_any_kN=min(float(np.min(f["/contact"][n][sd]["Q"][:]))
                                 for n in f["/contact"] for sd in ("left", "right")
                                 if sd in f["/contact"][n]) / 1e3,
                two_point=float(np.mean(w["regime"][:] == regime_code(f, "two_point"))))


def dynamic_rows(files: Dict[str, str], scen: str) -> List[dict]:
    """KEC and LUT against elastic on their common output times (the whole run)."""
    if "elastic" not in files:
        return []
    out = []
    with h5py.File(files["elastic"], "r") as fe:
        ws = leading_wheelset(fe)
        te = fe["/time"][:]
        seg = fe["/track/segments"]
        kinds = seg["kind"][:]
        curve0 = float(seg["start"][:][np.argmax(kinds == 2)]) if np.any(kinds == 2) else np.inf
        in_curve = fe["/bodies"][ws]["s"][:] >= curve0
        ref = {"y": fe["/bodies"][ws]["y"][:] * 1e3,
               "Y": fe["/contact"][ws]["right"]["Y"][:] / 1e3,
               "Q": fe["/contact"][ws]["right"]["Q"][:] / 1e3}
        for m in ("kec", "lut"):
            if m not in files:
                continue
            with h5py.File(files[m], "r") as fm:
                tm = fm["/time"][:]
                n = min(len(tm), len(te))
                if n == 0 or np.max(np.abs(tm[:n] - te[:n])) > 1e-9:
                    continue
                row = dict(scenario=scen, method=m, samples=n, t_end=float(tm[n - 1]))
                got = {"y": fm["/bodies"][ws]["y"][:n] * 1e3,
                       "Y": fm["/contact"][ws]["right"]["Y"][:n] / 1e3,
                       "Q": fm["/contact"][ws]["right"]["Q"][:n] / 1e3}
                dy = got["y"] - ref["y"][:n]
                c = in_curve[:n]
                row["y_rms_before_curve"] = float(np.sqrt(np.mean(dy[~c] ** 2))) if np.any(~c) else float("nan")
                row["y_rms_curve"] = float(np.sqrt(np.mean(dy[c] ** 2))) if np.any(c) else float("nan")
                row["curve_start_m"] = curve0
                for k in ("y", "Y", "Q"):
                    d = got[k] - ref[k][:n]
                    row[f"{k}_rms"] = float(np.sqrt(np.mean(d ** 2)))
                    row[f"{k}_max"] = float(np.max(np.abs(d)))
                    row[f"{k}_ref_rms"] = float(np.sqrt(np.mean((ref[k][:n] - np.mean(ref[k][:n])) ** 2)))
                out.append(row)
    return out


def cost_row(f: h5py.File) -> dict:
    st = f["/stats"]
    evals = int(st.attrs.get("rhs_evals", 0)) + int(st.attrs.get("rhs_evals_jac", 0))
    cpu = float(st.attrs.get("cpu_time_s", 0.0))
    share = float("nan")
    if "stage_names" in st:
        names = [_text(x) for x in st["stage_names"][:]]
        if "contact_patches" in names:
            share = float(st["stage_share"][:][names.index("contact_patches")])
    sim = float(st.attrs.get("t_reached", 0.0))
    return dict(cpu_s=cpu, rhs_evals=evals, steps=int(st.attrs.get("steps", 0)),
                us_per_eval=cpu / evals * 1e6 if evals else float("nan"),
                real_time=sim / cpu if cpu > 0 else float("nan"), contact_share=share,
                t_reached=sim)


def elastic_constants(f: h5py.File) -> dict:
    """The elastic method's constants of a run (/contact attributes elastic_*) and the tread's
    Hertz constant they imply, K = N0 / delta0^1.5 at the static wheel load."""
    a = f["/contact"].attrs
    n0 = float(a.get("elastic_static_load_N", float("nan")))
    d0 = float(a.get("elastic_static_approach_m", float("nan")))
    return dict(static_load_kN=n0 / 1e3, static_approach_um=d0 * 1e6,
                hertz_K=n0 / d0 ** 1.5 if d0 > 0 else float("nan"),
                vertical_hz=float(a.get("elastic_vertical_frequency_hz", float("nan"))),
                damping_ratio=float(a.get("elastic_damping_ratio", float("nan"))),
                damping_s_per_m=float(a.get("elastic_damping_s_per_m", float("nan"))),
                sample_step_mm=float(a.get("elastic_sample_step_m", float("nan"))) * 1e3,
                flange_height_mm=float(a.get("elastic_flange_height_m", float("nan"))) * 1e3)


def _switches(reg: np.ndarray) -> int:
    return int(np.sum(np.diff(reg) != 0))


def _spectrum(x: np.ndarray, dt: float, seg_s: float = 1.0) -> Tuple[np.ndarray, np.ndarray]:
    """One-sided PSD by Welch's method (Hann window, segments of about seg_s, half overlap)."""
    x = x - np.mean(x)
    n = min(len(x), max(16, int(round(seg_s / dt))))
    win = np.hanning(n)
    segs = [x[i:i + n] for i in range(0, len(x) - n + 1, n // 2)]
    P = np.mean([np.abs(np.fft.rfft(sg * win)) ** 2 for sg in segs], axis=0)
    return np.fft.rfftfreq(n, dt), P * 2.0 * dt / np.sum(win ** 2)


def _highpass_std(x: np.ndarray, dt: float, f0: float = 15.0) -> float:
    X = np.fft.rfft(x - np.mean(x))
    X[np.fft.rfftfreq(len(x), dt) <= f0] = 0.0
    return float(np.std(np.fft.irfft(X, len(x))))


def trial_rows(path: str, method: str) -> Tuple[List[dict], dict]:
    rows, series = [], {}
    with h5py.File(path, "r") as f:
        ws = leading_wheelset(f)
        t = f["/time"][:]
        sel = window(f, ws, TRIAL)
        w = f["/contact"][ws]["right"]
        idx0 = np.where(sel)[0]
        for dec in (1, TRIAL_DECIMATE):
            idx = idx0[::dec]
            dt = (t[1] - t[0]) * dec
            Y = w["Y"][:][idx] / 1e3
            Q = w["Q"][:][idx] / 1e3
            y = f["/bodies"][ws]["y"][:][idx] * 1e3
            reg = w["regime"][:][idx].astype(int)
            cnt = w["contact_count"][:][idx]
            sw = _switches(reg)
            F, P = _spectrum(Q, dt)
            FY, PY = _spectrum(Y, dt)
            hi = F > 15.0
            lo = F > 0.5
            rows.append(dict(
                method=method, output_ms=dt * 1e3, samples=len(idx),
                Y_mean=float(np.mean(Y)), Y_std=float(np.std(Y)), Y_min=float(np.min(Y)),
                Y_max=float(np.max(Y)), Q_mean=float(np.mean(Q)), Q_std=float(np.std(Q)),
                y_hf_std_mm=_highpass_std(y, dt), Y_hf_std=_highpass_std(Y, dt),
                two_point=float(np.mean(reg == 1)), patches_2plus=float(np.mean(cnt >= 2)),
                switches_per_s=sw / (len(idx) * dt), mean_run_samples=len(idx) / max(sw, 1),
                Y_peak_hz=float(FY[hi][np.argmax(PY[hi])]),
                peak_hz=float(F[hi][np.argmax(P[hi])]),
                hf_share=float(np.sum(P[hi]) / np.sum(P[lo]))))
            series[dec] = dict(F=F, P=P, FY=FY, PY=PY)
        series["t"] = t[idx0]
        series["Y"] = w["Y"][:][idx0] / 1e3
        series["reg"] = w["regime"][:][idx0]
    return rows, series


def write_csv(path: str, rows: List[dict]) -> None:
    if not rows:
        return
    keys = list(rows[0])
    for r in rows[1:]:
        keys += [k for k in r if k not in keys]
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=keys)
        w.writeheader()
        for r in rows:
            w.writerow({k: (f"{v:.6g}" if isinstance(v, float) else v) for k, v in r.items()})


def trial_figure(series: Dict[str, dict], path: str) -> None:
    from .style import RUN_COLORS, A4_WIDTH_IN, DPI
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(4, 1, figsize=(A4_WIDTH_IN, 9.5))
    for k, m in enumerate(METHODS):
        s = series.get(m)
        if not s:
            continue
        t0 = s["t"][0] + 6.0
        sel = (s["t"] >= t0) & (s["t"] <= t0 + 1.0)
        ax[0].plot(s["t"][sel], s["Y"][sel], color=RUN_COLORS[k], lw=0.8, label=m.upper())
        ax[1].semilogy(s[1]["FY"], s[1]["PY"], color=RUN_COLORS[k], lw=0.8, label=m.upper())
        ax[2].semilogy(s[1]["F"], s[1]["P"], color=RUN_COLORS[k], lw=0.8, label=m.upper())
        d = s[TRIAL_DECIMATE]
        ax[3].semilogy(d["F"], d["P"], color=RUN_COLORS[k], lw=0.8, label=m.upper())
    ax[0].set_xlabel("t [s]")
    ax[0].set_ylabel("Y [kN]")
    ax[0].set_title("Leading wheelset, outer wheel: Y over 1 s of the curve (2 ms output)",
                    fontsize=9)
    ax[1].set_title("PSD of Y, 2 ms output (Nyquist 250 Hz)", fontsize=9)
    ax[2].set_title("PSD of Q, 2 ms output (Nyquist 250 Hz)", fontsize=9)
    ax[3].set_title("PSD of Q at the trial's 10 ms output (Nyquist 50 Hz: 100 - f aliases)",
                    fontsize=9)
    for a in ax[1:]:
        a.set_xlabel("f [Hz]")
        a.set_ylabel("kN$^2$/Hz")
    ax[1].set_xlim(0, 150)
    ax[2].set_xlim(0, 150)
    ax[3].set_xlim(0, 50)
    for a in ax:
        a.grid(alpha=0.3)
        a.legend(fontsize=7, loc="upper right")
    fig.tight_layout()
    fig.savefig(path, dpi=DPI)
    plt.close(fig)


def case3_figure(files: Dict[str, str], path: str) -> None:
    from .style import RUN_COLORS, RUN_STYLES, A4_WIDTH_IN, DPI
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(2, 1, figsize=(A4_WIDTH_IN, 5.5), sharex=True)
    for k, m in enumerate(METHODS):
        if m not in files:
            continue
        with h5py.File(files[m], "r") as f:
            ws = leading_wheelset(f)
            s = f["/bodies"][ws]["s"][:]
            # The elastic reference on top, solid.
            style = dict(color=RUN_COLORS[k], lw=1.0 if m == "elastic" else 0.7,
                         ls="-" if m == "elastic" else RUN_STYLES[k],
                         zorder=3 if m == "elastic" else 2, label=m.upper())
            ax[0].plot(s, f["/bodies"][ws]["y"][:] * 1e3, **style)
            ax[1].plot(s, f["/contact"][ws]["right"]["Y"][:] / 1e3, **style)
    ax[0].set_ylabel("ws1 y [mm]")
    ax[1].set_ylabel("ws1 right wheel Y [kN]")
    ax[1].set_xlabel("s [m]")
    ax[0].set_title("Case 3 (R = 500 m, ORE B176 low, 20 m/s)", fontsize=9)
    for a in ax:
        a.grid(alpha=0.3)
        a.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(path, dpi=DPI)
    plt.close(fig)


def climb_figure(files: Dict[str, str], path: str) -> None:
    """Wheel climb: Y and Q of the leading outer wheel and Y/Q against Nadal's limit over the
    last 2 s."""
    from .style import RUN_COLORS, RUN_STYLES, A4_WIDTH_IN, DPI
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(3, 1, figsize=(A4_WIDTH_IN, 7.0), sharex=True)
    for k, m in enumerate(METHODS):
        if m not in files:
            continue
        with h5py.File(files[m], "r") as f:
            ws = leading_wheelset(f)
            t = f["/time"][:]
            sel = t >= t[-1] - 2.0
            w = f["/contact"][ws]["right"]
            style = dict(color=RUN_COLORS[k], lw=1.0 if m == "elastic" else 0.8,
                         ls="-" if m == "elastic" else RUN_STYLES[k], label=m.upper())
            Y, Q = w["Y"][:][sel] / 1e3, w["Q"][:][sel] / 1e3
            ax[0].plot(t[sel], Y, **style)
            ax[1].plot(t[sel], Q, **style)
            ax[2].plot(t[sel], Y / np.where(Q > 1, Q, np.nan), **style)
    mu, gamma = 0.5, np.radians(70.0)
    nadal = (np.tan(gamma) - mu) / (1 + mu * np.tan(gamma))
    ax[2].axhline(nadal, color="k", lw=0.8, ls=":", label=f"Nadal {nadal:.2f} (70 deg, mu 0.5)")
    ax[0].set_ylabel("Y [kN]")
    ax[1].set_ylabel("Q [kN]")
    ax[2].set_ylabel("Y/Q")
    ax[2].set_xlabel("t [s]")
    ax[0].set_title("Wheel climb (R = 100 m, 5 m/s, mu = 0.5): leading outer wheel", fontsize=9)
    for a in ax:
        a.grid(alpha=0.3)
        a.legend(fontsize=7, loc="upper right")
    fig.tight_layout()
    fig.savefig(path, dpi=DPI)
    plt.close(fig)


def main(argv=None) -> int:
    from .common import parser
    ap = parser("three-way", __doc__.split("\n\n")[0])
    ap.add_argument("outdir")
    a = ap.parse_args(argv)
    d = a.outdir
    path = os.path.join(d, "summary_cases.csv")
    if not os.path.exists(path):
        print(f"railbench three-way: {path} not found (run the study first)", file=sys.stderr)
        return 1
    with open(path, newline="") as f:
        cases = list(csv.DictReader(f))
    by_scen: Dict[str, Dict[str, str]] = {}
    steady, extremes, cost = [], [], []
    for c in cases:
        scen, method = split_label(c["label"])
        fpath = c.get("file") or ""
        if fpath and not os.path.isabs(fpath):
            fpath = os.path.join(d, fpath)
        if not fpath or not os.path.exists(fpath):
            fpath = os.path.join(d, c["case"] + "_r0.h5")
        if not os.path.exists(fpath):
            print(f"railbench three-way: {c['label']}: no result file", file=sys.stderr)
            continue
        by_scen.setdefault(scen, {})[method] = fpath
        with h5py.File(fpath, "r") as f:
            base = dict(scenario=scen, method=method)
            ok = _text(f["/stats"].attrs.get("status", "")) == "ok"
            s = steady_row(f, scen) if ok else None
            if s:
                steady.append({**base, **s})
            extremes.append({**base, **extremes_row(f)})
            cost.append({**base, **cost_row(f)})
    dynamic = []
    for scen, files in by_scen.items():
        if scen in ("case3", TRIAL, "stiff_flange"):
            dynamic += dynamic_rows({m: p for m, p in files.items() if m in METHODS}, scen)
    write_csv(os.path.join(d, "three_way_steady.csv"), steady)
    write_csv(os.path.join(d, "three_way_extremes.csv"), extremes)
    write_csv(os.path.join(d, "three_way_dynamic.csv"), dynamic)
    write_csv(os.path.join(d, "three_way_cost.csv"), cost)
    constants = []
    for scen, files in by_scen.items():
        if "elastic" in files:
            with h5py.File(files["elastic"], "r") as f:
                constants.append(dict(scenario=scen, **elastic_constants(f)))
    write_csv(os.path.join(d, "three_way_constants.csv"), constants)
    if TRIAL in by_scen:
        trial, series = [], {}
        for m, p in by_scen[TRIAL].items():
            rows, ser = trial_rows(p, m)
            trial += rows
            if m in METHODS:
                series[m] = ser
        write_csv(os.path.join(d, "three_way_trial.csv"), trial)
        trial_figure(series, os.path.join(d, "study_trial.png"))
    if "case3" in by_scen:
        case3_figure(by_scen["case3"], os.path.join(d, "study_case3.png"))
    if "wheel_climb" in by_scen:
        climb_figure(by_scen["wheel_climb"], os.path.join(d, "study_climb.png"))
    print(f"railbench three-way: {d}/three_way_*.csv")
    return 0


if __name__ == "__main__":
    sys.exit(main())
