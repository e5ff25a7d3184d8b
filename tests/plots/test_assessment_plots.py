"""Tests of the assessment figure (railbench/assessment.py, drawn by `plots/rbplot run` when a
result file has /assessment) and of the docs block `assessment_cases` of docs/assessment.md
(railbench/docs_blocks.py), on synthetic result files written with h5py after the layout of
/assessment (docs/assessment.md; the contract between the C++ writer and these plots): two
wheelsets with both wheels, comfort at three floor positions, stability at two bogie positions,
wear per wheel.

usage: /usr/bin/python3 -m pytest -q tests/plots/test_assessment_plots.py
"""
import csv
import os
import tempfile

import h5py
import numpy as np

from helpers import check, in_process, work_folder
from railbench import run as run_command
from railbench.assessment import fig_assessment, read_assessment, summary_items
from railbench.docs import generate
from railbench.docs import main as update_docs
from railbench.docs_blocks import NOT_GENERATED, assessment_cases_block
from railbench.result import load_result
from railbench.run import FIGURES, build_figure, panel_points
from railbench.style import plt

TMP = tempfile.mkdtemp(prefix="rb_assessment_test_")
ALL_PANELS = {"y_over_q", "sum_y", "dq_over_q", "comfort", "stability", "wear"}
WS = ("ws1", "ws2")

work_files = work_folder(TMP)

# The synthetic run: 200 m at 20 m/s, output every 10 ms.
T = np.arange(0.0, 10.0 + 1e-9, 0.01)
S = 20.0 * T
Q0 = 50e3


def _group(f, path, attrs, **data):
    g = f.require_group(path)
    for k, v in attrs.items():
        g.attrs[k] = v
    for k, v in data.items():
        g[k] = np.asarray(v, dtype=float)
    return g


def _check_attrs(value, limit, unit, clause, **extra):
    return dict(unit=unit, value=value, limit=limit, margin=limit - value,
                ok=int(value <= limit), clause=clause, **extra)


def _safety(f, yq_peak):
    s = np.arange(S[0] + 2.0, S[-1] + 1e-9, 0.5)
    f["/assessment/safety/s"] = s
    for i, ws in enumerate(WS):
        for side, sign in (("left", 1.0), ("right", -1.0)):
            yq = (yq_peak if (i, side) == (0, "left") else 0.3) * np.sin(s / 30.0) ** 2 * sign
            at = float(s[np.argmax(np.abs(yq))])
            _group(f, f"/assessment/safety/{ws}/{side}/y_over_q",
                   _check_attrs(float(np.max(np.abs(yq))), 0.8, "-", "EN 14363 (Y/Q)_2m",
                                at_s=at, nadal_limit=1.2003, flange_angle=np.radians(70.0),
                                mu=0.36), value=yq)
            dq = 0.2 * np.abs(np.sin(T / (1.0 + i)))
            _group(f, f"/assessment/safety/{ws}/{side}/dq_over_q",
                   _check_attrs(float(dq.max()), 0.6, "-", "EN 14363 twist", q0=Q0), value=dq)
        sy = 30e3 * np.sin(s / 40.0)
        _group(f, f"/assessment/safety/{ws}/sum_y",
               _check_attrs(float(np.max(np.abs(sy))), 10e3 + 2 * Q0 / 3, "N",
                            "EN 14363 (SumY)_2m", alpha=1.0, q0=Q0,
                            at_s=float(s[np.argmax(np.abs(sy))])), value=sy)


def _stability_comfort_wear(f):
    for bogie, pos in (("bogie1", "ws1"), ("bogie2", "ws3")):
        sr = np.arange(100.0, S[-1] + 1e-9, 10.0)
        rms = 1.5 + 0.5 * np.sin(sr / 20.0)
        _group(f, f"/assessment/stability/{bogie}/{pos}",
               _check_attrs(float(rms.max()), (12 - 2.6 / 5) / 2, "m/s^2", "EN 14363 simplified",
                            f0=5.0, bogie_mass=2600.0, at_s=float(sr[np.argmax(rms)])),
               s=sr, rms=rms, acceleration=np.sin(2 * np.pi * 5 * T))
    for pos, x0, n_mv in (("front", 7.0, 1.9), ("centre", 0.0, 1.4), ("rear", -7.0, 2.2)):
        data = {f"a_{c}": 0.1 * np.sin(T * (k + 1)) for k, c in enumerate("xyz")}
        data.update({f"nc_{c}": (0.5 + 0.3 * k) * (1 - np.exp(-T)) for k, c in enumerate("xyz")})
        _group(f, f"/assessment/comfort/{pos}",
               dict(n_mv=n_mv, limit=2.0, ok=int(n_mv <= 2.0), x_offset=x0, wz_lateral=2.1,
                    wz_vertical=1.9, clause="EN 12299 6.7.2"), **data)
    for ws in WS:
        for side in ("left", "right"):
            tg = 40.0 + 20.0 * np.sin(S / 25.0) ** 2
            _group(f, f"/assessment/wear/{ws}/{side}",
                   dict(max=float(tg.max()), mean=float(tg.mean()), energy=float(tg.sum())),
                   t_gamma=tg, power=tg * 20.0)


def _summary(f, yq_peak, parts):
    sm = f.require_group("/assessment/summary")
    rows = {"y_over_q": (yq_peak, 0.8, "ws1 left"), "sum_y": (30e3, 10e3 + 2 * Q0 / 3, "ws1"),
            "dq_over_q": (0.2, 0.6, "ws1 left")}
    if "stability" in parts:
        rows.update({"stability_rms": (2.0, 5.74, "bogie1 ws1"), "n_mv": (2.2, 2.0, "rear"),
                     "wz_lateral": (2.1, 2.5, "front"), "wz_vertical": (1.9, 2.5, "front")})
    for key, (v, lim, where) in rows.items():
        sm.attrs[key] = v
        sm.attrs[key + "_limit"] = lim
        sm.attrs[key + "_ok"] = int(v <= lim)
        sm.attrs[key + "_where"] = where
    if "stability" in parts:
        sm.attrs["t_gamma_max"] = 60.0
        sm.attrs["t_gamma_max_where"] = "ws2 right"


def _track(f):
    """A 200 m track: 50 m tangent, 50 m transition, 100 m curve of R = 500 m."""
    s = np.linspace(0.0, 200.0, 201)
    k = np.clip((s - 50.0) / 50.0, 0.0, 1.0) / 500.0
    cl = f.create_group("/track/centreline")
    for name, v in dict(s=s, x=s, y=0 * s, z=0 * s, heading=0 * s, slope=0 * s,
                        cant_angle=0 * s, curvature=k, cant=0 * s).items():
        cl[name] = v
    sg = f.create_group("/track/segments")
    for name, v in dict(start=[0, 50, 100], length=[50, 50, 100], kind=[0, 1, 2],
                        radius=[0, 500, 500], side=[0, 1, 1], cant=[0, 0, 0]).items():
        sg[name] = np.asarray(v, dtype=float)


def write_result(name, parts=("safety", "stability"), yq_peak=0.5, folder=TMP):
    """A synthetic result file: the track, bodies with s, and /assessment with `parts`
    ("safety"; "stability" adds stability, comfort and wear); no /assessment when empty."""
    path = os.path.join(folder, name + ".h5")
    with h5py.File(path, "w") as f:
        f.attrs["contact_method"] = "kec"
        _track(f)
        f["/time"] = T
        st = f.create_group("/stats")
        st.attrs["status"] = "ok"
        st.attrs["t_reached"] = float(T[-1])
        for ws in WS:
            g = f.create_group(f"/bodies/{ws}")
            g.attrs["kind"] = "wheelset"
            g["s"], g["y"], g["yaw"] = S, 0 * S, 0 * S
        if not parts:
            return path
        a = f.create_group("/assessment")
        a.attrs["standards"] = "EN 14363:2005, EN 12299:2009"
        a.attrs["sample_every"] = 0.01
        a["time"], a["distance"] = T, S
        if "safety" in parts:
            _safety(f, yq_peak)
        if "stability" in parts:
            _stability_comfort_wear(f)
        _summary(f, yq_peak, parts)
    return path


def _figure(path):
    r = load_result(path)
    spec = next(s for s in FIGURES if s.suffix == "assessment")
    return r, spec


def test_full_figure_has_six_panels_and_the_summary():
    r, spec = _figure(write_result("full"))
    check(spec.is_available(r), "the assessment figure is available with /assessment")
    fig = build_figure(r, spec)
    pts = panel_points(fig)
    check(set(pts) == ALL_PANELS, f"six panels, got {sorted(pts)}")
    check(all(n > 0 for n in pts.values()), f"every panel shows data {pts}")
    texts = " ".join(t.get_text() for ax in fig.axes for t in ax.texts)
    check("N_MV 2.20 > 2.00 EXCEEDED (rear)" in texts and "EXCEEDED: N_MV " in texts
          and "(Y/Q)_2m 0.500 ≤ 0.800 ok (ws1 left)" in texts
          and "(ΣY)_2m [kN] 30.0 ≤ 43.3 ok (ws1)" in texts,
          f"summary: values against limits, ok / EXCEEDED: {texts!r}")
    legends = {ax.get_gid(): [t.get_text() for t in ax.get_legend().get_texts()]
               for ax in fig.axes if ax.get_gid()}
    check("limit 0.80" in legends["y_over_q"] and "Nadal limit 1.20" in legends["y_over_q"],
          f"Y/Q: limit and Nadal limit in the legend {legends['y_over_q']}")
    check("limit 43.3 kN" in legends["sum_y"], f"ΣY limit alpha (10 kN + 2 Q0/3) {legends}")
    check("limit 0.60" in legends["dq_over_q"] and "limit 5.74 m/s²" in legends["stability"],
          "ΔQ/Q and stability limits in the legend")
    check(any("rear: N_MV = 2.20" in t and "EXCEEDED" in t for t in legends["comfort"]),
          f"N_MV per position in the comfort legend {legends['comfort']}")
    comfort = next(ax for ax in fig.axes if ax.get_gid() == "comfort")
    check(len([ln for ln in comfort.get_lines() if ln.get_gid() == "data"]) == 9,
          "comfort: 3 positions x 3 axes")
    plt.close(fig)


def test_cli_writes_the_assessment_png():
    path = write_result("cli")
    out = os.path.join(TMP, "cli_out")
    r = in_process(run_command.main, path, "--outdir", out)
    check(r.returncode == 0, f"rbplot run exit {r.returncode}: {r.stderr}")
    png = os.path.join(out, "cli_assessment.png")
    check(os.path.exists(png) and os.path.getsize(png) > 10000, "assessment png written")
    check(png in r.stdout.split(), "the png is listed")


def test_only_safety_draws_only_its_panels():
    r, spec = _figure(write_result("safety_only", parts=("safety",)))
    fig = build_figure(r, spec)
    check(set(panel_points(fig)) == {"y_over_q", "sum_y", "dq_over_q"},
          f"only the safety panels: {sorted(panel_points(fig))}")
    plt.close(fig)


def test_no_assessment_no_figure_no_error():
    path = write_result("none", parts=())
    r, spec = _figure(path)
    check(not spec.is_available(r), "no /assessment: the figure is not available")
    check(read_assessment(path) is None and fig_assessment(r) is None,
          "no /assessment: nothing read, nothing drawn")
    out = os.path.join(TMP, "none_out")
    res = in_process(run_command.main, path, "--outdir", out)
    check(res.returncode == 0 and not os.path.exists(os.path.join(out, "none_assessment.png")),
          f"rbplot run without /assessment: exit 0, no assessment png ({res.stderr})")


def test_summary_items_exceeded():
    items = {it.quantity.key: it for it in summary_items(
        read_assessment(write_result("exceeded", yq_peak=0.95)).summary)}
    check(items["y_over_q"].ok is False and items["y_over_q"].against() == "0.950 > 0.800 EXCEEDED",
          f"Y/Q above its limit: {items['y_over_q'].against()}")
    check(items["sum_y"].against() == "30.0 ≤ 43.3 ok", "ΣY in kN against its limit")
    check(items["t_gamma_max"].limit is None and items["t_gamma_max"].against() == "60",
          "T-gamma: no limit")


# ---- the docs block ---------------------------------------------------------------------------

def _study(folder, cases):
    """A validation study folder: summary_cases.csv naming each case's result file (cases:
    [(base, overrides, file)])."""
    os.makedirs(folder, exist_ok=True)
    with open(os.path.join(folder, "summary_cases.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, ["case", "label", "base", "overrides", "status", "file"])
        w.writeheader()
        for k, (base, ov, path) in enumerate(cases):
            w.writerow(dict(case=f"c{k}", label=base, base=base, overrides=ov, status="ok",
                            file=path))


def test_docs_block_from_synthetic_results():
    out = os.path.join(TMP, "studies")
    d = os.path.join(out, "validation")
    os.makedirs(d, exist_ok=True)
    files = {}
    for c in (2, 3):
        for m in ("kec", "lut"):
            peak = 0.95 if (c, m) == (3, "lut") else 0.5
            parts = () if (c, m) == (2, "lut") else ("safety", "stability")
            files[(c, m)] = write_result(f"case{c}_{m}", parts=parts, yq_peak=peak, folder=d)
    cases = [(f"../validation/case{c}_{m}.lua", "", files[(c, m)]) for c in (2, 3)
             for m in ("kec", "lut")]
    cases.append(("../validation/case3_kec.lua", "solver.method=dopri5 solver.rtol=1e-06",
                  os.path.join(d, "absent.h5")))
    _study(d, cases)
    block = assessment_cases_block(out)
    rows = {ln.split(" | ")[0].lstrip("| "): ln for ln in block.splitlines()
            if ln.startswith("| ")}
    yq = rows["max (Y/Q)_2m [-]"]
    check("0.500 ≤ 0.800 ok (ws1 left, s = " in yq, f"Y/Q value, limit, wheel, distance: {yq}")
    check(yq.count("EXCEEDED") == 1 and "0.950 > 0.800 EXCEEDED" in yq,
          f"case 3 LUT: Y/Q above its limit is EXCEEDED: {yq}")
    check("not generated" in yq.split(" | ")[2], f"case 2 LUT without /assessment: {yq}")
    check("30.0 ≤ 43.3 ok (ws1" in rows["max (ΣY)_2m [kN]"], "ΣY in kN with its limit")
    check("0.200 ≤ 0.600 ok" in rows["max ΔQ/Q0 [-]"], "ΔQ/Q0 with its limit")
    check("2.00 ≤ 5.74 ok (bogie1 ws1" in rows["stability rms [m/s²]"], "stability rms")
    check("2.20 > 2.00 EXCEEDED (rear)" in rows["N_MV [-] (target)"], "N_MV against its target")
    check("2.10 ≤ 2.50 ok" in rows["Wz lateral [-] (target)"] and
          "1.90 ≤ 2.50 ok" in rows["Wz vertical [-] (target)"], "Wz lateral and vertical")
    check("60 (ws2 right)" in rows["max T-gamma [N]"], "T-gamma without a limit")
    head = [ln for ln in block.splitlines() if ln.startswith("| quantity")][0]
    check(head.split(" | ")[1:] == ["case 2 KEC", "case 2 LUT", "case 3 KEC", "case 3 LUT |"],
          f"columns per case: {head}")
    check(NOT_GENERATED in block and "case2_lut.h5" in block,
          "the case without /assessment is named in a 'Not generated' line")
    check("figures/validation_case3_kec_assessment.png" in block and
          os.path.getsize(os.path.join(d, "study_case3_kec_assessment.png")) > 10000,
          "the figure of case 3 KEC, drawn into the study folder under the copied name")
    check(generate(out, out)["assessment.md"]["assessment_cases"] == block,
          "generate() writes the block to docs/assessment.md")
    # `plots/rbplot docs`: the block between its markers, stamped, and the figure copied; the
    # pages this docs folder lacks are left out with a note.
    docs = os.path.join(TMP, "docs")
    os.makedirs(docs)
    with open(os.path.join(docs, "assessment.md"), "w") as f:
        f.write("# hand text\n<!-- generated: assessment_cases (plots/rbplot docs) -->\nOLD\n"
                "<!-- end: assessment_cases -->\nhand text after\n"
                "<!-- generated: route_sections (plots/rbplot docs) -->\n"
                "<!-- end: route_sections -->\n")
    r = in_process(update_docs, out, "--build", os.path.join(TMP, "nobuild"), "--docs", docs)
    text = open(os.path.join(docs, "assessment.md")).read()
    check(r.returncode == 0 and "OLD" not in text and "hand text after" in text and
          "*Generated by `plots/rbplot docs`" in text and "| max (Y/Q)_2m [-] |" in text,
          f"rbplot docs writes the block ({r.stderr})")
    check(os.path.exists(os.path.join(docs, "figures", "validation_case3_kec_assessment.png")),
          "the figure of case 3 KEC is copied to docs/figures")
    check("studies.md missing" in r.stderr, "a page the docs folder lacks: a note, no error")


def test_docs_block_missing():
    empty = os.path.join(TMP, "empty")
    block = assessment_cases_block(empty)
    check(block.startswith(NOT_GENERATED), f"no study folder: Not generated ({block})")
    d = os.path.join(TMP, "noassess", "validation")
    os.makedirs(d)
    _study(d, [(f"../validation/case{c}_{m}.lua", "",
                write_result(f"c{c}{m}", parts=(), folder=d)) for c in (2, 3)
               for m in ("kec", "lut")])
    block = assessment_cases_block(os.path.join(TMP, "noassess"))
    check(block.startswith(NOT_GENERATED) and "/assessment" in block,
          f"result files without /assessment: Not generated ({block})")


# ---- sections, own positions (docs/assessment.md "Track sections and test zones") -------------

def _sections(path, offset=-10.0):
    """Adds two sections (tangent 0-100 m, curve 100-200 m of R = 500 m), the per-quantity
    window positions and a trailing wheelset ws2 `offset` metres behind ws1."""
    with h5py.File(path, "a") as f:
        g = f.require_group("/assessment/sections")
        g.attrs["names"] = "tangent1\ncurve2"
        for k, (name, kind, zone, lo, hi, yq) in enumerate(
                (("tangent1", "tangent", "zone 1", 0.0, 100.0, 0.1),
                 ("curve2", "curve", "zone 3", 100.0, 200.0, 0.95))):
            s = g.create_group(name)
            s.attrs.update(dict(order=k, kind=kind, zone=zone, to=hi, covered=hi - lo))
            s.attrs["from"] = lo
            if kind == "curve":
                s.attrs.update(dict(radius=500.0, cant=0.0, y_qst=20e3, y_qst_limit=60e3,
                                    y_qst_ok=1, y_qst_where="ws1 left"))
            s.attrs.update(dict(y_over_q=yq, y_over_q_limit=0.8, y_over_q_ok=int(yq <= 0.8),
                                y_over_q_where="ws1 left", sum_y=12e3, sum_y_limit=43.3e3,
                                sum_y_ok=1, sum_y_where="ws2"))
        a = f["/assessment"]
        a.attrs["q0_source"] = "static wheel loads on perfect level tangent track"
        for side in ("left", "right"):
            w = f[f"/assessment/safety/ws2/{side}"]
            w.attrs["s_offset"] = offset
            w["y_over_q/s"] = f["/assessment/safety/s"][()] + offset
            w["dq_over_q"].attrs["at_s"] = 150.0


def test_sections_in_the_summary_and_own_positions():
    path = write_result("sections")
    _sections(path)
    a = read_assessment(path)
    check([s.name for s in a.sections] == ["tangent1", "curve2"], "sections in track order")
    check(a.s_offset[("ws2", "left")] == -10.0, "s_offset per wheel")
    text = a.sections[1].text()
    check(text.startswith("curve2 (curve, zone 3, R 500 m, 100–200 m): Y/Q 0.95 EXCEEDED")
          and "Y_qst 20.0" in text, f"a section's line: {text!r}")
    r, spec = _figure(path)
    fig = build_figure(r, spec)
    texts = " ".join(t.get_text() for ax in fig.axes for t in ax.texts)
    check("per section (worst wheel; forces in kN):" in texts and "tangent1 (tangent, zone 1"
          in texts, f"the sections under the summary: {texts!r}")
    yq = next(ax for ax in fig.axes if ax.get_gid() == "y_over_q")
    starts = sorted({float(ln.get_xdata()[0]) for ln in yq.get_lines() if ln.get_gid() == "data"})
    check(starts[0] == S[0] + 2.0 - 10.0, f"ws2's windows in its own distance: {starts}")
    dq = next(ax for ax in fig.axes if ax.get_gid() == "dq_over_q")
    starts = sorted({float(ln.get_xdata()[0]) for ln in dq.get_lines() if ln.get_gid() == "data"})
    check(starts == [S[0] - 10.0, S[0]], f"ΔQ/Q0 of ws2 against its own distance: {starts}")
    plt.close(fig)


def test_route_sections_block():
    from railbench.docs_blocks import ROUTE, route_sections_block
    out = os.path.join(TMP, "route_studies")
    check(route_sections_block(out).startswith(NOT_GENERATED), "no run: not generated")
    d = os.path.join(out, ROUTE)
    os.makedirs(d, exist_ok=True)
    path = write_result("route", folder=d)
    _sections(path)
    block = route_sections_block(out)
    rows = [ln for ln in block.splitlines() if ln.startswith("| curve2 ")]
    check(len(rows) == 1 and "zone 3" in rows[0] and "0.950 > 0.800 EXCEEDED (ws1 left)" in rows[0]
          and "20.0 (ws1 left)" in rows[0], f"the curve's row: {rows}")
    check("| ws2 left | -10.00 |" in block and "| 150.0 |" in block,
          f"each wheel at its own distance: {block}")
