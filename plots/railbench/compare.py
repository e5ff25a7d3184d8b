"""Overlay the vehicle results of several railbench runs (paper Fig. 17, 19-22; Tables 5, 6).

usage: railbench compare-runs A.h5 B.h5 [C.h5 ...] [--labels KEC,LUT,...]
                                    [--outdir DIR] [--prefix NAME] [--fraction F]

Writes (default: in the folder of A.h5, prefix = the run stems joined by "_vs_")
    <prefix>_compare_wheelsets.png    y [mm] and yaw [mrad] of the wheelsets vs distance
    <prefix>_compare_bogies_car.png   the same for bogies and car body
    <prefix>_steady_state.csv         steady-curving means (one row per run and body)
and prints the written paths, then the steady-curving table: mean lateral displacement [mm]
and yaw angle [mrad] of every body over the last 20 % (--fraction) of the distance it
travelled in each run.  One colour and line style per run; the track of A.h5 is shaded.

Only bodies present in every run are drawn (the others are named on stderr); with none in
common, or on a missing/invalid file, one line "railbench compare-runs: error: ..." goes to stderr and
the exit status is 1.  A failed run is drawn up to where it stopped, marked "(failed)" in the
legend and table, and named in red above the figure titles.

CSV columns: label, file, status, body, kind, y_mm, yaw_mrad, s_from_m, s_to_m, samples.
"""
import csv
import os
import sys

import numpy as np

from .common import error, guarded, note, parser, save_figure
from .h5 import ResultFileError
from .layout import add_failure_banner, failure_text
from .result import load_result
from .run import steady_state
from .style import DPI
from .vehicle_figs import fig_kinematics


class CompareError(Exception):
    pass


def _labels(results, given):
    if given is not None:
        labels = [x.strip() for x in given.split(",")]
        if len(labels) != len(results):
            raise CompareError(f"--labels has {len(labels)} entries for {len(results)} runs")
        if any(not x for x in labels):
            raise CompareError("--labels has an empty entry")
        return labels
    labels = [r.label() for r in results]
    if len(set(labels)) < len(labels):  # e.g. two KEC runs: tell them apart by file stem
        labels = [f"{lab} ({r.stem})" if labels.count(lab) > 1 else lab
                  for lab, r in zip(labels, results)]
    if len(set(labels)) < len(labels):
        labels = [r.path for r in results]
    return labels


def common_bodies(results):
    """Kinematic bodies (with s) present in every run, in the order of the first run."""
    sets = [set(r.kinematic_bodies()) for r in results]
    return [n for n in results[0].kinematic_bodies() if all(n in s for s in sets)]


def _same_track(a, b):
    sa, sb = a.track.segments, b.track.segments
    return all(sa[k].shape == sb[k].shape and np.allclose(sa[k], sb[k]) for k in sa)


def steady_table(results, labels, names, fraction):
    """Rows {label, file, status, body, kind, y_mm, yaw_mrad, s_from_m, s_to_m, samples}."""
    rows = []
    for r, lab in zip(results, labels):
        by = {row["body"]: row for row in steady_state(r, fraction)}
        status = str((r.stats or {}).get("status", "")) or "-"
        for n in names:
            if n in by:
                rows.append(dict(label=lab, file=r.path, status=status, **by[n]))
    return rows


def format_table(rows, labels, names, results, fraction) -> str:
    """Paper Table 6 layout: bodies as columns, a block of rows per quantity and run."""
    failed = {lab for lab, r in zip(labels, results) if r.failed}
    val = {(row["label"], row["body"]): row for row in rows}
    w0 = max(len("yaw [mrad]"), 8)
    w1 = max(len(lab) + (2 if lab in failed else 0) for lab in labels) + 1
    wc = [max(9, len(n) + 1) for n in names]
    out = [f"Steady curving: mean over the last {fraction * 100:g} % of each body's distance"]
    out.append(" " * (w0 + w1 + 2) + "".join(f"{n:>{w}}" for n, w in zip(names, wc)))
    for qty, key in (("y [mm]", "y_mm"), ("yaw [mrad]", "yaw_mrad")):
        for i, lab in enumerate(labels):
            cells = []
            for n, w in zip(names, wc):
                v = val.get((lab, n), {}).get(key, float("nan"))
                cells.append(f"{v:>{w}.4f}" if np.isfinite(v) else f"{'-':>{w}}")
            tag = lab + (" *" if lab in failed else "")
            out.append(f"{qty if i == 0 else '':<{w0}}  {tag:<{w1}}" + "".join(cells))
    if failed:
        out.append("* run failed: its last part is not steady curving")
    return "\n".join(out)


def write_csv(path, rows):
    cols = ["label", "file", "status", "body", "kind", "y_mm", "yaw_mrad", "s_from_m", "s_to_m",
            "samples"]
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(cols)
        for row in rows:
            out = []
            for c in cols:
                v = row[c]
                if c in ("y_mm", "yaw_mrad"):
                    v = f"{v:.4f}" if np.isfinite(v) else "nan"
                elif c in ("s_from_m", "s_to_m"):
                    v = f"{v:.3f}"
                out.append(v)
            w.writerow(out)


def _banner(results, labels):
    txt = []
    for r, lab in zip(results, labels):
        f = failure_text(r)
        if f:
            txt.append(f"{lab}: {f}")
    return "; ".join(txt) or None


def compare(paths, labels=None, outdir=None, prefix=None, fraction=0.2, dpi=DPI, log=None):
    """Load the runs, write the figures and the CSV; return (written paths, table text).
    Notes go to `log` (default: sys.stderr at call time)."""
    log = log or sys.stderr
    if len(paths) < 2:
        raise CompareError("need at least two result files")
    results = [load_result(p) for p in paths]
    for r in results:
        if not r.kinematic_bodies():
            raise CompareError(f"{r.path}: no vehicle bodies with distance (/bodies/<name>/s) "
                               f"to compare")
    labels = _labels(results, labels)
    names = common_bodies(results)
    if not names:
        lists = "; ".join(f"{r.path}: {', '.join(r.kinematic_bodies())}" for r in results)
        raise CompareError(f"the runs have no bodies in common ({lists})")
    others = sorted({n for r in results for n in r.kinematic_bodies()} - set(names))
    if others:
        note("compare-runs", f"not in every run, not compared: {', '.join(others)}", log)
    for r in results[1:]:
        if not _same_track(results[0], r):
            note("compare-runs", f"{r.path} has another track than {results[0].path}; "
                                 f"the segments of the latter are shaded", log)

    ref = results[0]
    ws = [n for n in names if ref.bodies[n].kind == "wheelset"]
    bc = [n for n in names if ref.bodies[n].kind == "bogie"] + \
         [n for n in names if ref.bodies[n].kind == "car"]
    outdir = outdir or os.path.dirname(os.path.abspath(paths[0]))
    prefix = prefix or "_vs_".join(r.stem for r in results)[:80]
    os.makedirs(outdir, exist_ok=True)
    runs = list(zip(results, labels))
    what = " vs ".join(labels)
    banner = _banner(results, labels)
    written = []
    for suffix, sel, title in (
            ("compare_wheelsets", ws, f"Wheelsets: lateral displacement and yaw angle — {what}"),
            ("compare_bogies_car", bc,
             f"Bogies and car body: lateral displacement and yaw angle — {what}")):
        if not sel:
            continue
        fig = fig_kinematics(runs, sel, title)
        if banner:
            add_failure_banner(fig, banner)
        save_figure(fig, os.path.join(outdir, f"{prefix}_{suffix}.png"), written, dpi)
    names = ws + bc  # paper Table 6 order: wheelsets, bogies, car body
    rows = steady_table(results, labels, names, fraction)
    csv_path = os.path.join(outdir, f"{prefix}_steady_state.csv")
    write_csv(csv_path, rows)
    written.append(csv_path)
    return written, format_table(rows, labels, names, results, fraction)


def main(argv=None) -> int:
    ap = parser("compare-runs", "Overlay the vehicle results of several runs.")
    ap.add_argument("results", nargs="+", help="result files (.h5), at least two")
    ap.add_argument("--labels", default=None,
                    help="comma-separated legend labels, one per run (default: contact method)")
    ap.add_argument("--outdir", default=None, help="output folder (default: folder of the first)")
    ap.add_argument("--prefix", default=None,
                    help="output file prefix (default: the run stems joined by _vs_)")
    ap.add_argument("--fraction", type=float, default=0.2,
                    help="steady-state window: last fraction of the distance (default 0.2)")
    ap.add_argument("--dpi", type=int, default=DPI, help=f"resolution (default {DPI})")
    args = ap.parse_args(argv)
    if not 0 < args.fraction <= 1:
        return error("compare-runs", "--fraction must be in (0, 1]")

    def draw() -> int:
        paths, table = compare(args.results, args.labels, args.outdir, args.prefix,
                               args.fraction, args.dpi)
        for p in paths:
            print(p)
        print(table)
        return 0

    return guarded("compare-runs", draw, (CompareError, ResultFileError))
