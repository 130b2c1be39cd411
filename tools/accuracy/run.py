#!/usr/bin/env python3
"""Accuracy against cost: run the quantity modules q_<name>.py, write
DIR/results.json, DIR/<name>.csv and DIR/report.md with its plots.

  run.py --mode smoke|short|full --lmp PATH --out DIR [--exact PATH]
         [--only name,name] [--jobs N] [--report-only]

Each module has cases(mode) -> [setting dicts] and measure(case, lmp,
workdir) -> {metric: value, 'seconds': Loop time, 'particle_steps': n}
(q_waves: measure(case, lmp, pd_exact, workdir), skipped with a message
when there is no pd_exact binary), and optionally NAME, TITLE, PRIMARY
(the error metric the report ranks by; defaults: the file's name, the
docstring's first line, 'err' or PRIMARY below), family(case)
(the curve of a case), curve(case) (the plots' curve when it is not the
family), group(case) (recommendations are made per group),
COST ('per_particle_step', the default, or 'wall'), ERROR_UNIT and
TARGETS (the target errors of the recommendations, in the error's unit;
default pareto.TARGETS, relative errors) and QUADRATURE (True, or a
function of the case that says which: the driver adds 'quadrature
partial' copies of the cases when the binary accepts that pair_style
keyword)."""
import argparse
import concurrent.futures
import csv
import datetime
import importlib
import inspect
import json
import os
import re
import subprocess
import sys
import tempfile
import time
import traceback

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import deck      # noqa: E402
import pareto    # noqa: E402
import plot      # noqa: E402
import report    # noqa: E402

ORDER = ["waves", "constants", "fracture", "crack", "riemann", "kink"]
# what a module that does not say gets: its name from the file, its title
# from its docstring's first line, and its error metric
PRIMARY = {"waves": "phase_error"}


def modules(only):
    names = sorted((f[2:-3] for f in os.listdir(HERE) if f.startswith("q_") and f.endswith(".py")),
                   key=lambda n: (ORDER.index(n) if n in ORDER else len(ORDER), n))
    return [importlib.import_module("q_" + n) for n in names if not only or n in only]


def partial_quadrature(lmp):
    """The material styles whose pair_style accepts 'quadrature partial'
    (a tiny deck each, once)."""
    ok = []
    with tempfile.TemporaryDirectory() as d:
        for style in ("pd/bond", "pd/ordinary", "pd/corr"):
            if deck.accepts(lmp, d, deck.pair_lines({"style": style, "ratio": 3, "lattice": "sc",
                                                     "quadrature": "partial"}, 1e-3)):
                ok.append(style)
    return ok


def describe(mod):
    """(name, title, primary metric) of a quantity module."""
    name = getattr(mod, "NAME", mod.__name__[2:])
    doc = (mod.__doc__ or name).strip().splitlines()[0]
    return name, getattr(mod, "TITLE", doc), getattr(mod, "PRIMARY", PRIMARY.get(name, "err"))


def family(mod, case):
    if hasattr(mod, "family"):
        return mod.family(case)
    return " ".join(f"{k} {v}" for k, v in case.items() if k not in ("ratio", "seed") and v is not None)


def write_csv(path, rows):
    ckeys, mkeys = [], []
    for r in rows:
        ckeys += [k for k in r["case"] if k not in ckeys]
        mkeys += [k for k in (r.get("metrics") or {}) if k not in mkeys]
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(ckeys + mkeys + ["error"])
        for r in rows:
            m = r.get("metrics") or {}
            w.writerow([r["case"].get(k, "") for k in ckeys] + [m.get(k, "") for k in mkeys] + [r.get("error", "")])


def lammps_version(lmp):
    """'LAMMPS (29 Sep 2021 - Update 2)' from the binary's help text: the
    report names the release, not a path of the machine it ran on."""
    try:
        out = subprocess.run([lmp, "-h"], capture_output=True, text=True, timeout=60, env=deck.ENV).stdout
    except (OSError, subprocess.TimeoutExpired):
        return "LAMMPS"
    m = re.search(r"Simulator\s*-\s*(.+?)\s*$", out, re.M)
    return f"LAMMPS ({m.group(1)})" if m else "LAMMPS"


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--mode", choices=("smoke", "short", "full"), default="smoke")
    ap.add_argument("--lmp", default=os.environ.get("PDEXT_LMP", os.path.join(deck.ROOT, "build", "lmp")))
    ap.add_argument("--exact", default=os.environ.get("PDEXT_EXACT", os.path.join(deck.ROOT, "build", "pd_exact")),
                    help="the pd_exact binary (FFTW lattice solution) for q_waves")
    ap.add_argument("--out", required=True)
    ap.add_argument("--only", default="", help="comma-separated quantity names")
    ap.add_argument("--jobs", type=int, default=1,
                    help="cases run side by side, each one LAMMPS process on one core (their costs then carry "
                         "what the others take of the shared caches and memory)")
    ap.add_argument("--report-only", action="store_true", help="rewrite the report from DIR/results.json")
    a = ap.parse_args()
    out = os.path.abspath(a.out)
    os.makedirs(out, exist_ok=True)
    rpath = os.path.join(out, "results.json")
    if a.report_only:
        return finish(json.load(open(rpath)), out)

    lmp = os.path.abspath(a.lmp)
    if not os.access(lmp, os.X_OK):
        sys.exit(f"accuracy: no LAMMPS binary at {lmp} (give --lmp or PDEXT_LMP)")
    plot.gnuplot()          # fail before hours of runs, not after
    t0 = time.time()
    results = {"mode": a.mode, "lmp": lmp, "lammps": lammps_version(lmp),
               "date": datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M UTC"),
               "quantities": {}, "skipped": {}}
    partial = partial_quadrature(lmp)
    results["quadrature_partial"] = partial
    print(f"accuracy: {a.mode} mode, {lmp}; 'quadrature partial' accepted by: {' '.join(partial) or 'none'}"
          " (sweeping 'point' only for the others)", flush=True)
    only = set(filter(None, a.only.split(",")))
    for mod in modules(only):
        name, title, primary = describe(mod)
        needs_exact = len(inspect.signature(mod.measure).parameters) == 4
        if needs_exact and not os.access(a.exact, os.X_OK):
            why = f"no pd_exact binary at {a.exact} (give --exact PATH): quantity '{name}' not measured"
            print("accuracy: " + why, flush=True)
            results["skipped"][name] = why
            continue
        cases = mod.cases(a.mode)
        quad = getattr(mod, "QUADRATURE", False)
        if quad:
            cases += [dict(c, quadrature="partial") for c in cases
                      if c.get("quadrature", "point") == "point" and c.get("style") in partial
                      and (quad is True or quad(c))]
        rows = []
        q = {"title": title, "primary": primary, "cost": getattr(mod, "COST", "per_particle_step"),
             "error_unit": getattr(mod, "ERROR_UNIT", "relative error"),
             "targets": list(getattr(mod, "TARGETS", pareto.TARGETS)),
             "doc": (mod.__doc__ or "").strip(), "rows": rows}
        results["quantities"][name] = q
        def one(k):
            case = cases[k]
            wd = os.path.join(out, "work", name, f"{k:03d}")
            os.makedirs(wd, exist_ok=True)
            t = time.time()
            row = {"case": case, "family": family(mod, case)}
            if hasattr(mod, "group"):
                row["group"] = mod.group(case)
            if hasattr(mod, "curve"):
                row["curve"] = mod.curve(case)
            try:
                m = mod.measure(case, lmp, a.exact, wd) if needs_exact else mod.measure(case, lmp, wd)
                row["metrics"] = m
                msg = f"{primary} {m[primary]:.4g}"
            except Exception as err:      # one failed case is reported, the sweep goes on
                row["error"] = report.scrub(f"{type(err).__name__}: {err}")
                msg = "FAILED " + row["error"]
                traceback.print_exc()
            print(f"[{time.time() - t0:7.1f} s] {name} {k + 1}/{len(cases)} {row['family']} "
                  f"ratio {case.get('ratio', '')}: {msg} ({time.time() - t:.1f} s)", flush=True)
            return row

        # (threads: each case waits on its own LAMMPS process)
        with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, a.jobs)) as pool:
            rows += pool.map(one, range(len(cases)))
        if hasattr(mod, "note"):
            q["note"] = mod.note(rows)
        write_csv(os.path.join(out, f"{name}.csv"), rows)
        with open(rpath, "w") as f:
            json.dump(results, f, indent=1)
    results["seconds"] = time.time() - t0
    with open(rpath, "w") as f:
        json.dump(results, f, indent=1)
    return finish(results, out)


def finish(results, out):
    try:
        path = report.write(results, out)
    except plot.PlotError as err:
        sys.exit(f"accuracy: {err}")
    failed = sum(1 for q in results["quantities"].values() for r in q["rows"] if "error" in r)
    print(f"accuracy: report {path}" + (f" ({results['seconds']:.0f} s)" if "seconds" in results else "") +
          (f"; {failed} case(s) failed" if failed else ""))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
