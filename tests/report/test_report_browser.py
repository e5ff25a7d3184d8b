"""The report in a browser (ctest label `browser`): headless Chromium (Debian's `chromium`) opens
the page of a short run and of a forged result with markup in its strings.

- A copy of the page with a checker script (html_check.CHECK_SCRIPT, allowed by its nonce alone)
  reports after the load: every figure's PNG decoded (natural size > 0), the EN 14363 table's rows,
  no script error and no Content-Security-Policy violation (an unescaped <script> or a foreign
  image in the page would be one).
- The page itself, --dump-dom with Chromium's console on stderr: no console error, and the DOM
  Chromium built holds every figure and the table's rows.
- --screenshot of the page: a PNG of the window's size that is not blank.

Skipped, not failed, when no Chromium is installed (ctest counts it as skipped:
SKIP_REGULAR_EXPRESSION in tests/report/CMakeLists.txt): `apt-get install chromium`."""
import json
import os
import sys
import tempfile

import pytest

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.abspath(os.path.join(HERE, "..", ".."))
sys.path.insert(0, os.path.join(ROOT, "tests", "plots"))
sys.path.insert(0, os.path.join(ROOT, "tests", "hostile"))
sys.path.insert(0, HERE)

import html_check as hc  # noqa: E402
from helpers import work_folder  # noqa: E402

CHROMIUM = hc.chromium()
pytestmark = pytest.mark.skipif(CHROMIUM is None,
                                reason="chromium is not installed (apt-get install chromium)")

TMP = tempfile.mkdtemp(prefix="rb_report_browser_")
RESULT = os.path.join(TMP, "case3.h5")
PAGE = os.path.join(TMP, "case3.html")
FORGED = os.path.join(TMP, "forged")
FORGED_PAGE = os.path.join(TMP, "forged.html")
SHOT = os.path.join(TMP, "case3.png")
WINDOW = (1280, 4000)


def prepare():
    if CHROMIUM is None:
        return
    hc.run_and_report(RESULT, PAGE)
    import forge_result
    os.makedirs(FORGED, exist_ok=True)
    forge_result.forge("html_injection", FORGED)
    hc.rbplot_report(os.path.join(FORGED, "result.h5"), FORGED_PAGE)


work_files = work_folder(TMP, prepare)


def _read(path: str) -> str:
    with open(path, encoding="utf-8") as f:
        return f.read()


def _checked(page_path: str) -> dict:
    """What the checker script found in Chromium (the instrumented copy of the page)."""
    copy = page_path[:-5] + "_checked.html"
    with open(copy, "w", encoding="utf-8") as f:
        f.write(hc.instrumented(_read(page_path)))
    r = hc.run_chromium(CHROMIUM, ["--dump-dom", "file://" + copy])
    assert r.returncode == 0, r.stderr[-2000:]
    dom = hc.Page(r.stdout)
    assert "rb-check" in dom.by_id, "the checker script did not run:\n" + r.stderr[-2000:]
    return json.loads(dom.by_id["rb-check"].text)


def _console_errors(stderr: str):
    """Console messages of the page (not Chromium's own log about D-Bus, GPU and the like)."""
    return [ln for ln in stderr.splitlines() if "CONSOLE" in ln or "Refused" in ln or
            "Content Security Policy" in ln or "Uncaught" in ln]


def test_loads_with_every_figure_and_the_table():
    page = hc.Page(_read(PAGE))
    n_figures = len(page.tags("figure"))
    n_rows = len(page.by_id["en14363-sections"].find_all("tbody")[0].find_all("tr"))
    assert n_figures >= 8 and n_rows >= 3
    got = _checked(PAGE)
    assert got["errors"] == [] and got["violations"] == [], got
    assert got["figures"] == got["images"] == got["decoded"] == n_figures, got
    assert all(w > 300 and h > 100 for w, h in got["sizes"]), got["sizes"]
    assert got["section_rows"] == n_rows and got["summary_rows"] >= 8, got
    assert got["scripts"] == 1  # the checker's own
    assert got["title"] == "railbench report: case3.h5"


def test_page_as_is_has_no_console_error():
    r = hc.run_chromium(CHROMIUM, ["--enable-logging=stderr", "--v=0", "--dump-dom",
                                   "file://" + PAGE])
    assert r.returncode == 0, r.stderr[-2000:]
    assert _console_errors(r.stderr) == []
    dom = hc.Page(r.stdout)
    page = hc.Page(_read(PAGE))
    assert len(dom.tags("figure")) == len(page.tags("figure"))
    assert all(img.attrs["src"].startswith("data:image/png;base64,") for img in dom.tags("img"))
    rows = dom.by_id["en14363-sections"].find_all("tbody")[0].find_all("tr")
    assert [r.attrs["data-row"] for r in rows] == \
        [r.attrs["data-row"] for r in page.by_id["en14363-sections"].find_all("tr")[1:]]
    assert dom.tags("script") == []


def test_screenshot():
    if os.path.exists(SHOT):
        os.remove(SHOT)
    r = hc.run_chromium(CHROMIUM, ["--hide-scrollbars", f"--window-size={WINDOW[0]},{WINDOW[1]}",
                                   f"--screenshot={SHOT}", "file://" + PAGE])
    assert r.returncode == 0 and os.path.isfile(SHOT), r.stderr[-2000:]
    with open(SHOT, "rb") as f:
        data = f.read()
    assert data.startswith(b"\x89PNG\r\n\x1a\n")
    assert hc.png_size(data) == WINDOW
    import matplotlib.image
    px = matplotlib.image.imread(SHOT)
    assert px.std() > 0.05  # text, tables and figures, not a blank page
    print(f"screenshot: {SHOT} ({len(data)} bytes)")


def test_forged_markup_stays_text():
    got = _checked(FORGED_PAGE)
    assert got["violations"] == [] and got["errors"] == [], got
    assert got["scripts"] == 1 and got["title"] == "railbench report: result.h5", got
    r = hc.run_chromium(CHROMIUM, ["--dump-dom", "file://" + FORGED_PAGE])
    dom = hc.Page(r.stdout)
    assert dom.tags("script") == [] and dom.tags("iframe") == []
    assert all(img.attrs["src"].startswith("data:") for img in dom.tags("img"))
    assert '<script>alert("rb")</script>' in dom.by_id["warnings"].text
