"""Generated blocks of docs/three_way.md, from the CSVs `plots/rbplot three-way` writes into
OUT_DIR/three_way (`./wb studies --only three_way`), and the instruction counts of
`plots/rbplot effects-instructions` (study_three_way_instructions.csv) when they were measured.
"""
from __future__ import annotations

import os
from typing import Dict, List

from .docs_blocks import fmt, missing, num, read_csv, table

FOLDER = "three_way"
INSTRUCTIONS = "study_three_way_instructions.csv"
METHOD_NAMES = {"kec": "KEC", "lut": "LUT", "lut K=1e10": "LUT K=1e10", "elastic": "elastic"}
SCENARIOS = {
    "case1 R=300": "case 1, R = 300 m", "case1 R=500": "case 1, R = 500 m",
    "case1 R=700": "case 1, R = 700 m", "case1 R=900": "case 1, R = 900 m",
    "case2": "case 2 (R = 500 m, smooth)", "case3": "case 3 (R = 500 m, ORE B176 low)",
    "sharp_curve": "sharp curve (R = 150 m, 16 m/s)",
    "wheel_climb": "wheel climb (R = 100 m, 5 m/s, mu = 0.5)",
    "stiff_flange": "stiff flange (R = 200 m, 15 m/s, ORE B176 high)",
    "trial_r300": "trial (R = 300 m, 100 mm cant, ORE B176 high, 20.9 m/s)",
}


def _m(r: dict) -> str:
    return METHOD_NAMES.get(r["method"], r["method"])


def _s(r: dict) -> str:
    scen = r["scenario"]
    base, _, extra = scen.partition(" ")
    return SCENARIOS.get(scen) or (SCENARIOS.get(base, base) + (f", {extra}" if extra else ""))


def _f(r: dict, k: str, spec: str) -> str:
    return fmt(num(r.get(k)), spec)


def _pct(r: dict, k: str) -> str:
    v = num(r.get(k))
    return "–" if v is None or v != v else f"{100 * v:.0f} %"


def steady_block(d: str) -> str:
    rows = read_csv(os.path.join(d, "three_way_steady.csv"))
    if not rows:
        return missing(f"{d}/three_way_steady.csv (./wb studies --only three_way)")
    body = []
    for r in rows:
        body.append([_s(r), _m(r), r["window"], _f(r, "y_mm", "{:.2f}"),
                     _f(r, "yaw_mrad", "{:.2f}"), _f(r, "Y_kN", "{:.1f}"),
                     _f(r, "Q_kN", "{:.1f}"), _f(r, "YQ", "{:.3f}"), _f(r, "Y_std_kN", "{:.2f}"),
                     _pct(r, "two_point"), _pct(r, "flange_N_share"), _f(r, "patches", "{:.2f}"),
                     _f(r, "angle_rad", "{:.3f}")])
    return ("Means over each scenario's steady window; the leading wheelset (case 1: the single "
            "wheelset) and its outer (right) wheel. Y toward the track centre, Q upward on the "
            "wheel (EN 14363, per wheel the sum over its patches); \"two-point\": share of output "
            "samples with a tread and a flange patch (regime 1); \"flange N\": the flange patches' "
            "share of the normal force; \"patches\": mean number of patches (KEC: 2 inside its "
            "tread-flange band, both band ends, 1 outside); \"angle\": contact angle of the strongest patch.\n\n" +
            table(["scenario", "method", "window", "ws y [mm]", "ws yaw [mrad]", "Y [kN]",
                   "Q [kN]", "Y/Q", "std Y [kN]", "two-point", "flange N", "patches",
                   "angle [rad]"], body))


def _no_contact(r: dict) -> str:
    n = int(num(r.get("no_contact_samples"), 0) or 0)
    if n == 0:
        return "0"
    return f"{n} (first at t = {num(r.get('no_contact_first_t')):.2f} s)"


def extremes_block(d: str) -> str:
    rows = read_csv(os.path.join(d, "three_way_extremes.csv"))
    if not rows:
        return missing(f"{d}/three_way_extremes.csv (./wb studies --only three_way)")
    body = []
    for r in rows:
        if r["scenario"] not in ("stiff_flange", "sharp_curve", "wheel_climb", "trial_r300",
                                 "case3"):
            continue
        status = r["status"] + (f": {r['message'][:70]}" if r["status"] != "ok" else "")
        body.append([_s(r), _m(r), status, _f(r, "t_reached", "{:.3f}"),
                     _f(r, "y_max_mm", "{:.2f}"), _f(r, "Y_max_kN", "{:.1f}"),
                     _f(r, "Q_max_kN", "{:.1f}"), _f(r, "YQ_max", "{:.2f}"),
                     _f(r, "flange_N_max_kN", "{:.1f}"), _no_contact(r), _f(r, "Q_min_any_kN", "{:.1f}"),
                     _pct(r, "two_point")])
    return ("Whole runs (a stopped run: up to its stop). Leading wheelset and its outer wheel; "
            "\"flange N\" the largest normal force on that wheel's flange patches (LUT: the Hertz "
            "flange force; KEC: the flange-side band end; elastic: its patches classed as flange), "
            "\"no contact\": output samples in which some wheel of the vehicle has no patch at "
            "all (elastic only; a constraint keeps every wheel on its rail); \"min Q\": the "
            "smallest wheel load of any wheel of the vehicle.\n\n"
            + table(["scenario", "method", "status", "t reached [s]", "max abs y [mm]",
                     "max Y [kN]", "max Q [kN]", "max Y/Q", "max flange N [kN]",
                     "no contact [samples]", "min Q any wheel [kN]", "two-point"], body))


def dynamic_block(d: str) -> str:
    rows = read_csv(os.path.join(d, "three_way_dynamic.csv"))
    if not rows:
        return missing(f"{d}/three_way_dynamic.csv (./wb studies --only three_way)")
    body = []
    for r in rows:
        body.append([_s(r), _m(r), f"{num(r['t_end']):.2f}",
                     f"{num(r['y_rms']):.3f} / {num(r['y_max']):.2f}",
                     f"{num(r['y_rms_before_curve']):.3f} / {num(r['y_rms_curve']):.3f}",
                     f"{num(r['Y_rms']):.2f} / {num(r['Y_max']):.1f}",
                     f"{num(r['Q_rms']):.2f} / {num(r['Q_max']):.1f}",
                     f"{num(r['y_ref_rms']):.3f} / {num(r['Y_ref_rms']):.2f} / "
                     f"{num(r['Q_ref_rms']):.2f}"])
    return ("Differences from the elastic run on the same output times, over the whole run "
            "(0 to the end of the shorter run): rms / max of the leading wheelset's y and of "
            "its outer wheel's Y and Q; the last column is the elastic signal's own rms about "
            "its mean, the scale the differences compare with.\n\n" +
            table(["scenario", "method vs elastic", "up to t [s]", "y rms / max [mm]",
                   "y rms before the curve / in the curve [mm]",
                   "Y rms / max [kN]", "Q rms / max [kN]",
                   "elastic rms of y [mm] / Y / Q [kN]"], body))


def _instructions(d: str) -> Dict[str, dict]:
    return {r["label"]: r for r in read_csv(os.path.join(d, INSTRUCTIONS))}


def cost_block(d: str) -> str:
    rows = read_csv(os.path.join(d, "three_way_cost.csv"))
    if not rows:
        return missing(f"{d}/three_way_cost.csv (./wb studies --only three_way)")
    ins = _instructions(d)
    body = []
    for r in rows:
        label = f"{r['scenario']} | {r['method']}"
        i = ins.get(label)
        ipe = num(i.get("instructions_per_eval")) if i else None
        body.append([_s(r), _m(r), _f(r, "t_reached", "{:.2f}"), _f(r, "cpu_s", "{:.2f}"),
                     _f(r, "real_time", "{:.1f}x"), r["rhs_evals"], _f(r, "us_per_eval", "{:.1f}"),
                     _pct(r, "contact_share"),
                     fmt(ipe / 1e3 if ipe else None, "{:.1f} k")])
    note = ""
    if ins:
        durs = sorted({i.get("duration", "") for i in ins.values()} - {""})
        note = (" Instructions per evaluation: callgrind over the first "
                f"{', '.join(durs) or 'few'} s of the run (`plots/rbplot effects-instructions`, "
                "the integration only, result-file flushes excluded): case 3 on its tangent "
                "(single-point tread contact), the trial on its tangent and the start of its "
                "transition, the sharp curve through its transition with the leading wheelset "
                "on its flange from about 0.5 s.")
    else:
        note = " Instructions per evaluation not measured in this run (column empty)."
    return ("One run per case on a shared 2-core machine (CPU times scatter by 10-40 %). "
            "Evaluations include the finite-difference Jacobian columns (ABM: the Jacobians of "
            "the exponential treatment of the stiff components); \"contact share\" is the "
            "contact-patch stage's share of the rhs time (`/stats/stage_share`, 1 evaluation in "
            "64 timed)." + note + "\n\n" +
            table(["scenario", "method", "simulated [s]", "CPU [s]", "x real time", "rhs evals",
                   "us / eval", "contact share", "instructions / eval"], body))


def trial_block(d: str) -> str:
    rows = read_csv(os.path.join(d, "three_way_trial.csv"))
    if not rows:
        return missing(f"{d}/three_way_trial.csv (./wb studies --only three_way)")
    body = []
    for r in rows:
        body.append([_m(r), f"{num(r['output_ms']):g}", r["samples"],
                     _f(r, "Y_mean", "{:.1f}"), _f(r, "Y_std", "{:.2f}"),
                     f"{num(r['Y_min']):.1f} .. {num(r['Y_max']):.1f}", _f(r, "Q_mean", "{:.1f}"),
                     _f(r, "Q_std", "{:.2f}"), _pct(r, "two_point"), _pct(r, "patches_2plus"),
                     _f(r, "switches_per_s", "{:.1f}"), _f(r, "mean_run_samples", "{:.1f}"),
                     _f(r, "y_hf_std_mm", "{:.3f}"), _f(r, "Y_hf_std", "{:.2f}"),
                     _f(r, "Y_peak_hz", "{:.1f}"), _f(r, "peak_hz", "{:.1f}"),
                     _pct(r, "hf_share")])
    return ("The outer (right) wheel of the leading wheelset over s = 110..400 m (the whole wagon "
            "in the full-cant curve), at the run's 2 ms output and at every 5th sample (the "
            "trial's 10 ms). \"two-point\": regime 1 (a tread and a flange patch); \"2+ "
            "patches\": `contact_count` >= 2 (the KEC counts both ends of its band inside it); "
            "\"switches\": changes of the regime per second, and the mean number of output "
            "samples between them; \"> 15 Hz\" std: the standard deviation of the wheelset's y "
            "and of Y above 15 Hz; \"peak\": the largest peak of the spectrum (Welch, 1 s "
            "segments) above 15 Hz; \"Q var > 15 Hz\": the share of Q's variance (above "
            "0.5 Hz) above 15 Hz.\n\n" +
            table(["method", "output [ms]", "samples", "Y mean [kN]", "std Y [kN]",
                   "Y range [kN]", "Q mean [kN]", "std Q [kN]", "two-point", "2+ patches",
                   "switches / s", "samples between switches", "y std > 15 Hz [mm]",
                   "Y std > 15 Hz [kN]", "Y peak [Hz]", "Q peak [Hz]", "Q var > 15 Hz"], body) +
            "\n\n![trial](figures/three_way_trial.png)")


def constants_block(d: str) -> str:
    rows = read_csv(os.path.join(d, "three_way_constants.csv"))
    if not rows:
        return missing(f"{d}/three_way_constants.csv (./wb studies --only three_way)")
    body = [[_s(r), _f(r, "static_load_kN", "{:.2f}"), _f(r, "static_approach_um", "{:.1f}"),
             _f(r, "hertz_K", "{:.3g}"), _f(r, "vertical_hz", "{:.0f}"),
             _f(r, "damping_ratio", "{:.2g}"), _f(r, "damping_s_per_m", "{:.2f}"),
             _f(r, "sample_step_mm", "{:.2g}"), _f(r, "flange_height_mm", "{:.1f}")]
            for r in rows]
    return ("The elastic method's constants of each run (`/contact` attributes `elastic_*`); "
            "\"K tread\" = N0 / delta0^1.5, the Hertz constant of the static tread contact that "
            "they imply.\n\n" +
            table(["scenario", "static wheel load N0 [kN]", "static approach delta0 [um]",
                   "K tread [N/m^1.5]", "vertical frequency [Hz]", "damping ratio",
                   "Hunt-Crossley c_d [s/m]", "search step [mm]", "flange height [mm]"], body))


def three_way_blocks(outdir: str) -> Dict[str, str]:
    d = os.path.join(outdir, FOLDER)
    return {"three_way_steady": steady_block(d), "three_way_extremes": extremes_block(d),
            "three_way_dynamic": dynamic_block(d), "three_way_cost": cost_block(d),
            "three_way_trial": trial_block(d),
            "three_way_constants": constants_block(d)}
