"""`workbench check-result` (workbench/stress/result_checks.hpp), the checks of a run's result file
that `workbench stress` and the hard-case suite apply, on files of known content:

* the plausibility bound on a wheelset's lateral displacement is taken against the centre of its
  rails: alignment irregularities move the rails, and a wheelset that follows rails shifted by
  20 mm is plausible; 21 mm off the design centreline on rails without irregularities is not
  (also when the irregularities are in the track store the result references);
* NaN/Inf anywhere is a problem; a failed run needs its failure record; an implausible state in a
  failed run's partial result is a note, in a finished run a problem;
* bad input (no file, an unknown bound) is exit 1.
"""
import json
import os
import subprocess

import h5py
import numpy as np
import pytest

WORKBENCH = os.environ["WORKBENCH"]


def _result(path, y, rail_shift=None, status="ok", store=None):
    t = np.linspace(0.0, 1.0, 11)
    with h5py.File(path, "w") as f:
        f["time"] = t
        st = f.create_group("stats")
        st.attrs["status"] = status
        st.attrs["message"] = "" if status == "ok" else "failed at t = 1: wheel lift"
        st.attrs["t_reached"] = 1.0
        f["bodies/ws1/s"] = 10.0 + 20.0 * t
        f["bodies/ws1/y"] = np.full(11, y)
        for side in ("left", "right"):
            g = f.create_group(f"contact/ws1/{side}")
            g["normal_force"] = np.full(11, 50e3)
            for k in ("flange_force", "normal_flange", "flange_indentation"):
                g[k] = np.zeros(11)
            g["y_over_q"] = np.full(11, 0.1)
        tg = f.create_group("track")
        target = tg
        if store is not None:
            tg.attrs["stored_in"] = os.path.basename(store)
            tg.attrs["track_hash"] = "abc"
            sf = h5py.File(store, "w")
            target = sf.create_group("track")
            target.attrs["track_hash"] = "abc"
        if rail_shift is not None:
            ig = target.create_group("irregularities")
            s = np.linspace(0.0, 100.0, 1001)
            ig["s"] = s
            ig["alignment"] = np.full(s.size, rail_shift)
            ig["left_y"] = np.full(s.size, rail_shift)
            ig["right_y"] = np.full(s.size, rail_shift)
        if store is not None:
            sf.close()
    return str(path)


def _check(path, rc=0, *extra, t_end=1.0):
    p = subprocess.run([WORKBENCH, "check-result", path, "--exit-code", str(rc), "--t-end",
                        repr(t_end),
                        *extra], capture_output=True, text=True)
    assert p.returncode in (0, 2), p.stderr
    out = json.loads(p.stdout)
    assert p.returncode == (2 if out["problems"] else 0)
    return out


def _y_problems(path):
    return [p for p in _check(path)["problems"] if p.startswith("|y|")]


def test_wheelset_following_shifted_rails_is_plausible(tmp_path):
    assert _y_problems(_result(tmp_path / "shifted.h5", 21e-3, rail_shift=20e-3)) == []


def test_wheelset_far_off_plain_rails_is_implausible(tmp_path):
    assert _y_problems(_result(tmp_path / "plain.h5", 21e-3))
    assert _y_problems(_result(tmp_path / "opposite.h5", 0.0, rail_shift=-15e-3))


def test_rails_of_a_track_store(tmp_path):
    path = _result(tmp_path / "stored.h5", 21e-3, rail_shift=20e-3, store=tmp_path / "abc.h5")
    assert _y_problems(path) == []
    with h5py.File(tmp_path / "abc.h5", "a") as f:
        f["track"].attrs["track_hash"] = "other"
    assert any("track store" in p for p in _check(path)["problems"])


def test_non_finite_values_are_problems(tmp_path):
    path = _result(tmp_path / "nan.h5", 1e-3)
    with h5py.File(path, "a") as f:
        f["bodies/ws1/y"][3] = np.nan
        f["stats"].attrs["cpu_time_s"] = np.inf
    problems = _check(path)["problems"]
    assert any("NaN/Inf" in p and "/bodies/ws1/y" in p and "/stats@cpu_time_s" in p
               for p in problems), problems


def test_failed_run_needs_its_failure_record(tmp_path):
    path = _result(tmp_path / "failed.h5", 1e-3, status="failed")
    with h5py.File(path, "a") as f:
        f["stats"].attrs["t_reached"] = 0.5
    problems = _check(path, 2)["problems"]
    assert any("without a failure kind" in p for p in problems)
    assert any("partial output beyond t_reached" in p for p in problems)
    with h5py.File(path, "a") as f:
        f["stats"].attrs["failure_kind"] = "model"
        f["stats"].attrs["failure_reason"] = "wheel_lift"
        f["stats"].attrs["failure_t"] = 0.5
        f["stats"].attrs["failure_s"] = 20.0
        del f["time"]
        f["time"] = np.linspace(0.0, 0.5, 11)
    out = _check(path, 2)
    assert out["problems"] == []
    assert out["failure_text"].endswith("at t = 0.5 s, s = 20 m")


def test_implausible_partial_result_is_a_note(tmp_path):
    path = _result(tmp_path / "partial.h5", 30e-3, status="failed")
    with h5py.File(path, "a") as f:
        for k, v in (("failure_kind", "model"), ("failure_t", 1.5), ("failure_s", 40.0),
                     ("t_reached", 1.5)):
            f["stats"].attrs[k] = v
    out = _check(path, 2, t_end=2.0)
    assert out["problems"] == [] and any("|y|" in n for n in out["notes"])
    # A finished run with the same state fails the check; a wider bound accepts it.
    ok = _result(tmp_path / "wide.h5", 30e-3)
    assert _y_problems(ok)
    assert _check(ok, 0, "--bound", "y_mm=40")["problems"] == []


@pytest.mark.parametrize("args,words", [(["missing.h5"], "no such result file"),
                                        (["--bound", "nope=1"], "expected NAME=VALUE")])
def test_bad_input_is_exit_1(tmp_path, args, words):
    path = _result(tmp_path / "any.h5", 0.0)
    cmd = [WORKBENCH, "check-result"] + (args if args[0].endswith(".h5") else [path] + args)
    p = subprocess.run(cmd, capture_output=True, text=True, cwd=tmp_path)
    assert p.returncode == 1 and words in p.stderr
