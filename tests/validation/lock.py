#!/usr/bin/python3
"""Regenerate tests/validation/expected_values.csv, the values the ctest label "validation" locks.

    /usr/bin/python3 tests/validation/lock.py --workbench build/workbench/app/workbench
                                               [--out-dir DIR] [--expected FILE]

Runs every shipped validation case (scenarios/validation/case1_R{300,500,700,900}_{kec,lut},
case2_{kec,lut}, case3_{kec,lut}) unchanged with the given binary into DIR (default: a folder
"validation_lock" beside the binary's build tree), reduces them as docs/validation.md does (paper
Tables 5 and 6, Eq. (33) of case 3) and writes the expected file with its provenance: the commit
of this tree (+dirty when tracked files outside docs/ differ from it), the date, the binary's
build type, the workbench version and this command. Use a Release build of a committed tree, so
the recorded commit names the code that produced the values.
"""
import argparse
import os
import shlex
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import locked  # noqa: E402


def default_out_dir(workbench: str) -> str:
    d = os.path.dirname(os.path.abspath(workbench))
    while d != os.path.dirname(d) and not os.path.exists(os.path.join(d, "CMakeCache.txt")):
        d = os.path.dirname(d)
    base = d if os.path.exists(os.path.join(d, "CMakeCache.txt")) else "/tmp"
    return os.path.join(base, "validation_lock")


def collect(workbench: str, out_dir: str):
    rows = []
    for case in locked.CASE1 + locked.CASE2:
        print(f"running {case} ...", flush=True)
        rows += locked.steady_values(case, locked.run_case(workbench, case, out_dir))
    paths = []
    for case in locked.CASE3:
        print(f"running {case} ...", flush=True)
        paths.append(locked.run_case(workbench, case, out_dir))
    rows += locked.eq33_values(*paths)
    return rows


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--workbench", required=True)
    ap.add_argument("--out-dir")
    ap.add_argument("--expected", default=locked.EXPECTED)
    args = ap.parse_args(argv)
    out_dir = args.out_dir or default_out_dir(args.workbench)
    try:
        rows = collect(args.workbench, out_dir)
    except (RuntimeError, OSError) as e:
        print(f"lock.py: {e}", file=sys.stderr)
        return 1
    script = os.path.relpath(os.path.abspath(__file__), locked.ROOT)
    wb = os.path.abspath(args.workbench)
    wb = os.path.relpath(wb, locked.ROOT) if wb.startswith(locked.ROOT + os.sep) else wb
    command = " ".join(["/usr/bin/python3", script, "--workbench", shlex.quote(wb)])
    locked.write_expected(args.expected, rows, locked.provenance_lines(args.workbench, command))
    print(f"wrote {args.expected}: {len(rows)} values (results in {out_dir})")
    return 0


if __name__ == "__main__":
    sys.exit(main())
