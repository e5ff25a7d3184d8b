"""Report figures for railbench contact-table files (`workbench tables SCENARIO.lua --out F.h5`).

Reading
    load_tables(path) -> Tables          validated, in-memory copy of /profiles and /tables

Figures (each returns a matplotlib Figure; nothing is written)
    fig_profiles_contact(t)   (a) left wheel on left rail in the wheelset track frame for a few
                              lateral displacements y (LUT nodes: tread contact, flange point
                              when within 0.1 mm); (b) the KEC solved at the same y: knife edge
                              on the equivalent profile f_k(s_k) and the mapped real contact
                              s_w(s_k) on the real wheel profile (paper Fig. 1)
    fig_lut_z(t)              z(y) - z(0) and phi(y) for every gauge variation xi_g, and the
                              z table over (y, xi_g) with the two-point contact line (Fig. 7)
    fig_kec_map(t)            real wheel parameter s_w versus equivalent s_k per wheel, the
                              regularised transitions [lo, hi] shaded, weight w of the flange
                              point B, zoom on the transitions around the largest s_w jump
                              with their end points A and B (Fig. 9, 10)
    fig_rolling_radius(t)     delta r(y) = r_l - r_r and delta gamma(y), two-point contact marked
    fig_conicity(t)           EN 15302 equivalent conicity tan(gamma_e) versus amplitude

Geometry
    knife_point(y, z, phi, r0, lr)      (s_k, f_k) of the left wheel for a wheelset pose
    kec_solve(kec, y, r0, lr)           KEC pose (z, phi, s_lk, s_rk) at y (Eq. 22, Newton)

Driver
    FIGURES                   registry: (suffix, is_available(t), make(t))
    make_figures(t, outdir)   writes every available figure, returns the paths
    summary_line(t)           one-line summary (build times, sizes, conicity at 3 mm, ...)

Conventions (docs/contact_geometry.md, docs/profiles.md): Y to the left, Z up; left wheel
s_w > 0 and left rail s_r > 0 toward the field side; wheel h = radius, rail h = head height
(origin crown top of the uninclined head); rails at +-(Lr + xi_g/2) rotated by +-beta, wheels at
+-Lw; roll enters linearised, A = [[1, -phi], [phi, 1]]:
    wheel point  (y, z) + A (Lw + s_w, -h_w(s_w))
    rail point   (Lr + xi_g/2, 0) + Rx(beta) (s_r, h_r(s_r))
KEC knife point (Eq. 22 in the docs' form, zero irregularity):
    y + s_k + phi (r0 + f_k) - xi_g/2 = 0,   z + phi (Lr + s_k) - r0 - f_k = 0.
A group that is absent only removes its figures; a group that is present but broken (missing
or mis-shaped datasets) makes load_tables raise TablesFileError (one-line message).

Only numpy, matplotlib (Agg) and h5py are used; no scipy.
"""
from __future__ import annotations

from typing import Dict, List, Optional

from .common import FigureSpec, figure_command, write_figures
from .style import DPI
from .tables_data import Tables, TablesFileError, load_tables
from .tables_figs import fig_lut_z, fig_profiles_contact
from .tables_maps import conicity_at, fig_conicity, fig_kec_map, fig_rolling_radius


# Registry, driver, summary
# --------------------------------------------------------------------------------------------
FIGURES: List[FigureSpec] = [
    FigureSpec("profiles_contact",
               lambda t: t.lut is not None and t.wheel is not None and t.rail is not None
               and t.has_geometry, fig_profiles_contact,
               "profiles in the wheelset frame, contact points, KEC-equivalent profile"),
    FigureSpec("lut_z", lambda t: t.lut is not None, fig_lut_z,
               "z(y) - z(0) and phi(y) for every gauge variation, z table"),
    FigureSpec("kec_map", lambda t: t.kec is not None, fig_kec_map,
               "s_w versus s_k with the regularised transitions and the weight"),
    FigureSpec("rolling_radius", lambda t: t.derived is not None, fig_rolling_radius,
               "delta r(y) and delta gamma(y)"),
    FigureSpec("conicity", lambda t: t.conicity is not None, fig_conicity,
               "EN 15302 tan gamma_e versus amplitude"),
]


def make_figures(t: Tables, outdir: Optional[str] = None, stem: Optional[str] = None,
                 dpi: int = DPI, fmt: str = "png") -> List[str]:
    """Write every figure the file's content allows; return the written paths."""
    return write_figures(FIGURES, t, outdir, stem, dpi, fmt)


def _bytes(v) -> str:
    v = float(v)
    return f"{v / 1e6:.2f} MB" if v >= 1e5 else f"{v / 1e3:.1f} kB"


def _stats(a: Dict[str, object]) -> List[str]:
    out = []
    bt = a.get("build_time_s")
    if isinstance(bt, (int, float)):
        out.append(f"{bt:.3g} s")
    if isinstance(a.get("bytes"), (int, float)):
        out.append(_bytes(a["bytes"]))
    fl = a.get("failures")
    if isinstance(fl, (int, float)) and fl:
        out.append(f"{int(fl)} FAILURES")
    wn = [w for w in str(a.get("warnings", "")).split("\n") if w.strip()]
    if wn:
        out.append(f"{len(wn)} warning{'s' if len(wn) > 1 else ''}")
    return out


def summary_line(t: Tables) -> str:
    """'tables: LUT 361 x 11 (y x xi_g) 0.15 s, 4.84 MB; KEC 465 points 0.06 s, 0.22 MB;
    tan(gamma_e) at 3 mm = 0.177; two-point contact at y = 6.260 mm; config <hash>'."""
    parts = []
    if t.lut is not None:
        parts.append(f"LUT {t.lut.y.size} x {t.lut.xi_g.size} (y x xi_g) "
                     + ", ".join(_stats(t.lut.attrs)))
    if t.kec is not None:
        parts.append(f"KEC {t.kec.s_k.size} points " + ", ".join(_stats(t.kec.attrs)))
    if t.derived is not None:
        v3 = conicity_at(t, 3e-3)
        parts.append(f"tan(gamma_e) at 3 mm = {v3:.3f}" if v3 is not None
                     else "tan(gamma_e) at 3 mm: n/a")
    if t.lut is not None:
        tps = t.lut.two_points(float(t.lut.xi_g[t.lut.row(0.0)]))
        if tps:
            parts.append("two-point contact at y = " + ", ".join(
                f"{ty * 1e3:+.3f} mm" for ty, _ in sorted(tps)))
    h = t.geom.get("config_hash")
    if h:
        parts.append(f"config {h}")
    return "tables: " + ("; ".join(p.strip() for p in parts) if parts else "no tables")


def main(argv=None) -> int:
    return figure_command(argv, "tables", "Draw report figures from a railbench tables file.",
                          "tables file (.h5) written by `workbench tables`", load_tables,
                          make_figures, summary_line, (TablesFileError,))
