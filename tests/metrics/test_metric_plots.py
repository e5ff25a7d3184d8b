"""The study metric figures (plots/railbench/study_metrics.py) on a synthetic summary_cases.csv:
a 2 x 3 sweep, one value missing.

usage: PYTHONPATH=plots /usr/bin/python3 -m pytest -q tests/metrics/test_metric_plots.py
"""
import csv
import math
import os
import tempfile

import numpy as np

from railbench import study_metrics as sm

K = "vehicle.speed"
P = "vehicle.elements[1].stiffness"


def write_cases(folder):
    rows = []
    for v in (20, 30, 40):
        for k in ("1e6", "1e7"):
            value = "" if (v, k) == (40, "1e7") else repr(v * 0.001 + (1 if k == "1e7" else 0))
            rows.append({"case": f"c{v}{k}", "label": "", "role": "",
                         "overrides": f"{K}={v} {P}={k} run.distance=5",
                         "metric_y_max": value, "metric_flat": "1.5", "message": ""})
    rows.append({"case": "ref", "label": "ref", "role": "reference", "overrides": f"{K}=99",
                 "metric_y_max": "7", "metric_flat": "1.5", "message": ""})
    with open(os.path.join(folder, "summary_cases.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        w.writeheader()
        w.writerows(rows)


def test_lines_per_second_parameter_and_heat_map():
    folder = tempfile.mkdtemp(prefix="rb_metric_plots_")
    write_cases(folder)
    cases = [c for c in sm.load_cases(folder) if not c["role"]]
    keys, _ = sm.metric_sweeps(cases)
    assert keys == [K, P]  # run.distance does not vary: not a swept parameter
    assert sm.metric_names(cases) == ["y_max", "flat"]
    fig = sm.fig_metric_lines(cases, "y_max", keys)
    lines = fig.axes[0].get_lines()
    assert len(lines) == 2
    assert list(lines[0].get_xdata()) == [20, 30, 40]
    assert np.allclose(lines[0].get_ydata(), [0.02, 0.03, 0.04])
    assert list(lines[1].get_xdata()) == [20, 30]  # the missing value is left out
    xs, ys, grid = sm.metric_grid(cases, "y_max", keys)
    assert xs == ["20", "30", "40"] and ys == ["1e6", "1e7"]
    assert grid[1, 0] == 1.02 and math.isnan(grid[1, 2])
    written = []
    sm.make_metric_outputs(folder, written, dpi=40)
    names = sorted(os.path.basename(p) for p in written)
    assert names == ["study_metric_flat.png", "study_metric_flat_map.png",
                     "study_metric_y_max.png", "study_metric_y_max_map.png"]
    for p in written:
        assert os.path.getsize(p) > 0


def test_no_metrics_no_figures():
    folder = tempfile.mkdtemp(prefix="rb_metric_plots_")
    with open(os.path.join(folder, "summary_cases.csv"), "w") as f:
        f.write("case,label,role,overrides,message\nc1,,,a=1,\nc2,,,a=2,\n")
    written = []
    sm.make_metric_outputs(folder, written)
    assert written == []


def test_labels_units_and_limit_line():
    """study_labels.csv (written by the study runner from the schema) names the axes with units,
    and a metric with a standard limit gets its line (Y/Q 0.8, EN 14363)."""
    folder = tempfile.mkdtemp(prefix="rb_metric_plots_")
    write_cases(folder)
    with open(os.path.join(folder, "study_labels.csv"), "w", newline="") as f:
        f.write("kind,name,label,unit,limit,limit_source\n"
                f"parameter,{K},vehicle speed,m/s,,\n"
                f"parameter,{P},spring1 stiffness,N/m,,\n"
                "metric,y_max,y_max (y_over_q),-,0.8,EN 14363 limit of y_over_q\n")
    cases = [c for c in sm.load_cases(folder) if not c["role"]]
    keys, _ = sm.metric_sweeps(cases)
    labels = sm.load_labels(folder)
    fig = sm.fig_metric_lines(cases, "y_max", keys, labels)
    ax = fig.axes[0]
    assert ax.get_xlabel() == "vehicle speed [m/s]"
    assert ax.get_ylabel() == "y_max (y_over_q) [-]"
    texts = [t.get_text() for t in ax.get_legend().get_texts()]
    assert "spring1 stiffness = 1e6 N/m" in texts
    assert any(t.startswith("limit 0.8") and "EN 14363" in t for t in texts)
    assert any(list(line.get_ydata()) == [0.8, 0.8] for line in ax.get_lines())
    m = sm.fig_metric_map(cases, "y_max", keys, labels)
    assert m.axes[0].get_ylabel() == "spring1 stiffness [N/m]"
    assert "limit 0.8" in m.axes[0].get_title()
    # Without the file the raw paths stay (an old folder).
    assert sm.fig_metric_lines(cases, "y_max", keys).axes[0].get_xlabel() == K
