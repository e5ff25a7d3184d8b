"""The checks of a run's result file, shared by `workbench stress` (stress.py) and the hard-case
suite (tests/hard/hard_cases.py; docs/hard_cases.md, docs/stress.md):

* the result file exists and /stats/status agrees with the exit code (0 ok, 2 failed); after a
  failure the message names the failure time and distance, t_reached < t_end and the partial
  time history ends at or before t_reached;
* no NaN/Inf in any dataset or numeric attribute;
* plausibility bounds (BOUNDS): wheelset |y|, wheel normal forces, flange forces and indentation,
  |Y/Q|; required of a finished run, noted for a failed run's partial results.
"""
import math
import os

import h5py
import numpy as np

# Plausibility bounds. |y| of a wheelset relative to the centre of its rails (its lateral
# displacement less the rails' at its s: alignment irregularities move the rails, and the wheelset
# follows them): flange clearance of S1002/60E1 (~ 7-10 mm, the LUT flange is reached at
# y ~ -10 mm) plus a few mm; the LUT table ends at 18 mm. Wheel loads: static
# ~ 54 kN (wagon), 45 kN (single wheelset); 10x static is not plausible. Y/Q: the Nadal limit of a
# 70 deg flange is 1.5 at mu = 0.2364 and 0.95 at mu = 0.5; short impact peaks may exceed it, 4 may
# not.
BOUNDS = {"y_mm": 14.0, "normal_kN": 600.0, "lift_kN": 30.0, "flange_kN": 800.0,
          "indent_mm": 1.0, "yq": 4.0}


def attr(g, name, default=None):
    if name not in g.attrs:
        return default
    v = g.attrs[name]
    if isinstance(v, bytes):
        return v.decode()
    if isinstance(v, np.ndarray) and v.shape == ():
        return v.item()
    return v


def rail_centre(f, path):
    """(s, lateral displacement of the centre of the rails) [m] of the run's track
    irregularities (in the file, or in the track store it references), None without any."""
    g = f["/track"] if "/track" in f else None
    if g is None:
        return None
    store = None
    if "stored_in" in g.attrs:
        from .result import _open_stored_track
        store, g = _open_stored_track(path, g)
    try:
        if "irregularities" not in g:
            return None
        ig = g["irregularities"]
        if "left_y" in ig and "right_y" in ig:
            centre = 0.5 * (ig["left_y"][()] + ig["right_y"][()])
        else:
            centre = ig["alignment"][()]
        return np.asarray(ig["s"][()], float), np.asarray(centre, float)
    finally:
        if store is not None:
            store.close()


def check_file(path, rc, bounds, t_end_hint):
    """rc: the run's exit code (0 or 2); t_end_hint: its end time [s], 0 or None when unknown
    (a run given by distance). Returns (row fields, list of problems, list of notes).
    Plausibility is required of a finished run; in a failed run's partial results the last outputs before the failure may show
    the divergence that caused it (e.g. RK4 at 1 ms into the stiff flange): noted, not failed."""
    problems = []
    implausible = []
    row = {}
    with h5py.File(path, "r") as f:
        st = f["/stats"]
        status = attr(st, "status", "")
        msg = attr(st, "message", "")
        row["status"] = status
        row["message"] = msg
        for k in ("failure_kind", "failure_reason", "failure_body", "failure_t", "failure_s"):
            row[k] = attr(st, k, "")
        for k in ("t_reached", "rhs_evals", "rhs_evals_jac", "steps", "rejected_steps",
                  "jacobian_evals"):
            row[k] = attr(st, k, "")
        row["cpu_s"] = attr(st, "cpu_time_s", "")
        # Non-finite values anywhere: every numeric dataset and attribute.
        bad = []

        def visit(name, obj):
            for an, av in obj.attrs.items():
                a = np.asarray(av)
                if a.dtype.kind in "fc" and not np.all(np.isfinite(a)):
                    bad.append(name + "@" + an)
            if isinstance(obj, h5py.Dataset) and obj.dtype.kind in "fc":
                if not np.all(np.isfinite(obj[...])):
                    bad.append(name)
        f.visititems(visit)
        for an, av in f.attrs.items():
            a = np.asarray(av)
            if a.dtype.kind in "fc" and not np.all(np.isfinite(a)):
                bad.append("/@" + an)
        if bad:
            problems.append("NaN/Inf in " + ", ".join(bad[:5]))

        t = f["/time"][:] if "/time" in f else np.zeros(0)
        if len(t) == 0:
            problems.append("no /time samples (no partial result)")
        t_reached = float(row["t_reached"]) if row["t_reached"] != "" else float("nan")
        if rc == 0:
            if status != "ok":
                problems.append("exit 0 but /stats/status = %r" % status)
            if t_end_hint and len(t) and abs(t[-1] - t_end_hint) > 1e-6 * max(1.0, t_end_hint):
                problems.append("ok run ends at t = %g, not %g" % (t[-1], t_end_hint))
        else:
            if status != "failed":
                problems.append("exit 2 but /stats/status = %r" % status)
            # The failure record (/stats failure_kind, failure_t, failure_s; run/simulate.hpp).
            if attr(st, "failure_kind", "none") in ("", "none"):
                problems.append("failed without a failure kind: %r" % msg[:120])
            if attr(st, "failure_t") is None:
                problems.append("failure record without failure time: %r" % msg[:120])
            if attr(st, "failure_s") is None:
                problems.append("failure record without distance")
            if t_end_hint and not (t_reached < t_end_hint):
                problems.append("failed but t_reached = %g >= t_end" % t_reached)
            if len(t) and t[-1] > t_reached + 1e-9:
                problems.append("partial output beyond t_reached")
        row["t_end"] = t_end_hint

        ymax = nmax = fmax = imax = yqmax = nfmax = 0.0
        in_flange = np.zeros(len(t), dtype=bool)
        nmin = float("inf")
        pp = float("nan")
        rails = rail_centre(f, path)
        if "/contact" in f:
            for ws in f["/contact"]:
                y = f["/bodies/%s/y" % ws][:]
                if len(y):
                    rel = y
                    if rails is not None:
                        s_ws = f["/bodies/%s/s" % ws][:len(y)]
                        rel = y - np.interp(s_ws, rails[0], rails[1])
                    ymax = max(ymax, float(np.max(np.abs(rel))))
                if ws in ("ws1", "ws") and len(y):
                    last = t >= (t[-1] - 1.0) if len(t) else slice(None)
                    pp = float(np.ptp(y[last])) if np.any(last) else float("nan")
                for side in ("left", "right"):
                    g = f["/contact/%s/%s" % (ws, side)]
                    n = g["normal_force"][:]
                    if len(n) == 0:
                        continue
                    nmax = max(nmax, float(n.max()))
                    nmin = min(nmin, float(n.min()))
                    ff = g["flange_force"][:]
                    nf = g["normal_flange"][:]
                    fmax = max(fmax, float(ff.max()))
                    nfmax = max(nfmax, float(nf.max()))
                    if len(ff) == len(in_flange):
                        in_flange |= (ff > 0) | (nf > 0)
                    imax = max(imax, float(g["flange_indentation"][:].max()))
                    yqmax = max(yqmax, float(np.max(np.abs(g["y_over_q"][:]))))
        # Hunting onset: first time the peak-to-peak of ws1's y over the trailing second exceeds
        # 4 mm (a stable wagon stays near 1 mm at 60 m/s, hunting reaches ~7.5 mm); the speed
        # then from /vehicle/speed (speed ramp) if written.
        onset_v = float("nan")
        if "/bodies/ws1/y" in f and len(t) > 1:
            y1 = f["/bodies/ws1/y"][:]
            dt = t[1] - t[0]
            win = max(1, int(round(1.0 / dt)))
            for k in range(win, len(t)):
                if np.ptp(y1[k - win:k + 1]) > 4e-3:
                    if "/vehicle/speed" in f:
                        onset_v = float(f["/vehicle/speed"][k])
                    else:
                        onset_v = float("nan")
                    row["onset_t"] = float(t[k])
                    break
        row["onset_speed"] = onset_v
        row.update({"max_abs_y_mm": ymax * 1e3, "max_normal_kN": nmax / 1e3,
                    "min_normal_kN": (nmin if math.isfinite(nmin) else 0.0) / 1e3,
                    "max_flange_kN": fmax / 1e3, "max_normal_flange_kN": nfmax / 1e3,
                    "flange_time_share": float(np.mean(in_flange)) if len(t) else 0.0, "max_indent_mm": imax * 1e3,
                    "max_abs_yq": yqmax, "ws1_y_pp_last_mm": pp * 1e3})
        # Plausibility of what was computed.
        problems_before = problems
        problems = implausible
        if ymax * 1e3 > bounds["y_mm"]:
            problems.append("|y| relative to the rails = %.2f mm > %.1f mm"
                            % (ymax * 1e3, bounds["y_mm"]))
        if nmax / 1e3 > bounds["normal_kN"]:
            problems.append("normal force %.0f kN > %.0f kN" % (nmax / 1e3, bounds["normal_kN"]))
        if math.isfinite(nmin) and -nmin / 1e3 > bounds["lift_kN"]:
            problems.append("normal force %.0f kN (wheel lift beyond %.0f kN)"
                            % (nmin / 1e3, bounds["lift_kN"]))
        if fmax / 1e3 > bounds["flange_kN"]:
            problems.append("flange force %.0f kN > %.0f kN" % (fmax / 1e3, bounds["flange_kN"]))
        if imax * 1e3 > bounds["indent_mm"]:
            problems.append("flange indentation %.3f mm > %.1f mm"
                            % (imax * 1e3, bounds["indent_mm"]))
        if yqmax > bounds["yq"]:
            problems.append("|Y/Q| = %.2f > %.1f" % (yqmax, bounds["yq"]))
    if rc == 0:
        return row, problems_before + implausible, []
    return row, problems_before, ["partial results before the failure: " + "; ".join(implausible)] \
        if implausible else []


# The words of the failure record's names (the C++ name tables: integ::kFailureKindNames,
# dynamics::kContactFailureNames); a name missing here is shown as it is.
_REASONS = {"wheel_lift": "wheel lift", "derailment": "derailment",
            "table_range": "the contact left its table",
            "constraint_solve": "the contact constraints were not solved",
            "coupling": "the normal/tangential coupling did not converge",
            "body_rotation": "a body's pitch reached its guard",
            "singular": "a singular mass or constraint matrix",
            "non_finite": "a non-finite value"}
_KINDS = {"non_finite": "a non-finite value", "step_size": "the step size became too small",
          "too_much_work": "too much work", "convergence": "the Newton iteration failed",
          "solver": "the solver failed", "setup": "the solver could not be set up",
          "validity": "an output left the model's validity",
          "model": "the model refused the state"}
# The model's reasons past which it is not valid (docs/contact_dynamics.md): a run that fails
# there has found where the model stops, not a numerical problem.
VALIDITY_REASONS = ("wheel_lift", "derailment", "table_range")


def failure_summary(failure):
    """The short reason of a run's failure record (a Case's `failure` or the /stats attributes),
    with its time and distance: "wheel lift at t = 0.62 s, s = 49.9 m"."""
    failure = failure or {}
    kind, reason = failure.get("failure_kind") or "", failure.get("failure_reason") or ""
    text = _REASONS.get(reason, reason) if reason else _KINDS.get(kind, kind or "failed")
    where = []
    for key, fmt in (("failure_t", "t = %.4g s"), ("failure_s", "s = %.4g m")):
        try:
            where.append(fmt % float(failure.get(key)))
        except (TypeError, ValueError):
            pass
    return text + (" at " + ", ".join(where) if where else "")


def classify_run(status, message, file, t_end, bounds=None):
    """A run by its own checks: (outcome, row fields, problems, notes) with outcome "ok"
    (finished and passes check_file; its accuracy is judged by the caller), "failed cleanly"
    (exit 2 with a consistent partial result, or a run refused before its first step with a
    diagnostic: a fixed step beyond the stability limit, wheel lift in the initial state) or
    "failed badly" (no result otherwise, exit 3, a signal, NaN/Inf, an inconsistent or implausible
    result). status/message: the study summary's (ok, failed, error)."""
    bounds = bounds or BOUNDS
    # Refused before the first step with its diagnostic (a fixed step beyond the stability
    # limit, wheel lift already in the initial state): the model says where it stops being valid.
    # Every hardened case passed `workbench check` before the command ran anything, so this is
    # not bad input.
    if status == "error" and ("stability limit" in (message or "") or
                              "nothing was run" in (message or "")):
        return "failed cleanly", {}, [], ["refused before the run: " + message[:200]]
    if status not in ("ok", "failed") or not file or not os.path.exists(file):
        return "failed badly", {}, ["no result: " + ((message or status or "?")[:300])], []
    rc = 0 if status == "ok" else 2
    try:
        fields, problems, notes = check_file(file, rc, bounds, t_end)
    except Exception as e:  # an unreadable file is a result missing
        return "failed badly", {}, ["cannot read result: %s" % e], []
    if problems:
        return "failed badly", fields, problems, notes
    return ("ok" if rc == 0 else "failed cleanly"), fields, problems, notes
