#!/usr/bin/python3
"""Writes the rail slices of scenarios/turnout/*.lua into scenarios/turnout/slices/ (run it from
the project root: /usr/bin/python3 scenarios/turnout/make_slices.py).

60e1.txt is the 60E1 head of railbench's built-in profile (workbench/profiles/rail60e1.cpp, EN
13674-1), sampled every 0.2 mm (the same points as tests/run/data/rails/60e1_a.txt). head_wNN.txt
is that head cut to a width of NN mm from its gauge face (u = -36 mm, the head being 72 mm wide),
the field side dropping by 24 mm over 3 mm beyond the cut: the top of a switch blade or of a
crossing nose of that width whose gauge face is the running rail's (docs/turnouts.md). The cut is
rounded over 0.5 mm (a softplus) so that the profile stays smooth; its slopes stay below 10, what
the profile reader keeps.
"""
import math
import os

HERE = os.path.dirname(os.path.abspath(__file__))
SRC = os.path.join(HERE, "..", "..", "tests", "run", "data", "rails", "60e1_a.txt")
OUT = os.path.join(HERE, "slices")
# [mm] every 2 mm (1 mm up to 6 mm): a blade's or nose's field edge moves 2 mm at most from one
# slice to the next, so the blend of two neighbouring slices is close to the head between them.
WIDTHS = [1, 2, 3, 4, 5, 6] + list(range(8, 72, 2))
GAUGE_FACE = -36.0  # [mm] u of the head's gauge face (72 mm head)
DROP, RISE_WIDTH, ROUND = 24.0, 3.0, 0.5  # [mm]


def softplus(x):
    return x if x > 30 else math.log1p(math.exp(x))


def main():
    pts = []
    with open(SRC) as f:
        for line in f:
            if line.startswith("#") or not line.strip():
                continue
            u, z = map(float, line.split())
            pts.append((u, z))
    os.makedirs(OUT, exist_ok=True)
    head = ("# 60E1 rail head (EN 13674-1) as drawn by railbench's built-in profile "
            "(workbench/profiles/rail60e1.cpp),\n# sampled every 0.2 mm: y [mm] (field side > 0, "
            "left rail), z [mm] up. Written by scenarios/turnout/make_slices.py.\n")
    with open(os.path.join(OUT, "60e1.txt"), "w") as f:
        f.write(head)
        for u, z in pts:
            f.write("%.4f %.6f\n" % (u, z))
    slope = DROP / RISE_WIDTH
    for w in WIDTHS:
        cut = GAUGE_FACE + w
        with open(os.path.join(OUT, "head_w%02d.txt" % w), "w") as f:
            f.write(head.replace("\n# sampled", " cut to a width of %d mm from its gauge face "
                                 "(u = %.0f mm) for a blade or nose top,\n# sampled" % (w, GAUGE_FACE)))
            for u, z in pts:
                # Drop of slope DROP / RISE_WIDTH from the cut, DROP deep, both corners rounded.
                d = ROUND * slope * (softplus((u - cut) / ROUND) -
                                     softplus((u - cut - RISE_WIDTH) / ROUND))
                f.write("%.4f %.6f\n" % (u, z - d))


if __name__ == "__main__":
    main()
