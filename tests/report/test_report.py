"""`rbplot report` (plots/railbench/report.py) on a real run: a short run of the default scene
(html_check.run_and_report: scenarios/default/case3_kec_fast.lua for 9 s, 180 m over the tangent,
the transition and into the curve, so that the EN 14363 table has three sections), written
as one page and read back with Python's html.parser: every figure of `rbplot run` is there as a
data: URI PNG, the EN 14363 table holds every section of /assessment/sections with limits,
margins and the worst wheel's position, the warnings and the scene are those of the file, and
nothing outside the page is referenced.

The workbench program: $RAILBENCH_WORKBENCH, else build/workbench/app/workbench. Work files in a
temporary folder, kept when a test fails (or with RB_KEEP_TMP=1)."""
import contextlib
import io
import os
import subprocess
import sys
import tempfile

import pytest


HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.abspath(os.path.join(HERE, "..", ".."))
sys.path.insert(0, os.path.join(ROOT, "plots"))
sys.path.insert(0, os.path.join(ROOT, "tests", "plots"))
sys.path.insert(0, HERE)

import html_check as hc  # noqa: E402
from helpers import rbplot, work_folder  # noqa: E402
from railbench.assessment import read_assessment, summary_items  # noqa: E402
from railbench.result import load_result  # noqa: E402
from railbench.run import FIGURES  # noqa: E402

TMP = tempfile.mkdtemp(prefix="rb_report_")
RESULT = os.path.join(TMP, "case3.h5")
PAGE = os.path.join(TMP, "case3.html")
DURATION = hc.DURATION


def make_report():
    hc.run_and_report(RESULT, PAGE)


work_files = work_folder(TMP, make_report)
_cache = {}


def page() -> hc.Page:
    if "page" not in _cache:
        with open(PAGE, encoding="utf-8") as f:
            _cache["text"] = f.read()
        _cache["page"] = hc.Page(_cache["text"])
    return _cache["page"]


def result():
    if "result" not in _cache:
        with contextlib.redirect_stderr(io.StringIO()):
            _cache["result"] = load_result(RESULT)
    return _cache["result"]


def test_page_is_well_formed():
    p = page()
    assert p.doctype.lower() == "doctype html"
    assert p.problems == []
    assert [e.attrs.get("charset") for e in p.tags("meta") if "charset" in e.attrs] == ["utf-8"]
    csp = [e.attrs["content"] for e in p.tags("meta")
           if e.attrs.get("http-equiv") == "Content-Security-Policy"]
    assert csp and "default-src 'none'" in csp[0] and "img-src data:" in csp[0]
    for sid in ("run", "scene", "assessment", "figures", "status", "warnings", "provenance",
                "scenario-text", "assessment-summary", "en14363-sections"):
        assert sid in p.by_id, f"no element #{sid}"


def test_nothing_outside_the_page():
    assert hc.foreign_references(page()) == []
    # In-page links lead to an element of the page.
    for a in page().tags("a"):
        assert a.attrs["href"][1:] in page().by_id, a.attrs["href"]


def test_every_figure_embedded():
    r = result()
    want = [spec.suffix for spec in FIGURES if spec.is_available(r)]
    assert "assessment" in want and "contact_forces" in want  # the run has them to draw
    figures = page().by_id["figures"].find_all("figure")
    assert [f.attrs["data-figure"] for f in figures] == want
    for fig in figures:
        imgs = fig.find_all("img")
        assert len(imgs) == 1
        w, h = hc.png_size(hc.png_of(imgs[0]))
        assert w > 300 and h > 100, (fig.attrs["data-figure"], w, h)
        assert imgs[0].attrs.get("alt")
        assert fig.find_all("figcaption")


def test_en14363_table_per_section():
    a = read_assessment(RESULT)
    names = [s.name for s in a.sections]
    assert len(names) >= 3, names  # tangent, transition, curve
    table = page().by_id["en14363-sections"]
    heads = [th.text for th in table.find_all("th")]
    assert heads[:7] == ["section", "kind", "test zone", "R [m]", "cant [mm]", "s [m]", "run [m]"]
    assert heads[7:] == ["(Y/Q)_2m", "(ΣY)_2m [kN]", "ΔQ/Q0", "Y_qst [kN]", "Q_qst [kN]",
                         "Q_max [kN]"]
    rows = table.find_all("tbody")[0].find_all("tr")
    assert [r.attrs["data-row"] for r in rows] == names
    for sec, row in zip(a.sections, rows):
        cells = row.find_all("td")
        assert len(cells) == len(heads)
        assert cells[0].text == sec.name and cells[1].text == sec.attrs["kind"]
        # (Y/Q)_2m: value, limit and margin, and the worst wheel with its position.
        v, lim = sec.get("y_over_q"), sec.get("y_over_q_limit")
        text = cells[7].text
        assert f"{v:.3f}" in text and f"limit {lim:.3f}" in text
        assert f"margin {lim - v:.3f}" in text
        assert str(sec.attrs["y_over_q_where"]).split()[0] in text  # "ws1"
        if sec.get("y_over_q_at_s") is not None:
            assert f"s = {sec.get('y_over_q_at_s'):.1f} m" in text
    # Y_qst is assessed in the curve only.
    kinds = [s.attrs["kind"] for s in a.sections]
    assert rows[kinds.index("curve")].find_all("td")[10].text != "–"
    assert rows[kinds.index("tangent")].find_all("td")[10].text == "–"


def test_summary_comfort_stability_and_caveats():
    a = read_assessment(RESULT)
    items = summary_items(a.summary)
    rows = page().by_id["assessment-summary"].find_all("tbody")[0].find_all("tr")
    assert [r.find_all("td")[0].text for r in rows] == [it.quantity.label for it in items]
    for it, r in zip(items, rows):
        cells = [c.text for c in r.find_all("td")]
        assert cells[2] == it.number(it.value)
        if it.limit is not None:
            assert cells[3] == it.number(it.limit) and cells[4] == it.number(it.limit - it.value)
            assert cells[5] == it.verdict
    assert page().by_id["verdict"].text
    comfort = page().by_id["comfort"].find_all("tbody")[0].find_all("tr")
    assert len(comfort) == len(a.comfort)
    caveats = page().by_id["comfort-caveats"].text
    assert "not normative limits" in caveats
    assert "60 blocks of 5 s" in caveats and "indicative" in caveats  # a 9 s run
    assert len(page().by_id["stability"].find_all("tbody")[0].find_all("tr")) == len(a.stability)
    assert "f0 ± 2 Hz" in page().by_id["stability-caveats"].text
    notes = [n for n in str(a.attrs.get("notes", "")).split("\n") if n.strip()]
    if notes:
        assert [li.text for li in page().by_id["assessment-notes"].find_all("li")] == notes


def test_run_and_scene_from_the_file():
    r = result()
    assert "ok" in page().by_id["status"].text
    warnings = [w for w in str(r.stats.get("warnings", "")).split("\n") if w.strip()]
    el = page().by_id["warnings"]
    if warnings:
        assert [li.text for li in el.find_all("li")] == warnings
    else:
        assert el.text.startswith("none")
    assert page().by_id["scenario-text"].text == r.attrs["scenario_text"]
    assert page().by_id["scenario-modules"].text == r.attrs["scenario_modules"]
    prov = {row.find_all("td")[0].text: row.find_all("td")[1].text
            for row in page().by_id["provenance"].find_all("tr")[1:]}
    assert prov["scenario_file"] == r.attrs["scenario_file"]
    assert prov["version"] == r.attrs["version"]
    assert prov["overrides"] == f"run.duration={DURATION:g}" or \
        "run.duration" in prov["overrides"]


def test_missing_file_one_line_error():
    r = rbplot("report", os.path.join(TMP, "absent.h5"))
    assert r.returncode == 1
    assert r.stderr.strip().startswith("railbench report: error: no such file")
    assert r.stdout == ""


def test_study_report(tmp_path):
    """A study folder (the synthetic one of tests/plots/test_study_plots.py) as one page: its
    cases, the tables and figures `rbplot study` draws; markup in a CSV stays text, a file that
    is not a PNG and a link to a file elsewhere are not embedded."""
    import shutil
    import test_study_plots
    shutil.rmtree(test_study_plots.TMP, ignore_errors=True)  # its own work folder, unused here
    d = str(tmp_path / "study")
    os.makedirs(d)
    test_study_plots.make_study(d)
    with open(os.path.join(d, "study_notes.csv"), "w") as f:
        f.write('what,text\nnote,"<script>alert(1)</script>"\n')
    with open(os.path.join(d, "fake.png"), "w") as f:
        f.write("<svg onload=alert(1)>")
    os.symlink(os.path.join(TMP, "case3.h5"), os.path.join(d, "linked.png"))
    r = rbplot("report", d, timeout=300)
    out = os.path.join(d, "report.html")
    assert r.returncode == 0 and r.stdout.strip() == out, r.stderr
    with open(out, encoding="utf-8") as f:
        p = hc.Page(f.read())
    assert p.problems == [] and hc.foreign_references(p) == []
    cases = p.by_id["study-cases"].find_all("tbody")[0].find_all("tr")
    with open(os.path.join(d, "summary_cases.csv")) as f:
        assert len(cases) == len(f.read().strip().split("\n")) - 1
    figures = [fig.attrs["data-figure"] for fig in p.tags("figure")]
    assert "study_cost.png" in figures and "fake.png" not in figures
    assert "linked.png" not in figures
    for fig in p.tags("figure"):
        hc.png_of(fig.find_all("img")[0])
    assert "<script>alert(1)</script>" in p.tags("body")[0].text
    assert p.tags("script") == []


@pytest.mark.parametrize("name,scene,sets,want", [
    # Two wagons in a train{}: an assessment part per vehicle, the ids of each its own.
    ("train", "tests/run/data/train_two_wagons.lua", ["run.duration=0.3"], 0),
    # A failed run (exit 2): FAILED and its failure record, its figures.
    ("fail", "tests/plots/contact_short.lua",
     ["solver.method=rk4", "solver.step=0.01", "run.output.every=0.01",
      "solver.accept_unstable_step=true"], 2),
])
def test_train_and_failed_run(name, scene, sets, want):
    result, out = os.path.join(TMP, f"{name}.h5"), os.path.join(TMP, f"{name}.html")
    cmd = [hc.workbench(), "run", scene, "--out", result, "--quiet"]
    for s in sets:
        cmd += ["--set", s]
    r = subprocess.run(cmd, cwd=ROOT, env=dict(os.environ, RAILBENCH_ROOT=ROOT),
                       capture_output=True, text=True, timeout=300, stdin=subprocess.DEVNULL)
    assert r.returncode == want, r.stdout + r.stderr
    hc.rbplot_report(result, out)
    with open(out, encoding="utf-8") as f:
        p = hc.Page(f.read())
    assert p.problems == [] and hc.foreign_references(p) == []
    assert p.tags("figure") and all(hc.png_of(fig.find_all("img")[0])
                                    for fig in p.tags("figure"))
    if name == "train":
        assert [h.text for h in p.tags("h2")][2:4] == ["Assessment of vehicle front",
                                                       "Assessment of vehicle rear"]
        assert "en14363-sections-1" in p.by_id and "en14363-sections-2" in p.by_id
        labels = [fig.attrs["data-figure"] for fig in p.tags("figure")]
        assert "assessment (front)" in labels and "assessment (rear)" in labels
    else:
        assert "FAILED" in p.by_id["status"].text
        assert "failure_kind" in p.by_id["failure"].text
