"""Regenerates every run-derived table and figure of docs/ (studies.md, performance.md,
validation.md, hard_cases.md, integrators.md, assessment.md) from the outputs of `./wb studies`: no number that
comes from a run is typed into docs/ by hand.

    plots/rbplot docs OUT_DIR [--build BUILD_DIR] [--docs DOCS_DIR]

OUT_DIR holds one folder per study (efficiency_case3, flange_stiffness, refinement,
work_precision, effects, speed, each with the study_*.csv / *.png of `plots/rbplot study`; validation,
with the validation_*.csv of `plots/rbplot validation-tables`, and the result files of cases 2
and 3 whose /assessment/summary docs/assessment.md shows; the block draws the assessment figure of
case 3 KEC into the folder as study_case3_kec_assessment.png), bench_wagon.json (Google Benchmark,
one wagon evaluation and its parts) and bench_integrators.json (the integrators' overhead). BUILD_DIR/hard/hard_cases.csv is the hard-case suite's
record; BUILD_DIR/dynamics/coupling_*.csv (written by the coupling refinement tests of
test_dynamics and test_dynamics_long) feed the block of docs/contact_dynamics.md, which is left
as it is when they are missing and can be regenerated alone:

    plots/rbplot docs - --build BUILD_DIR --only contact_dynamics

Every generated block sits between the markers

    <!-- generated: NAME (plots/rbplot docs) -->
    ...
    <!-- end: NAME -->

in the markdown files: the text around them is written by hand and is kept; a block whose input
is missing is replaced by a line saying so (never by stale numbers). Every other block starts
with a stamp naming the git commit (and date) its runs were made with, from the provenance
records written when the runs were made (OUT_DIR/<study>/provenance.json and
OUT_DIR/<benchmark>.provenance.json by `./wb studies`, the `commit` column of hard_cases.csv by
tests/hard/hard_cases.py; `plots/rbplot provenance`); runs of a tree with uncommitted changes are
stamped as such. Figures are copied to docs/figures/<study>_<name>.png.
"""
from __future__ import annotations

import os
import re
import shutil
import sys
from typing import Dict, List, Optional

from . import provenance
from .common import parser
from .docs_blocks import ROUTE, route_sections_block, assessment_cases_block, accuracy_block, bench_block, bench_integrators_block, effects_block, efficiency_block, fmt, missing, num, read_csv, paper_settings_block, refinement_block, replace_block, speed_block, default_run_block, march_block, table, work_precision_block
from .docs_paper import PAPER_TABLES, flange_paper_block, paper_table_blocks, tables_9_10_block
from .docs_stability import FOLDERS as STABILITY, stability_blocks
from .docs_stress import stress_hard_block
from .docs_sweeps import SWEEP, THROUGHPUT, TRAIN_BRAKING, TRAIN_SCALING, TRAIN_SCALING_COUPLED, TURNOUT, sweep_blocks
from .docs_three_asks import EFFECTS, PRECISION, STRESS, STRESS_KEC, three_asks_blocks
from .docs_three_way import FOLDER as THREE_WAY, three_way_blocks
from .docs_tables import tables_block
from .docs_validation import hard_block, hard_detail_block, hard_rows, validation_blocks


# Where the runs behind each block were recorded: a study folder of OUT_DIR, a benchmark
# (BENCH_OUTPUTS) or "hard" (the hard-case record). A block not listed here is stamped from
# OUT_DIR/provenance.json (the `./wb studies` invocation).
BLOCK_SOURCES = {
    "efficiency": "efficiency_case3", "accuracy": "efficiency_case3",
    "flange": "flange_stiffness", "flange_paper": "flange_stiffness",
    "flange_accuracy": "flange_stiffness", "refinement": "refinement",
    "paper_tables9_10": "refinement",
    **{f"paper_table{spec.no}": spec.study for spec in PAPER_TABLES}, "work_precision": "work_precision", "hard_cases": "hard",
    "hard_cases_detail": "hard", "effects": "effects", "speed": "speed", "default_scene": "default_scene",
    "default_run": "default_run", "march": "march", "bench": "bench",
    "paper_settings": "paper_settings", "paper_settings_flange": "paper_settings_flange",
    "bench_integrators": "bench_integrators",
    "validation_case1": "validation", "validation_case2": "validation",
    "validation_case3": "validation", "validation_cost": "validation",
    "coupling_convergence": "build", "assessment_cases": "validation", "route_sections": ROUTE, "tables_summary": "tables",
    "stress_hard": "build", "three_asks_precision": PRECISION, "three_asks_stress": STRESS,
    "three_asks_stress_kec": STRESS_KEC, "three_asks_effects": EFFECTS,
    "stability_wagon": ("stability_kec", "stability_lut"), "stability_modes":
    ("stability_kec", "stability_lut"), "stability_method": STABILITY,
    "stability_verification": "build", SWEEP: SWEEP, THROUGHPUT: THROUGHPUT,
    TRAIN_SCALING: TRAIN_SCALING, TRAIN_BRAKING: TRAIN_BRAKING, TURNOUT: TURNOUT,
    TRAIN_SCALING_COUPLED: TRAIN_SCALING_COUPLED,
    **{b: THREE_WAY for b in ("three_way_steady", "three_way_extremes", "three_way_dynamic",
                              "three_way_cost", "three_way_trial",
                              "three_way_constants")},
}


# Benchmark sources: their JSON output (and provenance record) in OUT_DIR.
BENCH_OUTPUTS = {"bench": "bench_wagon", "bench_integrators": "bench_integrators"}


def source_files(name: str, outdir: str, build: str) -> List[str]:
    """The files whose modification says a block's runs were made anew: its study folders'
    provenance records, a benchmark's record, or the hard-case record; [] for the blocks of the
    build tree's tests and of the invocation's own record."""
    src = BLOCK_SOURCES.get(name)
    if src == "hard":
        return [os.path.join(build, "hard", "hard_cases.csv")]
    if src in (None, "build"):
        return []
    if isinstance(src, tuple):
        return [os.path.join(outdir, f, "provenance.json") for f in src]
    if src in BENCH_OUTPUTS:
        return [os.path.join(outdir, BENCH_OUTPUTS[src] + ".provenance.json")]
    return [os.path.join(outdir, src, "provenance.json")]


def made_since(name: str, outdir: str, build: str, since: float) -> bool:
    """Whether a block's runs were made at or after `since` (seconds since the epoch)."""
    return any(os.path.exists(f) and os.path.getmtime(f) >= since
               for f in source_files(name, outdir, build))


def block_provenance(name: str, outdir: str, build: str) -> List[dict]:
    src = BLOCK_SOURCES.get(name)
    if src == "build":  # written by the tests of the build tree now being documented
        return [provenance.current()]
    if src == "hard":
        seen = []
        for r in hard_rows(build):
            e = provenance.from_tag(r.get("commit") or "", r.get("run_date") or "")
            if not r.get("commit"):
                return []  # a record from before the suite wrote its commit: unknown
            if e not in seen:
                seen.append(e)
        return seen
    if isinstance(src, tuple):  # several folders: every run they name
        seen = []
        for folder in src:
            for e in provenance.read(os.path.join(outdir, folder, "provenance.json")):
                if e not in seen:
                    seen.append(e)
        return seen
    if src in BENCH_OUTPUTS:
        return provenance.read(os.path.join(outdir, BENCH_OUTPUTS[src] + ".provenance.json"))
    if src:
        return provenance.read(os.path.join(outdir, src, "provenance.json"))
    return provenance.read(os.path.join(outdir, "provenance.json"))


# ---- normal-force coupling (docs/contact_dynamics.md section 4.1) -------------------------------

COUPLING_CASES = (  # (csv under BUILD/dynamics, what it is, where it comes from)
    ("coupling_case3", "case 3 (wagon, 20 m/s, R = 500 m, ORE B176 low, KEC), first 9 s",
     "test_dynamics, Coupling.StepHalvingConvergesWithTheDefaultCoupling"),
)


def source_commit() -> str:
    """The commit of the source tree the numbers were generated in (with '+ uncommitted changes'
    when tracked files outside docs/ differ from it)."""
    import subprocess
    root = provenance.ROOT
    try:
        head = subprocess.run(["git", "-C", root, "rev-parse", "--short", "HEAD"], check=True,
                              capture_output=True, text=True).stdout.strip()
        dirty = subprocess.run(["git", "-C", root, "status", "--porcelain", "--untracked-files=no",
                                "--", ".", ":!docs"],
                               check=True, capture_output=True, text=True).stdout.strip()
    except (OSError, subprocess.CalledProcessError):
        return "unknown commit"
    return f"commit {head}" + (" + uncommitted changes" if dirty else "")


def coupling_block(build: str) -> Optional[str]:
    """Step-halving differences of RK4 with both couplings and their cost per evaluation, from the
    CSVs the tests write; None when no CSV exists."""
    parts = []
    for name, what, src in COUPLING_CASES:
        path = os.path.join(build, "dynamics", name + ".csv")
        rows = read_csv(path)
        if not rows:
            continue
        body = []
        for r in rows:
            d = num(r["diff_to_half_step_mm"])
            it = num(r["iterations_per_solve"])
            body.append([r["coupling"], f"{num(r['step_ms']):g}",
                         fmt(d, "{:.2g}") if d is not None else "–",
                         f"{num(r['cpu_s']):.2f}", r["rhs_evals"], f"{num(r['us_per_rhs']):.1f}",
                         fmt(it, "{:.2f}") if it else "–"])
        parts.append(f"**{what}** ({src}):\n\n" + table(
            ["coupling", "RK4 step h [ms]", "d(h) [mm]", "CPU [s]", "rhs evals",
             "µs / rhs", "Phi evaluations per wheelset solve"], body))
    if not parts:
        return None
    # The build folder as the reader's checkout names it (relative to the repository root).
    shown = os.path.relpath(os.path.abspath(build), provenance.ROOT)
    return (f"From `{shown}/dynamics/coupling_*.csv`:\n\n" + "\n\n".join(parts))


# ---- figures -----------------------------------------------------------------------------------

STUDIES = ("efficiency_case3", "flange_stiffness", "refinement", "work_precision", "effects",
           "speed", "default_scene", "paper_settings_flange", "paper_settings", "validation", "tables", PRECISION,
           STRESS_KEC, STRESS, EFFECTS, SWEEP, ROUTE, THREE_WAY, TURNOUT) + STABILITY


def copy_figures(outdir: str, docs: str, pages) -> List[str]:
    """Copies the figures the pages show (`figures/<study>_<name>.png`, from
    OUT/<study>/study_<name>.png, or OUT/<study>/<name>.png) and nothing else."""
    figdir = os.path.join(docs, "figures")
    os.makedirs(figdir, exist_ok=True)
    wanted = set()
    for md in pages:
        path = os.path.join(docs, md)
        if os.path.exists(path):
            with open(path) as f:
                wanted.update(re.findall(r"figures/([\w.+-]+\.png)", f.read()))
    copied = []
    for name in sorted(wanted):
        study = next((st for st in STUDIES if name.startswith(st + "_")), None)
        if study is None:
            continue
        src = os.path.join(outdir, study, "study_" + name[len(study) + 1:])
        if not os.path.exists(src):  # the commands' folders name their figures without "study_"
            src = os.path.join(outdir, study, name[len(study) + 1:])
        if os.path.exists(src):
            dst = os.path.join(figdir, name)
            shutil.copyfile(src, dst)
            copied.append(dst)
        else:
            print(f"railbench docs: {src} missing (figure {name} not updated)", file=sys.stderr)
    return copied


# ---- the pages ---------------------------------------------------------------------------------

def generate(outdir: str, build: str) -> Dict[str, Dict[str, str]]:
    """Every generated block of docs/: page -> block name -> content (without the stamp)."""
    blocks: Dict[str, Dict[str, str]] = {"studies.md": {}, "performance.md": {},
                                         "validation.md": {}, "hard_cases.md": {},
                                         "integrators.md": {}, "assessment.md": {}}
    blocks["studies.md"].update(efficiency_block(outdir))
    blocks["studies.md"].update(paper_table_blocks(outdir))
    blocks["studies.md"]["accuracy"] = accuracy_block(outdir)
    blocks["studies.md"].update(efficiency_block(outdir, "flange_stiffness", "flange"))
    blocks["studies.md"]["flange_paper"] = flange_paper_block(outdir)
    blocks["studies.md"]["flange_accuracy"] = accuracy_block(outdir, "flange_stiffness")
    blocks["studies.md"]["refinement"] = refinement_block(outdir)
    blocks["studies.md"]["paper_tables9_10"] = tables_9_10_block(outdir)
    blocks["studies.md"]["work_precision"] = work_precision_block(outdir)
    blocks["studies.md"]["hard_cases"] = hard_block(build)
    blocks["performance.md"]["effects"] = effects_block(outdir)
    blocks["performance.md"]["speed"] = speed_block(outdir)
    blocks["performance.md"]["default_scene"] = speed_block(outdir, "default_scene")
    blocks["performance.md"]["default_run"] = default_run_block(outdir)
    blocks["performance.md"]["march"] = march_block(outdir)
    blocks["performance.md"]["bench"] = bench_block(outdir)
    for study in ("paper_settings", "paper_settings_flange"):
        blocks["performance.md"][study] = paper_settings_block(outdir, study)
    blocks["validation.md"].update(validation_blocks(outdir))
    blocks["hard_cases.md"]["hard_cases_detail"] = hard_detail_block(build)
    blocks["integrators.md"]["bench_integrators"] = bench_integrators_block(outdir)
    blocks["assessment.md"]["assessment_cases"] = assessment_cases_block(outdir)
    blocks["assessment.md"]["route_sections"] = route_sections_block(outdir)
    blocks["contact_geometry.md"] = {"tables_summary": tables_block(outdir)}
    blocks["stress.md"] = {"stress_hard": stress_hard_block(build)}
    blocks["three_asks.md"] = three_asks_blocks(outdir)
    blocks["three_way.md"] = three_way_blocks(outdir)
    blocks["stability.md"] = stability_blocks(outdir, build)
    for md, items in sweep_blocks(outdir).items():
        blocks.setdefault(md, {}).update(items)
    coupling = coupling_block(build)
    blocks["contact_dynamics.md"] = {"coupling_convergence": coupling if coupling is not None
                                     else missing(f"{build}/dynamics/coupling_*.csv "
                                                  "(ctest -R Coupling, test_dynamics)")}
    return blocks


def main(argv=None) -> int:
    ap = parser("docs", __doc__.split("\n\n")[0])
    ap.add_argument("outdir")
    ap.add_argument("--build", default="build")
    ap.add_argument("--docs", default=os.path.join(provenance.ROOT, "docs"))
    ap.add_argument("--only", choices=("contact_dynamics",),
                    help="regenerate only the blocks of docs/NAME.md (inputs from --build, no "
                         "studies needed)")
    ap.add_argument("--since", type=float, metavar="EPOCH",
                    help="rewrite only the blocks whose runs were made at or after this time "
                         "(`./wb studies --only`: the other blocks keep what an earlier run "
                         "wrote)")
    ap.add_argument("--pages", nargs="+", metavar="PAGE",
                    help="rewrite only these pages (e.g. validation.md hard_cases.md) after a "
                         "partial ./wb studies run; the other pages keep their blocks")
    a = ap.parse_args(argv)
    coupling = coupling_block(a.build)
    if a.only == "contact_dynamics":
        if coupling is None:
            print(f"railbench docs: no {a.build}/dynamics/coupling_*.csv (run test_dynamics)",
                  file=sys.stderr)
            return 1
        path = os.path.join(a.docs, "contact_dynamics.md")
        with open(path) as f:
            text = replace_block(f.read(), "coupling_convergence", coupling,
                                 provenance.stamp([provenance.current()]))
        with open(path, "w") as f:
            f.write(text)
        print(f"updated {path}")
        return 0
    blocks = generate(a.outdir, a.build)
    if a.pages:
        unknown = [p for p in a.pages if p not in blocks]
        if unknown:
            print(f"railbench docs: no generated page {unknown} (pages: {sorted(blocks)})",
                  file=sys.stderr)
            return 1
        blocks = {md: items for md, items in blocks.items() if md in a.pages}
    for md, items in blocks.items():
        path = os.path.join(a.docs, md)
        if not os.path.exists(path):  # a docs folder without this page: nothing to write into
            print(f"railbench docs: {path} missing (its blocks not written)", file=sys.stderr)
            continue
        with open(path) as f:
            text = f.read()
        for name, body in items.items():
            if a.since is not None and not made_since(name, a.outdir, a.build, a.since):
                continue
            stamp = provenance.stamp(block_provenance(name, a.outdir, a.build))
            try:
                text = replace_block(text, name, body, stamp)
            except KeyError as e:
                print(f"railbench docs: {path}: {e}", file=sys.stderr)
                return 1
        with open(path, "w") as f:
            f.write(text)
        print(f"updated {path}")
    for p in copy_figures(a.outdir, a.docs, blocks):
        print(f"copied {p}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
