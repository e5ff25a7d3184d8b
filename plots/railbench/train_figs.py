"""The figure of a train's connections and motion (docs/trains.md): drawn once per result of a
run of several vehicles whose file has /train/connections.

Panels against the distance the front vehicle of each connection has travelled (its first body's
s less its start): the connection's longitudinal force (draw gear - buffers, tension > 0), the
lateral force it exerts on the rear car body, and, when the motion along the track is a state,
every vehicle's speed and its jerk over 1 s (/vehicles/<name>/motion/jerk_1s) against time.
"""
from __future__ import annotations

import warnings
from typing import List

import numpy as np

from .result import Result
from .style import RUN_COLORS, plt


def train_connections(result: Result) -> List[str]:
    """The connections' names (front-rear) of a run of several vehicles; [] otherwise."""
    if result.vehicle or "train" not in result.groups:
        return []
    import h5py
    with h5py.File(result.path, "r") as f:
        return list(f["/train/connections"].keys()) if "/train/connections" in f else []


def _front_distance(result: Result, name: str) -> np.ndarray:
    """Distance travelled by the connection's front vehicle (its first body's s from its start);
    the time when the file has no body positions."""
    import h5py
    front = name.split("-")[0]
    with h5py.File(result.path, "r") as f:
        bodies = f.get(f"/vehicles/{front}/bodies")
        if bodies is not None:
            for b in bodies.values():
                if "s" in b:
                    s = np.asarray(b["s"][()], dtype=float)
                    return s - s[0]
    return result.time


def fig_train(result: Result):
    names = train_connections(result)
    motion = [v for v in result.vehicles if f"/vehicles/{v}/motion/speed" in _datasets(result)]
    rows = 4 if motion else 2
    fig, ax = plt.subplots(rows, 1, figsize=(10, 3 * rows), sharex=False)
    for name in names:
        g = result.read_group(f"/train/connections/{name}")
        x = _front_distance(result, name)
        ax[0].plot(x, g["force"] * 1e-3, label=name)
        ax[1].plot(x, g["lateral_rear"] * 1e-3, label=name)
    ax[0].set_ylabel("longitudinal force [kN]\n(tension > 0)")
    ax[1].set_ylabel("lateral force on the\nrear car body [kN]")
    for a in ax[:2]:
        a.set_xlabel("distance travelled by the connection's front vehicle [m]")
        a.axhline(0.0, color="0.6", lw=0.6)
        a.legend(fontsize=8, ncol=3)
        a.grid(True, alpha=0.3)
    if motion:
        for v in motion:
            g = result.read_group(f"/vehicles/{v}/motion")
            ax[2].plot(result.time, g["speed"], label=v)
            if "jerk_1s" in g:
                ax[3].plot(result.time, g["jerk_1s"], label=v)
        ax[2].set_ylabel("speed [m/s]")
        ax[3].set_ylabel("jerk over 1 s [m/s$^3$]")
        ax[3].axhline(0.0, color="0.6", lw=0.6)
        for a in ax[2:]:
            a.set_xlabel("time [s]")
            a.legend(fontsize=8, ncol=4)
            a.grid(True, alpha=0.3)
    fig.suptitle("Train: in-train forces and motion — " + ", ".join(result.vehicles) +
                 f" ({result.stem})", fontsize=10)
    fig.tight_layout()
    return fig


def _datasets(result: Result) -> set:
    import h5py
    out = set()
    with h5py.File(result.path, "r") as f:
        f.visit(lambda p: out.add("/" + p))
    return out


def train_assessed(result: Result) -> List[str]:
    """The vehicles of a run of several whose file has an assessment; [] otherwise."""
    if result.vehicle or len(result.vehicles) < 2:
        return []
    import h5py
    with h5py.File(result.path, "r") as f:
        return [v for v in result.vehicles if f"/vehicles/{v}/assessment" in f]


def _envelope(series, signed: bool = False):
    """The largest |value| (signed: value) of several (s, value) series on the first one's s
    (each series interpolated onto it, NaN outside its own range); (None, None) without
    data."""
    series = [(np.asarray(s, float), np.asarray(v, float)) for s, v in series
              if s is not None and v is not None and len(s) > 1 and len(s) == len(v)]
    if not series:
        return None, None
    grid = series[0][0]
    stack = []
    for s, v in series:
        ok = np.isfinite(s) & np.isfinite(v)
        if ok.sum() < 2:
            continue
        order = np.argsort(s[ok])
        stack.append(np.interp(grid, s[ok][order], (v if signed else np.abs(v))[ok][order], left=np.nan,
                               right=np.nan))
    if not stack:
        return None, None
    with warnings.catch_warnings():  # a position no series covers: NaN, not a warning
        warnings.simplefilter("ignore", RuntimeWarning)
        return grid, np.nanmax(np.vstack(stack), axis=0)


def train_assessment_envelopes(result: Result):
    """Per assessed vehicle, the envelope along the track of its wheels' |Y/Q| (2 m), its
    wheelsets' |Sum Y|_2m over their own limits, its wheels' unloading dQ/Q0 (> 0 unloads), and its car body's lateral
    floor acceleration at the centre: {vehicle: {panel: (s, value)}}, and the Y/Q and dQ/Q0
    limits."""
    from .assessment import _own, _limits, read_assessment
    out, yq_limits, dq_limits = {}, set(), set()
    for v in train_assessed(result):
        a = read_assessment(result.path, f"/vehicles/{v}")
        if a is None:
            continue
        panels = {}
        panels["y_over_q"] = _envelope(
            [(q.series("s") if q.series("s") is not None else a.safety_s, q.series("value"))
             for q in a.y_over_q.values()])
        ratios = []
        for q in a.sum_y.values():
            lim = _limits([q])
            val = q.series("value")
            if lim and val is not None and lim[0] > 0:
                ratios.append((q.series("s") if q.series("s") is not None else a.safety_s,
                               val / lim[0]))
        panels["sum_y"] = _envelope(ratios)
        panels["dq_over_q"] = _envelope(
            [(_own(a, a.distance, ws, side), q.series("value"))
             for (ws, side), q in a.dq_over_q.items()], signed=True)
        centre = a.comfort.get("centre") or next(iter(a.comfort.values()), None)
        panels["a_y"] = (_envelope([(a.distance, centre.series("a_y"))]) if centre
                         else (None, None))
        yq_limits.update(_limits(a.y_over_q.values()))
        dq_limits.update(_limits(a.dq_over_q.values()))
        out[v] = panels
    return out, sorted(yq_limits), sorted(dq_limits)


_TRAIN_PANELS = (
    ("y_over_q", "|Y/Q|$_{2m}$ [-]", "(a) derailment quotient, largest of the vehicle's wheels"),
    ("sum_y", "(ΣY)$_{2m}$ / limit [-]",
     "(b) track shift force over its limit, largest of the vehicle's wheelsets"),
    ("dq_over_q", "ΔQ/Q$_0$ [-]", "(c) wheel unloading, largest of the vehicle's wheels"),
    ("a_y", "|a$_y$| [m/s$^2$]", "(d) car body lateral acceleration at the floor centre"),
)


def fig_train_assessment(result: Result):
    """The whole train's assessment along the track: one line per vehicle and panel, each the
    envelope of that vehicle's wheels or wheelsets, against the track position s, so where along
    the track each vehicle of the train comes nearest its limits shows on one page."""
    env, yq_limits, dq_limits = train_assessment_envelopes(result)
    fig, ax = plt.subplots(len(_TRAIN_PANELS), 1, figsize=(10, 2.6 * len(_TRAIN_PANELS)),
                           sharex=True)
    limits = {"y_over_q": yq_limits, "sum_y": [1.0], "dq_over_q": dq_limits}
    for a, (key, ylabel, title) in zip(ax, _TRAIN_PANELS):
        for k, (v, panels) in enumerate(env.items()):
            s, val = panels.get(key, (None, None))
            if s is not None:
                a.plot(s, val, lw=0.9, color=RUN_COLORS[k % len(RUN_COLORS)], label=v)
        for lim in limits.get(key, []):
            a.axhline(lim, color="k", ls="--", lw=0.8, label=f"limit {lim:g}")
        a.set_ylabel(ylabel)
        a.set_title(title, fontsize=9, loc="left")
        a.grid(True, alpha=0.3)
        a.legend(fontsize=7, ncol=6, loc="upper left")
    ax[-1].set_xlabel("track position s [m]")
    fig.suptitle("Train: assessment along the track, vehicle by vehicle — " +
                 f"{result.stem}", fontsize=10)
    fig.tight_layout()
    return fig
