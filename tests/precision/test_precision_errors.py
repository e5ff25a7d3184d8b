"""The numbers of `workbench precision` on result files of known content: the errors against a
reference, the reference's verification bound (a loose reference must be flagged), the Pareto
front (plots/railbench/precision_errors.py); a diverged run's error is infinite, the engine's rule."""
import math
import os

import h5py
import numpy as np
import pytest

from railbench.precision_errors import QuantityError, errors, parse_quantities, pareto, verify


def _result(path, t, ws, contact=True, other=None):
    """A result file with wheelsets ws = {name: (y [m], yaw [rad])} and a car body."""
    with h5py.File(path, "w") as f:
        f["time"] = np.asarray(t, float)
        g = f.create_group("bodies")
        g.attrs["names"] = "\n".join(list(ws) + ["car"])
        for n, (y, yaw) in ws.items():
            b = g.create_group(n)
            b.attrs["kind"] = "wheelset"
            b["y"] = np.asarray(y, float)
            b["yaw"] = np.asarray(yaw, float)
        car = g.create_group("car")
        car.attrs["kind"] = "body"
        car["y"] = np.asarray(other if other is not None else np.zeros(len(t)), float)
        car["yaw"] = np.zeros(len(t))
        if contact:
            f.create_group("contact")
    return path


def test_errors_max_and_rms(tmp_path):
    t = np.linspace(0, 1, 101)
    ref = _result(tmp_path / "ref.h5", t, {"ws1": (np.zeros(101), np.zeros(101)),
                                           "ws2": (np.zeros(101), np.zeros(101))})
    # ws1 off by 0.2 mm everywhere, ws2 by 0.1 mm; yaw of ws2 by 1 mrad on half the samples.
    yaw2 = np.where(t < 0.5, 1e-3, 0.0)
    case = _result(tmp_path / "case.h5", t, {"ws1": (np.full(101, 2e-4), np.zeros(101)),
                                             "ws2": (np.full(101, -1e-4), yaw2)})
    e = errors(str(case), str(ref), parse_quantities("y,yaw"))
    assert e["y"][0] == pytest.approx(0.2)
    assert e["y"][1] == pytest.approx(math.sqrt((0.2 ** 2 + 0.1 ** 2) / 2))
    n_on = int(np.sum(t < 0.5))
    assert e["yaw"][0] == pytest.approx(1.0)
    assert e["yaw"][1] == pytest.approx(math.sqrt(n_on / 202))


def test_errors_on_the_reference_times_inside_the_run(tmp_path):
    """A failed case that ran half the time: its error over the part it ran, interpolated onto
    the reference's output times."""
    t = np.linspace(0, 1, 11)
    ref = _result(tmp_path / "ref.h5", t, {"ws1": (t * 1e-3, np.zeros(11))})
    tc = np.linspace(0, 0.5, 21)
    case = _result(tmp_path / "case.h5", tc, {"ws1": (tc * 1e-3 + 5e-5, np.zeros(21))})
    e = errors(str(case), str(ref), parse_quantities("y"))
    assert e["y"][0] == pytest.approx(0.05)


def test_guided_vehicle_uses_the_other_bodies(tmp_path):
    t = np.linspace(0, 1, 11)
    ref = _result(tmp_path / "ref.h5", t, {"ws1": (np.zeros(11), np.zeros(11))}, contact=False)
    case = _result(tmp_path / "case.h5", t, {"ws1": (np.zeros(11), np.zeros(11))}, contact=False,
                   other=np.full(11, 3e-4))
    assert errors(str(case), str(ref), parse_quantities("y"))["y"][0] == pytest.approx(0.3)
    assert errors(str(case), str(ref), parse_quantities("car.y"))["car.y"][0] == \
        pytest.approx(0.3)


def test_loose_reference_is_flagged_unverified(tmp_path):
    """Two 'references' that differ by 0.05 mm: verified against a 0.1 mm limit, UNVERIFIED
    against the default 1 um limit, and unverified whenever one of them failed."""
    t = np.linspace(0, 1, 51)
    a = _result(tmp_path / "a.h5", t, {"ws1": (np.sin(t) * 1e-3, np.zeros(51))})
    b = _result(tmp_path / "b.h5", t, {"ws1": (np.sin(t) * 1e-3 + 5e-5 * t, np.zeros(51))})
    qs = parse_quantities("y,yaw")
    bound = errors(str(b), str(a), qs)
    assert bound["y"][0] == pytest.approx(0.05)
    assert verify(bound, qs, 0.1, True) == (True, "")
    ok, why = verify(bound, qs, 1e-3, True)
    assert not ok and "0.05 mm" in why
    assert not verify(bound, qs, 0.1, False)[0]
    assert not verify({"y": (0.0, 0.0)}, qs, 0.1, True)[0]  # yaw missing
    assert not verify({"y": (math.nan, 0.0), "yaw": (0.0, 0.0)}, qs, 0.1, True)[0]


def test_pareto():
    pts = [(1.0, 1.0), (0.5, 2.0), (0.8, 3.0), (0.01, 10.0), (0.02, 20.0)]
    assert pareto(pts) == [0, 1, 3]


def test_diverged_run_has_infinite_error(tmp_path):
    t = np.linspace(0, 1, 5)
    ref = _result(str(tmp_path / "ref.h5"), t, {"ws1": (np.zeros(5), np.zeros(5))})
    run = _result(str(tmp_path / "run.h5"), t,
                  {"ws1": ([0, 1e-6, math.nan, 1e-6, 0], np.zeros(5))})
    e = errors(run, ref, parse_quantities("y,yaw"))
    assert math.isinf(e["y"][0]) and e["yaw"][0] == 0.0


def test_bad_quantity():
    with pytest.raises(QuantityError):
        parse_quantities("y,lateral")
    assert [q.unit for q in parse_quantities("y,yaw,Q,Fy,Y,YQ,car.roll")] == \
        ["mm", "mrad", "kN", "kN", "kN", "-", "mrad"]
