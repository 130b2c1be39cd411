"""PNG plots with gnuplot: error against cost, one curve per setting
family (points joined in the order of the swept parameter), the Pareto
front drawn over them."""
import os
import shutil
import subprocess

FLOOR = 1e-9        # errors below this (exact models) are drawn at it on the log axis


class PlotError(RuntimeError):
    pass


def gnuplot():
    """The gnuplot program, or a PlotError that says how to get it."""
    exe = shutil.which("gnuplot")
    if not exe:
        raise PlotError("gnuplot not found: the accuracy report's plots need it "
                        "(Debian: apt-get install gnuplot-nox, or run tools/setup-deps.sh)")
    return exe


def _q(s):
    return '"' + s.replace('"', "'") + '"'


def error_vs_cost(path, curves, front, xlabel, ylabel, title, targets=()):
    """curves: {family: [(cost, err), ...]} in sweep order; front: [(cost,
    err), ...]; targets: error levels drawn as dotted lines. Writes path
    (PNG); returns path."""
    exe = gnuplot()
    data_dir = path + ".data"
    os.makedirs(data_dir, exist_ok=True)
    plots = []
    for k, (fam, pts) in enumerate(sorted(curves.items())):
        f = os.path.join(data_dir, f"c{k}.dat")
        with open(f, "w") as out:
            for c, e in pts:
                out.write(f"{c:.6e} {max(e, FLOOR):.6e}\n")
        plots.append(f"{_q(f)} using 1:2 with linespoints pt {k % 13 + 1} title {_q(fam)}")
    f = os.path.join(data_dir, "front.dat")
    with open(f, "w") as out:
        for c, e in front:
            out.write(f"{c:.6e} {max(e, FLOOR):.6e}\n")
    plots.append(f"{_q(f)} using 1:2 with steps lw 3 lc rgb 'black' dt 2 title 'Pareto front'")
    plots.append(f"{_q(f)} using 1:2 with points pt 6 ps 2.5 lc rgb 'black' notitle")
    script = (f"set terminal pngcairo size 1100,750 font ',10'\nset output {_q(path)}\n"
              "set logscale xy\nset grid\nset key outside right top font ',8'\n"
              "set format x '%.0e'\nset format y '%.0e'\n" +
              "".join(f"set arrow from graph 0, first {t!r} to graph 1, first {t!r} nohead dt 3 lc rgb 'gray50'\n"
                      for t in targets) +
              f"set xlabel {_q(xlabel)}\nset ylabel {_q(ylabel)}\nset title {_q(title)}\n"
              "plot " + ", \\\n     ".join(plots) + "\n")
    with open(path + ".gp", "w") as out:
        out.write(script)
    p = subprocess.run([exe, path + ".gp"], capture_output=True, text=True)
    if p.returncode != 0 or not os.path.exists(path) or os.path.getsize(path) == 0:
        raise PlotError(f"gnuplot failed on {path}.gp: {p.stderr.strip()[-400:]}")
    return path
