"""`workbench effects SCENARIO.lua`: the table and figure of what each optional effect of a scene
costs and changes (docs/effects.md). Run by the workbench after the cases ran:

    plots/rbplot effects DIR [--workbench BIN] [--root ROOT] [--quantities y,yaw]
                             [--cost-set run.duration=2] [--no-callgrind]

DIR holds the study of the command (summary_cases.csv, the case files) and effects_scene.csv (the
scene's effects and their states). For every case:
  cost      instructions per right-hand-side evaluation from callgrind (the case's command line run
            again under valgrind --tool=callgrind with --toggle-collect on rb::integ::integrate, for
            the simulated time of --cost-set; effects.py) less the result-file flushes (their
            number follows wall time), their difference to the full scene, and the CPU time per
            evaluation (median over the repeats) beside it;
  change    max and RMS difference against the full scene of every wheelset's quantities
            (the engine's summary_errors.csv: workbench/study/reference_errors.hpp, on the
            full scene's output times);
  check     the effect is on in the full scene's result and off in its case's result (the root
            attribute `effects`, /elements, /bodies/*/ax, the patch datasets, /assessment).
Writes DIR/effects.csv and DIR/effects.png and prints the table.
"""
from __future__ import annotations

import csv
import json
import math
import os
import subprocess
import sys
import tempfile
from typing import Dict, List, Optional

import h5py
import numpy as np

from .common import parser, read_csv
from .effects import callgrind_total, flush_instructions
from .provenance import ROOT
from .study_data import QUANTITY_TAGS, Case, StudyError, close_all, load_study

PROG = "effects"


# Whether an effect is on in a result file, per effect name (workbench/scenario/effect_names.hpp).
def _effects_attr(f) -> List[str]:
    v = f.attrs.get("effects", b"")
    v = v.decode() if isinstance(v, bytes) else str(v)
    return [x for x in v.split("\n") if x]


def _any_dataset(f, group: str, leaf: str) -> bool:
    found = []

    def visit(name, obj):
        if name.rsplit("/", 1)[-1] == leaf and isinstance(obj, h5py.Dataset):
            found.append(name)
            return True
        return None

    if group in f:
        f[group].visititems(visit)
    return bool(found)


def _scopes(f) -> List:
    """Where a vehicle's outputs are: the file's root, or each /vehicles/<name> of a train."""
    vehicles = f.get("vehicles")
    if isinstance(vehicles, h5py.Group):
        return [g for g in vehicles.values() if isinstance(g, h5py.Group)]
    return [f]


def _patches(g) -> bool:
    return _any_dataset(g, "contact", "patch0") or any(
        k.startswith("patch") for ws in g.get("contact", {}).values()
        if isinstance(ws, h5py.Group) for side in ws.values() if isinstance(side, h5py.Group)
        for k in side.keys())


# A vehicle's outputs are checked in every vehicle of a train: an effect is on when any has it.
VEHICLE_CHECKS = {
    # A suspension element's group has a deflection; an external force's (always written) not.
    "element_outputs": lambda g: "elements" in g and any(
        isinstance(e, h5py.Group) and "deflection" in e for e in g["elements"].values()),
    "patches": _patches,
    "body_accelerations": lambda g: _any_dataset(g, "bodies", "ax"),
    "assessment": lambda g: "assessment" in g and len(g["assessment"]) > 0,
    # The track under the rail: /contact/<ws>/<side>/track/rail_z.
    "track_support": lambda g: _any_dataset(g, "contact", "rail_z"),
}

CHECKS = {
    "irregularities": lambda f: "irregularities" in _effects_attr(f),
    "bump_stops": lambda f: "suspension:bumpstop" in _effects_attr(f),
    "series_dampers": lambda f: "suspension:series_damper" in _effects_attr(f),
    "creep_forces": lambda f: any(e.startswith("creep:") and e != "creep:none"
                                  for e in _effects_attr(f)),
    **{name: (lambda f, c=check: any(c(g) for g in _scopes(f)))
       for name, check in VEHICLE_CHECKS.items()},
}


def effect_state(path: str, name: str) -> Optional[bool]:
    """True/False: the effect is on/off in the result file; None: cannot tell."""
    check = CHECKS.get(name)
    if check is None or not path or not os.path.exists(path):
        return None
    try:
        with h5py.File(path, "r") as f:
            return bool(check(f))
    except OSError:
        return None


def verify(case: Case, measured: List[str], off: List[str]) -> str:
    """'ok' when every measured effect is on in the case's result except those in `off`."""
    if not case.file or not os.path.exists(case.file):
        return "no result"
    wrong = []
    for name in measured:
        want = name not in off
        got = effect_state(case.file, name)
        if got is None:
            wrong.append(f"{name}: cannot tell")
        elif got != want:
            wrong.append(f"{name} {'on' if got else 'off'} (expected {'on' if want else 'off'})")
    return "ok" if not wrong else "WRONG: " + "; ".join(wrong)


# Instructions per evaluation under callgrind.
def _cost_overrides(raw: str, cost_set: str) -> List[str]:
    """The case's overrides with its run length replaced by the cost run's."""
    keep = [o for o in raw.split() if not o.startswith(("run.duration=", "run.distance="))]
    return keep + ([cost_set] if cost_set else [])


def _case_hash(path: str) -> str:
    try:
        with h5py.File(path, "r") as f:
            v = f.attrs.get("input_hash", b"")
            return v.decode() if isinstance(v, bytes) else str(v)
    except OSError:
        return ""


def callgrind_case(row: dict, outdir: str, a) -> Dict[str, str]:
    """{instructions, rhs_evals, note} of one case, from the cache DIR/callgrind/<case>.json when its
    input hash and cost length match."""
    cache_dir = os.path.join(outdir, "callgrind")
    os.makedirs(cache_dir, exist_ok=True)
    cache = os.path.join(cache_dir, row["case"] + ".json")
    key = dict(input_hash=_case_hash(row.get("file", "")), cost_set=a.cost_set,
               method="integration without result-file flushes")
    if os.path.exists(cache):
        try:
            with open(cache) as f:
                old = json.load(f)
            if old.get("key") == key and key["input_hash"]:
                return old["value"]
        except (OSError, ValueError, KeyError):
            pass
    env = dict(os.environ)
    env.setdefault("RAILBENCH_TABLE_CACHE", os.path.join(outdir, ".table-cache"))
    with tempfile.TemporaryDirectory(prefix="rb_effects_cg_") as tmp:
        out = os.path.join(tmp, "run.h5")
        cg = os.path.join(tmp, "run.cg")
        cmd = ["valgrind", "--tool=callgrind", f"--callgrind-out-file={cg}",
               "--toggle-collect=rb::integ::integrate*", a.workbench, "--root", a.root,
               "run", row["base"], "--out", out, "--quiet"]
        for ov in _cost_overrides(row.get("overrides", ""), a.cost_set):
            cmd += ["--set", ov]
        try:
            r = subprocess.run(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True,
                               env=env)
        except OSError as e:
            return dict(instructions="", rhs_evals="", note=f"callgrind: {e}")
        if r.returncode != 0 or not os.path.exists(out) or not os.path.exists(cg):
            tail = r.stderr.strip().splitlines()[-1:] if r.stderr else []
            return dict(instructions="", rhs_evals="",
                        note=f"callgrind run failed (exit {r.returncode}) {' '.join(tail)}"[:200])
        with h5py.File(out, "r") as h:
            evals = int(h["stats"].attrs["rhs_evals"])
        flush = flush_instructions(cg)
        value = dict(instructions=str(callgrind_total(cg) - flush), rhs_evals=str(evals),
                     flush=str(flush), note="")
    with open(cache, "w") as f:
        json.dump(dict(key=key, value=value), f)
    return value


# The table.
def _fmt(v, f="{:.4g}") -> str:
    return "" if v is None or (isinstance(v, float) and not math.isfinite(v)) else f.format(v)


def _quantities(text: str) -> List[str]:
    tags = {v: k for k, v in QUANTITY_TAGS.items()}
    return [tags[q] for q in text.split(",") if q in tags]


def case_rows(study, scene: List[dict], a) -> List[dict]:
    measured = [s["effect"] for s in scene if s["state"] == "measured"]
    raw = {r["case"]: r for r in read_csv(os.path.join(a.study_dir, "summary_cases.csv"))}
    base = next((c for c in study.cases if c.role == "baseline"), None)
    quantities = _quantities(a.quantities)
    rows = []
    for c in study.cases:
        off = [k.split(".", 2)[2] for k, v in c.overrides.items()
               if k.startswith("run.effects.") and v == "false"]
        effect = "(full scene)" if c.role == "baseline" else (
            "(all of them)" if c.role == "minimal" else ",".join(off))
        evals = c.counts.get("rhs_evals", 0.0)
        row = dict(effect=effect, case=c.id, label=c.label, role=c.role, status=c.status,
                   check=verify(c, measured, off) if c.ok else "", rhs_evals=int(evals),
                   cpu_us_per_eval=c.cpu / evals * 1e6 if evals and c.ok else None,
                   instructions_per_eval=None, note=c.message if not c.ok else "")
        if not a.no_callgrind and c.id in raw:
            cg = callgrind_case(raw[c.id], a.study_dir, a)
            if cg["instructions"]:
                row["instructions_per_eval"] = int(cg["instructions"]) / int(cg["rhs_evals"])
            row["note"] = (row["note"] + " " + cg["note"]).strip()
        # A failed run keeps its partial result: the change is then over the time both ran.
        # (the engine's error against the full scene: summary_errors.csv)
        e = study.errors_of(c, "baseline") if base is not None else None
        errs = e[1] if e is not None else None
        for q in quantities:
            tag = QUANTITY_TAGS[q]
            e = (errs or {}).get(q)
            row[f"max_d{tag}"] = e[0] if e else None
            row[f"rms_d{tag}"] = e[1] if e else None
            row[f"unit_{tag}"] = e[2] if e else ""
        rows.append(row)
    b = next((r for r in rows if r["role"] == "baseline"), None)
    for r in rows:
        for k, pct in (("instructions_per_eval", "d_instructions_pct"),
                       ("cpu_us_per_eval", "d_cpu_pct")):
            ref = b.get(k) if b else None
            v = r.get(k)
            r[k.replace("_per_eval", "_saved_per_eval") if k == "instructions_per_eval" else
              "cpu_us_saved_per_eval"] = ref - v if (ref and v is not None) else None
            r[pct] = (ref - v) / ref * 100.0 if (ref and v is not None) else None
    for s in scene:
        if s["state"] != "measured":
            rows.append(dict(effect=s["effect"], role=s["state"], status=s["state"],
                             note=s["help"]))
    return rows


COLUMNS = ["effect", "label", "role", "status", "check", "rhs_evals", "instructions_per_eval",
           "instructions_saved_per_eval", "d_instructions_pct", "cpu_us_per_eval",
           "cpu_us_saved_per_eval", "d_cpu_pct"]


def write_csv(rows: List[dict], path: str, quantities: List[str]) -> None:
    cols = list(COLUMNS)
    for q in quantities:
        t = QUANTITY_TAGS[q]
        cols += [f"max_d{t}", f"rms_d{t}", f"unit_{t}"]
    cols += ["case", "note"]
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=cols, extrasaction="ignore")
        w.writeheader()
        for r in rows:
            w.writerow({k: (_fmt(v, "{:.6g}") if isinstance(v, float) else
                            ("" if v is None else v)) for k, v in r.items()})


def print_table(rows: List[dict], quantities: List[str]) -> None:
    head = f"{'effect switched off':22s} {'status':9s} {'instr/eval':>11s} {'saved':>10s} " \
           f"{'saved %':>7s} {'CPU us/eval':>11s} {'saved %':>7s}"
    for q in quantities:
        t = QUANTITY_TAGS[q]
        head += f" {'max d' + t:>10s} {'rms d' + t:>10s}"
    print(head + "  check")
    for r in rows:
        if r.get("role") in ("always on", "off in the scene"):
            print(f"{r['effect']:22s} {r['note']}")
            continue
        line = (f"{r['effect'][:22]:22s} {r['status'][:9]:9s} "
                f"{_fmt(r['instructions_per_eval'], '{:.0f}'):>11s} "
                f"{_fmt(r['instructions_saved_per_eval'], '{:.0f}'):>10s} "
                f"{_fmt(r['d_instructions_pct'], '{:.1f}'):>7s} "
                f"{_fmt(r['cpu_us_per_eval'], '{:.2f}'):>11s} {_fmt(r['d_cpu_pct'], '{:.1f}'):>7s}")
        for q in quantities:
            t = QUANTITY_TAGS[q]
            line += (f" {_fmt(r.get(f'max_d{t}'), '{:.3g}'):>10s}"
                     f" {_fmt(r.get(f'rms_d{t}'), '{:.3g}'):>10s}")
        print(line + "  " + (r.get("check") or r.get("note", ""))[:120])
    def unit(q):
        t = QUANTITY_TAGS[q]
        return next((r.get("unit_" + t) for r in rows if r.get("unit_" + t)), "-")
    units = ", ".join(f"d{QUANTITY_TAGS[q]} in {unit(q)}" for q in quantities)
    print(f"(saved = full scene minus case; change in answer against the full scene over every "
          f"wheelset: {units})")


def figure(rows: List[dict], path: str, quantities: List[str]) -> None:
    from .style import A4_WIDTH_IN, FAIL_COLOR, plt, report_style
    cases = [r for r in rows if r.get("role") in ("effect_off", "minimal")]
    if not cases:
        return
    use_cg = any(r.get("instructions_saved_per_eval") is not None for r in cases)
    key = "d_instructions_pct" if use_cg else "d_cpu_pct"
    tag = QUANTITY_TAGS[quantities[0]] if quantities else None
    with report_style():
        fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(A4_WIDTH_IN, 0.5 + 0.32 * len(cases) + 1.0),
                                       sharey=True)
        y = np.arange(len(cases))
        cost = [r.get(key) if r.get(key) is not None else 0.0 for r in cases]
        colors = ["#1f5fa8" if r.get("status") == "ok" else FAIL_COLOR for r in cases]
        ax1.barh(y, cost, color=colors)
        ax1.set_yticks(y, [r["effect"] if r["role"] != "minimal" else "minimal (all off)"
                           for r in cases])
        ax1.invert_yaxis()
        ax1.set_xlabel(("instructions" if use_cg else "CPU time") +
                       " / evaluation saved when off\n[% of the full scene]")
        for yi, v in zip(y, cost):
            ax1.annotate(f"{v:.1f}", (v, yi), xytext=(3 if v >= 0 else -3, 0),
                         textcoords="offset points", va="center", ha="left" if v >= 0 else "right",
                         fontsize=7)
        ax1.axvline(0, color="#222222", lw=0.6)
        if tag:
            mx = [r.get(f"max_d{tag}") or 0.0 for r in cases]
            rms = [r.get(f"rms_d{tag}") or 0.0 for r in cases]
            unit = next((r.get(f"unit_{tag}") for r in cases if r.get(f"unit_{tag}")), "")
            ax2.barh(y - 0.18, mx, height=0.36, color="#b2182b", label="max")
            ax2.barh(y + 0.18, rms, height=0.36, color="#e08214", label="RMS")
            ax2.set_xlabel(f"change in answer: {quantities[0]}\nvs the full scene [{unit}]")
            for yi, v in zip(y, mx):
                ax2.annotate(f"{v:.3g}", (v, yi - 0.18), xytext=(3, 0), textcoords="offset points",
                             va="center", fontsize=7)
            # A free row above the bars for the legend.
            ax1.set_ylim(len(cases) - 0.5, -1.3)
            ax2.legend(loc="upper right", ncol=2)
            ax2.margins(x=0.15)
            ax1.margins(x=0.15)
        fig.suptitle("What each effect costs and changes (workbench effects)")
        fig.tight_layout()
        fig.savefig(path)
        plt.close(fig)


def main(argv=None) -> int:
    ap = parser(PROG, __doc__.split("\n\n")[0])
    ap.add_argument("study_dir")
    ap.add_argument("--workbench", default=os.path.join(ROOT, "build", "workbench", "app",
                                                        "workbench"))
    ap.add_argument("--root", default=ROOT)
    ap.add_argument("--quantities", default="y,yaw")
    ap.add_argument("--cost-set", default="run.duration=2",
                    help="the run length override of each callgrind run")
    ap.add_argument("--no-callgrind", action="store_true")
    a = ap.parse_args(argv)
    scene_csv = os.path.join(a.study_dir, "effects_scene.csv")
    try:
        study = load_study(a.study_dir)
        scene = read_csv(scene_csv) if os.path.exists(scene_csv) else []
    except StudyError as e:
        print(f"railbench {PROG}: {e}", file=sys.stderr)
        return 1
    quantities = _quantities(a.quantities)
    rows = case_rows(study, scene, a)
    close_all()
    write_csv(rows, os.path.join(a.study_dir, "effects.csv"), quantities)
    print_table(rows, quantities)
    figure(rows, os.path.join(a.study_dir, "effects.png"), quantities)
    print(os.path.join(a.study_dir, "effects.csv"))
    wrong = [r for r in rows if str(r.get("check", "")).startswith("WRONG")]
    if wrong:
        print(f"railbench {PROG}: {len(wrong)} case(s) did not switch what they measure "
              f"(column check)", file=sys.stderr)
    return 0
