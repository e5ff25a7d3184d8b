"""Where the wheels touch a side with several rails (profiles.extra_rails: a switch blade beside
its stock rail, a crossing nose beside its wing rail; docs/turnouts.md).

fig_rails(result)      per side with several rails: the normal force of each wheel on each rail,
                       and the lateral track-frame position of its strongest patch on each rail,
                       versus distance (one colour per rail, one line style per wheelset)
rail_sides(result)     {side: {wheelset: {rail: {"normal_force", "y"}}}} read from the file
"""
from __future__ import annotations

from typing import Dict

import h5py
import numpy as np

from .result import Result
from .layout import _run_info
from .style import plt, report_style

_STYLES = ("-", "--", "-.", ":")


def rail_sides(result: Result) -> Dict[str, Dict[str, Dict[str, Dict[str, np.ndarray]]]]:
    """The per-rail outputs /contact/<ws>/<side>/rails/<rail>/{normal_force, y} of the result's
    vehicle, with each wheelset's distance under key "s" of its rail dictionary's parent."""
    out: Dict[str, Dict[str, Dict[str, Dict[str, np.ndarray]]]] = {}
    if result.contact is None:
        return out
    with h5py.File(result.path, "r") as f:
        base = result.prefix + "/contact"
        for ws in result.contact.wheelsets:
            for side in ("left", "right"):
                g = f.get(f"{base}/{ws}/{side}/rails")
                if g is None:
                    continue
                rails = {name: {k: g[name][k][:] for k in ("normal_force", "y") if k in g[name]}
                         for name in g}
                out.setdefault(side, {})[ws] = rails
    return out


def fig_rails(result: Result):
    """Normal force [kN] and contact position [mm] of every wheel on every rail of the sides
    with several rails, versus distance."""
    sides = rail_sides(result)
    with report_style():
        fig, axes = plt.subplots(2, len(sides), figsize=(7.5 * len(sides), 7.0), squeeze=False,
                                 sharex="col")
        for col, (side, wss) in enumerate(sorted(sides.items())):
            names = sorted({r for rails in wss.values() for r in rails},
                           key=lambda n: (n != "rail", n))
            colours = {n: f"C{i}" for i, n in enumerate(names)}
            for k, (ws, rails) in enumerate(wss.items()):
                body = result.bodies.get(ws)
                s = body.data["s"] if body is not None and body.has("s") else None
                for name, d in rails.items():
                    n = d.get("normal_force")
                    if n is None:
                        continue
                    x = s[: n.size] if s is not None else np.arange(n.size)
                    ls = _STYLES[k % len(_STYLES)]
                    axes[0][col].plot(x, n[: x.size] / 1e3, ls, color=colours[name], lw=1.0,
                                      label=f"{ws} on {name}")
                    y = d.get("y")
                    if y is not None:
                        # Only where the wheel touches the rail (0 is written where it does not).
                        yy = np.where(n[: x.size] > 0, y[: x.size] * 1e3, np.nan)
                        axes[1][col].plot(x, yy, ls, color=colours[name], lw=1.0)
            axes[0][col].set_title(f"{side} wheels")
            axes[0][col].set_ylabel("normal force on the rail [kN]")
            axes[1][col].set_ylabel("contact position y [mm] (track frame)")
            axes[1][col].set_xlabel("distance s [m]")
            axes[0][col].legend(fontsize=7, ncol=2)
            for ax in (axes[0][col], axes[1][col]):
                ax.grid(True, alpha=0.3)
        fig.suptitle(f"Contact on several rails — {_run_info(result)}")
        fig.tight_layout()
    return fig
