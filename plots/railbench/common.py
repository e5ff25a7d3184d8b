"""Helpers every command shares: the figure registry entry, writing figures and CSV files, and
the one-line error reporting of the command line."""
from __future__ import annotations

import argparse
import csv
import os
import sys
from dataclasses import dataclass
from typing import Callable, List, Optional, Sequence

from .style import DPI, plt

PROG = "railbench"


@dataclass
class FigureSpec:
    suffix: str                                  # file name: <stem>_<suffix>.png
    is_available: Callable[[object], bool]
    make: Callable[[object], "plt.Figure"]
    description: str = ""


def save_figure(fig, path: str, written: Optional[List[str]] = None, dpi: int = DPI) -> None:
    """Write `fig` (format from the path's extension) and close it; append the path to
    `written`. A None figure (nothing to draw) writes nothing."""
    if fig is None:
        return
    try:
        fig.savefig(path, dpi=dpi)
    finally:
        plt.close(fig)
    if written is not None:
        written.append(path)


def write_figures(specs: Sequence[FigureSpec], item, outdir: Optional[str], stem: Optional[str],
                  dpi: int, fmt: str, build: Optional[Callable] = None) -> List[str]:
    """Write every figure of `specs` that `item` (a loaded file with .path and .stem) allows,
    as <outdir>/<stem>_<suffix>.<fmt>; return the written paths."""
    outdir = outdir or os.path.dirname(os.path.abspath(item.path))
    stem = stem or item.stem
    os.makedirs(outdir, exist_ok=True)
    todo = [spec for spec in specs if spec.is_available(item)]

    def one(spec) -> List[str]:
        done: List[str] = []
        fig = build(item, spec) if build else spec.make(item)
        save_figure(fig, os.path.join(outdir, f"{stem}_{spec.suffix}.{fmt}"), done, dpi)
        return done

    jobs = plot_jobs(len(todo))
    if jobs <= 1:
        return [p for spec in todo for p in one(spec)]
    # The figures are independent: drawn by forked processes that share the loaded file (the
    # parent's memory), in the specs' order; a failure in one is raised here as before.
    import multiprocessing
    global _FORK_TASK
    _FORK_TASK = lambda k: one(todo[k])  # noqa: E731 (inherited by the forked workers)
    try:
        with multiprocessing.get_context("fork").Pool(jobs) as pool:
            parts = pool.map(_run_fork_task, range(len(todo)), chunksize=1)
    finally:
        _FORK_TASK = None
    return [p for part in parts for p in part]


_FORK_TASK: Optional[Callable] = None


def _run_fork_task(arg):
    return _FORK_TASK(arg)


def plot_jobs(n: int) -> int:
    """Processes that draw a file's figures: RAILBENCH_PLOT_JOBS, else one per core (at most the
    number of figures); 1 draws them in this process."""
    env = os.environ.get("RAILBENCH_PLOT_JOBS", "").strip()
    try:
        jobs = int(env) if env else (os.cpu_count() or 1)
    except ValueError:
        jobs = 1
    return max(1, min(jobs, n))


def write_csv(path: str, rows: List[dict]) -> None:
    """Rows of dicts as CSV; the columns are the keys in order of first appearance."""
    cols: List[str] = []
    for r in rows:
        for k in r:
            if k not in cols:
                cols.append(k)
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=cols)
        w.writeheader()
        for r in rows:
            w.writerow(r)


def read_csv(path: str) -> List[dict]:
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def parser(command: str, description: str) -> argparse.ArgumentParser:
    return argparse.ArgumentParser(prog=f"{PROG} {command}", description=description)


def add_figure_options(ap: argparse.ArgumentParser, input_help: str, name: str = "input") -> None:
    """The input file, --outdir and --dpi of the commands that draw one file's figures."""
    ap.add_argument(name, metavar="FILE", help=input_help)
    ap.add_argument("--outdir", default=None, help="output folder (default: the folder of FILE)")
    ap.add_argument("--dpi", type=int, default=DPI, help=f"resolution (default {DPI})")


def error(command: str, text: str) -> int:
    """One line "railbench COMMAND: error: TEXT" on stderr; the exit status 1."""
    print(f"{PROG} {command}: error: {text}", file=sys.stderr)
    return 1


def note(command: str, text: str, file=None) -> None:
    print(f"{PROG} {command}: note: {text}", file=file or sys.stderr)


def guarded(command: str, action: Callable[[], int], errors: tuple) -> int:
    """Run `action`; an expected error (`errors`) or an OSError (e.g. an unwritable output
    folder) becomes one error line and exit status 1 instead of a traceback."""
    try:
        return action()
    except errors as e:
        return error(command, str(e))
    except OSError as e:
        return error(command, f"{e.strerror or e}: {e.filename or ''}".rstrip(": "))


def figure_command(argv, command: str, description: str, input_help: str, load: Callable,
                   make: Callable, summary: Callable, errors: tuple) -> int:
    """The commands that draw the figures of one file: load it, write its figures, print the
    summary line (if any) and the written paths."""
    ap = parser(command, description)
    add_figure_options(ap, input_help, "input")
    args = ap.parse_args(argv)

    def draw() -> int:
        item = load(args.input)
        paths = make(item, outdir=args.outdir, dpi=args.dpi)
        line = summary(item)
        if line:
            print(line)
        for p in paths:
            print(p)
        if not paths:
            note(command, "nothing to plot in this file")
        return 0

    return guarded(command, draw, errors)
