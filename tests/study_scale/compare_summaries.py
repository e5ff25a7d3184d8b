#!/usr/bin/env python3
"""Fails unless two study folders hold the same summaries, cost columns aside.

usage: compare_summaries.py DIR_A DIR_B [EXPECTED_RUNS]

summary.csv and summary_cases.csv of both folders must have the same columns and rows after
dropping what depends on the machine or the folder (CPU and wall times, the stage shares and
the number of stage samples kept, since a sample is dropped when the process was descheduled,
file paths); every other field, the metrics and the counts included, must be equal as text, i.e. to
the last printed digit. With EXPECTED_RUNS, summary.csv must have that many rows, every one ok.
"""
import csv
import sys


def cost(column):
    return (column in ("cpu_time_s", "wall_time_s", "stage_samples", "file")
            or column.startswith("stage_share_")
            or column.endswith("_cpu_time_s"))


def table(path):
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    if not rows:
        raise SystemExit(f"{path}: empty")
    keep = [i for i, c in enumerate(rows[0]) if not cost(c)]
    return [[r[i] for i in keep] for r in rows]


def main():
    a, b = sys.argv[1], sys.argv[2]
    problems = []
    for name in ("summary.csv", "summary_cases.csv"):
        ta, tb = table(f"{a}/{name}"), table(f"{b}/{name}")
        if ta[0] != tb[0]:
            problems.append(f"{name}: columns differ:\n  {ta[0]}\n  {tb[0]}")
            continue
        if len(ta) != len(tb):
            problems.append(f"{name}: {len(ta) - 1} rows in {a}, {len(tb) - 1} in {b}")
        for ra, rb in zip(ta[1:], tb[1:]):
            for col, va, vb in zip(ta[0], ra, rb):
                if va != vb:
                    problems.append(f"{name}: case {ra[0]} column {col}: {va!r} != {vb!r}")
    if len(sys.argv) > 3:
        runs = table(f"{a}/summary.csv")
        status = runs[0].index("status")
        if len(runs) - 1 != int(sys.argv[3]):
            problems.append(f"{a}/summary.csv: {len(runs) - 1} runs, expected {sys.argv[3]}")
        problems += [f"{a}: run {r[0]} r{r[1]} is {r[status]}" for r in runs[1:]
                     if r[status] != "ok"]
    for p in problems:
        print("DIFFERENT:", p)
    if problems:
        return 1
    print(f"summaries of {a} and {b} are identical (cost columns aside)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
