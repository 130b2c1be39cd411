#!/usr/bin/env python3
"""The ballistic limit from a campaign's results.csv: a Lambert-Jonas fit
of the residual velocity against the impact velocity,

    v_r = a (v^p - v_bl^p)^(1/p)  for v > v_bl,  0 below,

and ballistic_limit.png (the cases as points, the fit as a curve).

  python3 ballistic_limit.py [results.csv] [ballistic_limit.png]

Standard library (and gnuplot for the picture). For each (v_bl, p) the
best a is a linear least-squares fit; (v_bl, p) come from a grid refined
six times around its best point, v_bl between the fastest impact that did
not perforate and the slowest that did."""
import csv
import os
import shutil
import subprocess
import sys


def model(v, a, p, vbl):
    return a * (v ** p - vbl ** p) ** (1.0 / p) if v > vbl else 0.0


def best_a(points, p, vbl):
    g = [model(v, 1.0, p, vbl) for v, _ in points]
    gg = sum(x * x for x in g)
    # a residual velocity is never above the impact's: 0 <= a <= 1
    a = min(max(sum(x * r for x, (_, r) in zip(g, points)) / gg, 0.0), 1.0) if gg > 0 else 0.0
    return a, sum((model(v, a, p, vbl) - r) ** 2 for v, r in points)


def fit(points):
    """points: [(v, v_r)] of decided cases (v_r 0: stopped); returns
    (a, p, v_bl, rms of the residuals, (fastest stop, slowest perforation))."""
    stopped = [v for v, r in points if r <= 0.0]
    through = [v for v, r in points if r > 0.0]
    if not through:
        raise SystemExit("ballistic_limit: no case perforated the plate: raise the impact velocities")
    lo, hi = (max(stopped) if stopped else 0.0), min(through)
    if lo > hi:
        raise SystemExit(f"ballistic_limit: {lo} m/s stopped but {hi} m/s perforated: no single limit")
    (v0, v1), (p0, p1), best = (lo, hi), (1.0, 6.0), None
    for _ in range(6):
        for i in range(41):
            for k in range(41):
                vbl, p = v0 + (v1 - v0) * i / 40, p0 + (p1 - p0) * k / 40
                a, sse = best_a(points, p, vbl)
                if best is None or sse < best[0]:
                    best = (sse, a, p, vbl)
        _, _, p, vbl = best
        dv, dp = (v1 - v0) / 8, (p1 - p0) / 8
        v0, v1, p0, p1 = max(lo, vbl - dv), min(hi, vbl + dv), max(1.0, p - dp), min(8.0, p + dp)
    sse, a, p, vbl = best
    return a, p, vbl, (sse / len(points)) ** 0.5, (lo, hi)


def read_cases(src):
    """A results.csv's decided cases [(v, v_r)] and its undecided impact
    velocities: a case that ran out of time with the sphere still moving
    down (through -1) says neither "stopped" nor "perforated", so it is
    left out of the fit, and named."""
    with open(src, newline="") as f:
        rows = list(csv.DictReader(f))
    undecided = sorted(float(r["v"]) for r in rows if float(r["through"]) < 0)
    points = sorted((float(r["v"]), float(r["vres"])) for r in rows if float(r["through"]) >= 0)
    return points, undecided


def picture(points, a, p, vbl, png):
    exe = shutil.which("gnuplot")
    if not exe:
        return "no picture: gnuplot not found (Debian: apt-get install gnuplot-nox)"
    vmax = max(v for v, _ in points) * 1.05
    data = "".join(f"{v!r} {r!r}\n" for v, r in points)
    script = f"""set terminal pngcairo size 900,600 font ',12'
set output '{png}'
set title 'Sphere through an aluminium plate: residual velocity (ballistic limit {vbl:.0f} m/s)'
set xlabel 'impact velocity (m/s)'
set ylabel 'residual velocity (m/s)'
set grid
set key top left
set xrange [0:{vmax!r}]
set yrange [0:*]
set samples 2000
f(x) = x > {vbl!r} ? {a!r} * (x**{p!r} - {vbl!r}**{p!r})**(1.0/{p!r}) : 0
plot '-' using 1:2 with points pt 7 ps 1.5 title 'cases (pd/ordinary, energy law)', \\
     f(x) with lines lw 2 title sprintf('Lambert-Jonas: a = %.3f, p = %.2f, v_{{bl}} = %.0f m/s', {a!r}, {p!r}, {vbl!r}), \\
     x with lines dt 2 lc rgb 'gray' title 'v_r = v (no plate)'
{data}e
"""
    r = subprocess.run([exe], input=script, capture_output=True, text=True)
    return f"picture: {png}" if r.returncode == 0 else f"no picture: gnuplot failed: {r.stderr.strip()[:300]}"


def main(argv):
    src = argv[1] if len(argv) > 1 else os.path.join("campaign.out", "results.csv")
    png = argv[2] if len(argv) > 2 else "ballistic_limit.png"
    points, undecided = read_cases(src)
    if undecided:
        print(f"ballistic_limit: left out, undecided at the case's tmax (raise it): "
              f"{', '.join(f'{v:g}' for v in undecided)} m/s")
    a, p, vbl, rms, (lo, hi) = fit(points)
    print(f"ballistic_limit: {len(points)} cases from {src}")
    for v, r in points:
        print(f"  v {v:7.1f} m/s  residual {r:7.1f} m/s  fit {model(v, a, p, vbl):7.1f}")
    print(f"ballistic_limit: v_bl = {vbl:.1f} m/s (between {lo:g} and {hi:g} m/s), a = {a:.4f}, p = {p:.3f}, "
          f"rms {rms:.1f} m/s")
    print(f"ballistic_limit: {picture(points, a, p, vbl, png)}")


if __name__ == "__main__":
    main(sys.argv)
