"""The report of one run or study: one self-contained HTML page
(`rbplot report RESULT.h5 [--out FILE]`, `rbplot report STUDY_DIR`).

    run_report(path, dpi=REPORT_DPI) -> str      the page of a result file
    study_report(outdir, dpi=REPORT_DPI) -> str  the page of a study folder (its cases, the
                                                 tables and figures of `rbplot study`)
    main(argv)                                   the command (exit 0, or 1 with one error line)

The page holds, from the result file alone (docs/report.md):
    - the run: status (ok / FAILED, with the failure record of /stats), the stats line of
      `rbplot run`, and every warning of /stats@warnings;
    - the scene: the provenance attributes of the file's root (program version, creation time,
      scenario file, overrides, effects, seeds), the scenario's text and the text of every file
      it required (/@scenario_text, /@scenario_modules);
    - the assessment (/assessment, docs/assessment.md): the summary (value, limit, margin,
      verdict, where), EN 14363 per track section (each quantity's worst wheel or wheelset, its
      limit and margin, and the position of that wheel), ride comfort (EN 12299 N_MV, Sperling's
      Wz) and running stability with their caveats, the notes and assumptions the run wrote;
    - every figure `rbplot run` draws for the file (run.FIGURES), embedded as base64 PNG.

Nothing outside the page is referenced (no script, no style sheet, no font, no image file), so
the page can be mailed or archived alone. Every string read from the file is HTML-escaped (a
result file may be forged: tests/hostile/forge_result.py `html_injection`), and the page's
Content-Security-Policy allows no script and no resource but its own data: images.
"""
from __future__ import annotations

import base64
import datetime
import html
import os
import tempfile
from typing import Dict, Iterable, List, Optional, Sequence, Tuple

from .assessment import (SECTION_COLUMNS, SUMMARY_BY_KEY, Assessment, read_assessment,
                         summary_items)
from .common import guarded, parser
from .h5 import ResultFileError
from .layout import _num
from .result import Result, load_result
from .run import FIGURES, make_figures, stats_summary

REPORT_DPI = 110  # a figure 6.5 in wide is 715 px: a screen's column, a few hundred kB each

# The root attributes shown as the scene's provenance, in this order (others follow sorted).
PROVENANCE_KEYS = ("scenario_file", "version", "created", "overrides", "effects", "seeds",
                   "contact_method", "solver", "compact")
# Long texts shown as blocks of their own, not in the provenance table.
TEXT_KEYS = ("scenario_text", "scenario_modules")

# The EN 14363 quantities per section: attribute key, heading, scale to the display unit,
# digits, unit.
SECTION_QUANTITIES = tuple((key, SUMMARY_BY_KEY[key].label if key in SUMMARY_BY_KEY else label,
                            scale, 3 if scale == 1.0 else 1, "" if scale == 1.0 else "kN")
                           for key, label, scale, _ in SECTION_COLUMNS)

CSP = ("default-src 'none'; img-src data:; style-src 'unsafe-inline'; base-uri 'none'; "
       "form-action 'none'")

STYLE = """
body { font-family: "DejaVu Sans", Arial, sans-serif; font-size: 14px; color: #222;
       max-width: 1200px; margin: 1.5em auto; padding: 0 1em; line-height: 1.4; }
h1 { font-size: 1.5em; margin-bottom: 0.2em; } h2 { font-size: 1.25em; margin-top: 1.6em;
     border-bottom: 1px solid #bbb; } h3 { font-size: 1.05em; margin-top: 1.2em; }
.meta { color: #555; font-size: 0.9em; }
table { border-collapse: collapse; margin: 0.5em 0 1em 0; font-size: 0.88em; }
th, td { border: 1px solid #ccc; padding: 3px 6px; text-align: left; vertical-align: top; }
th { background: #eef2f7; } td.num { text-align: right; white-space: nowrap; }
.ok { color: #1b7837; font-weight: bold; } .bad { color: #d00000; font-weight: bold; }
.sub { color: #555; font-size: 0.85em; display: block; white-space: nowrap; }
.caveat { background: #fff8e5; border-left: 4px solid #e0a800; padding: 0.4em 0.8em; }
.status-ok { background: #e6f4ea; border-left: 4px solid #1b7837; padding: 0.4em 0.8em; }
.status-failed { background: #fde8e8; border-left: 4px solid #d00000; padding: 0.4em 0.8em; }
pre { background: #f6f6f6; border: 1px solid #ddd; padding: 0.6em; overflow-x: auto;
      font-size: 0.82em; white-space: pre-wrap; word-break: break-word; }
figure { margin: 1em 0 2em 0; } figure img { max-width: 100%; border: 1px solid #ddd; }
figcaption { color: #444; font-size: 0.9em; }
nav ul { columns: 2; }
.wide { overflow-x: auto; }
"""


# ---- escaping ----------------------------------------------------------------------------------

def esc(v) -> str:
    """`v` as text, HTML-escaped (quotes too): every string from the file goes through here."""
    return html.escape(v if isinstance(v, str) else str(v), quote=True)


def _text(v) -> str:
    """An attribute as one string: a list or array of values joined by newlines."""
    if isinstance(v, str):
        return v
    try:
        import numpy as np
        if isinstance(v, np.ndarray):
            from .h5 import _str
            return "\n".join(_str(x) for x in v.reshape(-1)[:1000])
    except ImportError:  # pragma: no cover (numpy is always there)
        pass
    return str(v)


def _fmt(v: Optional[float], digits: int, scale: float = 1.0) -> str:
    return "–" if v is None else f"{v * scale:.{digits}f}"


def _table(headers: Sequence[str], rows: Iterable[Sequence[str]], table_id: str = "",
           row_ids: Optional[Sequence[str]] = None) -> str:
    """A table; headers are plain text (escaped), cells are HTML made here from escaped parts."""
    out = [f'<table id="{esc(table_id)}">' if table_id else "<table>", "<thead><tr>"]
    out += [f"<th>{esc(h)}</th>" for h in headers]
    out.append("</tr></thead><tbody>")
    for k, row in enumerate(rows):
        rid = f' data-row="{esc(row_ids[k])}"' if row_ids else ""
        out.append(f"<tr{rid}>" + "".join(
            c if c.startswith("<td") else f"<td>{c}</td>" for c in row) + "</tr>")
    out.append("</tbody></table>")
    return "".join(out)


def _num_cell(text: str) -> str:
    return f'<td class="num">{text}</td>'


def _verdict(ok: Optional[bool]) -> str:
    if ok is None:
        return ""
    return '<span class="ok">ok</span>' if ok else '<span class="bad">EXCEEDED</span>'


def _ok(v) -> Optional[bool]:
    """An _ok attribute (0/1) as a bool; None when absent or not a number."""
    if isinstance(v, bool):
        return v
    n = _num(v)
    return None if n is None else n != 0


# ---- the run -----------------------------------------------------------------------------------

def _run_section(result: Result) -> str:
    st = result.stats or {}
    status = _text(st.get("status", "")).strip() or "unknown"
    failed = result.failed
    out = ['<section id="run"><h2>Run</h2>']
    cls = "status-failed" if failed else ("status-ok" if status == "ok" else "caveat")
    line = stats_summary(result) or "the file has no /stats: the run did not finish writing it"
    out.append(f'<p class="{cls}" id="status">status <b>{esc(status.upper() if failed else status)}'
               f"</b><br>{esc(line)}</p>")
    if failed:
        rows = []
        for key in ("failure_kind", "failure_reason", "failure_body", "failure_t", "failure_s",
                    "message"):
            v = st.get(key)
            if v is not None and _text(v).strip():
                rows.append([esc(key), esc(_text(v))])
        if rows:
            out.append(_table(["failure record (/stats)", "value"], rows, "failure"))
    warnings = [w for w in _text(st.get("warnings", "")).split("\n") if w.strip()]
    out.append(f'<h3>Warnings ({len(warnings)})</h3>')
    if warnings:
        out.append('<ul id="warnings">' + "".join(f"<li>{esc(w)}</li>" for w in warnings) +
                   "</ul>")
    else:
        out.append('<p id="warnings">none (/stats@warnings is empty)</p>')
    out.append("</section>")
    return "\n".join(out)


# ---- the scene ---------------------------------------------------------------------------------

def _scene_section(result: Result) -> str:
    a = result.attrs
    keys = [k for k in PROVENANCE_KEYS if k in a]
    keys += sorted(k for k in a if k not in PROVENANCE_KEYS and k not in TEXT_KEYS)
    rows = [[esc(k), f"<pre>{esc(_text(a[k]))}</pre>" if "\n" in _text(a[k]) else esc(_text(a[k]))]
            for k in keys]
    out = ['<section id="scene"><h2>Scene</h2>',
           "<p>As the result file records it (attributes of its root group): the scene is "
           "rerun from its text with <code>workbench run</code>.</p>",
           _table(["provenance", "value"], rows, "provenance")]
    text = _text(a.get("scenario_text", ""))
    out.append("<h3>Scenario text</h3>")
    out.append(f'<pre id="scenario-text">{esc(text)}</pre>' if text.strip() else
               '<p id="scenario-text">the file records no scenario text</p>')
    modules = _text(a.get("scenario_modules", ""))
    if modules.strip():
        n = sum(1 for ln in modules.split("\n") if ln.startswith("-- file: "))
        files = "the file" if n == 1 else f"the {n} files"
        out.append(f"<details><summary>The text of {files} the scenario required</summary>"
                   f'<pre id="scenario-modules">{esc(modules)}</pre></details>')
    out.append("</section>")
    return "\n".join(out)


# ---- the assessment ----------------------------------------------------------------------------

def _where_at(where: str, at: Optional[float]) -> str:
    parts = [esc(" ".join(where.split()))] if where.strip() else []
    if at is not None:
        parts.append(f"s = {at:.1f} m")
    return ", ".join(parts)


def _summary_table(a: Assessment, sfx: str = "") -> str:
    rows = []
    for it in summary_items(a.summary):
        q = it.quantity
        unit = "" if q.unit == "-" else q.unit
        margin = None if it.limit is None else it.limit - it.value
        at = _num(a.summary.get(q.key + "_at_s"))
        rows.append([esc(q.label), esc(unit), _num_cell(esc(it.number(it.value))),
                     _num_cell("–" if it.limit is None else esc(it.number(it.limit))),
                     _num_cell("–" if margin is None else esc(it.number(margin))),
                     _verdict(it.ok), _where_at(it.where, at)])
    if not rows:
        return "<p>/assessment/summary holds no quantity.</p>"
    return _table(["quantity", "unit", "value", "limit", "margin", "", "where"], rows,
                  "assessment-summary" + sfx)


def _section_cell(attrs: Dict[str, object], key: str, scale: float, digits: int) -> str:
    v = _num(attrs.get(key))
    if v is None:
        return '<td class="num">–</td>'
    lim = _num(attrs.get(key + "_limit"))
    ok = _ok(attrs.get(key + "_ok"))
    if ok is None and lim is not None:
        ok = v <= lim
    value = f"{v * scale:.{digits}f}"
    head = f'<span class="bad">{value}</span>' if ok is False else value
    sub = []
    if lim is not None:
        sub.append(f"limit {lim * scale:.{digits}f}")
        sub.append(f"margin {(lim - v) * scale:.{digits}f}" + (" EXCEEDED" if ok is False else ""))
    where = _where_at(_text(attrs.get(key + "_where", "")), _num(attrs.get(key + "_at_s")))
    if where:
        sub.append(where)
    return ('<td class="num">' + head + "".join(f'<span class="sub">{s}</span>' for s in sub) +
            "</td>")


def _sections_table(a: Assessment, sfx: str = "") -> str:
    if not a.sections:
        return (f'<p id="en14363-sections{sfx}">The file has no /assessment/sections (a result '
                "written before the assessment was made per section): the summary above is "
                "the whole run.</p>")
    rows, ids, notes = [], [], []
    for sec in a.sections:
        s = sec.attrs
        r, lo, hi, cant = sec.get("radius"), sec.get("from"), sec.get("to"), sec.get("cant")
        kind = _text(s.get("kind", ""))
        rng = "–" if lo is None or hi is None else f"{lo:.0f}–{hi:.0f}"
        row = [esc(sec.name), esc(kind), esc(_text(s.get("zone", ""))),
               _num_cell("∞" if kind == "tangent" else _fmt(r, 0)),
               _num_cell(_fmt(cant, 0, 1e3)), _num_cell(rng),
               _num_cell(_fmt(sec.get("covered"), 0))]
        row += [_section_cell(s, key, scale, digits)
                for key, _, scale, digits, _ in SECTION_QUANTITIES]
        rows.append(row)
        ids.append(sec.name)
        note = _text(s.get("notes", "")).strip()
        if note:
            notes.append(f"<li><b>{esc(sec.name)}</b>: {esc(note)}</li>")
    heads = ["section", "kind", "test zone", "R [m]", "cant [mm]", "s [m]", "run [m]"]
    heads += [label + (f" [{unit}]" if unit else "") for _, label, _, _, unit in SECTION_QUANTITIES]
    out = '<div class="wide">' + _table(heads, rows, "en14363-sections" + sfx, ids) + "</div>"
    if notes:
        out += "<p>Notes per section:</p><ul>" + "".join(notes) + "</ul>"
    return out


def _comfort_table(a: Assessment, sfx: str = "") -> str:
    if not a.comfort:
        return ""
    rows, indicative = [], []
    for pos, q in a.comfort.items():
        at = q.attrs
        n_mv, limit = _num(at.get("n_mv")), _num(at.get("limit"))
        ok = _ok(at.get("ok"))
        if ok is None and n_mv is not None and limit is not None:
            ok = n_mv <= limit
        blocks = _num(at.get("blocks"))
        if blocks is not None and blocks < 60:
            indicative.append(f"{esc(pos)}: {blocks:.0f}")
        rows.append([esc(pos), _num_cell(_fmt(_num(at.get("x_offset")), 2)),
                     _num_cell(_fmt(n_mv, 2)), _num_cell(_fmt(limit, 2)),
                     _num_cell("–" if n_mv is None or limit is None else f"{limit - n_mv:.2f}"),
                     _verdict(ok), _num_cell(_fmt(blocks, 0)),
                     _num_cell(_fmt(_num(at.get("wz_lateral")), 2)),
                     _num_cell(_fmt(_num(at.get("wz_vertical")), 2))]
                    + [_num_cell(_fmt(_num(at.get(f"a_{ax}95")), 3)) for ax in "xyz"])
    out = ["<h3>Ride comfort (EN 12299, Sperling)</h3>",
           _table(["floor position", "x offset [m]", "N_MV", "target", "margin", "",
                   "5 s blocks", "Wz lateral", "Wz vertical", "a_x95 [m/s²]", "a_y95 [m/s²]",
                   "a_z95 [m/s²]"], rows, "comfort" + sfx)]
    caveats = ["N_MV and Wz are checked against comfort targets (run.assessment.comfort_limit; "
               "Wz 2.5), not normative limits."]
    if indicative:
        caveats.append("Mean comfort from fewer than the 60 blocks of 5 s EN 12299 asks for "
                       f"(blocks: {', '.join(indicative)}) is indicative: its verdict is not "
                       "the standard's.")
    out.append(f'<p class="caveat" id="comfort-caveats{sfx}">' + "<br>".join(caveats) + "</p>")
    return "\n".join(out)


def _stability_table(a: Assessment, sfx: str = "") -> str:
    if not a.stability:
        return ""
    rows = []
    for (bogie, pos), q in a.stability.items():
        at = q.attrs
        v, lim = _num(at.get("value")), _num(at.get("limit"))
        ok = _ok(at.get("ok"))
        if ok is None and v is not None and lim is not None:
            ok = v <= lim
        mass = _num(at.get("bogie_mass"))
        rows.append([esc(bogie), esc(pos), _num_cell(_fmt(v, 3)), _num_cell(_fmt(lim, 2)),
                     _num_cell("–" if v is None or lim is None else f"{lim - v:.2f}"),
                     _verdict(ok), _num_cell(_fmt(_num(at.get("at_s")), 1)),
                     _num_cell(_fmt(_num(at.get("f0")), 2)),
                     _num_cell(_fmt(mass, 2, 1e-3))])
    return "\n".join([
        "<h3>Running stability (EN 14363 simplified method)</h3>",
        _table(["bogie", "over", "max sliding rms [m/s²]", "limit [m/s²]", "margin", "",
                "at s [m]", "f0 [Hz]", "bogie mass [t]"], rows, "stability" + sfx),
        f'<p class="caveat" id="stability-caveats{sfx}">The bogie-frame lateral acceleration above '
        "each wheelset, band-pass filtered to f0 ± 2 Hz, its 100 m sliding rms against "
        "(12 − m+/5)/2; the filter type is an assumption (docs/assessment.md), and a run "
        "shorter than 100 m is not assessed.</p>"])


def _lines_block(title: str, text: str, block_id: str, open_: bool = False) -> str:
    lines = [ln for ln in text.split("\n") if ln.strip()]
    if not lines:
        return ""
    items = "".join(f"<li>{esc(ln)}</li>" for ln in lines)
    return (f"<details{' open' if open_ else ''}><summary>{esc(title)} ({len(lines)})</summary>"
            f'<ul id="{block_id}">{items}</ul></details>')


def _assessment_part(a: Optional[Assessment], heading: str, anchor: str) -> str:
    """One assessment's section; the ids of its parts end in the anchor's number (a vehicle of a
    train: "assessment-2" gives "en14363-sections-2"), none for the run's only one."""
    sfx = anchor[len("assessment"):]
    out = [f'<section id="{esc(anchor)}"><h2>{esc(heading)}</h2>']
    if a is None:
        out.append("<p>The file has no /assessment: the scene asked for none "
                   "(run.assessment), or the run ended before writing it.</p></section>")
        return "\n".join(out)
    items = summary_items(a.summary)
    exceeded = [it.quantity.label for it in items if it.ok is False]
    if items:
        cls, txt = (("status-failed", "EXCEEDED: " + ", ".join(exceeded)) if exceeded else
                    ("status-ok", "every assessed limit kept"))
        out.append(f'<p class="{cls}" id="verdict{sfx}">{esc(txt)}</p>')
    params = []
    for key, label in (("category", "vehicle category"), ("alpha", "alpha"),
                       ("yq_limit", "(Y/Q) limit"), ("mu", "mu"),
                       ("flange_angle", "flange angle [rad]"),
                       ("instability_frequency", "instability frequency f0 [Hz]"),
                       ("comfort_limit", "comfort target"), ("sample_every", "sampled every [s]"),
                       ("q0_source", "Q0")):
        if key in a.attrs:
            v = a.attrs[key]
            params.append(f"{esc(label)} {esc(_text(v) if _num(v) is None else f'{_num(v):.4g}')}")
    if params:
        out.append(f'<p class="meta" id="assessment-parameters{sfx}">' + " · ".join(params) +
                   "</p>")
    out.append("<h3>Summary (the worst of the run)</h3>")
    out.append(_summary_table(a, sfx))
    out.append("<h3>EN 14363 per track section</h3>")
    out.append("<p>Each quantity is that of the section's worst wheel (ΣY: wheelset), with its "
               "limit, the margin (limit − value) and where it occurs: the wheel and the "
               "distance s, in that wheel's own arc length, at which the 2 m window holding it "
               "ends. <i>run</i> is the length of the section the leading wheelset ran; Y_qst "
               "and Q_qst are assessed in curves (and given sections) only.</p>")
    out.append(_sections_table(a, sfx))
    out.append(_comfort_table(a, sfx))
    out.append(_stability_table(a, sfx))
    std = _text(a.attrs.get("standards", "")).strip()
    if std:
        out.append(f'<p class="meta">standards: {esc(std)}</p>')
    out.append(_lines_block("Notes of the assessment", _text(a.attrs.get("notes", "")),
                            "assessment-notes" + sfx, open_=True))
    out.append(_lines_block("Assumptions", _text(a.attrs.get("assumptions", "")),
                            "assessment-assumptions" + sfx))
    out.append("</section>")
    return "\n".join(p for p in out if p)


def _assessments(result: Result) -> List[Tuple[str, str, Optional[Assessment]]]:
    """(heading, anchor, Assessment or None) of the run, or of each vehicle of a train."""
    if not result.vehicles:
        a = read_assessment(result.path) if "assessment" in result.groups else None
        return [("Assessment", "assessment", a)]
    out = []
    for k, name in enumerate(result.vehicles):
        a = read_assessment(result.path, f"/vehicles/{name}")
        out.append((f"Assessment of vehicle {name}", f"assessment-{k + 1}", a))
    return out


# ---- figures -----------------------------------------------------------------------------------

def _figure_name(path: str, stem: str) -> Tuple[str, str]:
    """(vehicle, suffix) of a figure file make_figures wrote as <stem>[_<vehicle>]_<suffix>."""
    base = os.path.splitext(os.path.basename(path))[0][len(stem) + 1:]
    for spec in sorted(FIGURES, key=lambda s: -len(s.suffix)):
        if base == spec.suffix:
            return "", spec.suffix
        if base.endswith("_" + spec.suffix):
            return base[:-len(spec.suffix) - 1], spec.suffix
    return "", base


def _figures_section(result: Result, dpi: int) -> Tuple[str, List[str]]:
    """The figures of `rbplot run`, drawn into a scratch folder and embedded; the section's HTML
    and the figure ids."""
    describe = {s.suffix: s.description for s in FIGURES}
    out, ids = ['<section id="figures"><h2>Figures</h2>'], []
    with tempfile.TemporaryDirectory(prefix="rbreport_") as tmp:
        stem = "fig"
        paths = make_figures(result, outdir=tmp, stem=stem, dpi=dpi)
        for k, p in enumerate(paths):
            vehicle, suffix = _figure_name(p, stem)
            with open(p, "rb") as f:
                data = base64.b64encode(f.read()).decode("ascii")
            fid = f"fig-{k + 1}"
            ids.append(fid)
            what = describe.get(suffix, suffix)
            label = f"{suffix}" + (f" ({vehicle})" if vehicle else "")
            out.append(f'<figure id="{fid}" data-figure="{esc(label)}">'
                       f'<img src="data:image/png;base64,{data}" alt="{esc(label)}: {esc(what)}">'
                       f"<figcaption>Figure {k + 1}: <b>{esc(label)}</b> — {esc(what)}"
                       "</figcaption></figure>")
    if not paths:
        out.append("<p>The file holds nothing to draw.</p>")
    out.append("</section>")
    return "\n".join(out), ids


# ---- the page ----------------------------------------------------------------------------------

def run_report(path: str, dpi: int = REPORT_DPI) -> str:
    """The HTML page of the result file at `path` (ResultFileError when it cannot be read)."""
    result = load_result(path)
    parts = _assessments(result)
    figures, fig_ids = _figures_section(result, dpi)
    name = os.path.basename(path)
    created = _text(result.attrs.get("created", "")).strip()
    nav = [("run", "Run"), ("scene", "Scene")] + [(anchor, heading)
                                                  for heading, anchor, _ in parts]
    nav.append(("figures", f"Figures ({len(fig_ids)})"))
    now = datetime.datetime.now().astimezone().strftime("%Y-%m-%d %H:%M %Z")
    body = [
        f"<h1>Run report: {esc(name)}</h1>",
        f'<p class="meta">{esc(os.path.abspath(path))}' +
        (f" · run created {esc(created)}" if created else "") +
        f" · report written {esc(now)} by <code>rbplot report</code></p>",
        "<nav><ul>" + "".join(f'<li><a href="#{esc(a)}">{esc(t)}</a></li>' for a, t in nav) +
        "</ul></nav>",
        _run_section(result), _scene_section(result),
        *[_assessment_part(a, heading, anchor) for heading, anchor, a in parts],
        figures,
    ]
    return _page(f"railbench report: {name}", body)


# ---- a study's page ----------------------------------------------------------------------------

STUDY_TABLE_ROWS = 500     # rows of a CSV shown on the page (the rest: the CSV file itself)
PNG_MAGIC = b"\x89PNG\r\n\x1a\n"
MAX_PNG_BYTES = 20 << 20


def _csv_table(path: str, table_id: str) -> str:
    from .common import read_csv
    rows = read_csv(path)
    if not rows:
        return f'<p id="{esc(table_id)}">{esc(os.path.basename(path))}: no rows</p>'
    cols: List[str] = []
    for r in rows:
        cols += [k for k in r if k not in cols and k is not None]
    shown = rows[:STUDY_TABLE_ROWS]
    body = [[esc(r.get(c) if isinstance(r.get(c), str) else "") for c in cols] for r in shown]
    more = (f"<p>{len(rows) - len(shown)} more rows in {esc(os.path.basename(path))}.</p>"
            if len(rows) > len(shown) else "")
    return _table(cols, body, table_id) + more


def _folder_files(outdir: str, ext: str) -> List[str]:
    """Regular files (no links) of the folder with this extension, sorted."""
    out = []
    for name in sorted(os.listdir(outdir)):
        p = os.path.join(outdir, name)
        if name.endswith(ext) and not os.path.islink(p) and os.path.isfile(p):
            out.append(p)
    return out


def study_report(outdir: str, dpi: int = REPORT_DPI) -> str:
    """The page of a study folder (`workbench study`): its cases (summary_cases.csv), the failed
    runs, every table (study_*.csv) and figure (*.png) `rbplot study` wrote there (drawn first,
    as `rbplot study` does, when the folder has none)."""
    from .study import make_study_outputs
    from .study_data import StudyError
    if not os.path.isfile(os.path.join(outdir, "summary_cases.csv")):
        raise StudyError(f"{outdir}: no summary_cases.csv (not a study folder)")
    if not any(os.path.basename(p).startswith("study_") for p in _folder_files(outdir, ".png")):
        make_study_outputs(outdir, dpi=dpi)
    name = os.path.basename(os.path.normpath(outdir))
    from .common import read_csv
    cases = read_csv(os.path.join(outdir, "summary_cases.csv"))
    status: Dict[str, int] = {}
    for c in cases:
        st = (c.get("status") or "?") if isinstance(c.get("status"), str) else "?"
        status[st] = status.get(st, 0) + 1
    counts = ", ".join(f"{n} {esc(k)}" for k, n in sorted(status.items()))
    bad = any(k != "ok" for k in status)
    body = [f"<h1>Study report: {esc(name)}</h1>",
            f'<p class="meta">{esc(os.path.abspath(outdir))} · report written '
            f"{esc(datetime.datetime.now().astimezone().strftime('%Y-%m-%d %H:%M %Z'))} by "
            "<code>rbplot report</code></p>",
            f'<section id="cases"><h2>Cases</h2><p class="{"caveat" if bad else "status-ok"}" '
            f'id="status">{len(cases)} cases: {counts}</p>',
            _csv_table(os.path.join(outdir, "summary_cases.csv"), "study-cases"), "</section>"]
    prov = os.path.join(outdir, "provenance.json")
    if os.path.isfile(prov) and not os.path.islink(prov):
        with open(prov, encoding="utf-8", errors="replace") as f:
            body.append('<section id="provenance"><h2>Provenance</h2>'
                        f'<pre id="provenance-json">{esc(f.read(1 << 20))}</pre></section>')
    tables = [p for p in _folder_files(outdir, ".csv")
              if os.path.basename(p).startswith("study_")]
    if tables:
        body.append('<section id="tables"><h2>Tables</h2>')
        for k, p in enumerate(tables):
            body.append(f"<h3>{esc(os.path.basename(p))}</h3>" +
                        _csv_table(p, f"table-{k + 1}"))
        body.append("</section>")
    body.append('<section id="figures"><h2>Figures</h2>')
    n = 0
    for p in _folder_files(outdir, ".png"):
        if os.path.getsize(p) > MAX_PNG_BYTES:
            continue
        with open(p, "rb") as f:
            data = f.read()
        if not data.startswith(PNG_MAGIC):
            continue
        n += 1
        label = os.path.basename(p)
        body.append(f'<figure id="fig-{n}" data-figure="{esc(label)}"><img src="data:image/png;'
                    f'base64,{base64.b64encode(data).decode("ascii")}" alt="{esc(label)}">'
                    f"<figcaption>Figure {n}: {esc(label)}</figcaption></figure>")
    if not n:
        body.append("<p>The folder holds no figure.</p>")
    body.append("</section>")
    return _page(f"railbench study report: {name}", body)


def _page(title: str, body: List[str]) -> str:
    return ("<!DOCTYPE html>\n"
            '<html lang="en"><head><meta charset="utf-8">\n'
            f'<meta http-equiv="Content-Security-Policy" content="{CSP}">\n'
            '<meta name="viewport" content="width=device-width, initial-scale=1">\n'
            f"<title>{esc(title)}</title>\n"
            f"<style>{STYLE}</style></head>\n<body>\n" + "\n".join(body) +
            "\n</body></html>\n")


def main(argv=None) -> int:
    ap = parser("report", "One self-contained HTML page of a run: the scene, status and "
                          "warnings, the assessment (EN 14363 per section, comfort, stability) "
                          "and every figure, embedded.")
    ap.add_argument("input", metavar="FILE",
                    help="result file (.h5) written by `workbench run`, or a study folder")
    ap.add_argument("--out", default=None,
                    help="the page to write (default: <FILE without .h5>_report.html; for a "
                         "study folder DIR/report.html)")
    ap.add_argument("--dpi", type=int, default=REPORT_DPI,
                    help=f"resolution of the figures (default {REPORT_DPI})")
    args = ap.parse_args(argv)
    study = os.path.isdir(args.input)
    out = args.out or (os.path.join(args.input, "report.html") if study else
                       os.path.splitext(args.input)[0] + "_report.html")

    def write() -> int:
        page = study_report(args.input, args.dpi) if study else run_report(args.input, args.dpi)
        tmp = out + ".tmp"
        with open(tmp, "w", encoding="utf-8") as f:
            f.write(page)
        os.replace(tmp, out)
        print(out)
        return 0

    from .study_data import StudyError
    return guarded("report", write, (ResultFileError, StudyError))
