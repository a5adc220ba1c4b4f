#!/usr/bin/python3
"""Draws the study's charts and writes its summary (docs/study/).

    plot_study.py WORK_DIR DOCS_DIR

Reads the CSV files the study decks wrote with IMPR_MESURE (WORK_DIR/out/*.csv) and
CalculiX's rows (chart_2d_ccx.csv), copies them to DOCS_DIR, and draws SVG + PNG
figures and README.md (per method, the cheapest run reaching 1 % and 0.1 %).
Debian packages only: python3-matplotlib.
"""
import csv
import datetime
import os
import platform
import re
import shutil
import subprocess
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import matplotlib.ticker  # noqa: E402,F401

FLOOR = 1e-10  # errors below are drawn at the floor (round-off: the method is exact)


def read(path):
    if not os.path.exists(path):
        return []
    with open(path) as f:
        return list(csv.DictReader(f))


def num(row, key):
    try:
        return float(row.get(key, ""))
    except ValueError:
        return None


def save(fig, docs, name):
    fig.tight_layout()
    for ext in ("svg", "png"):
        fig.savefig(os.path.join(docs, f"{name}.{ext}"), dpi=110)
    plt.close(fig)


def style(method):
    colors = {"CONTINUE-GAUSS": "#1f77b4", "CONTINUE-SIMPSON": "#2ca02c", "CONTINUE-NCOTES": "#17becf",
              "CONTRAINTE": "#d62728", "PENALISATION-1e7": "#ff7f0e", "PENALISATION-1e9": "#e377c2",
              "PENALISATION-1e11": "#8c564b", "MORTAR": "#bcbd22", "MORTAR-PEN-1e11": "#393b79",
              "CONTINUE": "#1f77b4", "MORTAR-PEN-1e13": "#393b79", "PENALISATION-1e13": "#8c564b"}
    if method.startswith("CalculiX"):
        c = {"NTS": "#7f7f7f", "STS": "#000000", "MORTAR": "#9467bd"}[method.split("-")[1]]
        return dict(color=c, ls="--", marker="s" if "1e11" in method else "D", mfc="white")
    if method.startswith("MORTAR"):
        return dict(color=colors.get(method, "#333333"), ls="-", marker="*")
    return dict(color=colors.get(method, "#333333"), ls="-", marker="o")


def chart(rows, docs, name, title):
    fig, ax = plt.subplots(figsize=(9, 6.5))
    methods = []
    for r in rows:
        if r["method"] not in methods:
            methods.append(r["method"])
    for m in methods:
        pts = [(num(r, "t_total"), max(num(r, "err_p"), FLOOR), r["k"]) for r in rows
               if r["method"] == m and r["status"] == "ok" and num(r, "err_p") is not None]
        if not pts:
            continue
        pts.sort(key=lambda p: float(p[2]))
        ax.plot([p[0] for p in pts], [p[1] for p in pts], label=m, lw=1.4, ms=5, **style(m))
        for t, e, k in pts:
            ax.annotate(k, (t, e), textcoords="offset points", xytext=(3, 3), fontsize=7, color=style(m)["color"])
    for level in (1e-2, 1e-3):
        ax.axhline(level, color="#bbbbbb", lw=0.8, ls=":")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("wall time of the run (s): read + assemble + contact + factorise/solve + post")
    ax.set_ylabel("max relative error of the contact pressure over the interface")
    ax.set_title(title + f"\n(points labelled by refinement k; errors < {FLOOR:g} drawn at {FLOOR:g})", fontsize=10)
    ax.legend(fontsize=7.5, loc="center left", bbox_to_anchor=(1.0, 0.5))
    ax.grid(True, which="major", color="#eeeeee")
    save(fig, docs, name)


def cheapest(rows, level):
    out = {}
    for r in rows:
        e, t = num(r, "err_p"), num(r, "t_total")
        if r["status"] != "ok" or e is None or e > level:
            continue
        if r["method"] not in out or t < num(out[r["method"]], "t_total"):
            out[r["method"]] = r
    return out


SOLVE_BAR = 1e-6  # relative residual of one linear solve that lunaster accepts (static_solver.cpp)


def sweep(rows, docs, name, xkey, xlabel, extra=None):
    fig, axes = plt.subplots(1, 3, figsize=(16, 5.6))
    for k in sorted({r["k"] for r in rows}, key=float):
        sel = [r for r in rows if r["k"] == k]
        ok = [r for r in sel if r["status"] == "ok"]
        bad = [r for r in sel if r["status"] != "ok"]
        axes[0].plot([num(r, xkey) for r in ok], [max(num(r, "err_p"), FLOOR) for r in ok], "o-", label=f"k = {k}")
        for r in bad:
            axes[0].plot(num(r, xkey), 1.0, "kx", ms=9)
        axes[1].plot([num(r, xkey) for r in ok], [num(r, "newton_iter") for r in ok], "o-", label=f"Newton, k = {k}")
        axes[1].plot([num(r, xkey) for r in ok], [num(r, "contact_passes") for r in ok], "s--", label=f"contact passes, k = {k}")
        acc = [r for r in ok if num(r, "solve_resid_raw") is not None]
        if acc:
            line, = axes[2].plot([num(r, xkey) for r in acc], [max(num(r, "solve_resid_raw"), 1e-17) for r in acc], "o-",
                                 label=f"one solve, from the factorisation, k = {k}")
            axes[2].plot([num(r, xkey) for r in acc], [max(num(r, "solve_resid"), 1e-17) for r in acc], "s:",
                         color=line.get_color(), label=f"after iterative refinement, k = {k}")
            axes[2].plot([num(r, xkey) for r in acc], [max(num(r, "resi_glob_rela"), 1e-17) for r in acc], "^--",
                         color=line.get_color(), alpha=0.6, label=f"RESI_GLOB_RELA reached, k = {k}")
    axes[2].axhline(SOLVE_BAR, color="#d62728", lw=0.8, ls=":")
    axes[2].annotate("1e-6: a solve is accepted below, and Newton's RESI_GLOB_RELA bar", (0.02, SOLVE_BAR),
                     xycoords=("axes fraction", "data"), textcoords="offset points", xytext=(0, 3), fontsize=7,
                     color="#d62728")
    axes[2].set_xscale("log"); axes[2].set_yscale("log"); axes[2].set_xlabel(xlabel)
    axes[2].set_ylabel("relative residual |K du + r| / |r| (largest of the run)")
    axes[2].set_title("accuracy: linear solves and the Newton residual reached", fontsize=9)
    if extra:
        extra(axes[0])
    axes[0].set_xscale("log"); axes[0].set_yscale("log")
    axes[0].set_xlabel(xlabel); axes[0].set_ylabel("max relative pressure error (x: failed run)")
    axes[1].set_xscale("log"); axes[1].set_xlabel(xlabel); axes[1].set_ylabel("iterations")
    for ax in axes[:2]:
        ax.legend(fontsize=7); ax.grid(True, color="#eeeeee")
    axes[2].legend(fontsize=6.5, loc="upper center", bbox_to_anchor=(0.5, -0.16), ncol=2)
    axes[2].grid(True, color="#eeeeee")
    save(fig, docs, name)


def main():
    work, docs = sys.argv[1], sys.argv[2]
    out = os.path.join(work, "out")
    os.makedirs(docs, exist_ok=True)
    for f in os.listdir(out):
        if f.endswith(".csv"):
            shutil.copy(os.path.join(out, f), os.path.join(docs, f))
    c2 = read(os.path.join(out, "chart_2d.csv")) + read(os.path.join(out, "chart_2d_ccx.csv"))
    c3 = read(os.path.join(out, "chart_3d.csv")) + read(os.path.join(out, "chart_3d_ccx.csv"))
    chart(c2, docs, "chart_2d", "SSNP121 2D: 12k x 12k QUAD4 over 11k x 11k QUAD4 (non-matching); lunaster and CalculiX")
    for fam in sorted({r["family"] for r in c3}):
        chart([r for r in c3 if r["family"] == fam], docs, f"chart_{fam.lower().replace('-', '')}",
              f"SSNP121 {fam}: lunaster and CalculiX")

    pen = read(os.path.join(out, "atlas_penalty.csv"))
    gap = {(r["k"], float(r["E_N"])): num(r, "penetration") for r in read(os.path.join(out, "atlas_penalty_gap.csv"))}

    def penetration(ax):
        for k in sorted({r["k"] for r in pen}, key=float):
            xs = sorted(e for kk, e in gap if kk == k)
            ax.plot(xs, [gap[(k, e)] / 0.05 for e in xs], "v:", label=f"penetration / 0.05 m, k = {k}")
    sweep(pen, docs, "atlas_penalty", "E_N", "E_N (Pa/m), discrete PENALISATION", penetration)
    sweep(read(os.path.join(out, "atlas_coef.csv")), docs, "atlas_coef", "COEF_CONT", "COEF_CONT, CONTINUE-SIMPSON")

    ratio = read(os.path.join(out, "atlas_ratio.csv"))
    fig, ax = plt.subplots(figsize=(9, 5.5))
    for m in dict.fromkeys(r["method"] for r in ratio):
        pts = sorted((num(r, "ratio"), max(num(r, "err_p"), FLOOR)) for r in ratio if r["method"] == m and r["status"] == "ok")
        ax.plot([p[0] for p in pts], [p[1] for p in pts], label=m, **style(m))
    ax.set_xscale("log"); ax.set_yscale("log")
    ax.set_xlabel("h_slave / h_master (slave AB, master EF with 24 cells)")
    ax.set_ylabel("pressure oscillation: max relative error on the slave")
    ax.axvline(1.0, color="#bbbbbb", lw=0.8)
    ax.legend(fontsize=7.5, loc="center left", bbox_to_anchor=(1.0, 0.5)); ax.grid(True, color="#eeeeee")
    save(fig, docs, "atlas_ratio")

    inc = read(os.path.join(out, "atlas_incompat.csv"))
    if inc:
        fig, ax = plt.subplots(figsize=(9, 4.5))
        pairs = list(dict.fromkeys(r["pairing"] for r in inc))
        methods = list(dict.fromkeys(r["method"] for r in inc))
        w = 0.8 / len(pairs)
        for i, p in enumerate(pairs):
            vals = []
            for m in methods:
                r = next((r for r in inc if r["pairing"] == p and r["method"] == m), None)
                vals.append(max(num(r, "err_p") or 1.0, FLOOR) if r and r["status"] == "ok" else 1.0)
            ax.bar([j + i * w for j in range(len(methods))], vals, w, label=p)
        ax.set_xticks([j + 0.4 - w / 2 for j in range(len(methods))], methods, fontsize=8)
        ax.set_yscale("log"); ax.set_ylabel("max relative pressure error"); ax.legend()
        ax.set_title("Incompatible pairings (3D, 4x4x4): what each method gives", fontsize=10)
        save(fig, docs, "atlas_incompat")

    d23 = read(os.path.join(out, "atlas_2d3d.csv"))
    if d23:
        fig, axes = plt.subplots(1, 2, figsize=(11, 4.5))
        methods = list(dict.fromkeys(r["method"] for r in d23))
        for m in methods:
            two = {r["k"]: r for r in d23 if r["method"] == m and r["family"] == "2D" and r["status"] == "ok"}
            three = {r["k"]: r for r in d23 if r["method"] == m and r["family"] == "3D-slab" and r["status"] == "ok"}
            ks = sorted(set(two) & set(three), key=float)
            axes[0].plot([max(num(two[k], "err_p"), FLOOR) for k in ks], [max(num(three[k], "err_p"), FLOOR) for k in ks],
                         label=m, **style(m))
            axes[1].plot([float(k) for k in ks], [num(three[k], "t_total") / num(two[k], "t_total") for k in ks], label=m, **style(m))
        lims = [FLOOR, 1.0]
        axes[0].plot(lims, lims, color="#bbbbbb", lw=0.8)
        axes[0].set_xscale("log"); axes[0].set_yscale("log")
        axes[0].set_xlabel("pressure error, 2D plane strain"); axes[0].set_ylabel("pressure error, 3D slab")
        axes[1].set_xscale("log", base=2); axes[1].set_xlabel("refinement k"); axes[1].set_ylabel("wall time 3D / 2D")
        for ax in axes:
            ax.grid(True, color="#eeeeee")
        axes[1].legend(fontsize=7)
        save(fig, docs, "atlas_2d3d")

    hz = read(os.path.join(out, "chart_hertz.csv")) + read(os.path.join(out, "chart_hertz_ccx.csv"))
    if hz:
        hertz_chart(hz, docs)
    summary(work, docs, c2, c3, hz)


HERTZ_FAMILIES = {  # family -> (panel title, colour of its envelope)
    "D_PLAN": ("D_PLAN: cylinder on block (line contact, b = R/50), QUAD8 graded 1.1", "#1f77b4"),
    "AXIS-U": ("AXIS: sphere on block (a = R/10), QUAD8 uniform", "#9467bd"),
    "AXIS-G": ("AXIS: sphere on block (a = R/10), QUAD8 graded 1.5", "#2ca02c"),
    "3D-U": ("3D quarter: sphere on block (a = R/10), HEXA20 uniform", "#ff7f0e"),
    "3D-G": ("3D quarter: sphere on block (a = R/10), HEXA20 graded 1.5", "#d62728"),
}
HERTZ_LEVELS = (5e-2, 1e-2, 5e-3)


def hertz_ok(rows):
    return [r for r in rows if r["status"] == "ok" and num(r, "err_p0") is not None and num(r, "t_total") is not None]


def hertz_lost(rows, r, level):
    """The finer runs of r's family and method that are above `level` again."""
    return [s for s in hertz_ok(rows) if s["family"] == r["family"] and s["method"] == r["method"]
            and float(s["k"]) > float(r["k"]) and num(s, "err_p0") > level]


def hertz_cheapest(rows, level, kept=True):
    """Cheapest run at or under `level`; with kept, only runs whose finer runs (same family and
    method) stay under it too: a coarse mesh that hits p0 by chance (3D-U has h0 >= a) or a
    method that loses it on a finer mesh does not count."""
    hits = [r for r in hertz_ok(rows) if num(r, "err_p0") <= level and not (kept and hertz_lost(rows, r, level))]
    return min(hits, key=lambda r: num(r, "t_total")) if hits else None


def hertz_chart(rows, docs):
    """chart_hertz: one panel per model family (a line per method, over refinement), and a last
    panel with, per family, the lower envelope: the cheapest run reaching each error."""
    fams = [f for f in HERTZ_FAMILIES if any(r["family"] == f for r in rows)]
    n = len(fams) + 1
    cols = 3
    fig, axes = plt.subplots((n + cols - 1) // cols, cols, figsize=(16, 5.2 * ((n + cols - 1) // cols)), squeeze=False)
    axes = axes.ravel()
    for ax, fam in zip(axes, fams):
        sel = [r for r in rows if r["family"] == fam]
        for m in dict.fromkeys(r["method"] for r in sel):
            pts = sorted(((num(r, "t_total"), max(num(r, "err_p0"), FLOOR), r["k"]) for r in hertz_ok(sel)
                          if r["method"] == m), key=lambda p: float(p[2]))
            if not pts:
                continue
            ax.plot([p[0] for p in pts], [p[1] for p in pts], label=m, lw=1.4, ms=5, **style(m))
            for t, e, k in pts:
                ax.annotate(k, (t, e), textcoords="offset points", xytext=(3, 3), fontsize=7, color=style(m)["color"])
        failed = sorted({r["method"] for r in sel if r["status"] != "ok"})
        title = HERTZ_FAMILIES[fam][0] + (("\nfailed: " + ", ".join(failed)) if failed else "")
        ax.set_title(title, fontsize=8.5)
        ax.legend(fontsize=7)
    last = axes[len(fams)]
    for fam in fams:
        ok = sorted(hertz_ok([r for r in rows if r["family"] == fam]), key=lambda r: num(r, "t_total"))
        env, best = [], None
        for r in ok:  # the runs that beat every cheaper run of the family
            e = num(r, "err_p0")
            if best is None or e < best:
                best = e
                env.append((num(r, "t_total"), max(e, FLOOR)))
        if env:
            last.step([p[0] for p in env], [p[1] for p in env], where="post", color=HERTZ_FAMILIES[fam][1], lw=1.6,
                      marker="o", ms=4, label=fam)
    last.set_title("per family: best error reached within a time (any method, CalculiX included)", fontsize=8.5)
    last.legend(fontsize=7.5)
    for ax in axes[:n]:
        for level in HERTZ_LEVELS:
            ax.axhline(level, color="#bbbbbb", lw=0.8, ls=":")
        ax.set_xscale("log"); ax.set_yscale("log")
        ax.xaxis.set_minor_formatter(matplotlib.ticker.NullFormatter())
        ax.set_xlabel("wall time of the run (s)"); ax.set_ylabel("|p - p(r)| / p0 at the node nearest O")
        ax.grid(True, which="major", color="#eeeeee")
    for ax in axes[n:]:
        ax.axis("off")
    fig.suptitle("Hertz contact: peak-pressure error against cost over refinement (points labelled by k; "
                 "dotted: 5 %, 1 %, 0.5 %)", fontsize=10)
    save(fig, docs, "chart_hertz")


def hertz_text(rows):
    """Summary section of the Hertz chart: cheapest run per family and level, and the cost ratio
    of the 2D model (AXIS if present, else D_PLAN) over 3D at equal accuracy."""
    if not rows:
        return []
    lines = ["## Hertz contact: model no more than the scene needs", "",
             "![Hertz chart](chart_hertz.png)", "",
             "Peak-pressure error |p - p(r)| / p0 against Hertz at the slave node nearest O (or the axis) "
             "carrying a pressure, r = 0 but for AXIS QUAD8 mortar (the axis node has no multiplier: r = h0/2) "
             "and CalculiX's CAX8 (no pressure on the axis) (chart_hertz.lua, ccx_run.py --hertz): D_PLAN "
             "cylinder with b = R/50, sphere with a = R/10 (quarter model in 3D), R = 1 m, E = 1e9 Pa, nu = 0.3, "
             "the ball held by the contact alone (CONTACT_INIT = 'OUI'). Cheapest run (any method, CalculiX included) "
             "reaching each level and staying under it on every finer mesh of the same method:", "",
             "| family | " + " | ".join(f"{l * 100:g} %: method k, time, error" for l in HERTZ_LEVELS) + " | best error |",
             "|---|" + "---|" * (len(HERTZ_LEVELS) + 1)]
    fams = [f for f in HERTZ_FAMILIES if any(r["family"] == f for r in rows)]

    def run(r):
        return f"{r['family']} {r['method']} k={r['k']}, {num(r, 't_total'):.3g} s, {num(r, 'err_p0'):.2g}"
    for fam in fams:
        sel = [r for r in rows if r["family"] == fam]
        cells = []
        for level in HERTZ_LEVELS:
            r, loose = hertz_cheapest(sel, level), hertz_cheapest(sel, level, kept=False)
            cell = run(r).split(" ", 1)[1] if r else "never"
            if loose and loose is not r:
                lost = max(hertz_lost(sel, loose, level), key=lambda s: float(s["k"]))
                cell += (f" (before it: {run(loose).split(' ', 1)[1]}, not kept: k={lost['k']} at "
                         f"{num(lost, 'err_p0'):.2g})")
            cells.append(cell)
        errs = [num(r, "err_p0") for r in hertz_ok(sel)]
        lines.append(f"| {fam} | " + " | ".join(cells) + (f" | {min(errs):.2g} |" if errs else " | - |"))
    lines.append("")
    groups = [("AXIS", [f for f in fams if f.startswith("AXIS")]), ("D_PLAN", [f for f in fams if f == "D_PLAN"]),
              ("3D", [f for f in fams if f.startswith("3D")])]
    groups = {g: [r for r in rows if r["family"] in fs] for g, fs in groups if fs}
    if "3D" in groups and len(groups) > 1:
        lines += ["Cost ratio at equal accuracy: the cheapest kept run of the 2D model (any of its families, "
                  "any method) over that of the 3D model; in brackets, counting the runs a finer mesh loses. "
                  "D_PLAN is another scene (line contact).", "",
                  "| level | 2D model | 2D run | 3D run | time ratio 2D / 3D | not kept: 2D run, ratio |",
                  "|---|---|---|---|---|---|"]
        for level in HERTZ_LEVELS:
            b3 = hertz_cheapest(groups["3D"], level)
            for g in ("AXIS", "D_PLAN"):
                if g not in groups:
                    continue
                a2, l2 = hertz_cheapest(groups[g], level), hertz_cheapest(groups[g], level, kept=False)
                ratio = f"{num(a2, 't_total') / num(b3, 't_total'):.2g}" if a2 and b3 else "-"
                loose = (f"{run(l2)}, {num(l2, 't_total') / num(b3, 't_total'):.2g}"
                         if l2 and b3 and l2 is not a2 else "same")
                lines.append(f"| {level * 100:g} % | {g} | {run(a2) if a2 else 'never'} | {run(b3) if b3 else 'never'} | "
                             f"{ratio} | {loose} |")
        lines.append("")
        # The trade the issue names: the graded axisymmetric model against the uniform 3D one.
        fam_rows = {f: [r for r in rows if r["family"] == f] for f in ("AXIS-G", "3D-U")}
        if all(fam_rows.values()):
            lines += ["AXIS graded against 3D uniform (the model a user would build without grading or symmetry "
                      "of revolution), cheapest kept runs:", ""]
            for level in HERTZ_LEVELS:
                a, b = hertz_cheapest(fam_rows["AXIS-G"], level), hertz_cheapest(fam_rows["3D-U"], level)
                if a and b:
                    lines.append(f"- {level * 100:g} %: {run(a)} against {run(b)}: "
                                 f"{num(b, 't_total') / num(a, 't_total'):.3g} times cheaper")
                else:
                    lines.append(f"- {level * 100:g} %: {run(a) if a else 'AXIS-G never'}; {run(b) if b else '3D-U never'}")
            lines.append("")
    if any(r["family"].startswith("AXIS") and r["method"].startswith("CalculiX") for r in rows):
        lines += ["CalculiX on the AXIS meshes (CAX8, which it expands to a 2-degree wedge of 3D elements): its "
                  "reaction on BLOCK_BOTTOM equals the applied load (checked on AXIS-U k=20: 4070 N on the "
                  "wedge, F x 2/360), but its nodal contact pressures CPRESS near the axis integrate to about "
                  "4 times that force, so its AXIS error points measure its pressure output there, not the "
                  "contact solution. Finer AXIS meshes exceed its time limit or cut back.", ""]
    lines += hertz_limits(rows)
    failed = [r for r in rows if r["status"] != "ok"]
    if failed:
        lines += ["Hertz runs that failed (kept out of the chart):", ""]
        lines += [f"- {r['family']} {r['method']} k={r['k']}: {r['status'][:160]}" for r in failed]
        lines.append("")
    return lines


def pct(x):
    """A fraction as a percentage with two significant digits (101 %, 4.8 %, 0.48 %)."""
    return f"{x * 100:.0f} %" if x >= 0.1 else f"{x * 100:.2g} %"


def hertz_limits(rows):
    """Where the Hertz rows do not measure convergence, from the rows themselves: the discrete
    methods' pressure on the axis of the AXIS families, and the 3D-U meshes whose cell at O
    holds the whole contact zone."""
    lines = []
    discrete = [r for r in hertz_ok(rows)
                if r["family"].startswith("AXIS") and r["method"].split("-")[0] in ("CONTRAINTE", "PENALISATION")]
    if discrete:
        errs = [num(r, "err_p0") for r in discrete]
        flat = sorted((r for r in hertz_ok(rows) if r["family"] == "D_PLAN" and r["method"] == "CONTRAINTE"),
                      key=lambda r: float(r["k"]))
        plane = (" D_PLAN, whose contact point O is an ordinary vertex, converges (CONTRAINTE: " +
                 ", ".join(f"k={r['k']} {pct(num(r, 'err_p0'))}" for r in flat) + ")." if flat else "")
        lines += [f"The discrete methods (CONTRAINTE, PENALISATION) on the AXIS families stay {pct(min(errs))} "
                  f"to {pct(max(errs))} off at the axis whatever the mesh. Their slave nodes are the vertices "
                  "of BLOCK_TOP's SEG3 faces alone (the mid-side nodes are free, which lunaster warns of), and "
                  "the pressure printed at a node is its force over its tributary area (the integral of r times "
                  "the linear shape function). On the SEG3 face that touches the axis, the quadratic shape "
                  "function of the axis vertex integrates to zero against r: the elements put little force "
                  "there, and the axis vertex reads about half of p0 while the vertices next to it are within a "
                  "few per cent (tests/bench/README.md, eleventh session)." + plane, ""]
    uniform = sorted((r for r in hertz_ok(rows) if r["family"] == "3D-U"), key=lambda r: float(r["k"]))
    coarse = [r for r in uniform if 1.0 / float(r["k"]) >= 0.1]  # h0 = R/k against a = R/10
    if coarse:
        ks = list(dict.fromkeys(r["k"] for r in coarse))  # coarse is sorted by k
        by_method = {}
        for r in coarse:
            by_method.setdefault(r["method"], []).append(f"k={r['k']} {pct(num(r, 'err_p0'))}")
        lines += [f"The 3D-U meshes of k = {', '.join(ks)} have h0 = R/k at least the contact radius a = R/10: "
                  "the whole contact zone lies in the cell at O, and their errors are those of one quadratic "
                  "cell, not a convergence (" + "; ".join(f"{m}: {', '.join(v)}" for m, v in by_method.items()) +
                  "). The comparisons above that use a 3D-U run inherit this.", ""]
    return lines


def summary(work, docs, c2, c3, hz=()):
    cpu = "unknown CPU"
    for line in open("/proc/cpuinfo"):
        if line.startswith("model name"):
            cpu = line.split(":", 1)[1].strip()
            break
    lines = ["# SSNP121 speed/accuracy study (generated by `make study`)", "",
             f"Run on {datetime.date.today().isoformat()}, {platform.node() or 'host'}: {cpu}, "
             f"{os.cpu_count()} cores, {platform.system()} {platform.release()}.",
             "Every number below comes from the CSV files next to this page, written by the decks of "
             "tests/bench/study/ (IMPR_MESURE) and by tests/bench/study/ccx/ccx_run.py (CalculiX).", "",
             "![2D chart](chart_2d.png)", ""]
    for title, rows in (("2D family (12k x 12k over 11k x 11k QUAD4)", c2), ("3D families", c3)):
        lines += [f"## Cheapest run reaching 1 % and 0.1 % pressure error: {title}", "",
                  "| method | 1 %: k, time (s), error | 0.1 %: k, time (s), error | best error reached |", "|---|---|---|---|"]
        one, milli = cheapest(rows, 1e-2), cheapest(rows, 1e-3)
        for m in dict.fromkeys(r["method"] for r in rows):
            fam = lambda r: f"{r['family']} k={r['k']}" if rows is c3 else f"k={r['k']}"
            cell = lambda d: (f"{fam(d[m])}, {num(d[m], 't_total'):.3g}, {num(d[m], 'err_p'):.2g}" if m in d else "never")
            errs = [num(r, "err_p") for r in rows if r["method"] == m and r["status"] == "ok" and num(r, "err_p") is not None]
            lines.append(f"| {m} | {cell(one)} | {cell(milli)} | {min(errs):.2g} |" if errs else f"| {m} | failed | failed | - |")
        lines.append("")
        # The leftmost point of the chart at each level: the cheapest run of any method (CalculiX included).
        for level in (1e-2, 1e-3, 1e-6, 1e-9):
            best = cheapest(rows, level)
            if best:
                m = min(best, key=lambda k: num(best[k], "t_total"))
                lines.append(f"- cheapest run reaching {level:g}: {m} ({fam(best[m])}, {num(best[m], 't_total'):.3g} s)")
            else:
                lines.append(f"- cheapest run reaching {level:g}: none")
        lines.append("")
    lines += ["## Time ratio lunaster / CalculiX at equal accuracy (same run)", "",
              "Cheapest lunaster run over cheapest CalculiX run that both reach the error level, per "
              "mesh family (pairs where one of them never reaches it are left out).", "",
              "| family | lunaster | CalculiX | error level | time (s) lunaster | time (s) CalculiX | time ratio |",
              "|---|---|---|---|---|---|---|"]
    both = c2 + c3
    for fam in dict.fromkeys(r["family"] for r in both):
        rows = [r for r in both if r["family"] == fam]
        for m_l in dict.fromkeys(r["method"] for r in rows if not r["method"].startswith("CalculiX")):
            for m_c in dict.fromkeys(r["method"] for r in rows if r["method"].startswith("CalculiX")):
                for level in (1e-2, 1e-3):
                    a = cheapest([r for r in rows if r["method"] == m_l], level)
                    b = cheapest([r for r in rows if r["method"] == m_c], level)
                    if m_l in a and m_c in b:
                        tl, tc = num(a[m_l], "t_total"), num(b[m_c], "t_total")
                        lines.append(f"| {fam} | {m_l} (k={a[m_l]['k']}) | {m_c} (k={b[m_c]['k']}) | {level:g} | "
                                     f"{tl:.3g} | {tc:.3g} | {tl / tc:.3g} |")
    lines += ["", "## Time ratio lunaster / CalculiX on the same mesh (same run)", "",
              "On the finest mesh each CalculiX formulation solved, lunaster's most accurate method on "
              "that mesh: the cost of the same model, with the accuracy each reaches.", "",
              "| family | k | CalculiX | time (s), error | lunaster | time (s), error | time ratio |",
              "|---|---|---|---|---|---|---|"]
    for fam in dict.fromkeys(r["family"] for r in both):
        rows = [r for r in both if r["family"] == fam and r["status"] == "ok"]
        for m_c in dict.fromkeys(r["method"] for r in rows if r["method"].startswith("CalculiX")):
            c_rows = [r for r in rows if r["method"] == m_c]
            c = max(c_rows, key=lambda r: float(r["k"]))
            same = [r for r in rows if r["k"] == c["k"] and not r["method"].startswith("CalculiX")]
            if same:
                r = min(same, key=lambda r: (num(r, "err_p"), num(r, "t_total")))
                lines.append(f"| {fam} | {c['k']} | {m_c} | {num(c, 't_total'):.3g}, {num(c, 'err_p'):.2g} | "
                                 f"{r['method']} | {num(r, 't_total'):.3g}, {num(r, 'err_p'):.2g} | "
                                 f"{num(r, 't_total') / num(c, 't_total'):.3g} |")
    lines += ["", "## Errors at the points (finest successful run of each method)", "",
              "Relative error of the contact pressure at A, O, B (2D) and A21, A22, A23 (3D): LAGS_C for "
              "CONTINUE, SIGM_NOEU for the discrete methods (slave EF), CalculiX's nodal CPRESS; "
              "err_sig is the nodal normal stress over both faces, err_u the normal displacement. "
              "CalculiX's .frd prints 6 digits: its errors below ~1e-5 are not resolved.", "",
              "| family | method | k | err_p | A / A21 | O / A22 | B / A23 | err_sig | err_u |",
              "|---|---|---|---|---|---|---|---|---|"]
    for fam in dict.fromkeys(r["family"] for r in both):
        for m in dict.fromkeys(r["method"] for r in both if r["family"] == fam):
            ok = [r for r in both if r["family"] == fam and r["method"] == m and r["status"] == "ok"]
            if ok:
                r = max(ok, key=lambda r: float(r["k"]))
                cols = [f"{num(r, c):.2g}" if num(r, c) is not None else "-"
                        for c in ("err_p", "err_A", "err_O", "err_B", "err_sig", "err_u")]
                lines.append(f"| {fam} | {m} | {r['k']} | " + " | ".join(cols) + " |")
    failed = [r for r in both if r["status"] != "ok"]
    if failed:
        lines += ["", "Runs that failed (kept out of the charts):", ""]
        lines += [f"- {r['family']} {r['method']} k={r['k']}: {r['status'][:140]}" for r in failed]
    lines.append("")
    lines += hertz_text(list(hz))
    lines += atlas_text(os.path.join(work, "out"), docs)
    with open(os.path.join(docs, "summary.md"), "w") as f:
        f.write("\n".join(lines))


def loss_of_accuracy(rows, xkey, resi_bar=1e-6):
    """Per k, in words: how accurate the linear solves were, what residual Newton could
    reach, and where runs start failing, from the rows of a sweep."""
    L = []
    for k in sorted({r["k"] for r in rows}, key=float):
        sel = sorted((r for r in rows if r["k"] == k), key=lambda r: float(r[xkey]))
        ok = [r for r in sel if r["status"] == "ok" and num(r, "solve_resid_raw") is not None]
        if not ok:
            continue
        worst = max(ok, key=lambda r: num(r, "solve_resid_raw"))
        words = (f"- k = {k}: the least accurate linear solve of a run left a relative residual from "
                 f"{min(num(r, 'solve_resid_raw') for r in ok):.1e} to {num(worst, 'solve_resid_raw'):.1e} "
                 f"(at {xkey} = {worst[xkey]}) straight from the factorisation")
        refined = [r for r in ok if (num(r, "refinements") or 0) > 0]
        if refined:
            words += (f"; iterative refinement was used in {len(refined)} of {len(ok)} runs and left at most "
                      f"{max(num(r, 'solve_resid') for r in refined):.1e}")
        reached = [r for r in ok if num(r, "resi_glob_rela") is not None]
        if reached:
            words += (f". The residual Newton reached (RESI_GLOB_RELA) went from {num(reached[0], 'resi_glob_rela'):.1e} "
                      f"at {xkey} = {reached[0][xkey]} to {num(reached[-1], 'resi_glob_rela'):.1e} at {reached[-1][xkey]}")
            near = [r for r in reached if num(r, "resi_glob_rela") > 0.1 * resi_bar]
            if near:
                words += (f", within a factor 10 of the convergence bar {resi_bar:g} from {xkey} = {near[0][xkey]}: "
                          "there the round-off of the terms scaled by " + xkey + ", not the linear solver, "
                          "decides whether Newton can converge")
        failed = [r for r in sel if r["status"] != "ok"]
        if failed:
            status = failed[0]["status"]
            pivot = re.search(r"pivot lost ([0-9.]+) significant digits \(more than (\d+)\)", status)
            why = (f"a pivot lost {pivot[1]} significant digits, more than SOLVEUR NPREC = {pivot[2]} allows: "
                   "code_aster's singularity test, which a larger NPREC moves" if pivot
                   else status[8:110].strip() + "...")
            words += f". The first failed run is at {xkey} = {failed[0][xkey]} ({why})"
        L.append(words + ".")
    return L


def schemes_table(out, docs):
    """Integration scheme x geometry: the LAGS_C error of each run of atlas_schemes.csv, as a
    Markdown table (returned) and as a scheme x geometry CSV (DOCS/atlas_schemes_table.csv)."""
    rows = read(os.path.join(out, "atlas_schemes.csv"))
    if not rows:
        return []
    geos = list(dict.fromkeys((r["geometry"], r["faces"]) for r in rows))
    schemes = list(dict.fromkeys(r["scheme"] for r in rows))
    failures = []

    def cell(r, markdown):
        if r is None:
            return "-"
        if r["status"] == "ok":
            return f"{num(r, 'err_p'):.2g}"
        if not markdown:
            return r["status"]
        if r["status"] not in failures:
            failures.append(r["status"])
        return f"failed ({failures.index(r['status']) + 1})"

    find = lambda s, g: next((r for r in rows if r["scheme"] == s and r["geometry"] == g[0]), None)
    with open(os.path.join(docs, "atlas_schemes_table.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["scheme"] + [f"{g} ({faces})" for g, faces in geos])
        for s in schemes:
            w.writerow([s] + [cell(find(s, g), False) for g in geos])
    L = ["", "### Integration schemes x face types (SSNP121 E, F, J, K, matching interfaces)", "",
         "Max relative error of LAGS_C over the slave SURESC (exact: -1e5 Pa), CONTINUE, slave face on master face, "
         "scheme-ORDRE_INT (atlas_schemes.csv, atlas_schemes_table.csv). The exact degree of each rule per face type "
         "is tabulated in engine/contact/integration_rules.hpp. A TRIA6 slave needs a rule exact for its shape "
         "functions (degree 2) and at least 6 points (its LAGS_C unknowns); a TRIA3 slave on a quadratic master needs "
         "points off its vertices, or the master mid-side nodes carry no force.", "",
         "| scheme | " + " | ".join(f"{g}: {faces}" for g, faces in geos) + " |",
         "|---|" + "---|" * len(geos)]
    for s in schemes:
        L.append(f"| {s} | " + " | ".join(cell(find(s, g), True) for g in geos) + " |")
    if failures:
        L += [""] + [f"- ({i + 1}) {msg.removeprefix('failed: ')[:200]}" for i, msg in enumerate(failures)]
    return L


def atlas_text(out, docs):
    """The stability atlas in words, from its CSV files."""
    L = ["## Stability atlas", ""]
    pen = read(os.path.join(out, "atlas_penalty.csv"))
    gap = {(r["k"], float(r["E_N"])): r["penetration"] for r in read(os.path.join(out, "atlas_penalty_gap.csv"))}
    L += ["### Penalty sweep (discrete PENALISATION, E_N = 1e3 .. 1e16): ![](atlas_penalty.png)", "",
          "Right panel: the largest relative residual |K du + r| / |r| of one linear solve, straight from the "
          f"factorisation and after iterative refinement (lunaster accepts a solve below {SOLVE_BAR:g} and refines "
          "one above 1e-10), and the RESI_GLOB_RELA Newton reached.", ""]
    L += loss_of_accuracy(pen, "E_N")
    L += ["", "| k | E_N | status | pressure error | penetration (m) | Newton iterations | solve residual: raw / refined | RESI_GLOB_RELA |",
          "|---|---|---|---|---|---|---|---|"]
    L += [f"| {r['k']} | {r['E_N']} | {r['status'][:160]} | {r['err_p']} | {gap.get((r['k'], float(r['E_N'])), '')} | "
          f"{r['newton_iter']} | {r.get('solve_resid_raw', '')} / {r.get('solve_resid', '')} | {r.get('resi_glob_rela', '')} |"
          for r in pen]
    coef = read(os.path.join(out, "atlas_coef.csv"))
    L += ["", "### COEF_CONT sweep (CONTINUE-SIMPSON, 1e-5 .. 1e16): ![](atlas_coef.png)", ""]
    L += loss_of_accuracy(coef, "COEF_CONT")
    L += ["", "| k | COEF_CONT | status | pressure error | Newton | contact passes | solve residual: raw / refined |",
          "|---|---|---|---|---|---|---|"]
    L += [f"| {r['k']} | {r['COEF_CONT']} | {r['status'][:160]} | {r['err_p']} | {r['newton_iter']} | {r['contact_passes']} | "
          f"{r.get('solve_resid_raw', '')} / {r.get('solve_resid', '')} |"
          for r in coef]
    L += ["", "### Slave/master element size ratio 1/4 .. 4: ![](atlas_ratio.png)", "",
          "Largest pressure deviation on the slave side (the oscillation), per method, over the ratios "
          "(atlas_ratio.csv for every point):", "", "| method | min | max | at ratio 1 |", "|---|---|---|---|"]
    ratio = read(os.path.join(out, "atlas_ratio.csv"))
    for m in dict.fromkeys(r["method"] for r in ratio):
        es = [(num(r, "err_p"), r["ratio"]) for r in ratio if r["method"] == m and r["status"] == "ok"]
        one = [e for e, x in es if abs(float(x) - 1) < 1e-9]
        if es:
            L.append(f"| {m} | {min(es)[0]:.2g} (ratio {float(min(es)[1]):.3g}) | {max(es)[0]:.2g} (ratio {float(max(es)[1]):.3g}) | "
                     f"{one[0]:.2g} |" if one else f"| {m} | {min(es)[0]:.2g} | {max(es)[0]:.2g} | - |")
    L += ["", "### Incompatible pairings (3D, slave SURMAI on master SURESC): ![](atlas_incompat.png)", "",
          "| pairing | method | status | pressure error |", "|---|---|---|---|"]
    L += [f"| {r['pairing']} | {r['method']} | {r['status'][:110]} | {r['err_p']} |"
          for r in read(os.path.join(out, "atlas_incompat.csv"))]
    log = os.path.join(os.path.dirname(out), "logs", "atlas_incompat_full.log")
    warns = sorted({l.strip()[:160] for l in open(log) if l.startswith("<A>") or "warning" in l.lower()}) \
        if os.path.exists(log) else []
    L += ["", "Warnings printed to the user:" if warns else "No warning was printed for these pairings.", ""]
    L += [f"    {w[:200]}" for w in warns[:6]]
    L += ["", "### Modelisation G (pressure-loaded block) and CONTACT_INIT", "", "| CONTACT_INIT | what the user gets | pressure error |",
          "|---|---|---|"]
    L += [f"| {r['CONTACT_INIT']} | {r['status']} | {r['err_p']} |" for r in read(os.path.join(out, "atlas_init.csv"))]
    L += schemes_table(out, docs)
    d23 = read(os.path.join(out, "atlas_2d3d.csv"))
    L += ["", "### 2D plane strain against the same scene in 3D (one-cell slab): ![](atlas_2d3d.png)", "",
          "| method | k | error 2D | error 3D | time 2D (s) | time 3D (s) | 3D / 2D |", "|---|---|---|---|---|---|---|"]
    for r in d23:
        if r["family"] != "2D" or r["status"] != "ok":
            continue
        t = next((x for x in d23 if x["family"] == "3D-slab" and x["method"] == r["method"] and x["k"] == r["k"]), None)
        if t and t["status"] == "ok":
            L.append(f"| {r['method']} | {r['k']} | {num(r, 'err_p'):.3g} | {num(t, 'err_p'):.3g} | {num(r, 't_total'):.3g} | "
                     f"{num(t, 't_total'):.3g} | {num(t, 't_total') / num(r, 't_total'):.3g} |")
    return L + [""]


if __name__ == "__main__":
    main()
