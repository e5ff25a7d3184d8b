#!/usr/bin/python3
"""Figures and tables of a railbench study (called by `workbench study` when the study ends).

usage: /usr/bin/python3 plots/plot_study.py STUDY_OUTDIR [--dpi N]

Reads STUDY_OUTDIR/summary.csv, summary_cases.csv and the case result files, and writes into
STUDY_OUTDIR (what applies to the study):
    study_cost.csv / .png              every case: CPU time (median, min, max, each repeat),
                                       evaluations, steps, µs per evaluation, contact table build
                                       time and size; figure = paper Fig. 23 (Tables 7, 12-16):
                                       groups = solver settings, bars = models, failed = red
    study_failures.csv                 every run that is not ok, with its reason
    study_tables.png                   table build time and size, when refined tables are in it
    study_accuracy_lut_vs_kec.csv/.png LUT vs KEC with the same solver: max / mean |dy| of each
                                       wheelset and Eq. 33 (paper Table 8)
    study_lut_integrators.png          LUT at one K with every solver (paper Fig. 24)
    study_lut_stiffness_<solver>.png   LUT flange indentation / force per K (paper Fig. 25)
    study_work_precision.csv           error against the reference case (max, RMS) of wheelset y,
                                       yaw, normal force and lateral creep force
    study_work_precision{,_rms}.png    error vs CPU time, log-log
    study_effects.csv / .png           µs per evaluation of every variant vs the baseline
and prints the written paths, one per line.  Exit status 1 with one line on stderr when the
folder is not a study folder.
"""
import argparse
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

import railbench_plots as rp  # noqa: E402
import railbench_study as rs  # noqa: E402


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(prog="plot_study", description="Figures of a railbench study.")
    ap.add_argument("outdir", help="study output folder (with summary.csv)")
    ap.add_argument("--dpi", type=int, default=rp.DPI, help=f"resolution (default {rp.DPI})")
    args = ap.parse_args(argv)
    try:
        paths = rs.make_study_outputs(args.outdir, dpi=args.dpi)
    except rs.StudyError as e:
        print(f"plot_study: error: {e}", file=sys.stderr)
        return 1
    except OSError as e:
        print(f"plot_study: error: {e.strerror or e}: {e.filename or ''}".rstrip(": "),
              file=sys.stderr)
        return 1
    for p in paths:
        print(p)
    return 0


if __name__ == "__main__":
    sys.exit(main())
