#!/usr/bin/env python3
"""A picture of particles from a LAMMPS text dump (dump custom / write_dump
custom), coloured by one column, with a colour scale, axis labels, units
and the time: what dump image cannot label. Standard library and gnuplot.

  pd_picture.py DUMP OUT.png --color c_dmg [--x x] [--y y] [--range 0 1]
                [--label 'damage'] [--title TEXT] [--time SECONDS] [--slab C LO HI]
                [--length-unit mm] [--cyclic] [--size 900x700]

--x, --y     the columns drawn across and up (default x, y)
--color      the column that colours each particle
--range      the colour scale's ends (default: the column's min and max)
--slab C LO HI  only the particles with LO <= column C <= HI (a cut)
--spacing    the particle spacing (in the dump's length unit), for the
             points' size (default: the median nearest-neighbour distance
             in the drawn plane, too small where layers overlap in it)
--cyclic     a repeating palette for labels (fragment IDs): neighbouring
             IDs get different colours, the scale shows none
--length-unit  positions are drawn in mm (default) or m
--time       printed in the title (in microseconds); default: the dump's
             time ('dump_modify time yes'), else its step
"""
import argparse
import shutil
import subprocess
import sys


def read_dump(path):
    """(timestep, time or None, columns, rows) of the last snapshot of a
    text dump ('dump_modify time yes' writes the time)."""
    step, time, cols, rows, mode = None, None, None, [], None
    with open(path) as f:
        for line in f:
            if line.startswith("ITEM: TIMESTEP"):
                mode, rows = "step", []
            elif line.startswith("ITEM: TIME"):
                mode = "time"
            elif line.startswith("ITEM: ATOMS"):
                cols, mode = line.split()[2:], "atoms"
            elif line.startswith("ITEM:"):
                mode = None
            elif mode == "step":
                step, mode = int(line), None
            elif mode == "time":
                time, mode = float(line), None
            elif mode == "atoms" and line.strip():
                rows.append(line.split())
    if not cols:
        raise SystemExit(f"pd_picture: {path} has no 'ITEM: ATOMS' block (a text dump custom is needed)")
    return step, time, cols, rows


def point_size(pts, w, h, spacing=None):
    """gnuplot's ps for points about one particle spacing wide: the median
    distance to the nearest neighbour (from up to 400 particles, on a grid
    of cells) in pixels of the equal-axes plot (its area about 70% x 80% of
    the picture); pt 7 at ps 1 is about 7 px wide."""
    xs, ys = [p[0] for p in pts], [p[1] for p in pts]
    xext, yext = max(xs) - min(xs) or 1.0, max(ys) - min(ys) or 1.0
    cell = max(xext, yext) / max(1.0, len(pts) ** 0.5)
    grid = {}
    for p in pts:
        grid.setdefault((int(p[0] // cell), int(p[1] // cell)), []).append(p)
    near = []
    for p in pts[::max(1, len(pts) // 400)]:
        cx, cy = int(p[0] // cell), int(p[1] // cell)
        d = [((q[0] - p[0]) ** 2 + (q[1] - p[1]) ** 2) ** 0.5 for i in (-1, 0, 1) for j in (-1, 0, 1)
             for q in grid.get((cx + i, cy + j), ()) if q is not p]
        d = [x for x in d if x > 0.0]
        if d:
            near.append(min(d))
    if spacing is None:
        spacing = sorted(near)[len(near) // 2] if near else cell
    px = min(0.7 * w / xext, 0.8 * h / yext)
    return max(0.2, min(4.0, 0.9 * spacing * px / 7.0))


def main(argv):
    a = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    a.add_argument("dump")
    a.add_argument("png")
    a.add_argument("--x", default="x")
    a.add_argument("--y", default="y")
    a.add_argument("--color", required=True)
    a.add_argument("--range", nargs=2, type=float)
    a.add_argument("--label")
    a.add_argument("--title", default="")
    a.add_argument("--time", type=float)
    a.add_argument("--length-unit", choices=("mm", "m"), default="mm")
    a.add_argument("--cyclic", action="store_true")
    a.add_argument("--slab", nargs=3)
    a.add_argument("--spacing", type=float)
    a.add_argument("--size", default="900x700")
    o = a.parse_args(argv)
    step, time, cols, rows = read_dump(o.dump)
    if o.time is None:
        o.time = time
    for c in (o.x, o.y, o.color):
        if c not in cols:
            raise SystemExit(f"pd_picture: {o.dump} has no column '{c}' (it has {' '.join(cols)})")
    ix, iy, ic = cols.index(o.x), cols.index(o.y), cols.index(o.color)
    if o.slab:
        c, lo_s, hi_s = o.slab[0], float(o.slab[1]), float(o.slab[2])
        if c not in cols:
            raise SystemExit(f"pd_picture: --slab: {o.dump} has no column '{c}'")
        rows = [r for r in rows if lo_s <= float(r[cols.index(c)]) <= hi_s]
        if not rows:
            raise SystemExit(f"pd_picture: --slab {c} {lo_s:g} {hi_s:g} holds no particle")
    scale = 1e3 if o.length_unit == "mm" else 1.0
    data = "".join(f"{float(r[ix]) * scale!r} {float(r[iy]) * scale!r} {float(r[ic])!r}\n" for r in rows)
    values = [float(r[ic]) for r in rows]
    lo, hi = o.range if o.range else (min(values), max(values))
    title = o.title + (f"   t = {o.time * 1e6:.1f} us" if o.time is not None else f"   step {step}")
    w, h = (int(v) for v in o.size.split("x"))
    pts = [(float(r[ix]) * scale, float(r[iy]) * scale) for r in rows]
    ps = point_size(pts, w, h, o.spacing * scale if o.spacing else None)
    # enough points per particle to touch their neighbours at this size
    palette = ("set palette model HSV functions (gray*7.3 - floor(gray*7.3)), 0.8, 0.95\n"
               f"set cbrange [0:1]\nunset colorbox\n" if o.cyclic else
               "set palette defined (0 '#3b4cc0', 0.35 '#9abbff', 0.5 '#dddddd', 0.7 '#f49a7b', 1 '#b40426')\n"
               f"set cbrange [{lo!r}:{hi!r}]\nset cblabel '{o.label or o.color}'\n")
    using = "1:2:(($3*0.6180339887) - floor($3*0.6180339887))" if o.cyclic else "1:2:3"
    script = (f"set terminal pngcairo size {w},{h} font ',12'\nset output '{o.png}'\n"
              "set termoption noenhanced\n"
              f"set title '{title}'\nset xlabel '{o.x} ({o.length_unit})'\nset ylabel '{o.y} ({o.length_unit})'\n"
              "set size ratio -1\nunset key\nset offsets graph 0.03, graph 0.03, graph 0.03, graph 0.03\n" + palette +
              f"plot '-' using {using} with points pt 7 ps {ps:.2f} lc palette\n{data}e\n")
    exe = shutil.which("gnuplot")
    if not exe:
        raise SystemExit("pd_picture: gnuplot not found (Debian: apt-get install gnuplot-nox)")
    r = subprocess.run([exe], input=script, capture_output=True, text=True)
    if r.returncode != 0:
        raise SystemExit(f"pd_picture: gnuplot failed: {r.stderr.strip()[:400]}")
    print(f"pd_picture: {o.png} ({len(rows)} particles, {o.color} {lo:g} to {hi:g})")


if __name__ == "__main__":
    main(sys.argv[1:])
