"""Figures and tables of a railbench study folder (written by `workbench study`).

A study folder holds summary.csv (one row per run), summary_cases.csv (one row per case) and one
HDF5 result per run (<case>_r<repeat>.h5).  Everything here reads those and writes PNG + CSV.

Reading
    load_study(outdir) -> Study            cases with their overrides parsed (method,
                                           integrator, tolerance / step, flange stiffness K,
                                           refined tables), runs, status and reason
Analyses (each returns rows = list of dicts; the CSV columns are the dict keys)
    cost_rows(study)                       paper Tables 7, 12-16 (one row per case)
    failure_rows(study)                    every run that is not ok, with its reason
    accuracy_rows(study)                   paper Eq. 33 / Table 8: LUT vs KEC pairs (same solver)
    work_precision_rows(study)             error of every case against its reference case
    effect_rows(study)                     cost per evaluation of each variant vs the baseline
Figures
    fig_cost(study)                        paper Fig. 23 / 26: CPU time and evaluations per case
    fig_accuracy(study, rows)              Table 8 as bars
    fig_lut_integrators(study)             Fig. 24: y, flange indentation and force of the LUT
                                           cases with every integrator at one K
    fig_lut_stiffness(study, solver)       Fig. 25: flange indentation and force per K
    fig_work_precision(rows, stat)         error vs CPU time, log-log, per quantity
    fig_effects(rows)                      microseconds per evaluation per variant
    fig_tables(study)                      contact table build time and size (default/refined)
    make_metric_outputs(outdir, written)   each metric against the swept parameters
                                           (study_metrics.py)
Driver
    make_study_outputs(outdir)             everything that applies; returns the written paths

Case roles (the study file's `role` key in a case): "reference" (work-precision reference,
one per contact model, e.g. on the refined tables), "reference_check" (the reference at a
tighter tolerance: the difference between the two is the reference's own error),
"reference_same_tables" (the reference's settings on the cases' own tables: errors against it
are integration errors only, its difference to the reference is the tables' error),
"baseline" (full model of an effects study).  Reference and case are matched by their model (the overrides that are not
numerical settings: solver.*, profiles.refined_tables, contact.normal_forces, run.output.*,
and the base scenario).

Only numpy, matplotlib (Agg) and h5py are used.
"""
from __future__ import annotations

import os
from typing import List

from .common import guarded, parser, save_figure, write_csv
from .style import DPI
from .study_data import StudyError, close_all, load_study
from .study_cost import accuracy_rows, cost_rows, failure_rows, fig_accuracy, fig_cost, fig_lut_integrators, fig_lut_stiffness, fig_tables
from .study_precision import effect_rows, fig_effects, fig_work_precision, work_precision_rows
from .study_metrics import make_metric_outputs


# Driver
# --------------------------------------------------------------------------------------------
def make_study_outputs(outdir: str, dpi: int = DPI) -> List[str]:
    study = load_study(outdir)
    p = lambda name: os.path.join(outdir, name)  # noqa: E731
    written: List[str] = []
    try:
        write_csv(p("study_cost.csv"), cost_rows(study))
        written.append(p("study_cost.csv"))
        write_csv(p("study_failures.csv"), failure_rows(study))
        written.append(p("study_failures.csv"))
        name = os.path.splitext(os.path.basename(study.study_file))[0]
        save_figure(fig_cost(study, f"Computation cost per case — {name}" if name else ""),
              p("study_cost.png"), written, dpi)
        save_figure(fig_tables(study), p("study_tables.png"), written, dpi)

        acc = accuracy_rows(study)
        if acc:
            write_csv(p("study_accuracy_lut_vs_kec.csv"), acc)
            written.append(p("study_accuracy_lut_vs_kec.csv"))
            save_figure(fig_accuracy(acc), p("study_accuracy_lut_vs_kec.png"), written, dpi)
        save_figure(fig_lut_integrators(study), p("study_lut_integrators.png"), written, dpi)
        for solver in dict.fromkeys(c.solver_key for c in study.cases if c.method == "lut"):
            safe = "".join(ch if ch.isalnum() or ch in "-." else "_" for ch in solver)
            save_figure(fig_lut_stiffness(study, solver), p(f"study_lut_stiffness_{safe}.png"),
                  written, dpi)

        wp = work_precision_rows(study)
        wpi = work_precision_rows(study, "reference_same_tables")
        if wp or wpi:
            write_csv(p("study_work_precision.csv"), wp + wpi)
            written.append(p("study_work_precision.csv"))
        for rows, against, suffix in ((wp, "reference", ""),
                                      (wpi, "reference_same_tables", "_integration")):
            if rows:
                save_figure(fig_work_precision(rows, "max", against),
                      p(f"study_work_precision{suffix}.png"), written, dpi)
                save_figure(fig_work_precision(rows, "rms", against),
                      p(f"study_work_precision{suffix}_rms.png"), written, dpi)

        make_metric_outputs(outdir, written, dpi)

        eff = effect_rows(study)
        if eff:
            write_csv(p("study_effects.csv"), eff)
            written.append(p("study_effects.csv"))
            save_figure(fig_effects(eff), p("study_effects.png"), written, dpi)
    finally:
        close_all()
    return written


def main(argv=None) -> int:
    ap = parser("study", "Figures of a railbench study.")
    ap.add_argument("outdir", help="study output folder (with summary.csv)")
    ap.add_argument("--dpi", type=int, default=DPI, help=f"resolution (default {DPI})")
    args = ap.parse_args(argv)

    def draw() -> int:
        for p in make_study_outputs(args.outdir, dpi=args.dpi):
            print(p)
        return 0

    return guarded("study", draw, (StudyError,))
