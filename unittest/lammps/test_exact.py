"""LAMMPS against the exact solution of the linearized lattice equation
(tools/pd_exact; EW06 section 3).

1. The tool against a hand-derived single mode: a chain with PMB bonds
   p = 1..3 spacings, v0 = sin(k x): u(t) = sin(k x) sin(w t)/w with
   rho w^2 = sum_p 2 c V (1 - cos k p h)/(p h); and the classical chain,
   w = k sqrt(E / rho). Round-off only: 1e-12.
2. pd/bond and pd/ordinary (3D simple cubic; 2D square plane stress; 2D
   hexagonal PMB; 3D with 'quadrature partial' when the build has it) from a random smooth velocity field of strain ~1e-7 on a
   periodic box (no displacement: the bonds' reference x0 is where the
   atoms are created; tools/accuracy/q_waves.py builds the runs). The
   linearized equation is exact to O(strain) = 1e-7 and the tool is exact
   to round-off, so the difference is velocity Verlet's: at 1/2, 1/4 and
   1/8 of the stable step the fitted order is within 0.1 of 2, and at 1/8
   the error is below 1e-3 (its phase error w T (w dt)^2 / 24 for the
   fastest excited mode is ~3e-4).
3. The classical solution with the same constants differs by the
   dispersion and the lattice error of the constants: at least 10 times
   the time error at the smallest step, and the same at every step
   (within 5%): it is not the integrator's.

PDEXT_EXACT_BREAK=hand|order|classical breaks one group of checks on
purpose (each must then fail).
"""
import math
import os
import subprocess
import sys

from lmptest import LMP, check, check_le, finish, workdir

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "../../tools/accuracy"))
import q_waves  # noqa: E402

EXACT = os.path.abspath(os.environ.get("PDEXT_EXACT") or os.path.join(HERE, "../../build/pd_exact"))
BREAK = os.environ.get("PDEXT_EXACT_BREAK", "")


def chain_single_mode(d):
    n, h, rho, c, p_max, e_mod = 32, 1e-3, 1000.0, 1e20, 3, 5e9
    k = 2 * math.pi * 3 / (n * h)
    t = 2e-6
    with open(os.path.join(d, "chain.fields"), "w") as f:
        for i in range(n):
            f.write(f"{i * h!r} 0 0 0 0 0 {math.sin(k * i * h)!r} 0 0\n")
    c_tool = c * (1.001 if BREAK == "hand" else 1.0)
    for model, extra in (("pmb", f"c {c_tool!r}"), ("classical", f"E {e_mod!r}")):
        with open(os.path.join(d, "in.chain"), "w") as f:
            f.write(f"lattice chain\nn {n}\nspacing {h}\nhorizon {p_max * h * 1.000001!r}\nmodel {model}\n"
                    f"{extra}\ndensity {rho}\ntime {t}\nfields chain.fields\noutput chain.out\n")
        subprocess.run([EXACT, "in.chain"], cwd=d, check=True, capture_output=True)
        if model == "pmb":
            a = sum(2 * c * h * (1 - math.cos(k * p * h)) / (p * h) for p in range(1, p_max + 1))
            w = math.sqrt(a / rho)
        else:
            w = k * math.sqrt(e_mod / rho)
        err = 0.0
        rows = [list(map(float, l.split())) for l in open(os.path.join(d, "chain.out")) if not l.startswith("#")]
        for i, r in enumerate(rows):
            s = math.sin(k * i * h)
            err = max(err, abs(r[3] - s * math.sin(w * t) / w) * w, abs(r[6] - s * math.cos(w * t)))
        check_le(f"pd_exact chain {model}: single mode against the hand-derived solution (w t = {w * t:.1f})",
                 err, 1e-12, "round-off only")


def fitted_order(dts, errs):
    """Least-squares slope of log(error) against log(dt)."""
    x = [math.log(v) for v in dts]
    y = [math.log(v) for v in errs]
    mx, my = sum(x) / len(x), sum(y) / len(y)
    return sum((a - mx) * (b - my) for a, b in zip(x, y)) / sum((a - mx) ** 2 for a in x)


CASES = [
    ("pd/bond 3D sc", dict(style="pd/bond", dim=3, lattice="sc", spacing=1e-3)),
    ("pd/ordinary 3D sc", dict(style="pd/ordinary", dim=3, lattice="sc", spacing=1e-3)),
    ("pd/ordinary 2D sq plane stress", dict(style="pd/ordinary", dim=2, lattice="sq", spacing=5e-4)),
    ("pd/bond 2D hex plane stress", dict(style="pd/bond", dim=2, lattice="hex", spacing=5e-4)),
]


def against_lammps(d):
    cases = CASES + [
        ("pd/bond 3D sc quadrature partial",
         dict(style="pd/bond", dim=3, lattice="sc", spacing=1e-3, quadrature="partial")),
        ("pd/ordinary 3D sc quadrature partial",
         dict(style="pd/ordinary", dim=3, lattice="sc", spacing=1e-3, quadrature="partial"))]
    for name, base in cases:
        runs = []
        for frac in (0.5, 0.25, 0.125):
            case = dict(base, ratio=3.0, dt_fraction=frac)
            r = q_waves.measure(case, LMP, EXACT, os.path.join(d, name.replace(" ", "_").replace("/", "")))
            if BREAK == "order":    # an error that does not shrink with dt
                r["time_error"] += 1e-3
                r["velocity_time_error"] += 1e-3
            if BREAK == "classical":   # 'classical' = the lattice solution itself
                r["phase_error"] = r["time_error"]
            runs.append(r)
        dts = [r["dt"] for r in runs]
        for key, what in (("time_error", "displacement"), ("velocity_time_error", "velocity")):
            errs = [r[key] for r in runs]
            order = fitted_order(dts, errs)
            print(f"  {name}: {what} errors {', '.join(f'{e:.3g}' for e in errs)} at "
                  f"{', '.join(str(r['steps']) for r in runs)} steps ({runs[0]['atoms']} atoms)")
            check_le(f"{name}: {what} error against the exact lattice solution is second order "
                     f"(fitted {order:.3f})", abs(order - 2.0), 0.1, "velocity Verlet")
        check_le(f"{name}: displacement error at 1/8 of the stable step", runs[-1]["time_error"], 1e-3,
                 "Verlet's phase error of the fastest excited mode ~3e-4")
        phases = [r["phase_error"] for r in runs]
        print(f"  {name}: against the classical solution {', '.join(f'{p:.4f}' for p in phases)} "
              f"(lattice error of the constants, worst mode {runs[0]['moduli_error']:.4f})")
        check(f"{name}: classical-solution gap (dispersion) at least 10x the time error",
              min(phases) >= 10 * runs[-1]["time_error"], f"{min(phases):.3g} vs {runs[-1]['time_error']:.3g}")
        # |gap(dt1) - gap(dt3)| <= |L1 - L3| / |C| <= (t1 + t3) |E| / |C| (triangle
        # inequality; |E| / |C| <= 1 + |E - C| / |C|): what moves the gap is the
        # integrator's error, the gap itself is the model's dispersion
        bound = (runs[0]["time_error"] + runs[-1]["time_error"]) * (1 + runs[0]["lattice_vs_classical"])
        check_le(f"{name}: classical-solution gap moves with dt only by the time errors",
                 max(phases) - min(phases), bound, "dispersion is the model's, not the integrator's")


d = workdir()
chain_single_mode(d)
against_lammps(d)
finish()
