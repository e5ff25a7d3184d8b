"""The generated block of docs/contact_geometry.md: the contact tables of the paper's profile pair
(S1002 on 60E1 at 1:40, the validation cases' set-up), written by `./wb studies --only tables`
(`workbench tables scenarios/validation/case3_lut.lua --out OUT/tables/study.h5`, then
`plots/rbplot tables`, whose figures OUT/tables/study_<name>.png the page shows as
figures/tables_<name>.png: the paper's Fig. 1 and Fig. 7 among them)."""
import os
from typing import List

from .docs_blocks import missing, table
from .tables import summary_line
from .tables_data import TablesFileError, load_tables
from .tables_maps import conicity_at

AMPLITUDES_MM = (1.0, 2.0, 3.0, 4.0, 5.0, 6.0)


def tables_block(outdir: str) -> str:
    path = os.path.join(outdir, "tables", "study.h5")
    if not os.path.exists(path):
        return missing(f"{path} (./wb studies --only tables)")
    try:
        t = load_tables(path)
    except TablesFileError as e:
        return missing(f"{path}: {e}")
    parts: List[str] = [f"`rbplot tables` summary: {summary_line(t)}."]
    cells = []
    for a in AMPLITUDES_MM:
        v = conicity_at(t, a * 1e-3)
        cells.append("–" if v is None else f"{v:.4f}")
    parts.append("EN 15302 equivalent conicity (jumps of delta r kept sharp, section 5):\n\n" +
                 table(["amplitude [mm]"] + [f"{a:g}" for a in AMPLITUDES_MM],
                       [["tan gamma_e"] + cells]))
    d = t.derived or {}
    if "jump_y" in d and getattr(d["jump_y"], "size", 0):
        rows = [[f"{y * 1e3:+.4f}", f"{lft * 1e3:.4f}", f"{rgt * 1e3:.4f}"]
                for y, lft, rgt in sorted(zip(d["jump_y"], d["jump_delta_r_left"],
                                              d["jump_delta_r_right"]))]
        parts.append("Jumps of the rolling-radius difference (contact-point jumps located by "
                     "the engine):\n\n" + table(["y [mm]", "delta r left limit [mm]",
                                                 "delta r right limit [mm]"], rows))
    return "\n\n".join(parts)
