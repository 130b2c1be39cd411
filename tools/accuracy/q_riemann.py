"""Quantity 5: nonlinear strain order against interpenetration, the
Riemann problem of T14 5.3 (examples/riemann-2d/in.riemann: a 2 m x 1 m
plane-strain bar whose halves collide at 2 x 1200 m/s, horizon 0.05 m,
the interface pre-fractured, broken bonds pushing at any length).

After 100 us, the overlap is how far the left half reaches past the right
half's leftmost particle (positive: the halves interpenetrate), and the
close particles are those with a neighbour nearer than a third of the
spacing. Error: the overlap in horizons (0 when the halves stay apart)
plus the close particles per particle of the interface (1 m / spacing):
0 when the halves neither pass through each other nor locally overlap. Swept: the
strain order m, the spacings per horizon, the time step."""
import os
import re
import deck

NAME = "riemann"
PRIMARY = "err"
TITLE = "Interpenetration in the Riemann problem (overlap / horizon)"
ERROR_UNIT = "overlap in horizons + close particles per interface particle"
COST = "wall"
DELTA = 0.05
DT, T_END = 2.0e-7, 1.0e-4


def cases(mode):
    if mode == "smoke":
        return [{"m": 0.5, "ratio": 3, "dt_frac": 1.0}]
    # full: every m <= 1/4 keeps the halves apart at every resolution and
    # half the time step changes nothing, so one m below 0 and one
    # halved step
    ms = [0.5, 0, -1] if mode == "short" else [0.5, 0.25, 0, -1]
    nhs = [3] if mode == "short" else [3, 4, 5]
    out = [{"m": m, "ratio": nh, "dt_frac": 1.0} for m in ms for nh in nhs]
    if mode == "full":
        out.append({"m": 0.5, "ratio": 5, "dt_frac": 0.5})
    return out


def family(case):
    return f"m {case['m']:g}" + (f" dt x{case['dt_frac']:g}" if case["dt_frac"] != 1.0 else "")


def setting(case):
    """The measured setting as deck keys (the example's pair style)."""
    return {"style": "pd/ordinary", "lattice": "square", "plane": "plane strain", "recontact": "any",
            "h": DELTA / case["ratio"], "ratio": case["ratio"], "m": case["m"], "timestep": DT * case["dt_frac"]}


def measure(case, lmp, workdir):
    text = open(os.path.join(deck.ROOT, "examples", "riemann-2d", "in.riemann")).read()
    text, n = re.subn(r"^dump.*\n", "", text, flags=re.M)
    if n != 2:
        raise RuntimeError(f"examples/riemann-2d/in.riemann: expected 2 dump lines, found {n}")
    # the example leaves the neighbor settings to LAMMPS's defaults: state them
    text, n = re.subn(r"^(lattice\s.*\n)", lambda m: m.group(1) + deck.NEIGHBOR.format(skin=f"$({deck.SKIN!r}*v_h)"),
                      text, count=1, flags=re.M)
    if n != 1:
        raise RuntimeError("examples/riemann-2d/in.riemann: no lattice line")
    dt = DT * case["dt_frac"]
    text, n = re.subn(r"^timestep\s+\S+", f"timestep {dt!r}", text, flags=re.M)
    if n != 1:
        raise RuntimeError("examples/riemann-2d/in.riemann: no timestep line")
    steps = int(round(T_END / dt))
    out, t = deck.run(lmp, text, workdir, name="in.riemann",
                      variables={"m": case["m"], "nh": case["ratio"], "steps": steps, "tag": "acc"})
    m = re.search(r"RIEMANN m \S+ overlap_m (\S+) close_particles (\S+)", out)
    natoms = int(re.search(r"Loop time of \S+ on \d+ procs for \d+ steps with (\d+) atoms", out).group(1))
    overlap, close = float(m.group(1)), float(m.group(2))
    per_interface = close / (1.0 / (DELTA / case["ratio"]))
    return {"err": max(overlap, 0.0) / DELTA + per_interface, "overlap_m": overlap, "close_particles": close,
            "seconds": t["loop"][-1], "particle_steps": natoms * steps, "wall": t["wall"]}
