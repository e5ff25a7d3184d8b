#!/usr/bin/env python3
"""The shipped turnout scene and the sliced-rail validations, measured (docs/turnouts.md).

usage: bench/turnout.py [CSV] [--workbench BIN]

Runs scenarios/turnout/diverging_r190.lua (the Manchester wagon into the diverging route of a
60E1-190 switch at 40 km/h) and reads, for the leading wheelset's left (outer) wheel, where the
switch blade takes over the wheel from the stock rail, the forces on the blade and the
derailment quotient there; then the same wagon on the same track with a plain rail (the scene
without its slices and further rails) for the cost of the turnout's rails and for how the
contact differs; the crossing on the through route (scenarios/turnout/crossing_through.lua) on
its flexible track, with a lighter rail mass and on rigid rails; the scene on a flexible track (contact.elastic.rail_support, a rail mass per
wheel: docs/track_support.md); then the validation scenes of tests/run/test_sliced_rails.cpp (rails lowered
along the track, the load moving between two rails).

Rows of the CSV (default out/studies/turnout/turnout.csv): quantity, value, reference, unit,
commit.
"""
import math
import os
import re
import sys
import tempfile

import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "plots"))
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import scene_runs  # noqa: E402
from railbench.result import load_result  # noqa: E402
from railbench.run import build_figure  # noqa: E402

SCENE = "scenarios/turnout/diverging_r190.lua"
CROSSING = "scenarios/turnout/crossing_through.lua"
TP = 60.0  # [m] the crossing scene's theoretical point
TOE = 60.0  # [m] the scene's toe
# The flexible track's support (docs/track_support.md): ASSUMPTION, as in the track tests.
FLEX = "{ mass = 150, k_z = 1e8, c_z = 5e4, k_y = 4e7, c_y = 5e4 }"
LEFT_RADIUS = 190 + 1.435 / 2  # [m] scenarios/turnout/lib.lua


def crossing(s, a, b):
    """The first s where a - b changes sign from > 0 to <= 0 (linear between samples)."""
    d = a - b
    for i in range(1, len(s)):
        if d[i - 1] > 0 >= d[i]:
            return float(s[i - 1] + (s[i] - s[i - 1]) * d[i - 1] / (d[i - 1] - d[i]))
    return math.nan


def main(argv=None) -> int:
    a = scene_runs.arguments(__doc__, "turnout/turnout.csv", argv)
    commit = scene_runs.commit()
    rows = []

    def row(q, value, reference, unit):
        rows.append(dict(quantity=q, value=f"{value:.6g}",
                         reference="" if reference is None else f"{reference:.6g}", unit=unit,
                         commit=commit))

    with tempfile.TemporaryDirectory(prefix="rb_turnout_") as tmp:
        text = open(os.path.join(ROOT, SCENE)).read()
        plain_text, n = re.subn(r",\n\s*rail_slices = \{ left = stock \}, extra_rails = "
                                r"\{ left = \{ blade \} \}", "", text)
        if n != 1:
            raise RuntimeError(f"{SCENE}: its rails are not where this study expects them")
        # The same scene on a flexible track (docs/track_support.md; its values an ASSUMPTION, as
        # in tests/run/data/rail_support_tangent.lua), with the smaller step the rail masses' stiff
        # modes need.
        flex_text, n1 = re.subn(r'contact \{ method = "elastic", creep = "polach", mu = 0\.2364 \}',
                                'contact { method = "elastic", creep = "polach", mu = 0.2364, '
                                'elastic = { rail_support = ' + FLEX + ' } }', text)
        flex_text, n2 = re.subn(r"c\.abm\(speed, 2\.5e-4\)", "c.abm(speed, 1e-4)", flex_text)
        if n1 != 1 or n2 != 1:
            raise RuntimeError(f"{SCENE}: its contact or solver is not where this study expects it")
        plain_lua = os.path.join(ROOT, "scenarios", "turnout", ".plain_tmp.lua")
        flex_lua = os.path.join(ROOT, "scenarios", "turnout", ".flex_tmp.lua")
        try:
            for path, body in ((plain_lua, plain_text), (flex_lua, flex_text)):
                with open(path, "w") as f:
                    f.write(body)
            t = scene_runs.run(a.workbench, SCENE, os.path.join(tmp, "turnout.h5"))
            p = scene_runs.run(a.workbench, plain_lua, os.path.join(tmp, "plain.h5"))
            fx = scene_runs.run(a.workbench, flex_lua, os.path.join(tmp, "flex.h5"))
        finally:
            for path in (plain_lua, flex_lua):
                if os.path.exists(path):
                    os.remove(path)
        # The scene's rails figure, for docs/turnouts.md (figures/turnout_rails.png).
        fig = build_figure(load_result(os.path.join(tmp, "turnout.h5")), "rails")
        fig.savefig(os.path.join(os.path.dirname(os.path.abspath(a.csv)), "rails.png"), dpi=110)
        g = "/contact/ws1/left/"
        s = t["/bodies/ws1/s"][:]
        stock, blade = t[g + "rails/rail/normal_force"][:], t[g + "rails/blade/normal_force"][:]
        on_blade = blade > 0
        first = float(s[np.argmax(on_blade)]) if on_blade.any() else math.nan
        width = lambda x: (x - TOE) ** 2 / (2 * LEFT_RADIUS) * 1e3  # noqa: E731  [mm]
        row("ws1 left wheel: first contact with the blade (x after the toe)", first - TOE, None,
            "m")
        row("... the blade's width there (the stock rail's offset x^2 / 2 R_L)", width(first),
            None, "mm")
        last_stock = float(s[np.nonzero(stock > 0)[0][-1]]) if (stock > 0).any() else math.nan
        row("ws1 left wheel: last contact with the stock rail (x after the toe)",
            last_stock - TOE, None, "m")
        row("... the blade's width there", width(last_stock), None, "mm")
        Y, Q = t[g + "Y"][:], t[g + "Q"][:]
        row("ws1 left wheel: largest lateral force Y while on the blade", float(Y[on_blade].max()),
            None, "N")
        row("ws1 left wheel: largest Y/Q (instantaneous, 200 Hz samples) while on the blade",
            float((Y[on_blade] / Q[on_blade]).max()), None, "-")
        row("ws1 left wheel: largest normal force on the blade", float(blade.max()), None, "N")
        bq = t[g + "rails/blade/Q"][:]
        carried = bq > 0.5 * bq.max()
        row("ws1 left wheel: the blade's own Y/Q (rails/blade/y_over_q), largest where the blade "
            "carries more than half its largest Q", float(t[g + "rails/blade/y_over_q"][:][carried].max()),
            None, "-")
        row("ws1 left wheel: largest wear number T gamma on the blade",
            float(t[g + "rails/blade/t_gamma"][:].max()), None, "N")
        tp = p["/contact/ws1/left/"]
        sp = p["/bodies/ws1/s"][:]
        row("plain rail, same track: ws1 left wheel's largest Y after the toe",
            float(tp["Y"][:][sp > TOE].max()), None, "N")
        row("plain rail, same track: ws1 left wheel's largest Y/Q after the toe",
            float((tp["Y"][:] / tp["Q"][:])[sp > TOE].max()), None, "-")
        fg = fx[g]
        f_on = fg["rails/blade/normal_force"][:] > 0
        fY, fQ = fg["Y"][:], fg["Q"][:]
        row("flexible track: ws1 left wheel: largest lateral force Y while on the blade",
            float(fY[f_on].max()), None, "N")
        row("flexible track: ws1 left wheel: largest Y/Q (instantaneous) while on the blade",
            float((fY[f_on] / fQ[f_on]).max()), None, "-")
        row("flexible track: ws1 left wheel: largest normal force on the blade",
            float(fg["rails/blade/normal_force"][:].max()), None, "N")
        row("flexible track: the rail mass under ws1's left wheel: largest lateral deflection",
            float(np.abs(fg["track/rail_y"][:]).max()) * 1e3, None, "mm")
        row("flexible track: the rail mass under ws1's left wheel: largest vertical deflection",
            float(np.abs(fg["track/rail_z"][:]).max()) * 1e3, None, "mm")
        for label, f in (("turnout rails", t), ("plain rail", p), ("flexible track", fx)):
            st = f["stats"].attrs
            row(f"{label}: CPU time ({f['/time'][-1]:.2f} s simulated)", float(st["cpu_time_s"]),
                None, "s")
            row(f"{label}: rhs evaluations", float(st["rhs_evals"]), None, "-")
        # The crossing on the through route (scenarios/turnout/crossing_through.lua): on its
        # flexible track, with a lighter rail mass, and on rigid rails.
        ctext = open(os.path.join(ROOT, CROSSING)).read()
        variants = [("crossing, flexible track (150 kg rail mass)", ctext)]
        # (the lighter rail mass's stiffer mode needs a smaller step)
        light, n1 = re.subn(r"mass = 150,", "mass = 50,", ctext)
        light, n3 = re.subn(r"c\.abm\(speed, 1e-4\)", "c.abm(speed, 5e-5)", light)
        n1 = n1 * n3
        rigid, n2 = re.subn(r",\n\s*elastic = \{ rail_support = \{[^}]*\} \} \}", " }", ctext)
        if n1 != 1 or n2 != 1:
            raise RuntimeError(f"{CROSSING}: its support is not where this study expects it")
        variants += [("crossing, flexible track (50 kg rail mass)", light),
                     ("crossing, rigid rails", rigid)]
        for k, (label, body) in enumerate(variants):
            lua = os.path.join(ROOT, "scenarios", "turnout", f".crossing_tmp{k}.lua")
            try:
                with open(lua, "w") as f:
                    f.write(body)
                h5 = os.path.join(tmp, "crossing_through.h5" if k == 0 else f"crossing{k}.h5")
                cx = scene_runs.run(a.workbench, lua, h5)
            finally:
                os.remove(lua)
            if k == 0:  # the shipped scene's rails figure, for docs/turnouts.md
                fig = build_figure(load_result(h5), "rails")
                fig.savefig(os.path.join(os.path.dirname(os.path.abspath(a.csv)),
                                         "crossing_rails.png"), dpi=110)
            q0 = float(cx["/contact"].attrs["elastic_static_load_N"])
            cs = cx["/bodies/ws1/s"][:]
            cg = cx["/contact/ws1/right/rails/"]
            wing, nose_n = cg["rail/normal_force"][:], cg["nose/normal_force"][:]
            x = crossing(cs, wing, nose_n) - TP
            z = cx["/bodies/ws1/z"][:]
            dip = z[cs < TP - 1.0][-1] - z[(cs > TP - 0.4) & (cs < TP + x + 0.01)].min()
            row(f"{label}: ws1 right wheel from the wing rail to the nose at x after the "
                "theoretical point", x, None, "m")
            row(f"{label}: ... the nose's width there (x / 9)", x / 9 * 1e3, None, "mm")
            row(f"{label}: ws1's dip before the nose", dip * 1e3, None, "mm")
            row(f"{label}: largest normal force on the nose (ws1 right wheel)",
                float(nose_n.max()), None, "N")
            row(f"{label}: ... in static wheel loads", float(nose_n.max()) / q0, None, "-")
            st = cx["stats"].attrs
            row(f"{label}: CPU time ({cx['/time'][-1]:.2f} s simulated)",
                float(st["cpu_time_s"]), None, "s")
        # Validation scenes (tests/run/test_sliced_rails.cpp).
        beta = 0.025
        lw = scene_runs.run(a.workbench, "tests/run/data/sliced_rails_lowered.lua",
                 os.path.join(tmp, "lowered.h5"))
        drops = [float(lw[f"/bodies/{w}/z"][-1] - lw[f"/bodies/{w}/z"][0])
                 for w in ("ws1", "ws2", "ws3", "ws4")]
        row("both rails lowered 3 mm: wheelsets' drop (mean of 4; reference 3 cos(beta))",
            -np.mean(drops) * 1e3, 3 * math.cos(beta), "mm")
        ll = scene_runs.run(a.workbench, "tests/run/data/sliced_rails_lowered_left.lua",
                 os.path.join(tmp, "lowered_left.h5"))
        rolls = [float(ll[f"/bodies/{w}/roll"][-1] - ll[f"/bodies/{w}/roll"][0])
                 for w in ("ws1", "ws2", "ws3", "ws4")]
        row("left rail lowered 3 mm: wheelsets' roll (mean of 4; reference 3 cos(beta) / 1.5 m)",
            -np.mean(rolls) * 1e3, 3 * math.cos(beta) / 1.5, "mrad")
        tr = scene_runs.run(a.workbench, "tests/run/data/sliced_rails_transfer.lua",
                 os.path.join(tmp, "transfer.h5"))
        for w in ("ws1", "ws4"):
            c = f"/contact/{w}/right/rails/"
            x = crossing(tr[f"/bodies/{w}/s"][:], tr[c + "rail/normal_force"][:],
                         tr[c + "nose/normal_force"][:])
            row(f"two rails level at s = 80 m: {w}'s load half on each at", x, 80.0, "m")
    scene_runs.write_rows(a.csv, rows, ("quantity", "value", "reference", "unit"))
    return 0


if __name__ == "__main__":
    sys.exit(main())
