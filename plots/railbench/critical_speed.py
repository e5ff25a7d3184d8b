"""`workbench critical-speed`: the bifurcation diagram and the ramp's lateral displacement.

    plots/rbplot critical-speed DIR [--dpi N]

DIR is the output folder of `workbench critical-speed` (critical_speed.h5). Writes
DIR/critical_speed.png with two panels:
  - the bifurcation diagram: limit-cycle amplitude (the largest half peak-to-peak wheelset lateral
    displacement in a window) against speed: the ramp-down curve (one point per window) and the
    constant-speed runs (last window; filled = hunting, open = stable, orange diamond = sustained
    small-amplitude oscillation below the threshold: not stable), the critical speed of each
    method and the hunting modes' linear one marked;
  - the first wheelset's lateral displacement against speed along the ramp-down run.
Exit status 0 when drawn, 1 on bad input.
"""
from __future__ import annotations

import math
import os

import numpy as np

from .common import guarded, parser, save_figure
from .h5 import ResultFileError, _attrs, open_h5
from .style import DPI, plt

COMMAND = "critical-speed"


def _ds(f, path):
    return np.asarray(f[path][()], dtype=float) if path in f else np.zeros(0)


def load(folder: str) -> dict:
    path = os.path.join(folder, "critical_speed.h5")
    with open_h5(path, ResultFileError, "critical-speed result") as f:
        d = {"attrs": _attrs(f), "path": path}
        for name in ("ramp/speed", "ramp/y", "ramp/window_speed", "ramp/window_amplitude",
                     "bisection/speed", "bisection/amplitude", "bisection/unstable",
                     "bisection/small_cycle"):
            d[name] = _ds(f, name)
    return d


def _mark(ax, value, label, color):
    if isinstance(value, (int, float)) and math.isfinite(value):
        ax.axvline(value, color=color, ls="--", lw=1.0, label=f"{label} {value:.2f} m/s")


def figure(d: dict):
    a = d["attrs"]
    fig, (top, bottom) = plt.subplots(2, 1, figsize=(8, 7.5), sharex=True)
    if d["ramp/window_speed"].size:
        top.plot(d["ramp/window_speed"], d["ramp/window_amplitude"] * 1e3, "-", color="C0",
                 lw=1.2, label="ramp-down (per window)")
    s, amp, unst = d["bisection/speed"], d["bisection/amplitude"] * 1e3, d["bisection/unstable"]
    if s.size:
        hunt = unst > 0.5
        small = d["bisection/small_cycle"] > 0.5 if d["bisection/small_cycle"].size == s.size \
            else np.zeros(s.size, bool)
        stable = ~hunt & ~small
        top.plot(s[hunt], amp[hunt], "o", color="C3", label="constant speed: hunting")
        top.plot(s[stable], amp[stable], "o", mfc="none", color="C2",
                 label="constant speed: stable")
        if small.any():
            top.plot(s[small], amp[small], "D", mfc="none", color="C1",
                     label="constant speed: sustained small-amplitude oscillation (not stable)")
    thr = a.get("threshold")
    if isinstance(thr, (int, float)):
        top.axhline(thr * 1e3, color="0.5", lw=0.8, ls=":", label="threshold")
    for ax in (top, bottom):
        _mark(ax, a.get("critical_speed_ramp"), "ramp-down", "C0")
        _mark(ax, a.get("critical_speed_bisection"), "bisection", "C3")
        _mark(ax, a.get("critical_speed_linear"), "linear (hunting modes)", "m")
    top.set_ylabel("limit-cycle amplitude [mm]")
    # Log scale: a cycle just below the threshold must be told from one that died out.
    amps = np.concatenate([d["ramp/window_amplitude"], d["bisection/amplitude"]]) * 1e3
    amps = amps[np.isfinite(amps) & (amps > 0)]
    if amps.size:
        floor = amps.min() / 2
        if isinstance(thr, (int, float)):
            floor = max(floor, thr * 1e3 / 1000)
        top.set_yscale("log")
        top.set_ylim(bottom=floor)
    top.set_title(f"nonlinear critical speed ({a.get('contact', '')}, "
                  f"{a.get('criterion', '')} criterion)")
    top.legend(fontsize=8)
    top.grid(alpha=0.3)
    if d["ramp/speed"].size:
        bottom.plot(d["ramp/speed"], d["ramp/y"] * 1e3, lw=0.6, color="C0")
    bottom.set_xlabel("speed [m/s]")
    bottom.set_ylabel("ramp: ws1 lateral y [mm]")
    bottom.grid(alpha=0.3)
    fig.tight_layout()
    return fig


def main(argv) -> int:
    ap = parser(COMMAND, "bifurcation diagram of `workbench critical-speed`")
    ap.add_argument("folder", metavar="DIR", help="output folder of workbench critical-speed")
    ap.add_argument("--dpi", type=int, default=DPI, help=f"resolution (default {DPI})")
    args = ap.parse_args(argv)

    def draw() -> int:
        d = load(args.folder)
        out = os.path.join(args.folder, "critical_speed.png")
        save_figure(figure(d), out, dpi=args.dpi)
        print(out)
        return 0

    return guarded(COMMAND, draw, (ResultFileError, KeyError))
