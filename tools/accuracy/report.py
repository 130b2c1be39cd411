"""report.md from results.json: per quantity the plots (error against
cost per particle-step and against run time, one curve per setting family,
the Pareto front marked) and a table of every setting; at the end the
recommendation table (for each target error, the cheapest setting as the
lines to paste into a deck)."""
import importlib
import os
import re

import deck
import pareto
import plot

# a path of the machine the report ran on: an absolute one (kept: its
# last part) or a build folder
ABSOLUTE = re.compile(r"(?<![\w.$])/(?:[\w.+-]+/)+([\w.+-]+)")
BUILD = re.compile(r"\bbuild[\w.-]*/")


def scrub(text):
    """text without the paths of the machine it was written on."""
    return BUILD.sub("", ABSOLUTE.sub(r"\1", text))


def module(name):
    """The quantity's module q_<name>, or None."""
    try:
        return importlib.import_module("q_" + name)
    except ImportError:
        return None


def paste(name, case):
    """The deck lines of a measured case: the quantity module's
    setting(case) when it has one (what its decks fix), else the case."""
    mod = module(name)
    return deck.user_lines(mod.setting(case) if hasattr(mod, "setting") else case)


def recommendable(name, pts):
    """The points a recommendation may pick: the quantity module's
    trusted(points) when it has one (e.g. a setting measured at two
    resolutions, with its worst error), else every measured point."""
    mod = module(name)
    return mod.trusted(pts) if hasattr(mod, "trusted") else pts


def per_step(m):
    return m["seconds"] / m["particle_steps"] if m.get("particle_steps") else float("nan")


def setting_text(case):
    return ", ".join(str(v) if k == "plane" else f"{k} {v}" for k, v in case.items()
                     if v is not None and k != "seed" and (k != "quadrature" or v != "point"))


def plot_name(name, group, kind):
    """The PNG of a quantity (and group) against a cost kind."""
    slug = "".join(ch if ch.isalnum() else "_" for ch in group) if group else ""
    return f"{name}{'_' + slug if slug else ''}_{kind}.png"


def _points(rows, primary, cost):
    pts = []
    for r in rows:
        m = r.get("metrics")
        if not m or primary not in m:
            continue
        c = per_step(m) if cost == "per_particle_step" else m.get("wall", m["seconds"])
        if not c > 0:
            continue        # a cost of 0 or NaN has no place on a log axis
        pts.append((c, m[primary], r))
    return pts


def _curves(pts, order_key):
    curves = {}
    for c, e, r in sorted(pts, key=lambda p: order_key(p[2]["case"])):
        curves.setdefault(r.get("curve", r["family"]), []).append((c, e))
    return curves


def write(results, out_dir):
    """Writes out_dir/report.md and its plots; returns the report's path.
    Raises plot.PlotError (with how to install gnuplot) without gnuplot."""
    plot.gnuplot()
    qs = results["quantities"]
    lines = [f"# Accuracy against cost: {results['mode']} mode", "",
             f"{results.get('lammps', 'LAMMPS')} with this package; one MPI rank on a machine shared with other "
             "jobs (times are as measured, noisy to some 10-30%).", "",
             "Quadrature: `quadrature partial` is " +
             (f"swept for {', '.join(results['quadrature_partial'])}" if results.get("quadrature_partial")
              else "not accepted by this binary: every case uses the one-point quadrature") + ".", "",
             "Cost: seconds of LAMMPS's Loop time per particle-step, or the wall time of the whole "
             "measurement (all its LAMMPS runs). Errors are relative (0.05 = 5%) unless the quantity says "
             "otherwise.", "",
             "The recommendations (the cheapest measured setting for each target error) are the "
             "table at the end.", ""]
    rec = ["## Recommendations", "",
           "For each quantity and target error, the cheapest measured setting that meets it (cost as the "
           "quantity's plot ranks it), as the lines to paste into a deck: `a` is the spacing (the cube, "
           "in 2D the square, root of the volume or area per particle), `${E}`, `${nu}`, `${Gc}` and "
           "`${t}` the material's constants and plate thickness. `not met`: no measured setting meets "
           "the target, the most accurate one is shown.", "",
           "| quantity | target | deck lines | error | cost |", "|---|---|---|---|---|"]
    sections = []
    for name, q in qs.items():
        rows = q["rows"]
        cost_kind = q.get("cost", "per_particle_step")
        unit = "s per particle-step" if cost_kind == "per_particle_step" else "s (run time)"
        err_unit = " deg" if "degree" in q.get("error_unit", "") else ""
        pts = _points(rows, q["primary"], cost_kind)
        targets = q.get("targets") or pareto.TARGETS     # in the quantity's error unit
        groups = sorted({r.get("group", "") for _, _, r in pts})
        rpts = recommendable(name, pts)
        for g in groups:
            label = f"{name} ({g})" if g else name
            gpts = [p for p in rpts if p[2].get("group", "") == g]
            if not gpts:
                rec.append(f"| {label} | | no setting measured as the quantity requires (see its section) | | |")
                continue
            for t in targets:
                best = pareto.cheapest(gpts, t)
                pick = best or min(gpts, key=lambda p: p[1])
                code = "<br>".join(f"`{line}`" for line in paste(name, pick[2]["case"]))
                rec.append(f"| {label} | {t:g}{'' if best else ' not met'} | {code} | {pick[1]:.3g}{err_unit} | "
                           f"{pick[0]:.3g} {unit} |")
        sec = [f"## {name}: {q['title']}", "", q.get("doc", ""), ""]
        if q.get("note"):
            sec += [q["note"], ""]
        if pts:
            order = lambda c: tuple(str(c.get(k)) for k in sorted(c) if k != "ratio") + (float(c.get("ratio", 0)),)
            for g in groups:
                glabel = f" ({g})" if g else ""
                for kind, label in (("per_particle_step", "Loop time per particle-step (s)"),
                                    ("wall", "run time of the measurement (s)")):
                    pk = [p for p in _points(rows, q["primary"], kind) if p[2].get("group", "") == g]
                    png = os.path.join(out_dir, plot_name(name, g, kind))
                    plot.error_vs_cost(png, _curves(pk, order), [(c, e) for c, e, _ in pareto.front(pk)],
                                       label, f"{q['primary']} ({q.get('error_unit', 'relative error')})",
                                       f"{name}{glabel}: {q['title']}", targets)
                    sec += [f"![{name}{glabel}: error against {label}]({os.path.basename(png)})", ""]
                frontier = pareto.front([p for p in pts if p[2].get("group", "") == g])
                sec += [f"Pareto front{glabel} ({unit}):", ""]
                sec += [f"- {setting_text(r['case'])}: error {e:.3g}, cost {c:.3g}" for c, e, r in frontier]
                sec += [""]
        metric_keys = []
        for r in rows:
            for k in (r.get("metrics") or {}):
                if k not in metric_keys and k not in ("seconds", "particle_steps", "wall"):
                    metric_keys.append(k)
        show = [q["primary"]] + [k for k in metric_keys if k != q["primary"]][:q.get("table_columns", 8)]
        sec += ["| family | " + " | ".join(["ratio"] + show + ["s/particle-step", "run time (s)"]) + " |",
                "|" + "---|" * (len(show) + 4)]
        for r in rows:
            m = r.get("metrics")
            if not m:
                sec.append(f"| {r['family']} | {r['case'].get('ratio', '')} | failed: {r.get('error', '?')} |")
                continue
            vals = [f"{m[k]:.4g}" if isinstance(m.get(k), (int, float)) else str(m.get(k, "")) for k in show]
            sec.append(f"| {r['family']} | {r['case'].get('ratio', '')} | " + " | ".join(vals) +
                       f" | {per_step(m):.3g} | {m.get('wall', float('nan')):.3g} |")
        sections += sec + [""]
    for name, why in results.get("skipped", {}).items():
        sections += [f"## {name}: skipped", "", why, ""]
    path = os.path.join(out_dir, "report.md")
    with open(path, "w") as f:
        f.write(scrub("\n".join(lines + [""] + sections + rec + [""])))
    return path
