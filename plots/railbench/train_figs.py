"""The figure of a train's connections and motion (docs/trains.md): drawn once per result of a
run of several vehicles whose file has /train/connections.

Panels against the distance the front vehicle of each connection has travelled (its first body's
s less its start): the connection's longitudinal force (draw gear - buffers, tension > 0), the
lateral force it exerts on the rear car body, and, when the motion along the track is a state,
every vehicle's speed against time.
"""
from __future__ import annotations

from typing import List

import numpy as np

from .result import Result
from .style import plt


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
    rows = 3 if motion else 2
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
        ax[2].set_xlabel("time [s]")
        ax[2].set_ylabel("speed [m/s]")
        ax[2].legend(fontsize=8, ncol=4)
        ax[2].grid(True, alpha=0.3)
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
