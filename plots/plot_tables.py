#!/usr/bin/python3
"""Draw the report figures of a railbench contact-tables file.

usage: /usr/bin/python3 plots/plot_tables.py TABLES.h5 [--outdir DIR] [--dpi N]

TABLES.h5 is written by `workbench tables SCENARIO.lua --out TABLES.h5`.  Writes (default: next
to the file) every figure its groups allow:
    <stem>_profiles_contact.png  wheel and rail in the wheelset frame at a few y, contact points,
                                 KEC-equivalent profile with the knife edge (paper Fig. 1)
    <stem>_lut_z.png             z(y) - z(0), phi(y) per gauge variation, z table (Fig. 7)
    <stem>_kec_map.png           s_w versus s_k, regularised transitions, weight (Fig. 9, 10)
    <stem>_rolling_radius.png    delta r(y), delta gamma(y), two-point contact
    <stem>_conicity.png          EN 15302 tan(gamma_e) versus amplitude
A missing group only skips its figures.  Prints a one-line summary starting with "tables: "
(LUT/KEC build times and sizes, conicity at 3 mm, two-point contact), then the written paths,
one per line.  On a missing, unreadable or broken file it prints one line
"plot_tables: error: ..." to stderr and exits with status 1.
"""
import argparse
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

import railbench_tables as rt  # noqa: E402


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(prog="plot_tables",
                                 description="Draw report figures from a railbench tables file.")
    ap.add_argument("tables", help="tables file (.h5) written by `workbench tables`")
    ap.add_argument("--outdir", default=None,
                    help="output folder (default: the folder of TABLES)")
    ap.add_argument("--dpi", type=int, default=rt.DPI, help=f"resolution (default {rt.DPI})")
    args = ap.parse_args(argv)
    try:
        t = rt.load_tables(args.tables)
        paths = rt.make_figures(t, outdir=args.outdir, dpi=args.dpi)
    except rt.TablesFileError as e:
        print(f"plot_tables: error: {e}", file=sys.stderr)
        return 1
    except OSError as e:  # e.g. unwritable output folder
        print(f"plot_tables: error: {e.strerror or e}: {e.filename or ''}".rstrip(": "),
              file=sys.stderr)
        return 1
    print(rt.summary_line(t))
    for p in paths:
        print(p)
    if not paths:
        print("plot_tables: note: nothing to plot in this file", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
