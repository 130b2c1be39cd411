"""The campaign's curve: results.png by gnuplot, from `plot = x y [y ...]`.

One panel per y column, y against x; the cases that differ in another
case variable are separate curves, labelled by it."""
import os
import shutil
import subprocess


def number(s):
    try:
        return float(s)
    except ValueError:
        return None


def label(c, col):
    return c.labels.get(col, col).replace("'", "")


def curves(c, done, x, y):
    """{label: [(x, y), ...]} sorted by x; label names the other case variables."""
    out = {}
    for row in done.values():
        xv, yv = number(row[x]), number(row[y])
        if xv is None or yv is None:
            continue
        curve = " ".join(f"{n}={row[n]}" for n in c.names if n != x)
        out.setdefault(curve, []).append((xv, yv))
    return {k: sorted(v) for k, v in out.items()}


def draw(c, done):
    """Writes <out>/results.png; returns a line saying what was done."""
    exe = shutil.which("gnuplot")
    if not exe:
        return "no plot: gnuplot not found (Debian: apt-get install gnuplot-nox)"
    x, ys = c.plot[0], c.plot[1:]
    png = os.path.join(c.out, "results.png")
    data = os.path.join(c.out, "plot")
    os.makedirs(data, exist_ok=True)
    script = [f"set terminal pngcairo size 800,{320 * len(ys)} font ',11'", f"set output '{png}'",
              f"set multiplot layout {len(ys)},1 title '{c.name}: {len(done)} of {len(c.cases)} cases'",
              "set termoption noenhanced", "set grid", "set key outside right", "set datafile separator ' '"]
    for y in ys:
        plots = []
        for j, (name, pts) in enumerate(sorted(curves(c, done, x, y).items())):
            f = os.path.join(data, f"{y}.{j}.dat")
            with open(f, "w") as out:
                out.writelines(f"{a!r} {b!r}\n" for a, b in pts)
            title = f"title '{name}'" if name else "notitle"
            plots.append(f"'{f}' using 1:2 with linespoints pt 7 {title}")
        script += [f"set xlabel '{label(c, x)}'", f"set ylabel '{label(c, y)}'",
                   "plot " + ", ".join(plots) if plots else "plot NaN notitle"]
    script.append("unset multiplot")
    p = subprocess.run([exe], input="\n".join(script) + "\n", capture_output=True, text=True)
    if p.returncode != 0:
        return f"no plot: gnuplot failed: {p.stderr.strip()[:300]}"
    return f"plot: {os.path.relpath(png)}"
