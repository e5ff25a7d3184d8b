#!/usr/bin/python3
"""Draw the report figures of one railbench result file.

usage: /usr/bin/python3 plots/plot_run.py RESULT.h5 [--outdir DIR] [--dpi N]

Writes <stem>_<figure>.png (default: next to RESULT.h5) for every figure the file's content
allows and prints the written paths, one per line.  When the file has /stats, a one-line run
summary starting with "stats: " is printed first (status, solver, CPU time, real-time factor
t_reached / cpu_time_s, rhs evaluations, steps).  A failed run (/stats status "failed") is still
plotted up to where it stopped, with "FAILED at t = ... s: <message>" in red above every figure's
title.  On a missing or invalid file it prints one line "plot_run: error: ..." to stderr and
exits with status 1.
"""
import argparse
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

import railbench_plots as rp  # noqa: E402


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(prog="plot_run",
                                 description="Draw report figures from a railbench HDF5 result.")
    ap.add_argument("result", help="result file (.h5) written by railbench")
    ap.add_argument("--outdir", default=None,
                    help="output folder (default: the folder of RESULT)")
    ap.add_argument("--dpi", type=int, default=rp.DPI, help=f"resolution (default {rp.DPI})")
    args = ap.parse_args(argv)
    try:
        res = rp.load_result(args.result)
        paths = rp.make_figures(res, outdir=args.outdir, dpi=args.dpi)
    except rp.ResultFileError as e:
        print(f"plot_run: error: {e}", file=sys.stderr)
        return 1
    except OSError as e:  # e.g. unwritable output folder
        print(f"plot_run: error: {e.strerror or e}: {e.filename or ''}".rstrip(": "),
              file=sys.stderr)
        return 1
    summary = rp.stats_summary(res)
    if summary:
        print(summary)
    for p in paths:
        print(p)
    if not paths:
        print("plot_run: note: nothing to plot in this file", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
