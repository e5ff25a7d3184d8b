"""`workbench modes`: the root locus and the damping ratio versus speed (docs/stability.md).

    plots/rbplot modes DIR [--dpi N]

DIR is the output folder of `workbench modes` (modes.h5). Writes DIR/modes_root_locus.png (Re
against Im of the hunting-relevant modes: wheelset and bogie hunting, bogie yaw/lateral, car body
sway and yaw, coloured by speed) and DIR/modes_damping.png (damping ratio of those modes against
speed, the least damped hunting mode drawn bold, the linear critical speed marked). Exit status 0
drawn, 1 bad input.
"""
from __future__ import annotations

import os
import sys

import numpy as np

from .common import error, parser, save_figure

RELEVANT = ("hunting", "sway", "car body yaw", "bogie yaw/lateral")
# The root locus shows the lightly damped modes, which decide the stability; the wheelsets' own
# creep-damped pairs (damping ratio near 1, Re ~ -500 1/s) would squash them against the axis.
LOCUS_MAX_DAMPING = 0.6


def _str(v) -> str:
    return v.decode() if isinstance(v, bytes) else str(v)


def _load(path: str) -> dict:
    import h5py
    with h5py.File(path, "r") as f:
        if "modes" not in f:
            raise ValueError(f"{path}: no /modes group")
        g = f["modes"]
        out = {"speeds": np.asarray(g["speeds"][()], dtype=float),
               "hunting_damping": np.asarray(g["hunting_damping"][()], dtype=float),
               "critical": _str(g.attrs.get("critical_speed", "none")),
               "critical_value": float(g.attrs.get("critical_speed_value", 0.0)),
               "critical_mode": _str(g.attrs.get("critical_mode", "")),
               "hunting_value": float(g.attrs.get("hunting_critical_speed_value", 0.0)),
               "method": _str(g.attrs.get("contact_method", "")),
               "creep": _str(g.attrs.get("creep_law", "")), "per_speed": []}
        for i in range(len(out["speeds"])):
            s = g[f"speed_{i}"]
            out["per_speed"].append({
                "re": np.asarray(s["re"][()], dtype=float),
                "im": np.asarray(s["im"][()], dtype=float),
                "freq": np.asarray(s["frequency"][()], dtype=float),
                "zeta": np.asarray(s["damping_ratio"][()], dtype=float),
                "unstable": (np.asarray(s["unstable"][()], dtype=float) if "unstable" in s
                             else np.zeros(len(s["re"][()]))),
                "label": [_str(x) for x in s["label"][()]]})
        return out


def _relevant(label: str) -> bool:
    return any(k in label for k in RELEVANT) and "aperiodic" not in label


def _root_locus(d: dict):
    import matplotlib.pyplot as plt
    from matplotlib import cm, colors
    fig, ax = plt.subplots(figsize=(7.5, 5.5))
    v = d["speeds"]
    norm = colors.Normalize(vmin=v.min(), vmax=max(v.max(), v.min() + 1e-9))
    markers = {}
    for speed, s in zip(v, d["per_speed"]):
        for re, im, z, lab in zip(s["re"], s["im"], s["zeta"], s["label"]):
            if not _relevant(lab) or im <= 0 or z > LOCUS_MAX_DAMPING:
                continue
            mk = markers.setdefault(lab, "os^vD<>ph*"[len(markers) % 10])
            ax.scatter(re, im, c=[cm.viridis(norm(speed))], marker=mk, s=22)
    for lab, mk in markers.items():
        ax.scatter([], [], c="grey", marker=mk, label=lab)
    ax.axvline(0.0, color="k", lw=0.8)
    ax.set_xlabel("Re $\\lambda$ [1/s]")
    ax.set_ylabel("Im $\\lambda$ [rad/s]")
    ax.set_title(f"Root locus ({d['method']}, {d['creep']}; damping ratio <= "
                 f"{LOCUS_MAX_DAMPING})")
    sm = cm.ScalarMappable(norm=norm, cmap=cm.viridis)
    fig.colorbar(sm, ax=ax, label="speed [m/s]")
    ax.legend(fontsize=7, loc="upper left")
    ax.grid(alpha=0.3)
    fig.tight_layout()
    return fig


def _damping(d: dict):
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(7.5, 5.0))
    v = d["speeds"]
    pts = {}
    for speed, s in zip(v, d["per_speed"]):
        for z, f, lab in zip(s["zeta"], s["freq"], s["label"]):
            if _relevant(lab) and f > 0:
                pts.setdefault(lab, []).append((speed, z))
    for lab, p in sorted(pts.items()):
        p = np.asarray(p)
        ax.scatter(p[:, 0], p[:, 1], s=12, label=lab)
    # Every unstable mode, whatever its kind or frequency (the engine's flag), ringed in red.
    bad = [(speed, z) for speed, s in zip(v, d["per_speed"])
           for z, u in zip(s["zeta"], s["unstable"]) if u > 0]
    if bad:
        b = np.asarray(bad)
        ax.scatter(b[:, 0], b[:, 1], s=60, facecolors="none", edgecolors="r", lw=1.2,
                   label="unstable mode")
    hd = d["hunting_damping"]
    ok = hd < 1.0
    if ok.any():
        ax.plot(v[ok], hd[ok], "k-", lw=2, label="least damped hunting mode")
    ax.axhline(0.0, color="k", lw=0.8)
    if d["critical_value"] > 0:
        ax.axvline(d["critical_value"], color="r", ls="--",
                   label=f"linear critical speed {d['critical_value']:.1f} m/s (any mode)")
        if d["critical_mode"]:
            ax.set_title("first unstable: " + d["critical_mode"], fontsize=8)
    else:
        ax.set_title("linear critical speed: " + d["critical"], fontsize=8, wrap=True)
    if d["hunting_value"] > 0 and d["hunting_value"] != d["critical_value"]:
        ax.axvline(d["hunting_value"], color="m", ls=":",
                   label=f"hunting modes unstable from {d['hunting_value']:.1f} m/s")
    ax.set_xlabel("speed [m/s]")
    ax.set_ylabel("damping ratio [-]")
    ax.legend(fontsize=7)
    ax.grid(alpha=0.3)
    fig.tight_layout()
    return fig


def main(argv) -> int:
    ap = parser("modes", "root locus and damping versus speed of `workbench modes`")
    ap.add_argument("dir", help="output folder of workbench modes (modes.h5)")
    ap.add_argument("--dpi", type=int, default=120)
    a = ap.parse_args(argv)
    path = os.path.join(a.dir, "modes.h5")
    if not os.path.isfile(path):
        return error("modes", f"{path}: no such file")
    try:
        d = _load(path)
    except (OSError, KeyError, ValueError) as e:
        return error("modes", str(e))
    save_figure(_root_locus(d), os.path.join(a.dir, "modes_root_locus.png"), dpi=a.dpi)
    save_figure(_damping(d), os.path.join(a.dir, "modes_damping.png"), dpi=a.dpi)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
