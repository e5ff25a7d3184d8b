"""Generated blocks of docs/stability.md: the Manchester wagon's linear (`workbench modes`) and
nonlinear (`workbench critical-speed`) critical speeds, run by `./wb studies --only stability`
into OUT_DIR/stability_*, and the single-wheelset verification the tests write into
BUILD/stability/*.csv (tests/wickens).
"""
from __future__ import annotations

import os
from typing import Dict, List, Optional, Tuple

from .docs_blocks import fmt, missing, num, read_csv, table

# (folder, contact, what differs from the wagon's defaults)
WAGON = (("stability_kec", "KEC", "Manchester wagon 1 as published (Kpx = 31.4 MN/m)"),
         ("stability_lut", "LUT", "Manchester wagon 1 as published (Kpx = 31.4 MN/m)"))
METHOD = (
    ("stability_kec", "KEC", "the wagon (reference of the rows below)"),
    ("stability_kpx15_kec", "KEC", "primary longitudinal stiffness Kpx = 15 MN/m"),
    ("stability_kpx7p5_kec", "KEC", "Kpx = 7.5 MN/m"),
    ("stability_kecspin", "KEC", "prescribed wheelset spin (theta_dot = V / r0)"),
    ("stability_kecbdf", "KEC", "ramp integrated with BDF instead of dopri5"),
    ("stability_kecabm", "KEC", "ramp integrated with ABM, h = 0.25 ms"),
    ("stability_lut", "LUT", "the wagon, LUT K = 1e10 N/m^1.5 (reference of the rows below)"),
    ("stability_kpx15_lut", "LUT", "Kpx = 15 MN/m"),
    ("stability_kpx7p5_lut", "LUT", "Kpx = 7.5 MN/m"),
    ("stability_lutK1e9", "LUT", "flange stiffness K = 1e9 N/m^1.5"),
    ("stability_lutK1e11", "LUT", "flange stiffness K = 1e11 N/m^1.5"),
)
FOLDERS = tuple(sorted({f for f, _, _ in METHOD}))


def _attrs(path: str) -> Optional[Dict[str, object]]:
    if not os.path.exists(path):
        return None
    import h5py  # only when there is something to read
    with h5py.File(path, "r") as f:
        g = f["modes"] if "modes" in f else f
        out = {}
        for k, v in g.attrs.items():
            out[k] = v.decode() if isinstance(v, bytes) else v
        if "runs" in f:
            cpu = evals = 0.0
            for r in f["runs"].values():
                cpu += float(r.attrs.get("cpu_s", 0.0))
                evals += float(r.attrs.get("rhs_evals", 0.0))
            out["runs"], out["runs_cpu_s"], out["runs_rhs_evals"] = len(f["runs"]), cpu, evals
        return out


def _speed(a: Optional[dict], key: str) -> str:
    v = None if a is None else num(a.get(key))
    return fmt(v, "{:.1f}")


def _cases(outdir: str, folder: str) -> Tuple[Optional[dict], Optional[dict]]:
    d = os.path.join(outdir, folder)
    return _attrs(os.path.join(d, "modes.h5")), _attrs(os.path.join(d, "critical_speed.h5"))


def wagon_block(outdir: str) -> str:
    """Linear and nonlinear critical speeds of the wagon with KEC and LUT, with their cost, and
    the figures of both analyses."""
    rows = []
    for folder, contact, _ in WAGON:
        modes, crit = _cases(outdir, folder)
        if modes is None or crit is None:
            return missing(f"{outdir}/{folder}/modes.h5 and critical_speed.h5 "
                           "(./wb studies --only stability)")
        bracket = f"{_speed(crit, 'bracket_low')}..{_speed(crit, 'bracket_high')}"
        ratio = (num(crit.get("critical_speed_ramp")) or 0.0) / (num(modes.get(
            "critical_speed_value")) or float("nan"))
        unc = num(modes.get("critical_speed_step_uncertainty"))
        linear = _speed(modes, "critical_speed_value") + (
            f" ± {fmt(unc, '{:.2g}')}" if unc is not None and unc >= 0 else "")
        rows.append([contact, linear,
                     _speed(crit, "critical_speed_ramp"),
                     f"{_speed(crit, 'critical_speed_bisection')} ({bracket})",
                     fmt(ratio, "{:.2f}"), _speed(crit, "start_speed"),
                     f"{fmt(num(modes.get('cpu_s')), '{:.2f}')} s / "
                     f"{int(num(modes.get('rhs_evaluations'), 0)):,}",
                     f"{crit.get('runs', 0)} runs, {fmt(crit.get('runs_cpu_s'), '{:.1f}')} s / "
                     f"{int(crit.get('runs_rhs_evals', 0)):,}"])
    out = [table(["contact", "linear [m/s] (± finite-difference step)", "nonlinear ramp-down [m/s]",
                  "nonlinear bisection [m/s] (bracket)", "ramp / linear", "ramp start [m/s]",
                  "modes: CPU / rhs evals (23 speeds + refinement)",
                  "critical-speed: CPU / rhs evals"], rows)]
    for folder, contact, _ in WAGON:
        out.append(f"\n{contact}: damping of the modes against speed, root locus, bifurcation "
                   "diagram\n")
        out.append(f"![{contact} damping versus speed](figures/{folder}_modes_damping.png)")
        out.append(f"![{contact} root locus](figures/{folder}_modes_root_locus.png)")
        out.append(f"![{contact} bifurcation diagram](figures/{folder}_critical_speed.png)")
    return "\n".join(out)


def _modes_at(outdir: str, folder: str, speed: float) -> List[dict]:
    rows = read_csv(os.path.join(outdir, folder, "modes.csv"))
    return [r for r in rows if abs(float(r["speed_m_s"]) - speed) < 1e-6]


def modes_block(outdir: str, speed: float = 20.0) -> str:
    """The oscillatory modes below 20 Hz at `speed`, one row per label (the first of the pairs
    that the two bogies and their wheelsets give), KEC and LUT side by side."""
    per = {}
    for folder, contact, _ in WAGON:
        rows = _modes_at(outdir, folder, speed)
        if not rows:
            return missing(f"{outdir}/{folder}/modes.csv (./wb studies --only stability)")
        seen = {}
        for r in rows:
            f = float(r["frequency_hz"])
            # Oscillatory modes only: the creep-dominated real eigenvalues (and pairs split off
            # them by round-off, zeta within 1e-3 of 1) have no frequency to show.
            if float(r["im_1_s"]) <= 0.0 or f > 20.0 or float(r["damping_ratio"]) > 0.999:
                continue
            prev = seen.get(r["label"])
            if prev is None or float(r["damping_ratio"]) < float(prev["damping_ratio"]):
                seen[r["label"]] = r
        per[contact] = seen
    labels = sorted({lab for s in per.values() for lab in s},
                    key=lambda lab: min(float(s[lab]["frequency_hz"]) for s in per.values()
                                        if lab in s))
    body = []
    for lab in labels:
        line = [lab]
        for contact in ("KEC", "LUT"):
            r = per[contact].get(lab)
            line += (["–", "–"] if r is None else
                     [fmt(float(r["frequency_hz"]), "{:.2f}"),
                      fmt(float(r["damping_ratio"]), "{:.3f}")])
        body.append(line)
    return table(["mode (least damped of its kind)", "KEC f [Hz]", "KEC zeta", "LUT f [Hz]",
                  "LUT zeta"], body)


def method_block(outdir: str) -> str:
    """How the critical speeds move with the primary yaw stiffness, the wheelset spin model, the
    integrator and the flange stiffness."""
    body = []
    for folder, contact, what in METHOD:
        modes, crit = _cases(outdir, folder)
        if crit is None:
            body.append([contact, what, "–", "not run", "–", "–"])
            continue
        findings = (crit.get("findings") or "").strip()
        # A sustained small-amplitude oscillation (not stable, below the threshold) is said too.
        caveats = (crit.get("caveats") or "").strip()
        body.append([contact, what, _speed(modes, "critical_speed_value"),
                     _speed(crit, "critical_speed_ramp"),
                     _speed(crit, "critical_speed_bisection"),
                     f"{crit.get('runs', 0)} runs, {fmt(crit.get('runs_cpu_s'), '{:.1f}')} s"
                     + ("; " + findings.splitlines()[0][:160] if findings else "")
                     + ("; caveat: " + caveats.splitlines()[0][:160] if caveats else "")])
    if all(r[3] == "not run" for r in body):
        return missing(f"{outdir}/stability_*/critical_speed.h5 (./wb studies --only stability)")
    return table(["contact", "variant", "linear [m/s]", "ramp-down [m/s]", "bisection [m/s]",
                  "critical-speed cost; findings"], body)


def verification_block(build: str) -> str:
    """Single wheelset: our linear critical speed against Wickens' closed form and the extended
    2-dof model, the conicity scaling and the kinematic (Klingel) frequency."""
    d = os.path.join(build, "stability")
    w, c, k = (read_csv(os.path.join(d, n + ".csv")) for n in ("wickens", "conicity", "klingel"))
    if not (w and c and k):
        return missing(f"{d}/{{wickens,conicity,klingel}}.csv (ctest -R Wickens)")
    out = ["Critical speed of the single wheelset (k_y = 2 MN/m, k_psi = 0.8 MN m/rad, Kalker "
           "linear creep):", ""]
    rows = []
    for r in w:
        v = float(r["v_ours"])
        rows.append([r["method"].upper(), "1:" + r["inclination"], fmt(num(r["lambda"]), "{:.4f}"),
                     fmt(v, "{:.2f}"), fmt(num(r["v_wickens"]), "{:.2f}"),
                     fmt(100 * (v / float(r["v_wickens"]) - 1), "{:+.2f} %"),
                     fmt(100 * (v / float(r["v_wickens_kgrav_kspin"]) - 1), "{:+.2f} %"),
                     fmt(num(r["v_extended_2dof"]), "{:.2f}"),
                     fmt(100 * (v / float(r["v_extended_2dof"]) - 1), "{:+.2f} %"),
                     r["rhs_evals"]])
    out.append(table(["contact", "inclination", "lambda", "ours [m/s]", "Wickens [m/s]",
                      "ours vs Wickens", "vs Wickens + k_grav + k_spin", "extended 2-dof [m/s]",
                      "ours vs extended", "rhs evals"], rows))
    out += ["", "Conicity through the rail inclination (V_c sqrt(lambda) should be constant):",
            ""]
    rows = []
    for r in c:
        rows.append([r["method"].upper(), "1:" + r["inclination"], fmt(num(r["lambda"]), "{:.5f}"),
                     f"{fmt(num(r['lambda_1um']), '{:.5f}')} / "
                     f"{fmt(num(r['lambda_0p1mm']), '{:.5f}')}",
                     fmt(num(r["v_ours"]), "{:.2f}"), fmt(num(r["v_wickens"]), "{:.2f}"),
                     fmt(num(r["v_sqrt_lambda"]), "{:.3f}")])
    out.append(table(["contact", "inclination", "lambda (10 um)", "lambda (1 um / 0.1 mm)",
                      "V_c ours [m/s]", "V_c Wickens [m/s]", "V_c sqrt(lambda) ours"], rows))
    for method in sorted({r["method"] for r in c}):
        s = [float(r["v_sqrt_lambda"]) for r in c if r["method"] == method]
        v = [float(r["v_ours"]) for r in c if r["method"] == method]
        out.append(f"\n{method.upper()}: V_c sqrt(lambda) varies by "
                   f"{100 * (max(s) / min(s) - 1):.2f} % while V_c varies by a factor of "
                   f"{max(v) / min(v):.2f}.")
    out += ["", "Free wheelset (no springs): the kinematic oscillation at 5 m/s against "
            "Klingel's omega = V sqrt(lambda / (r0 l0)) and its 3-D form (divided by sqrt(rho), "
            "rho = 1 + r0 d(roll)/dy):", ""]
    rows = []
    for r in k:
        om = float(r["omega_5ms"])
        rows.append([r["method"].upper(), "1:" + r["inclination"], fmt(om, "{:.4f}"),
                     fmt(num(r["omega_klingel"]), "{:.4f}"),
                     fmt(100 * (om / float(r["omega_klingel"]) - 1), "{:+.2f} %"),
                     fmt(100 * (om / float(r["omega_klingel_corrected"]) - 1), "{:+.2f} %"),
                     fmt(num(r["zeta_5ms"]), "{:.4f}"), fmt(num(r["re_20ms"]), "{:+.3f}")])
    out.append(table(["contact", "inclination", "omega at 5 m/s [rad/s]", "Klingel [rad/s]",
                      "vs Klingel", "vs 3-D Klingel", "zeta at 5 m/s", "Re at 20 m/s [1/s]"],
                     rows))
    return "\n".join(out)


def stability_blocks(outdir: str, build: str) -> Dict[str, str]:
    return {"stability_wagon": wagon_block(outdir), "stability_modes": modes_block(outdir),
            "stability_method": method_block(outdir),
            "stability_verification": verification_block(build)}
