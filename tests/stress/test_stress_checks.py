"""The plausibility bound on a wheelset's lateral displacement (plots/railbench/stress_checks.py)
is taken against the centre of its rails: alignment irregularities move the rails, and a wheelset
that follows rails shifted by 20 mm is plausible; 21 mm off the design centreline on rails
without irregularities is not."""
import h5py
import numpy as np

from railbench.stress_checks import BOUNDS, check_file


def _result(path, y, rail_shift=None):
    t = np.linspace(0.0, 1.0, 11)
    with h5py.File(path, "w") as f:
        f["time"] = t
        st = f.create_group("stats")
        st.attrs["status"] = "ok"
        st.attrs["message"] = ""
        st.attrs["t_reached"] = 1.0
        f["bodies/ws1/s"] = 10.0 + 20.0 * t
        f["bodies/ws1/y"] = np.full(11, y)
        for side in ("left", "right"):
            g = f.create_group(f"contact/ws1/{side}")
            g["normal_force"] = np.full(11, 50e3)
            for k in ("flange_force", "normal_flange", "flange_indentation"):
                g[k] = np.zeros(11)
            g["y_over_q"] = np.full(11, 0.1)
        f.create_group("track")
        if rail_shift is not None:
            ig = f.create_group("track/irregularities")
            s = np.linspace(0.0, 100.0, 1001)
            ig["s"] = s
            ig["alignment"] = np.full(s.size, rail_shift)
            ig["left_y"] = np.full(s.size, rail_shift)
            ig["right_y"] = np.full(s.size, rail_shift)
    return str(path)


def _y_problems(path):
    _, problems, _ = check_file(path, 0, BOUNDS, 1.0)
    return [p for p in problems if p.startswith("|y|")]


def test_wheelset_following_shifted_rails_is_plausible(tmp_path):
    assert _y_problems(_result(tmp_path / "shifted.h5", 21e-3, rail_shift=20e-3)) == []


def test_wheelset_far_off_plain_rails_is_implausible(tmp_path):
    assert _y_problems(_result(tmp_path / "plain.h5", 21e-3))
    assert _y_problems(_result(tmp_path / "opposite.h5", 0.0, rail_shift=-15e-3))
