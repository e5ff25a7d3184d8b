"""Issue 47 for Python's reader of result files (plots/railbench/h5.py): `rbplot run` on the
forged files of the hostile corpus (forge_result.py) refuses each with exit 1 and one line naming
the dataset or link, reads nothing through a link and leaves the linked file as it was.
`rbplot report` (issue 50) refuses the same files, and shows markup forged into a file's strings
as text (html_injection)."""
import os
import sys
import tempfile

import pytest

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.abspath(os.path.join(HERE, "..", ".."))
sys.path.insert(0, os.path.join(ROOT, "plots"))
sys.path.insert(0, os.path.join(ROOT, "tests", "plots"))
sys.path.insert(0, os.path.join(ROOT, "tests", "report"))
sys.path.insert(0, HERE)

import forge_result  # noqa: E402
import html_check  # noqa: E402
from helpers import in_process, one_line_error  # noqa: E402
from railbench import report as report_command  # noqa: E402
from railbench import run as run_command  # noqa: E402


@pytest.fixture()
def work():
    with tempfile.TemporaryDirectory(prefix="rbplot_hostile_") as tmp:
        w = os.path.join(tmp, "work")
        os.mkdir(w)
        yield w


def _plot(work, kind):
    forge_result.forge(kind, work)
    return in_process(run_command.main, os.path.join(work, "result.h5"), "--outdir",
                      os.path.join(work, "figs"))


def test_plain_forged_result_draws(work):
    r = _plot(work, "plain")
    assert r.returncode == 0, r.stderr


def test_external_link_refused(work):
    victim = os.path.join(work, "..", "victim.h5")
    r = _plot(work, "external_schema")
    one_line_error(r, "run", "/schema is an external link to '../victim.h5:/schema'")
    with open(victim, "rb") as f:
        assert b"not railbench" in f.read()


def test_fifo_track_store_refused(work):
    r = _plot(work, "fifo_store")
    one_line_error(r, "run", "tracks/0123456789abcdef.h5: is a FIFO")


def test_huge_declared_refused(work):
    r = _plot(work, "huge_declared")
    one_line_error(r, "run", "/contact/ws1/left/Q declares 100000000000 values")


def test_nan_sample_refused(work):
    r = _plot(work, "nan_signal")
    one_line_error(r, "run", "/bodies/ws1/y holds nan at sample 100")


# ---- rbplot report (plots/railbench/report.py) -------------------------------------------------

def _report(work, kind):
    forge_result.forge(kind, work)
    return in_process(report_command.main, os.path.join(work, "result.h5"), "--out",
                      os.path.join(work, "report.html"))


def test_report_escapes_markup(work):
    """Markup in the scenario text, the warnings, the failure record, the assessment's `where`,
    notes and section names stays text: no element, attribute or link of the page comes from the
    file, and every hostile string is shown as written."""
    r = _report(work, "html_injection")
    assert r.returncode == 0, r.stderr
    with open(os.path.join(work, "report.html"), encoding="utf-8") as f:
        page = html_check.Page(f.read())
    assert page.problems == []
    assert html_check.foreign_references(page) == []
    # The only images are the embedded figures; the page's elements are the report's own.
    assert all(img.parent.tag == "figure" for img in page.tags("img"))
    assert {e.tag for e in page.elements} <= {
        "html", "head", "meta", "title", "style", "body", "h1", "h2", "h3", "p", "b", "i", "br",
        "code", "nav", "ul", "li", "a", "section", "table", "thead", "tbody", "tr", "th", "td",
        "span", "div", "pre", "details", "summary", "figure", "img", "figcaption"}
    text = page.tags("body")[0].text
    for s in (forge_result.INJECT, forge_result.INJECT_ATTR, forge_result.INJECT_NAME,
              '<iframe src="http://example.invalid/"></iframe>'):
        assert s in text, s
    assert forge_result.INJECT in page.by_id["scenario-text"].text
    assert [li.text for li in page.by_id["warnings"].find_all("li")] == [
        f"first warning {forge_result.INJECT}", f"<b>second</b> {forge_result.INJECT_ATTR}"]
    rows = page.by_id["en14363-sections"].find_all("tbody")[0].find_all("tr")
    assert [row.attrs["data-row"] for row in rows] == [forge_result.INJECT_NAME]


@pytest.mark.parametrize("kind,needle", [
    ("external_schema", "/schema is an external link to '../victim.h5:/schema'"),
    ("huge_declared", "/contact/ws1/left/Q declares 100000000000 values"),
    ("nan_signal", "/bodies/ws1/y holds nan at sample 100"),
])
def test_report_refuses_forged(work, kind, needle):
    r = _report(work, kind)
    one_line_error(r, "report", needle)
    assert not os.path.exists(os.path.join(work, "report.html"))
