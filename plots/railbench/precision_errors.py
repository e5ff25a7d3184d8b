"""The quantities of `workbench precision` (docs/precision.md) as the figures label them, and the
Pareto front the figures draw. The errors, the references' verification and the recommendation
are the engine's (workbench/precision/answer.cpp: one error rule), read from the files it writes
(plots/railbench/precision.py), never computed here."""
from __future__ import annotations

import math
import re
from dataclasses import dataclass
from typing import List, Sequence, Tuple


# Display unit per dataset: (scale from SI, unit).
_BODY_UNITS = {"y": (1e3, "mm"), "z": (1e3, "mm"), "s": (1e3, "mm"), "roll": (1e3, "mrad"),
               "pitch": (1e3, "mrad"), "yaw": (1e3, "mrad")}
# Per-wheel quantities: the wheel/rail normal force, the lateral creep force, and the EN 14363
# running-safety quantities of the contact output (track-lateral wheel force Y and Y/Q).
_WHEEL_TAGS = {"Q": ("normal_force", 1e-3, "kN"), "Fy": ("creep_force_y", 1e-3, "kN"),
               "Y": ("Y", 1e-3, "kN"), "YQ": ("y_over_q", 1.0, "-")}


class QuantityError(ValueError):
    """A --quantities entry that names nothing this command knows. One line."""


@dataclass(frozen=True)
class Quantity:
    """An error quantity: tag as the user wrote it, what it covers, its display unit."""
    tag: str
    group: str      # "wheelsets" (y, yaw: every wheelset; guided: every other body), "wheels",
                    # "body" (one named body)
    dataset: str
    scale: float
    unit: str
    body: str = ""

    @property
    def title(self) -> str:
        if self.group == "body":
            return f"{self.body} {self.dataset}"
        if self.group == "wheels":
            return f"{self.tag} (every wheel)"
        return f"{self.dataset} (every wheelset)"


def parse_quantities(text: str) -> List[Quantity]:
    out = []
    for tag in [t.strip() for t in (text or "y,yaw").split(",")]:
        if tag in ("y", "yaw"):
            sc, unit = _BODY_UNITS[tag]
            out.append(Quantity(tag, "wheelsets", tag, sc, unit))
        elif tag in _WHEEL_TAGS:
            ds, sc, unit = _WHEEL_TAGS[tag]
            out.append(Quantity(tag, "wheels", ds, sc, unit))
        elif re.fullmatch(r"[A-Za-z0-9_\-]+\.(y|z|roll|pitch|yaw)", tag):
            body, ds = tag.rsplit(".", 1)
            sc, unit = _BODY_UNITS[ds]
            out.append(Quantity(tag, "body", ds, sc, unit, body))
        else:
            raise QuantityError(f"--quantities: unknown '{tag}' (y, yaw, Q, Fy, Y, YQ or "
                                f"BODY.y|z|roll|pitch|yaw)")
    if not out:
        raise QuantityError("--quantities: no entry")
    return out


def pareto(points: Sequence[Tuple[float, float]]) -> List[int]:
    """Indices of the Pareto front of (error, cost) points: no other point is both cheaper (or
    as cheap) and more accurate. Ordered by cost."""
    order = sorted(range(len(points)), key=lambda i: (points[i][1], points[i][0]))
    front, best = [], math.inf
    for i in order:
        e = points[i][0]
        if e < best:
            front.append(i)
            best = e
    return front
