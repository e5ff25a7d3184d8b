"""Forged result files for the hostile corpus (directive `forge=KIND`, README.md): each KIND writes
`result.h5` (and what else it needs) into the case's work folder with h5py, so the corpus holds
the recipe, not a binary file. The base is the smallest result `assess` and `check-result`
accept: 2 s of one wheelset at 20 m/s sampled every 2.5 ms, /stats of an ok run."""
import os

import numpy as np

DT = 2.5e-3  # [s] at most assess's 5 ms output interval
N = 801  # 2 s
SPEED = 20.0  # [m/s]
Q0 = 50e3  # [N] static wheel load


def _signals():
    t = np.arange(N) * DT
    rng = np.random.default_rng(47)
    q = Q0 + 1e3 * rng.standard_normal(N)
    y = 2e3 * np.sin(2 * np.pi * 1.5 * t)
    return t, y, q


def _base(f):
    """A complete run of one wheelset: /time, /bodies/ws1, /contact/ws1/{left,right}, /stats."""
    t, y, q = _signals()
    f.attrs["content"] = "railbench result (forged by tests/hostile/forge_result.py)"
    f["time"] = t
    f["bodies/ws1/s"] = SPEED * t
    f["bodies/ws1/y"] = 1e-3 * np.sin(2 * np.pi * 1.5 * t)
    for side, sign in (("left", 1.0), ("right", -1.0)):
        g = f.create_group(f"contact/ws1/{side}")
        g["Y"] = sign * y
        g["Q"] = q
        g["y_track"] = sign * y
        g["normal_force"] = q
    _track(f, t)
    s = f.create_group("stats")
    s.attrs["status"] = np.bytes_("ok")
    s.attrs["message"] = np.bytes_("")
    s.attrs["t_reached"] = t[-1]
    s.attrs["cpu_time_s"] = 0.1
    return t


def _track(f, t):
    """A straight /track under the run (centreline and one tangent segment), as rbplot reads it."""
    s = np.linspace(0.0, SPEED * t[-1] + 10.0, 11)
    zero = np.zeros_like(s)
    cl = f.create_group("track/centreline")
    for k, v in (("s", s), ("x", s), ("y", zero), ("z", zero), ("heading", zero),
                 ("slope", zero), ("cant_angle", zero), ("curvature", zero), ("cant", zero)):
        cl[k] = v
    sg = f.create_group("track/segments")
    for k, v in (("start", 0.0), ("length", s[-1]), ("kind", 0.0), ("radius", 0.0),
                 ("side", 0.0), ("cant", 0.0)):
        sg[k] = np.array([v])


def _assessment(f, t):
    """/assessment as a run's assessment writes it (safety only), so assess recomputes from it."""
    _, y, q = _signals()
    a = f.create_group("assessment")
    a.attrs["sample_every"] = DT
    a["time"] = t
    a["distance"] = SPEED * t
    for side, sign in (("left", 1.0), ("right", -1.0)):
        g = a.create_group(f"safety/ws1/{side}")
        g.attrs["q0"] = Q0
        g.attrs["s_offset"] = 0.0
        g["Y"] = sign * y
        g["Q"] = q
        g["y_track"] = sign * y


def external_schema(work):
    """/schema is an external link to a file outside the work folder (`../victim.h5`), whose
    /schema/assessment a writer through the link would replace."""
    with h5py().File(os.path.join(work, "..", "victim.h5"), "w") as v:
        v["schema/assessment/path"] = np.array([b"/victim/data"])
        v.attrs["owner"] = np.bytes_("not railbench")
    with h5py().File(os.path.join(work, "result.h5"), "w") as f:
        _base(f)
        f["schema"] = h5py().ExternalLink("../victim.h5", "/schema")


def fifo_store(work):
    """/track@stored_in names a FIFO in the track store folder: opening it would block."""
    with h5py().File(os.path.join(work, "result.h5"), "w") as f:
        _base(f)
        del f["track/centreline"], f["track/segments"]
        f["track"].attrs["stored_in"] = np.bytes_("tracks/0123456789abcdef.h5")
        f["track"].attrs["track_hash"] = np.bytes_("0123456789abcdef")
    os.mkdir(os.path.join(work, "tracks"))
    os.mkfifo(os.path.join(work, "tracks", "0123456789abcdef.h5"))


def huge_declared(work):
    """/contact/ws1/left/Q declares 1e11 samples (800 GB) in a file of a few kB: HDF5 allocates
    nothing until it is written, a reader that allocates from the declared size runs out."""
    with h5py().File(os.path.join(work, "result.h5"), "w") as f:
        _base(f)
        del f["contact/ws1/left/Q"]
        f.create_dataset("contact/ws1/left/Q", shape=(10**11,), dtype="f8")


def nan_assessment(work):
    """One NaN sample in /assessment/safety/ws1/left/Y of an otherwise valid assessment."""
    with h5py().File(os.path.join(work, "result.h5"), "w") as f:
        t = _base(f)
        _assessment(f, t)
        y = f["assessment/safety/ws1/left/Y"]
        y[400] = np.nan


def array_attribute(work):
    """/stats@t_reached holds 4096 values where readers read one: a reader that reads it into one
    double writes 32 kB over its stack."""
    with h5py().File(os.path.join(work, "result.h5"), "w") as f:
        _base(f)
        f["stats"].attrs["t_reached"] = np.full(4096, 2.0)


def nan_signal(work):
    """One NaN sample in /bodies/ws1/y of a run's outputs."""
    with h5py().File(os.path.join(work, "result.h5"), "w") as f:
        _base(f)
        f["bodies/ws1/y"][100] = np.nan


def short_assessment(work):
    """An /assessment of 3 samples (7.5 ms): no assessment window fits, and a quantity computed
    over an empty window would be NaN."""
    with h5py().File(os.path.join(work, "result.h5"), "w") as f:
        t = _base(f)
        _assessment(f, t)
        for name in list(f["assessment"].keys()):
            del f["assessment"][name]
        _assessment_of(f["assessment"], t[:3])


def _assessment_of(a, t):
    n = len(t)
    _, y, q = _signals()
    a["time"] = t
    a["distance"] = SPEED * t
    for side, sign in (("left", 1.0), ("right", -1.0)):
        g = a.create_group(f"safety/ws1/{side}")
        g.attrs["q0"] = Q0
        g.attrs["s_offset"] = 0.0
        g["Y"] = sign * y[:n]
        g["Q"] = q[:n]
        g["y_track"] = sign * y[:n]


def comfort_sample_every(work):
    """/assessment of 7 s sampled every 5 ms with floor accelerations, but @sample_every says
    2.5 ms: by its times the run holds a 5 s block of EN 12299, by its samples at the stated
    interval (3.5 s) none."""
    with h5py().File(os.path.join(work, "result.h5"), "w") as f:
        _base(f)
        t = np.arange(1400) * 5e-3
        a = f.create_group("assessment")
        _assessment_of(a, t[:N])
        del a["time"], a["distance"]
        a["time"] = t
        a["distance"] = SPEED * t
        for side in ("left", "right"):
            for k in ("Y", "Q", "y_track"):
                v = a[f"safety/ws1/{side}/{k}"][()]
                del a[f"safety/ws1/{side}/{k}"]
                a[f"safety/ws1/{side}/{k}"] = np.resize(v, t.size)
        a.attrs["sample_every"] = 2.5e-3
        g = a.create_group("comfort/p1")
        g.attrs["x_offset"] = 0.0
        for k in ("a_x", "a_y", "a_z"):
            g[k] = 0.1 * np.sin(2 * np.pi * 1.0 * t)


INJECT = '<script>alert("rb")</script>'
INJECT_ATTR = '"><img src=x onerror=alert(1)>'  # breaks out of a quoted attribute
INJECT_NAME = "<img src=x onerror=alert(2)>"  # an HDF5 name holds no '/': no closing tag


def html_injection(work):
    """Markup in every string a report shows (`rbplot report`, plots/railbench/report.py): the
    scenario text and file, the overrides, a warning, the failure message, an assessment's
    `where`, notes and a section named like an element: a report that does not escape them runs
    a script or loads an image from elsewhere."""
    with h5py().File(os.path.join(work, "result.h5"), "w") as f:
        t = _base(f)
        f.attrs["scenario_text"] = np.bytes_(f"-- {INJECT}\nrun {{ duration = 2 }}\n")
        f.attrs["scenario_file"] = np.bytes_(f"scene{INJECT_ATTR}.lua")
        f.attrs["scenario_modules"] = np.bytes_(f"-- file: lib{INJECT_ATTR}.lua\n{INJECT}\n")
        f.attrs["overrides"] = np.bytes_('<iframe src="http://example.invalid/"></iframe>')
        f.attrs["created"] = np.bytes_(INJECT_ATTR)
        s = f["stats"]
        s.attrs["status"] = np.bytes_("failed")
        s.attrs["message"] = np.bytes_(f"solver gave up {INJECT}")
        s.attrs["failure_reason"] = np.bytes_(INJECT_ATTR)
        s.attrs["warnings"] = np.bytes_(f"first warning {INJECT}\n<b>second</b> {INJECT_ATTR}")
        a = f.create_group("assessment")
        _assessment_of(a, t)
        a.attrs["notes"] = np.bytes_(INJECT)
        a.attrs["assumptions"] = np.bytes_(INJECT_ATTR)
        a.attrs["category"] = np.bytes_(INJECT)
        sm = a.create_group("summary")
        sm.attrs["y_over_q"] = 0.3
        sm.attrs["y_over_q_limit"] = 0.8
        sm.attrs["y_over_q_ok"] = 1
        sm.attrs["y_over_q_where"] = np.bytes_(f"ws1 left {INJECT}")
        sec = a.create_group("sections")
        sec.attrs["names"] = np.bytes_(INJECT_NAME)
        g = sec.create_group(INJECT_NAME)
        g.attrs["kind"] = np.bytes_(INJECT)
        g.attrs["zone"] = np.bytes_(INJECT_ATTR)
        g.attrs["from"] = 0.0
        g.attrs["to"] = 40.0
        g.attrs["y_over_q"] = 0.3
        g.attrs["y_over_q_limit"] = 0.8
        g.attrs["y_over_q_ok"] = 1
        g.attrs["y_over_q_where"] = np.bytes_(INJECT_ATTR)
        g.attrs["notes"] = np.bytes_(INJECT)


def plain(work):
    """The base alone (for the command-line options' cases)."""
    with h5py().File(os.path.join(work, "result.h5"), "w") as f:
        _base(f)


def h5py():
    import h5py as mod  # only the cases that forge files need it

    return mod


KINDS = {k: v for k, v in globals().items()
         if callable(v) and not k.startswith("_") and k != "h5py"}


def forge(kind, work):
    if kind not in KINDS:
        raise ValueError(f"unknown forge kind '{kind}' (one of {', '.join(sorted(KINDS))})")
    KINDS[kind](str(work))
