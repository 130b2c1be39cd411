#!/usr/bin/env python3
"""The fragmentation study's table, cumulative distributions and pictures
from the campaigns' folders (standard library and gnuplot).

  report.py ring.out [tube.out] [--check]

For each folder: results.csv (one row per case: v, n, seed, frags, mass,
...), the per-case distributions <tag>.dist and dumps <tag>.dump. Prints
a table per velocity (spacing, fragments, mean fragment mass pooled over
the seeds, the seeds' range, S09's value), writes cdf.png and the
pictures into the folder. --check: exit 1 unless every spacing is there,
the finer three agree at 600 m/s (within TOLERANCE) and 200 m/s gives
fewer fragments than 600 m/s at every spacing."""
import csv
import os
import shutil
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
PICTURE = os.path.join(HERE, "..", "..", "tools", "pd_picture.py")
S09 = {3: 27.1, 5: 37.8, 7: 35.9, 10: 33.5}      # S09's mean fragment mass (g), 600 m/s
SPACINGS = (3, 5, 7, 10)                          # particles across the 10 mm wall
# --check: the finer three means within 25% of each other: S09's 15% plus
# twice the scatter of a mean pooled over three seeds (5%; round-off of
# another build changes the fragments as another seed does)
TOLERANCE = 0.25


def dx(n):
    return 10.0 / n


def tag(dim, n, v, seed):
    return f"d{dim}_n{n}_v{v}_s{seed}"


def read_rows(out):
    path = os.path.join(out, "results.csv")
    if not os.path.isfile(path):
        raise SystemExit(f"report: {path} missing: run the campaign first")
    with open(path) as f:
        return [{k: float(x) for k, x in r.items()} for r in csv.DictReader(f)]


def pooled(rows, v, n):
    """(fragments per seed, mean mass over all seeds' fragments, lowest and
    highest seed mean, seeds) of one spacing and velocity; None if absent."""
    rs = [r for r in rows if r["v"] == v and r["n"] == n]
    if not rs:
        return None
    count = sum(r["frags"] for r in rs)
    mass = sum(r["frags"] * r["mass"] for r in rs) / count
    return count / len(rs), mass, min(r["mass"] for r in rs), max(r["mass"] for r in rs), [int(r["seed"]) for r in rs]


def spread(values):
    """How far apart: (largest - smallest) / smallest."""
    return (max(values) - min(values)) / min(values)


def table(rows, dim, v):
    lines = [f"{'2D ring' if dim == 2 else '3D tube'}, {v:g} m/s",
             "| dx (mm) | fragments >= 2 g | mean fragment mass (g) | seeds' range (g) | S09 (g) |",
             "|---|---|---|---|---|"]
    means = {}
    for n in SPACINGS:
        p = pooled(rows, v, n)
        if p is None:
            continue
        frags, mass, lo, hi, seeds = p
        means[n] = mass
        rng = f"{lo:.2f} - {hi:.2f}" if len(seeds) > 1 else "(one seed)"
        ref = f"{S09[n]:.1f}" if v == 600 else "-"
        lines.append(f"| {dx(n):.2f} | {frags:.1f} | {mass:.2f} | {rng} | {ref} |")
    finer = [means[n] for n in SPACINGS[1:] if n in means]
    if len(finer) == 3:
        ref = spread([S09[n] for n in SPACINGS[1:]])
        lines.append(f"finer three spacings: within {100 * spread(finer):.0f}% of each other" +
                     (f" (S09: {100 * ref:.0f}%)" if v == 600 else ""))
    return lines, means


def read_dist(path):
    """[(upper edge in g, fragments of mass <= edge)] of one case."""
    rows = []
    with open(path) as f:
        for line in f:
            w = line.split()
            if len(w) == 4 and not line.startswith("#"):
                rows.append((float(w[1]) * 1e3, float(w[2])))
    return rows


def cdf_plot(out, rows, dim):
    """cdf.png: fraction of the fragments lighter than m at 600 m/s,
    pooled over the seeds, one curve per spacing."""
    plots = []
    for v in (600,):
        for i, n in enumerate(SPACINGS):
            cases = [r for r in rows if r["v"] == v and r["n"] == n]
            dists = [read_dist(os.path.join(out, tag(dim, n, v, int(r["seed"])) + ".dist")) for r in cases]
            dists = [d for d in dists if d]
            if not dists:
                continue
            total = sum(d[-1][1] for d in dists)
            data = os.path.join(out, f"cdf_v{v}_n{n}.txt")
            with open(data, "w") as f:
                f.write("# mass (g), fraction of the fragments (>= 2 g) of at most this mass\n")
                for k in range(len(dists[0])):
                    f.write(f"{dists[0][k][0]!r} {sum(d[k][1] for d in dists) / total!r}\n")
            plots.append(f"'{data}' using 1:2 with steps lw 2 lc {i + 1} title 'dx = {dx(n):.2f} mm'")
    if not plots or not shutil.which("gnuplot"):
        return None
    png = os.path.join(out, "cdf.png")
    seeds = len({r["seed"] for r in rows})
    what = ("2D ring (plane strain, 10 mm thick)" if dim == 2 else "3D tube section (10 mm long, free ends)")
    title = (f"Expanding steel tube at 600 m/s, {what}\\nfragments of at least 2 g" +
             (f", {seeds} seeds pooled" if seeds > 1 else ""))
    script = (f"set terminal pngcairo size 900,600 font ',12'\nset output '{png}'\n"
              "set termoption noenhanced\n"
              f'set title "{title}"\n'
              "set logscale x\nset xrange [2:200]\nset yrange [0:1]\n"
              "set xlabel 'fragment mass m (g)'\nset ylabel 'fraction of the fragments of mass <= m'\n"
              "set key right bottom\nset grid\n"
              "plot " + ", ".join(plots) + "\n")
    subprocess.run(["gnuplot"], input=script, text=True, check=True)
    return png


def quarter(path):
    """A copy of a one-snapshot text dump with the particles of x, y > 0
    only: a quarter of the ring, drawn larger."""
    head, atoms, cols = [], [], None
    for line in open(path):
        if cols is None:
            head.append(line)
            if line.startswith("ITEM: ATOMS"):
                cols = line.split()[2:]
        elif line.strip():
            w = line.split()
            if float(w[cols.index("x")]) > 0 and float(w[cols.index("y")]) > 0:
                atoms.append(line)
    i = head.index("ITEM: NUMBER OF ATOMS\n")
    head[i + 1] = f"{len(atoms)}\n"
    part = path[:-len(".dump")] + ".quarter.dump"
    with open(part, "w") as f:
        f.writelines(head + atoms)
    return part


def pictures(out, rows, dim):
    """Fragments at 600 m/s (two spacings) and damage at 200 m/s, early
    (cracks still growing) and at the end."""
    what = "2D ring" if dim == 2 else "3D tube"
    seed = int(min(r["seed"] for r in rows))
    todo = []
    for n in (5, 10):
        todo.append((tag(dim, n, 600, seed) + ".dump", f"fragments_v600_n{n}.png", True,
                     ["--spacing", repr(dx(n) * 1e-3), "--color", "c_frag", "--cyclic",
                      "--title", f"{what}, dx = {dx(n):.2f} mm, 600 m/s: fragments (colour = fragment), a quarter"]))
    for when in ("early", ""):
        name = tag(dim, 10, 200, seed) + (".early" if when else "") + ".dump"
        todo.append((name, f"damage_v200_n10{'_early' if when else ''}.png", True,
                     ["--spacing", repr(dx(10) * 1e-3), "--color", "c_dmg", "--range", "0", "1",
                      "--label", "damage (broken share of bonds)",
                      "--title", f"{what}, dx = 1.00 mm, 200 m/s: damage, a quarter"]))
    made = []
    for dump, png, part, opts in todo:
        path = os.path.join(out, dump)
        if os.path.isfile(path):
            path = quarter(path) if part else path
            subprocess.run([sys.executable, PICTURE, path, os.path.join(out, png), "--size", "900x800"] + opts,
                           check=True, stdout=subprocess.DEVNULL)
            made.append(png)
    return made


def main(argv):
    check = "--check" in argv
    folders = [a for a in argv if a != "--check"] or [os.path.join(HERE, "ring.out")]
    ok = True
    for out in folders:
        rows = read_rows(out)
        dim = 2 if any(f.startswith("d2_") for f in os.listdir(out)) else 3
        counts = {}
        for v in (600, 200):
            lines, means = table(rows, dim, v)
            print("\n".join(lines) + "\n")
            counts[v] = {n: pooled(rows, v, n)[0] for n in means}
            if check and v == 600:
                if len(means) < 4:
                    print(f"report: CHECK FAILED: {out}: {len(means)} of 4 spacings at 600 m/s")
                    ok = False
                elif spread([means[n] for n in SPACINGS[1:]]) > TOLERANCE:
                    print(f"report: CHECK FAILED: the finer three spacings are not within {100 * TOLERANCE:.0f}% "
                          "of each other at 600 m/s")
                    ok = False
        if check and any(counts[200].get(n, 1e9) >= counts[600].get(n, 0) for n in SPACINGS):
            print("report: CHECK FAILED: 200 m/s does not give fewer fragments than 600 m/s at every spacing")
            ok = False
        png = cdf_plot(out, rows, dim)
        made = pictures(out, rows, dim)
        print(f"report: {out}: " + ", ".join(([os.path.basename(png)] if png else []) + made))
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
