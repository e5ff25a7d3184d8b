#!/usr/bin/python3
"""One ctest test of the label "validation" (tests/validation/README.md).

    check.py --workbench BIN --out-dir DIR --case CASE [--expected FILE]

CASE is a shipped scenario of scenarios/validation/ (case1_R300_kec, ..., case2_lut, case3_kec,
case3_lut) or case3_eq33. Cases 1 and 2 run the scenario into DIR/CASE.h5 and compare its steady
means (paper Tables 5 and 6) with the expected file; case3_kec and case3_lut only run (the ctest
fixture of case3_eq33), which compares Eq. (33) of the two result files. A failure names the
quantity, the expected value, the value got, the tolerance and the provenance of the expected
value; exit 0 on agreement, 1 otherwise.
"""
import argparse
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import locked  # noqa: E402


def values(case: str, workbench: str, out_dir: str):
    if case == locked.EQ33:
        paths = [locked.result_path(out_dir, c) for c in locked.CASE3]
        missing = [p for p in paths if not os.path.exists(p)]
        if missing:
            raise RuntimeError(f"{case}: result files missing (run the case3_kec and case3_lut "
                               f"tests first): {', '.join(missing)}")
        return locked.eq33_values(*paths)
    path = locked.run_case(workbench, case, out_dir)
    return [] if case in locked.CASE3 else locked.steady_values(case, path)


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--workbench", required=True)
    ap.add_argument("--out-dir", required=True)
    ap.add_argument("--case", required=True,
                    choices=locked.CASE1 + locked.CASE2 + locked.CASE3 + [locked.EQ33])
    ap.add_argument("--expected", default=locked.EXPECTED)
    args = ap.parse_args(argv)
    try:
        expected, prov = locked.read_expected(args.expected)
        got = values(args.case, args.workbench, args.out_dir)
    except (RuntimeError, OSError, ValueError, KeyError) as e:
        print(f"FAIL {e}", file=sys.stderr)
        return 1
    if args.case in locked.CASE3:
        print(f"{args.case}: run ok, {locked.result_path(args.out_dir, args.case)}")
        return 0
    print(locked.report(args.case, got, expected))
    failures = locked.compare(args.case, got, expected, prov)
    for f in failures:
        print("FAIL " + f, file=sys.stderr)
    if failures:
        print(f"{args.case}: {len(failures)} of {len(got)} quantities outside their tolerance; "
              "if the change is intended, regenerate the expected file "
              "(tests/validation/README.md)", file=sys.stderr)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
