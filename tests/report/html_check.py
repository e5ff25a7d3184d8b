"""What the report tests share: a short run and its report, the page parsed with Python's
html.parser (elements, their attributes and text by id, unbalanced tags), the checks that it is
self-contained and holds no active content, and headless Chromium (Debian's `chromium`)."""
import base64
import os
import re
import shutil
import subprocess
from html.parser import HTMLParser
from typing import Dict, List, Optional, Tuple

VOID = {"area", "base", "br", "col", "embed", "hr", "img", "input", "link", "meta", "source",
        "track", "wbr"}
# Elements that run code, embed other documents or load resources: none belongs in a report.
ACTIVE = {"script", "iframe", "frame", "object", "embed", "applet", "link", "base", "form",
          "input", "button", "video", "audio", "source", "svg", "math", "template"}
URL_ATTRS = {"src", "href", "srcset", "action", "formaction", "data", "poster", "background",
             "cite", "longdesc", "usemap", "xlink:href", "ping"}


class Element:
    def __init__(self, tag: str, attrs: Dict[str, Optional[str]], parent: Optional["Element"]):
        self.tag, self.attrs, self.parent = tag, attrs, parent
        self.children: List["Element"] = []
        self.text_parts: List[str] = []

    @property
    def text(self) -> str:
        """The text of the element and everything under it."""
        return "".join(self.text_parts)

    def find_all(self, tag: str) -> List["Element"]:
        out = []
        for c in self.children:
            if c.tag == tag:
                out.append(c)
            out += c.find_all(tag)
        return out


class Page(HTMLParser):
    """A parsed page: .root (a tree of Element), .by_id, .elements (every start tag in order),
    .problems (unbalanced or stray end tags), .doctype."""

    def __init__(self, text: str):
        super().__init__(convert_charrefs=True)
        self.root = Element("#document", {}, None)
        self.stack = [self.root]
        self.elements: List[Element] = []
        self.by_id: Dict[str, Element] = {}
        self.problems: List[str] = []
        self.doctype = ""
        self.feed(text)
        self.close()
        if len(self.stack) > 1:
            self.problems.append("unclosed: " + " ".join(e.tag for e in self.stack[1:]))

    def handle_decl(self, decl):
        self.doctype = decl

    def handle_starttag(self, tag, attrs):
        el = Element(tag, dict(attrs), self.stack[-1])
        self.stack[-1].children.append(el)
        self.elements.append(el)
        if el.attrs.get("id"):
            if el.attrs["id"] in self.by_id:
                self.problems.append(f"duplicate id {el.attrs['id']}")
            self.by_id[el.attrs["id"]] = el
        if tag not in VOID:
            self.stack.append(el)

    def handle_startendtag(self, tag, attrs):
        self.handle_starttag(tag, attrs)
        if tag not in VOID:
            self.stack.pop()

    def handle_endtag(self, tag):
        if tag in VOID:
            return
        if self.stack[-1].tag != tag:
            self.problems.append(f"</{tag}> closes <{self.stack[-1].tag}>")
            if any(e.tag == tag for e in self.stack[1:]):
                while self.stack[-1].tag != tag:
                    self.stack.pop()
            else:
                return
        self.stack.pop()

    def handle_data(self, data):
        for el in self.stack[1:]:
            el.text_parts.append(data)

    def tags(self, tag: str) -> List[Element]:
        return [e for e in self.elements if e.tag == tag]


def foreign_references(page: Page) -> List[str]:
    """Everything that would make the page load, run or link something outside itself: active
    elements, event-handler attributes, URL attributes other than data: images and in-page
    anchors, url() and @import in style, and a refresh."""
    bad = []
    for e in page.elements:
        if e.tag in ACTIVE:
            bad.append(f"<{e.tag}> element")
        for k, v in e.attrs.items():
            v = v or ""
            if k.startswith("on"):
                bad.append(f"<{e.tag} {k}=...> event handler")
            elif k in URL_ATTRS:
                if e.tag == "img" and k == "src" and v.startswith("data:image/png;base64,"):
                    continue
                if e.tag == "a" and k == "href" and v.startswith("#"):
                    continue
                bad.append(f"<{e.tag} {k}={v[:60]!r}>")
            elif k == "style" and re.search(r"url\s*\(|@import|expression", v, re.I):
                bad.append(f"<{e.tag} style={v[:60]!r}>")
        if e.tag == "meta" and (e.attrs.get("http-equiv") or "").lower() == "refresh":
            bad.append("<meta http-equiv=refresh>")
    for st in page.tags("style"):
        if re.search(r"url\s*\(|@import", st.text, re.I):
            bad.append("url() or @import in <style>")
    return bad


def png_of(img: Element) -> bytes:
    """The PNG bytes of a data: URI image (AssertionError when it is not one)."""
    src = img.attrs.get("src") or ""
    prefix = "data:image/png;base64,"
    assert src.startswith(prefix), f"img src {src[:40]!r} is not a data: PNG"
    data = base64.b64decode(src[len(prefix):], validate=True)
    assert data.startswith(b"\x89PNG\r\n\x1a\n"), "img data is not a PNG"
    return data


def png_size(data: bytes) -> Tuple[int, int]:
    """(width, height) from a PNG's IHDR."""
    return int.from_bytes(data[16:20], "big"), int.from_bytes(data[20:24], "big")


# ---- a run and its report ----------------------------------------------------------------------

ROOT = os.path.abspath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
SCENE = "scenarios/default/case3_kec_fast.lua"
# [s] at 20 m/s: 180 m over the tangent, the transition and into the curve, so the EN 14363 table
# has three sections and the stability criterion its 100 m.
DURATION = 9.0


def workbench() -> str:
    """The program: $RAILBENCH_WORKBENCH, else build/workbench/app/workbench."""
    return os.environ.get("RAILBENCH_WORKBENCH") or \
        os.path.join(ROOT, "build", "workbench", "app", "workbench")


def run_and_report(result: str, page: str, duration: float = DURATION) -> None:
    """`workbench run` of SCENE for `duration` into `result`, then `plots/rbplot report` of it
    into `page` (RuntimeError with the output when either fails)."""
    wb = workbench()
    if not os.access(wb, os.X_OK):
        raise RuntimeError(f"no workbench program at {wb} (set RAILBENCH_WORKBENCH)")
    cmd = [wb, "run", SCENE, "--out", result, "--quiet", "--set", f"run.duration={duration:g}"]
    r = subprocess.run(cmd, cwd=ROOT, env=dict(os.environ, RAILBENCH_ROOT=ROOT),
                       capture_output=True, text=True, timeout=300, stdin=subprocess.DEVNULL)
    if r.returncode != 0:
        raise RuntimeError(f"{' '.join(cmd)} exited {r.returncode}:\n{r.stdout}{r.stderr}")
    rbplot_report(result, page)


def rbplot_report(result: str, page: str) -> None:
    cmd = [os.path.join(ROOT, "plots", "rbplot"), "report", result, "--out", page]
    r = subprocess.run(cmd, capture_output=True, text=True, timeout=300)
    if r.returncode != 0 or r.stdout.strip() != page:
        raise RuntimeError(f"{' '.join(cmd)} exited {r.returncode}:\n{r.stdout}{r.stderr}")


# ---- headless Chromium -------------------------------------------------------------------------

def chromium() -> Optional[str]:
    """The browser: $RAILBENCH_CHROMIUM when set (None when that is no program: the browser
    tests skip), else Debian's `chromium` (or another Chromium/Chrome) on PATH; None when
    absent."""
    given = os.environ.get("RAILBENCH_CHROMIUM")
    if given is not None:
        return given if given and os.access(given, os.X_OK) else None
    for name in ("chromium", "chromium-browser", "google-chrome"):
        p = shutil.which(name)
        if p:
            return p
    return None


# The checker a copy of the page gets (the report itself has no script, and its policy allows
# none): allowed by its nonce alone, so any script the page itself held would still be refused
# and reported as a policy violation. On load it writes what it found into <pre id="rb-check">.
CHECK_NONCE = "rbcheck"
CHECK_SCRIPT = """<script nonce="%s">
(function () {
  var errors = [], violations = [];
  window.addEventListener('error', function (e) {
    errors.push(String(e.message || e.type));
  }, true);
  document.addEventListener('securitypolicyviolation', function (e) {
    violations.push(e.violatedDirective + ' ' + e.blockedURI);
  });
  window.addEventListener('load', function () {
    var imgs = Array.prototype.slice.call(document.querySelectorAll('figure img'));
    var rows = document.querySelectorAll('#en14363-sections tbody tr');
    var out = {
      images: imgs.length,
      decoded: imgs.filter(function (i) { return i.complete && i.naturalWidth > 0; }).length,
      sizes: imgs.map(function (i) { return [i.naturalWidth, i.naturalHeight]; }),
      figures: document.querySelectorAll('figure').length,
      section_rows: rows.length,
      summary_rows: document.querySelectorAll('#assessment-summary tbody tr').length,
      scripts: document.scripts.length,
      errors: errors, violations: violations,
      title: document.title,
      height: document.documentElement.scrollHeight
    };
    var pre = document.createElement('pre');
    pre.id = 'rb-check';
    pre.textContent = JSON.stringify(out);
    document.body.appendChild(pre);
  });
})();
</script>""" % CHECK_NONCE


def instrumented(page_html: str) -> str:
    """The page with CHECK_SCRIPT right after its Content-Security-Policy, the policy allowing
    that script by its nonce (and nothing else more)."""
    m = re.search(r'<meta http-equiv="Content-Security-Policy" content="([^"]*)">', page_html)
    assert m, "the page has no Content-Security-Policy"
    policy = m.group(1) + f"; script-src 'nonce-{CHECK_NONCE}'"
    tag = f'<meta http-equiv="Content-Security-Policy" content="{policy}">'
    return page_html[:m.start()] + tag + CHECK_SCRIPT + page_html[m.end():]


def run_chromium(binary: str, args: List[str], timeout: float = 120) -> subprocess.CompletedProcess:
    """Headless Chromium with a throw-away profile; stdout and stderr as text."""
    import tempfile
    with tempfile.TemporaryDirectory(prefix="rb_chromium_") as profile:
        cmd = [binary, "--headless", "--disable-gpu", "--no-sandbox", "--no-first-run",
               "--disable-extensions", "--disable-background-networking", "--mute-audio",
               f"--user-data-dir={profile}", *args]
        env = dict(os.environ, HOME=profile)
        return subprocess.run(cmd, capture_output=True, text=True, timeout=timeout, env=env)
