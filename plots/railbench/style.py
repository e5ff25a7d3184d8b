"""Report style: figure size, colours, line styles and the matplotlib rc of every figure
(Agg backend, no display)."""
from __future__ import annotations

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402  (after the backend choice)



# --------------------------------------------------------------------------------------------
# Style
# --------------------------------------------------------------------------------------------
DPI = 150
A4_WIDTH_IN = 6.5  # usable text width of an A4 page with ~2.3 cm margins

# By segment kind name (the result's /schema/enums/segment_kind gives the name of each code).
# Paper Fig. 17: white tangent, grey transition, blue curve.
SEGMENT_FILL = {"tangent": "#ffffff", "transition": "#d9d9d9", "curve": "#d6e6f5"}
SEGMENT_LINE = {"tangent": "#222222", "transition": "#8c8c8c", "curve": "#1f5fa8"}

# By irregularity channel (the result's channels: Irregularities.channels).
CHANNEL_TITLES = {
    "alignment": "Alignment",
    "vertical": "Vertical profile",
    "gauge": "Gauge variation",
    "cross_level": "Cross level",
}
CHANNEL_COLORS = {
    "alignment": "#1f5fa8",
    "vertical": "#b2182b",
    "gauge": "#1b7837",
    "cross_level": "#6a3d9a",
}

# Overlaid runs (paper Fig. 17, 19-22: one colour per method); line styles keep them apart in
# black-and-white print.
RUN_COLORS = ("#1f5fa8", "#b2182b", "#1b7837", "#e08214", "#6a3d9a", "#555555")
RUN_STYLES = ("-", (0, (5, 2.5)), (0, (1.2, 1.6)), (0, (6, 2, 1.2, 2)), (0, (3, 1.5)), "-")
SIDE_STYLE = {"left": dict(color="#1f5fa8", ls="-"),
              "right": dict(color="#b2182b", ls=(0, (5, 2.5)))}
FAIL_COLOR = "#d00000"
KINEMATIC_KINDS = ("wheelset", "bogie", "car")

_RC = {
    "font.size": 8.5,
    "axes.titlesize": 9,
    # Titles at a fixed height: matplotlib's search for the height that clears top-axis labels
    # costs about a third of drawing a figure; the two figures with a top axis pad their titles.
    "axes.titley": 1.0,
    "axes.labelsize": 8.5,
    "legend.fontsize": 7.5,
    "xtick.labelsize": 7.5,
    "ytick.labelsize": 7.5,
    "axes.grid": True,
    "grid.color": "#b0b0b0",
    "grid.linewidth": 0.4,
    "grid.alpha": 0.6,
    "axes.linewidth": 0.6,
    "lines.linewidth": 1.0,
    "xtick.direction": "in",
    "ytick.direction": "in",
    "xtick.major.width": 0.6,
    "ytick.major.width": 0.6,
    "legend.frameon": True,
    "legend.framealpha": 0.9,
    "legend.edgecolor": "#cccccc",
    "savefig.dpi": DPI,
    "figure.dpi": DPI,
    "axes.axisbelow": True,
}


def report_style():
    """Context manager with the report rcParams (use: `with report_style(): ...`)."""
    return plt.rc_context(_RC)
