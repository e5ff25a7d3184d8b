"""Study cost (paper Tables 7, 12-16; Fig. 23, 26) and LUT-vs-KEC accuracy (Eq. 33,
Table 8, Fig. 24, 25)."""
from __future__ import annotations

import math
from typing import List, Optional, Sequence, Tuple

from matplotlib.patches import Patch
import numpy as np

from .style import A4_WIDTH_IN, FAIL_COLOR, plt, report_style
from .layout import _run_style
from .study_data import Case, Study, _num, compact, on_grid, series


# Cost (paper Tables 7, 12-16; Fig. 23, 26)
# --------------------------------------------------------------------------------------------
def cost_rows(study: Study) -> List[dict]:
    rows = []
    for c in study.cases:
        ev = c.counts["rhs_evals"]
        cpu_runs = [_num(r.get("cpu_time_s"), 0.0) for r in c.repeats if r.get("status") == "ok"]
        rows.append(dict(
            case=c.id, label=c.label, role=c.role, model=c.model_key, solver=c.solver_key,
            method=c.method, integrator=c.integrator,
            tol="" if c.tol is None else compact(c.tol),
            step_s="" if c.step is None else f"{c.step:g}",
            max_step_s="" if c.max_step is None else f"{c.max_step:g}",
            K="" if c.K is None else compact(c.K), refined_tables=str(c.refined).lower(),
            interpolation=c.interpolation,
            status=c.status, runs=c.runs, runs_ok=c.runs_ok,
            cpu_median_s=f"{c.cpu_median:.4f}", cpu_min_s=f"{c.cpu_min:.4f}",
            cpu_max_s=f"{c.cpu_max:.4f}", cpu_runs_s=";".join(f"{x:.4f}" for x in cpu_runs),
            rhs_evals=int(ev), rhs_evals_jac=int(c.counts["rhs_evals_jac"]),
            steps=int(c.counts["steps"]), rejected_steps=int(c.counts["rejected_steps"]),
            jacobian_evals=int(c.counts["jacobian_evals"]),
            model_evaluations=int(c.counts["model_evaluations"]),
            us_per_eval=f"{c.cpu_median / ev * 1e6:.3f}" if c.ok and ev > 0 else "",
            t_reached_s=f"{c.counts['t_reached']:.4f}",
            table_build_time_s=_fmt(c.attr("contact_table_build_time_s")),
            table_bytes=_fmt(c.attr("contact_table_bytes"), "{:.0f}"),
            message=c.message, file=c.file))
    return rows


def _fmt(v, f="{:.4g}"):
    return "" if v is None else f.format(v)


def failure_rows(study: Study) -> List[dict]:
    rows = []
    for c in study.cases:
        for r in c.repeats:
            if r.get("status") != "ok":
                rows.append(dict(case=c.id, label=c.label, repeat=r.get("repeat", ""),
                                 status=r.get("status", ""),
                                 t_reached_s=r.get("t_reached", ""), reason=r.get("message", ""),
                                 overrides=r.get("overrides", ""), file=r.get("file", "")))
    return rows


def _groups(study: Study):
    """Solver keys (x groups, in study order) and model keys (series, in study order)."""
    sk, mk = [], []
    for c in study.cases:
        if c.solver_key not in sk:
            sk.append(c.solver_key)
        if c.model_key not in mk:
            mk.append(c.model_key)
    return sk, mk


def fig_cost(study: Study, title: str = ""):
    """CPU time (median, min-max bar) and evaluations per case: groups = solver settings,
    bars = models (method, K, tables, ...); failed cases as red hatched stubs marked 'failed'."""
    sk, mk = _groups(study)
    nb = max(1, len(mk))
    width = 0.8 / nb
    w_in = min(16.0, max(A4_WIDTH_IN, 0.22 * len(study.cases) + 1.5))
    cmap = plt.get_cmap("tab10" if nb <= 10 else "tab20")
    n_fail = any(not c.ok for c in study.cases)
    ncol = max(1, min(len(mk) + n_fail, int(w_in / 2.2)))
    leg_rows = math.ceil((len(mk) + n_fail) / ncol)
    leg_h = 0.18 * leg_rows + 0.15
    with report_style():
        fig = plt.figure(figsize=(w_in, 6.2 + leg_h), layout="constrained")
        gs = fig.add_gridspec(3, 1, height_ratios=[3.1, 3.1, leg_h])
        ax0 = fig.add_subplot(gs[0])
        axes = [ax0, fig.add_subplot(gs[1], sharex=ax0)]
        lax = fig.add_subplot(gs[2])
        lax.axis("off")
        for ax, key, ylabel in ((axes[0], "cpu", "CPU time [s] (median)"),
                                (axes[1], "rhs_evals", "right-hand side evaluations")):
            vals = [c.cpu_median if key == "cpu" else c.counts["rhs_evals"]
                    for c in study.cases if c.ok]
            good = [v for v in vals if v > 0]
            lo = min(good) / 3 if good else 0.1
            for c in study.cases:
                i, j = sk.index(c.solver_key), mk.index(c.model_key)
                x = i - 0.4 + width * (j + 0.5)
                col = cmap(j % cmap.N)
                if c.ok:
                    v = c.cpu_median if key == "cpu" else c.counts["rhs_evals"]
                    ax.bar(x, v, width * 0.92, color=col, edgecolor="none", bottom=0)
                    if key == "cpu" and c.runs_ok > 1:
                        ax.plot([x, x], [c.cpu_min, c.cpu_max], color="k", lw=0.7)
                else:
                    ax.bar(x, lo * 2.2, width * 0.92, bottom=lo, color="none",
                           edgecolor=FAIL_COLOR, hatch="xxx", lw=0.6)
                    ax.text(x, lo * 3.4, "failed", rotation=90, ha="center", va="bottom",
                            fontsize=6, color=FAIL_COLOR)
            ax.set_yscale("log")
            if good:
                ax.set_ylim(lo, max(good) * 3)
            ax.set_ylabel(ylabel)
        axes[1].set_xticks(range(len(sk)))
        axes[1].set_xticklabels(sk, rotation=30, ha="right")
        plt.setp(axes[0].get_xticklabels(), visible=False)
        handles = [Patch(color=cmap(j % cmap.N), label=m) for j, m in enumerate(mk)]
        if n_fail:
            handles.append(Patch(facecolor="none", edgecolor=FAIL_COLOR, hatch="xxx",
                                    label="failed (reason: study_failures.csv)"))
        lax.legend(handles=handles, ncols=ncol, loc="center", fontsize=6.5)
        _title(fig, title or "Computation cost per case (paper Fig. 23, Tables 7, 12-16)")
    return fig


def fig_tables(study: Study):
    """Contact table build time and size per model (paper Tables 9-10), or None."""
    seen = {}
    for c in study.cases:
        bt, nb = c.attr("contact_table_build_time_s"), c.attr("contact_table_bytes")
        if bt is None or nb is None:
            continue
        seen.setdefault(c.model_key, []).append((bt, nb))
    if not seen or not any(c.refined for c in study.cases):
        return None
    names = list(seen)
    with report_style():
        fig, axes = plt.subplots(1, 2, figsize=(A4_WIDTH_IN, 2.8), layout="constrained")
        axes[0].bar(range(len(names)), [np.median([v[0] for v in seen[n]]) for n in names],
                    color="#1f5fa8")
        axes[0].set_ylabel("table build time [s] (median)")
        axes[1].bar(range(len(names)), [seen[n][0][1] / 1024 for n in names], color="#b2182b")
        axes[1].set_ylabel("table memory [KiB]")
        for ax in axes:
            ax.set_xticks(range(len(names)))
            ax.set_xticklabels(names, rotation=30, ha="right", fontsize=6.5)
        fig.suptitle("Contact tables: default vs refined grids (paper Tables 9, 10)")
    return fig


# --------------------------------------------------------------------------------------------
# Accuracy: LUT vs KEC (paper Eq. 33, Table 8, Fig. 24, 25)
# --------------------------------------------------------------------------------------------
def _pair_key(c: Case) -> Tuple:
    ov = {k: v for k, v in c.overrides.items()
          if k not in ("contact.method", "contact.flange_stiffness", "contact.flange_damping")}
    return (c.base, tuple(sorted(ov.items())))


def lut_kec_pairs(study: Study) -> List[Tuple[Case, Case]]:
    """(LUT case, KEC case) with every other override equal (same integrator and tolerance)."""
    kec = {}
    for c in study.cases:
        if c.method == "kec" and not c.role.startswith("reference"):
            kec.setdefault(_pair_key(c), c)
    return [(c, kec[_pair_key(c)]) for c in study.cases
            if c.method == "lut" and not c.role.startswith("reference") and _pair_key(c) in kec]


def accuracy_rows(study: Study) -> List[dict]:
    """Per pair and wheelset: max and mean |y_KEC - y_LUT| [mm] on the LUT output times inside
    both runs, and Eq. 33 (the same divided by max |y_LUT|); wheelset 'all': max / mean over
    the four wheelsets."""
    rows = []
    for lut, kec in lut_kec_pairs(study):
        sl, sk = series(lut), series(kec)
        extra = " ".join(t for t in lut.model_key.split()[1:] if not t.startswith("K="))
        base = dict(lut_case=lut.id, kec_case=kec.id, lut_label=lut.label, kec_label=kec.label,
                    group=(lut.solver_key + " " + extra).strip(), solver=lut.solver_key,
                    integrator=lut.integrator, K=compact(lut.K), lut_status=lut.status,
                    kec_status=kec.status)
        if sl is None or sk is None or len(sl.t) < 2 or len(sk.t) < 2:
            rows.append(dict(base, wheelset="all", max_abs_mm="", mean_abs_mm="",
                             eq33_max="", eq33_mean="", t_from_s="", t_to_s="", samples=0,
                             note="result file missing"))
            continue
        maxes, means = [], []
        for ws in sl.wheelsets:
            yl, yk = sl.body(ws, "y"), sk.body(ws, "y")
            if yl is None or yk is None:
                continue
            m, ykg = on_grid(sl.t[:len(yl)], sk.t, yk)
            if not m.any():
                continue
            ylm = yl[:len(m)][m]
            d = np.abs(ykg - ylm)
            den = np.max(np.abs(ylm)) or 1.0
            maxes.append(d.max())
            means.append(d.mean())
            tm = sl.t[:len(m)][m]
            rows.append(dict(base, wheelset=ws, max_abs_mm=f"{d.max() * 1e3:.5g}",
                             mean_abs_mm=f"{d.mean() * 1e3:.5g}",
                             eq33_max=f"{d.max() / den:.4g}", eq33_mean=f"{d.mean() / den:.4g}",
                             t_from_s=f"{tm[0]:.3f}", t_to_s=f"{tm[-1]:.3f}", samples=int(m.sum()),
                             note="" if lut.ok and kec.ok else "a run failed: compared up to its "
                                                               "end"))
        if maxes:
            rows.append(dict(base, wheelset="all", max_abs_mm=f"{max(maxes) * 1e3:.5g}",
                             mean_abs_mm=f"{np.mean(means) * 1e3:.5g}", eq33_max="",
                             eq33_mean="", t_from_s="", t_to_s="", samples="",
                             note="max / mean over the wheelsets"))
    return rows


def _title(fig, text: str):
    import textwrap
    width = max(40, int(fig.get_size_inches()[0] * 72 / (0.6 * 10.5)))
    fig.suptitle("\n".join(textwrap.wrap(text, width)))


def fig_accuracy(rows: List[dict]):
    """Table 8 as bars: max and mean |y_KEC - y_LUT| over the wheelsets per solver and K."""
    rows = [r for r in rows if r["wheelset"] == "all" and r["max_abs_mm"] != ""]
    if not rows:
        return None
    solvers = list(dict.fromkeys(r["group"] for r in rows))
    Ks = sorted(set(r["K"] for r in rows), key=float)
    cmap = plt.get_cmap("viridis")
    w = 0.8 / len(Ks)
    with report_style():
        fig, axes = plt.subplots(2, 1, figsize=(max(A4_WIDTH_IN, 0.9 * len(solvers) + 2), 5),
                                 sharex=True, layout="constrained")
        for ax, key, lab in ((axes[0], "max_abs_mm", "max |y_KEC - y_LUT| [mm]"),
                             (axes[1], "mean_abs_mm", "mean |y_KEC - y_LUT| [mm]")):
            for r in rows:
                i, j = solvers.index(r["group"]), Ks.index(r["K"])
                failed = r["lut_status"] != "ok" or r["kec_status"] != "ok"
                ax.bar(i - 0.4 + w * (j + 0.5), float(r[key]), w * 0.92,
                       color=cmap(j / max(1, len(Ks) - 1)),
                       hatch="xxx" if failed else None,
                       edgecolor=FAIL_COLOR if failed else "none")
            ax.set_ylabel(lab)
            ax.set_ylim(bottom=0)
        axes[1].set_xticks(range(len(solvers)))
        axes[1].set_xticklabels(solvers, rotation=30, ha="right")
        handles = [Patch(color=cmap(j / max(1, len(Ks) - 1)), label=f"LUT K = {k} N/m^1.5")
                   for j, k in enumerate(Ks)]
        if any(r["lut_status"] != "ok" or r["kec_status"] != "ok" for r in rows):
            handles.append(Patch(facecolor="none", edgecolor=FAIL_COLOR, hatch="xxx",
                                    label="a run failed: compared up to where it stopped"))
        axes[0].legend(handles=handles, fontsize=6.5, ncols=3)
        _title(fig, "LUT vs KEC with the same integrator: wheelset lateral displacement "
                    "difference, max / mean over time and the four wheelsets (paper Eq. 33, "
                    "Table 8)")
    return fig


def flange_wheel(cases: Sequence[Case]) -> Optional[Tuple[str, str]]:
    """(wheelset, side) with the largest flange force in any of the cases."""
    best, arg = -1.0, None
    for c in cases:
        s = series(c)
        if s is None:
            continue
        for ws in s.wheelsets:
            for side in ("left", "right"):
                f = s.wheel(ws, side, "flange_force")
                if f is not None and len(f) and np.nanmax(f) > best:
                    best, arg = float(np.nanmax(f)), (ws, side)
    return arg


def _lut_panels(runs: Sequence[Tuple[Case, str]], wheel: Tuple[str, str], title: str,
                with_y: bool):
    ws, side = wheel
    rows = ([("y", "lateral displacement y [mm]", 1e3)] if with_y else []) + [
        ("flange_indentation", "flange indentation [mm]\n(< 0: clearance)", 1e3),
        ("flange_force", "flange normal force [kN]", 1e-3)]
    with report_style():
        fig, axes = plt.subplots(len(rows), 1, figsize=(A4_WIDTH_IN, 1.9 * len(rows) + 0.8),
                                 sharex=True, layout="constrained")
        for k, (c, lab) in enumerate(runs):
            s = series(c)
            if s is None:
                continue
            st = _run_style(k)
            for ax, (q, ylab, sc) in zip(axes, rows):
                a = s.body(ws, q) if q == "y" else s.wheel(ws, side, q)
                if a is None:
                    continue
                t = s.t[:len(a)]
                ax.plot(t, a * sc, label=lab + ("" if c.ok else " (failed)"), **st)
                ax.set_ylabel(ylab)
        axes[-1].set_xlabel("time [s]")
        axes[0].legend(fontsize=6.5, ncols=2)
        _title(fig, f"{title}; {ws}, {side} wheel (the largest flange force of these runs)")
    return fig


def _fig24_setting(c: Case) -> bool:
    """The settings of the paper's Fig. 24 (section 5.4): fixed steps of 1 ms, adaptive steps
    with the 1 ms largest step."""
    if c.step is not None:
        return abs(c.step - 1e-3) < 1e-12
    return c.max_step is not None and abs(c.max_step - 1e-3) < 1e-12


def fig_lut_integrators(study: Study):
    """Fig. 24: LUT with every solver at K = 1e12 (else the largest K with runs), with the
    paper's Fig. 24 settings where the study has them (else every setting)."""
    lut = [c for c in study.cases
           if c.method == "lut" and not c.role.startswith("reference") and c.file]
    fig24 = [c for c in lut if _fig24_setting(c)]
    if len({c.solver_key for c in fig24}) >= 2:
        lut = fig24
    if len({c.solver_key for c in lut}) < 2:
        return None
    Ks = sorted({c.K for c in lut})
    K = 1e12 if 1e12 in Ks else Ks[-1]
    sel = [c for c in lut if c.K == K and c.model_key == min(
        (x.model_key for x in lut if x.K == K), key=len)]
    wheel = flange_wheel(sel)
    if wheel is None:
        return None
    return _lut_panels([(c, c.solver_key) for c in sel], wheel,
                       f"LUT, K = {compact(K)} N/m^1.5, every integrator (paper Fig. 24)", True)


def fig_lut_stiffness(study: Study, solver: str):
    """Fig. 25: LUT flange indentation and force per K with one solver setting."""
    sel = [c for c in study.cases
           if c.method == "lut" and not c.role.startswith("reference") and c.file
           and c.solver_key == solver and not c.refined]
    if len({c.K for c in sel}) < 2:
        return None
    sel.sort(key=lambda c: c.K)
    wheel = flange_wheel(sel)
    if wheel is None:
        return None
    return _lut_panels([(c, f"K = {compact(c.K)}") for c in sel], wheel,
                       f"LUT flange contact per stiffness, {solver} (paper Fig. 25)", False)


# --------------------------------------------------------------------------------------------
