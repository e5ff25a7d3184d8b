"""What the scripts of bench/ that run shipped scenes share: the command line (an output CSV and
the workbench binary), a run of a scene into an HDF5 file, and the CSV of rows with the commit
they came from (docs blocks stamp it)."""
import argparse
import csv
import os
import subprocess
import sys

import h5py

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "plots"))
from railbench import provenance  # noqa: E402


def arguments(doc: str, csv_default: str, argv=None):
    """CSV (default out/studies/<csv_default>) and --workbench BIN."""
    ap = argparse.ArgumentParser(description=doc.split("\n\n")[0])
    ap.add_argument("csv", nargs="?", default=os.path.join(ROOT, "out", "studies", csv_default))
    ap.add_argument("--workbench", default=os.path.join(ROOT, "build", "workbench", "app",
                                                        "workbench"))
    return ap.parse_args(argv)


def commit() -> str:
    return provenance.tag(provenance.current())


def run(wb: str, lua: str, out: str) -> h5py.File:
    """`workbench run lua --out out` from the project root; the result file, open."""
    r = subprocess.run([wb, "--root", ROOT, "run", lua, "--out", out, "--quiet"], cwd=ROOT,
                       stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    if r.returncode != 0:
        raise RuntimeError(f"{lua}: exit {r.returncode}: {r.stderr[-500:]}")
    return h5py.File(out, "r")


def write_rows(path: str, rows, echo=()) -> None:
    """The rows (dicts with the same keys) as CSV at path; each row's `echo` columns printed."""
    os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, list(rows[0].keys()))
        w.writeheader()
        w.writerows(rows)
    for r in rows:
        print(*(r[c] for c in echo))
