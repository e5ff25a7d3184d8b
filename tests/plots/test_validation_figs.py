"""Tests of the validation figures (railbench/validation_figs.py: the paper's Fig. 17, 19-22 and
27) that `plots/rbplot validation-tables` draws: on synthetic result files with a track, and,
for Fig. 27, on the bump-stop rig run by the real workbench.

usage: /usr/bin/python3 -m pytest -q tests/plots/test_validation_figs.py
    Fig. 27 needs the workbench program: $RAILBENCH_WORKBENCH, else build/workbench/app/workbench
    (skipped when neither exists). Work files go to a temp dir, removed on success (kept on
    failure, or always with RB_KEEP_TMP=1).
"""
import csv
import subprocess
import os
import tempfile

import h5py
import numpy as np
import pytest

from helpers import ROOT, check, work_folder

from railbench import validation as vt
from railbench import validation_figs as vf
from railbench.common import save_figure
from railbench.result import load_result
from railbench.style import SEGMENT_FILL

TMP = tempfile.mkdtemp(prefix="rb_validation_figs_")
work_files = work_folder(TMP)
WORKBENCH = os.environ.get("RAILBENCH_WORKBENCH") or os.path.join(
    ROOT, "build", "workbench", "app", "workbench")
WAGON = [("ws1", "wheelset"), ("ws2", "wheelset"), ("ws3", "wheelset"), ("ws4", "wheelset"),
         ("bogie1", "bogie"), ("bogie2", "bogie"), ("car", "car")]


def _track(f, tangent, transition, curve, radius):
    """Track groups of a tangent, a left transition and a left curve of `radius`."""
    length = tangent + transition + curve
    s = np.linspace(0.0, length, int(length) + 1)
    k = np.clip((s - tangent) / transition, 0.0, 1.0) / radius
    cl = f.create_group("/track/centreline")
    for name, v in dict(s=s, x=s, y=0 * s, z=0 * s, heading=0 * s, slope=0 * s,
                        cant_angle=0 * s, curvature=k, cant=0 * s).items():
        cl[name] = v
    sg = f.create_group("/track/segments")
    for name, v in dict(start=[0, tangent, tangent + transition],
                        length=[tangent, transition, curve], kind=[0, 1, 2],
                        radius=[0, radius, radius], side=[0, 1, 1], cant=[0, 0, 0]).items():
        sg[name] = np.asarray(v, dtype=float)
    sg.attrs["codes"] = "0=tangent,1=transition,2=curve"  # as the writer (io/track_output.cpp)


def write_run(path, method, bodies, speed, track, y0, status="ok"):
    """A result file: the track, and every body (name, kind) with s, y = y0 * (k + 1) * ramp(s)
    and yaw = -y / 2 [rad] (k: its index)."""
    t = np.arange(0.0, (sum(track[:3]) - 20.0) / speed, 0.01)
    with h5py.File(path, "w") as f:
        f.attrs["contact_method"] = method
        f.attrs["solver"] = "abm"
        _track(f, *track)
        f["/time"] = t
        g = f.create_group("/bodies")
        g.attrs["names"] = "\n".join(n for n, _ in bodies)
        for k, (name, kind) in enumerate(bodies):
            b = g.create_group(name)
            b.attrs["kind"] = kind
            s = speed * t + 10.0 - 2.0 * k
            y = y0 * (k + 1) * np.clip((s - track[0]) / track[1], 0.0, 1.0)
            b["s"] = s
            b["y"] = y
            b["yaw"] = -0.5 * y
        f.create_group("/stats").attrs["status"] = status
    return path


def _case_files():
    """Synthetic results of case 1 (R = 300 and 700 m) and cases 2 and 3 (KEC and LUT)."""
    files = {}
    for radius in (300, 700):
        for m, y0 in (("kec", -0.4e-3), ("lut", -0.3e-3)):
            files[(1, str(radius), m)] = write_run(
                os.path.join(TMP, f"c1_R{radius}_{m}.h5"), m,
                [("frame", "frame"), ("ws", "wheelset")], 10.0, (30, 50, 40, radius), y0)
    for case in (2, 3):
        for m, y0 in (("kec", -5e-3), ("lut", -6e-3)):
            files[(case, "", m)] = write_run(os.path.join(TMP, f"c{case}_{m}.h5"), m, WAGON,
                                             20.0, (100, 50, 350, 500), y0)
    return files


def _lines(ax, gid="data"):
    return [ln for ln in ax.get_lines() if ln.get_gid() == gid]


def _spans(ax):
    """(start, end, face colour) of the shaded segment spans of a panel."""
    from matplotlib.colors import to_hex
    out = []
    for p in ax.patches:
        xs = np.asarray(p.get_xy())[:, 0]
        out.append((float(xs.min()), float(xs.max()), to_hex(p.get_facecolor(), keep_alpha=False)))
    return sorted(out)


def test_fig17_columns_from_the_tracks():
    files = _case_files()
    columns = vf._case1_columns(files)
    check([ws for ws, _ in columns] == ["ws", "ws"], "Fig. 17: the wheelset, not the frame")
    fig = vf.fig17_case1(columns)
    axes = [ax for ax in fig.axes if ax.get_gid()]
    gids = [ax.get_gid() for ax in axes]
    check(sorted(gids) == ["y:R300", "y:R700", "yaw:R300", "yaw:R700"],
          f"Fig. 17: y and yaw per radius, radius read from /track/segments: {gids}")
    titles = sorted(ax.get_title() for ax in axes if ax.get_title())
    check(titles == ["R = 300 m", "R = 700 m"], f"column titles {titles}")
    for ax in axes:
        key, rad = ax.get_gid().split(":R")
        lines = _lines(ax)
        check([ln.get_label() for ln in lines] == ["KEC", "LUT"], f"{ax.get_gid()}: KEC and LUT")
        for ln, m in zip(lines, ("kec", "lut")):
            r = load_result(files[(1, rad, m)])
            want = r.bodies["ws"].data[key] * 1e3
            check(np.allclose(ln.get_xdata(), r.bodies["ws"].data["s"]) and
                  np.allclose(ln.get_ydata(), want),
                  f"{ax.get_gid()} {m}: the wheelset's {key} in mm / mrad against its s")
        # Shading from the file's segments: grey transition 30..80 m, blue curve 80..120 m.
        check(_spans(ax) == [(30.0, 80.0, SEGMENT_FILL["transition"]), (80.0, 120.0, SEGMENT_FILL["curve"])],
              f"{ax.get_gid()}: segment shading {_spans(ax)}")
        check("[mm]" in ax.get_ylabel() or "[mrad]" in ax.get_ylabel() or not ax.get_ylabel(),
              "units in the row labels")
    save_figure(fig, os.path.join(TMP, "fig17.png"))


def test_make_figures_writes_every_figure(monkeypatch):
    files = _case_files()
    d = os.path.join(TMP, "study")
    os.makedirs(d)
    # No workbench: Fig. 27 is left out with a note, the others are drawn.
    paths = vf.make_figures(d, files, workbench=os.path.join(TMP, "no_workbench"))
    names = sorted(os.path.basename(p) for p in paths)
    check(names == ["study_fig17_case1.png", "study_fig19_case2_wheelsets.png",
                    "study_fig20_case2_bodies.png", "study_fig21_case3_wheelsets.png",
                    "study_fig22_case3_bodies.png"], f"figures written: {names}")
    for p in paths:
        check(os.path.getsize(p) > 20000, f"{p}: a drawn figure")
    # The series of Fig. 19 and 20: wheelsets, then bogies and car, KEC and LUT each.
    runs = vf._pair_runs(files, 2)
    check([lab for _, lab in runs] == ["KEC", "LUT"], "case 2: KEC and LUT runs")
    figs = {}
    monkeypatch.setattr(vf, "save_figure", lambda fig, path, written=None:
                        figs.__setitem__(os.path.basename(path), fig))
    vf.make_figures(d, files, workbench=os.path.join(TMP, "no_workbench"))
    for name, bodies in (("study_fig19_case2_wheelsets.png", ["ws1", "ws2", "ws3", "ws4"]),
                         ("study_fig20_case2_bodies.png", ["bogie1", "bogie2", "car"]),
                         ("study_fig22_case3_bodies.png", ["bogie1", "bogie2", "car"])):
        gids = [ax.get_gid() for ax in figs[name].axes if ax.get_gid()]
        check(sorted(gids) == sorted(f"{q}:{b}" for q in ("y", "yaw") for b in bodies),
              f"{name}: panels {gids}")
        for ax in figs[name].axes:
            if ax.get_gid():
                check(len(_lines(ax)) == 2, f"{name} {ax.get_gid()}: KEC and LUT drawn")
    car = next(ax for ax in figs["study_fig20_case2_bodies.png"].axes if ax.get_gid() == "y:car")
    r = load_result(files[(2, "", "lut")])
    check(np.allclose(_lines(car)[1].get_ydata(), r.bodies["car"].data["y"] * 1e3),
          "Fig. 20: the car's y of the LUT run in mm")


def test_validation_tables_lists_the_figures():
    """`validation.make` draws the figures of the scenario-solver runs named in
    summary_cases.csv (a dopri5 case is not drawn)."""
    files = _case_files()
    d = os.path.join(TMP, "tables")
    os.makedirs(d)
    rows = []
    for (case, radius, m), path in files.items():
        base = f"../validation/case1_R{radius}_{m}.lua" if case == 1 else \
            f"../validation/case{case}_{m}.lua"
        rows.append(dict(case=os.path.basename(path), base=base, overrides="", status="ok",
                         t_reached="12", steps="60000", file=path))
    rows.append(dict(rows[-1], overrides="solver.method=dopri5 solver.rtol=1e-06",
                     file=os.path.join(d, "absent.h5")))
    with open(os.path.join(d, "summary_cases.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, list(rows[0]))
        w.writeheader()
        w.writerows(rows)
    written = vt.make(d, workbench=os.path.join(TMP, "no_workbench"))
    figs = sorted(os.path.basename(p) for p in written if p.endswith(".png"))
    check(len(figs) == 5 and figs[0] == "study_fig17_case1.png",
          f"validation-tables writes the figures beside its tables: {figs}")


@pytest.mark.skipif(not os.path.exists(WORKBENCH), reason="no workbench program")
def test_fig27_bumpstop_law_from_the_rig():
    d = os.path.join(TMP, "rig")
    os.makedirs(d)
    check(vf.vehicle_module(None) == vf.VEHICLE_MODULE, "default vehicle module")
    rig = vf.run_bumpstop_rig(d, WORKBENCH, ROOT, vf.VEHICLE_MODULE)
    check(rig is not None, "the rig runs")
    h5, name, table = rig
    check(name.startswith("bump_y_") and name.endswith(vf.VEHICLE_MODULE),
          f"the vehicle file's bump stop: {name}")
    check(table.ndim == 2 and table.shape[1] == 2 and len(table) >= 3 and table[0, 1] == 0,
          f"table points printed by the rig: {table}")
    r = load_result(h5)
    e = r.elements["bump"]
    dfl, force = e["deflection"], e["force"]
    d_end, f_end = table[-1]
    check(dfl.max() > d_end and dfl.min() < -d_end,
          "the rig drives the stop past the table's last point on both sides")
    clear = table[table[:, 1] == 0, 0].max()
    check(np.all(force[np.abs(dfl) < clear] == 0), "no force inside the clearance")
    order = np.argsort(dfl)
    check(np.all(np.diff(force[order]) >= -1e-6), "force non-decreasing in the deflection")
    # The element output passes through the table points (odd law): interpolated between the
    # dense samples, within a small fraction of the local force.
    for dk, fk in table[1:]:
        for sign in (1, -1):
            got = np.interp(sign * dk, dfl[order], force[order])
            check(abs(got - sign * fk) <= 0.02 * fk + 50.0,
                  f"F({sign * dk * 1e3:g} mm) = {got:.1f} N, table {sign * fk:g} N")
    fig = vf.fig27_bumpstop(r, name=name, table=table)
    ax = fig.axes[0]
    data, pts = _lines(ax)[0], _lines(ax, "table")[0]
    check(np.allclose(np.sort(data.get_xdata()), np.sort(dfl) * 1e3) and
          np.allclose(np.sort(data.get_ydata()), np.sort(force) * 1e-3),
          "Fig. 27: every element output sample in mm and kN")
    check(len(pts.get_xdata()) == 2 * len(table), "the table points, mirrored")
    check(ax.get_xlabel() == "relative displacement d [mm]" and ax.get_ylabel() == "force F [kN]",
          "axes and units")
    save_figure(fig, os.path.join(d, "fig27.png"))
    check(os.path.getsize(os.path.join(d, "fig27.png")) > 20000, "Fig. 27 written")


def test_set_up_variants_parse_as_their_case_and_are_told_apart():
    """The variants of scenarios/validation/variants/ parse as their case and method, carry
    their variant tag, and the shipped scenarios carry none."""
    base = "../validation/variants/case1_R300_kec_centred.lua"
    check(vt.parse_case(base) == (1, "300", "kec"), f"parse {base}")
    check(vt.variant(base) == "centred", f"variant of {base}")
    base = "../validation/variants/case2_lut_table4.lua"
    check(vt.parse_case(base) == (2, "", "lut"), f"parse {base}")
    check(vt.variant(base) == "table4", f"variant of {base}")
    check(vt.variant("../validation/case2_lut.lua") == "", "shipped case 2 has no variant")
    check(vt.parse_case("../validation/variants/case2_lut_other.lua") is None,
          "an unknown variant is not taken for a case")
    for f in os.listdir(os.path.join(ROOT, "scenarios", "validation", "variants")):
        check(vt.parse_case(f) is not None and vt.variant(f), f"shipped variant {f} parses")


def test_tables_block_of_contact_geometry():
    """docs/contact_geometry.md's generated block (railbench/docs_tables.py): "missing" without a
    tables file; with the validation cases' tables the conicity row and the six delta r jumps."""
    from railbench.docs_tables import tables_block
    out = os.path.join(TMP, "tables_docs")
    check("Not generated" in tables_block(out), "no tables file: a 'not generated' note")
    if not os.path.exists(WORKBENCH):
        pytest.skip("no workbench program")
    os.makedirs(os.path.join(out, "tables"), exist_ok=True)
    h5 = os.path.join(out, "tables", "study.h5")
    r = subprocess.run([WORKBENCH, "tables", "scenarios/validation/case3_lut.lua", "--out", h5],
                       cwd=ROOT, capture_output=True, text=True,
                       env=dict(os.environ, RAILBENCH_ROOT=ROOT))
    check(r.returncode == 0, f"workbench tables: {r.stderr}")
    block = tables_block(out)
    check("tan gamma_e" in block and "| 3 |" in block, "conicity row over the amplitudes")
    jumps = [l for l in block.splitlines() if l.startswith("| +") or l.startswith("| -")]
    check(len(jumps) == 6, f"six located delta r jumps (three per side), got {len(jumps)}")
