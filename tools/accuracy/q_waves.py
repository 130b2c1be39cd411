"""Linear waves: phase error against classical elasticity.

A periodic box 16 mm on a side holds a random smooth velocity field of
small amplitude (four of the box's longest Fourier modes, strain 1e-7:
the linear regime). LAMMPS (pd/bond or pd/ordinary) advances it for half
the time a bar wave takes to cross the box; tools/pd_exact gives the exact
solution of the same linearized lattice equation (FFT, EW06 section 3) and
that of local elasticity with the same constants. Errors are relative L2
norms of the displacement over all particles:
  phase_error  LAMMPS against local elasticity: the nonlocal dispersion
               (k delta = 1.2 to 2 at delta = 3 mm), the lattice error of
               the constants, and the time error;
  time_error   LAMMPS against the exact lattice solution: the time
               integrator's error alone (second order in dt).
Spacing is the cube (square) root of the volume (area) per particle; the
time step a fraction of the package's stable estimate (MS07 eq. 43).
"""
# Interface for the sweep driver (tools/accuracy/run.py):
#   cases(mode) -> [case dict], mode 'smoke' | 'short' | 'full'
#   measure(case, lmp, pd_exact, workdir) -> dict with phase_error,
#       time_error, seconds (LAMMPS 'Loop time'), particle_steps, extras.
# Case keys (missing ones take DEFAULTS): style ('pd/bond', 'pd/ordinary'),
# dim (2, 3), lattice ('sc', 'fcc', 'sq' or 'square', 'hex'), ratio
# (horizon / spacing), spacing (m), influence (pd/ordinary), dt_fraction,
# order (strain order m, pd/ordinary), quadrature ('point', the default;
# 'partial' goes to the pair style and to pd_exact, which reproduces partial
# cells when built with core/pd_quadrature: with QUADRATURE the driver adds
# those copies where the binary has them), seed (of the random field). A
# run that fails (LAMMPS or pd_exact refusing a setting) raises
# RuntimeError naming the input.
import math
import os
import random
import re
import subprocess

import deck as pdeck    # the neighbor settings every deck states

# One material for every case: E = 22.35 GPa; pd/ordinary nu = 0.33 (not 1/4,
# where its lambda_bar = lambda - mu vanishes and the dilatation term would
# go untested); bonds take the nu bond-based elasticity fixes (1/4, 1/3 in
# plane stress).
E, RHO, NU_ORDINARY, THICKNESS = 22.35e9, 2200.0, 0.33, 1e-3
BOX = 0.016          # box side (m), every case: the same physical problem
STRAIN = 1e-7        # velocity amplitude / bar speed: the linear regime
CROSSINGS = 0.5      # run time in box crossings of a bar wave sqrt(E / rho)
SHELL = 1.0 + 1e-6   # a lattice shell on the horizon belongs to the family

DEFAULTS = dict(style="pd/ordinary", dim=3, lattice="sc", ratio=3.0, spacing=1e-3,
                influence=None, dt_fraction=0.5, order=0.5, quadrature="point", seed=1)

# for the sweep driver (tools/accuracy/run.py)
NAME = "waves"
TITLE = "Linear waves: phase error against classical elasticity"
PRIMARY = "phase_error"
QUADRATURE = True     # the driver adds 'quadrature partial' copies where the binary has it
# every case is the same physical problem, so its total cost is what a
# setting costs: ranked by 'seconds' (LAMMPS's Loop time; no 'wall' key),
# not per particle-step, which would not charge a finer spacing
COST = "wall"


def family(case):
    """A curve: everything but the horizon ratio."""
    c = settings(case)
    return " ".join(str(c[k]) for k in ("style", "lattice", "influence", "quadrature", "spacing",
                                        "dt_fraction") if c.get(k) is not None)


def group(case):
    """Recommendations within a dimension."""
    return "3d" if settings(case)["dim"] == 3 else "plane stress"


def cases(mode):
    """The wave cases of a sweep mode, as lists of settings dicts."""
    out = []

    def add(**kw):
        c = dict(DEFAULTS)
        c.update(kw)
        c["lattice"] = kw.get("lattice", "sc" if c["dim"] == 3 else "sq")
        out.append(c)

    if mode == "smoke":
        add(style="pd/ordinary", dim=3, ratio=3.0, spacing=2e-3, dt_fraction=0.5)
        add(style="pd/bond", dim=2, ratio=3.0, spacing=1e-3, dt_fraction=0.5)
        return out
    if mode == "short":
        # about 50 s on one core: 3D at 1 mm (4096 particles) over ratio and
        # time step, 3D at 0.5 mm (32768) at ratio 3, 2D at two spacings
        for style in ("pd/bond", "pd/ordinary"):
            for ratio in (2.5, 3.0, 4.0):
                for dtf in (0.25, 0.5, 0.9):
                    add(style=style, dim=3, ratio=ratio, spacing=1e-3, dt_fraction=dtf)
                for spacing in (5e-4, 2.5e-4):
                    add(style=style, dim=2, ratio=ratio, spacing=spacing, dt_fraction=0.5)
            add(style=style, dim=3, ratio=3.0, spacing=5e-4, dt_fraction=0.5)
        add(style="pd/ordinary", dim=3, ratio=3.0, spacing=1e-3, influence="constant")
        return out
    if mode != "full":
        raise ValueError(f"q_waves.cases: mode '{mode}' is not smoke, short or full")
    # half the stable step; the step swept on one family (its time error is
    # below the nonlocal and lattice errors at every fraction). 3D: the
    # spacing sets the error (fixed box), so the finer one at 3 and 4
    # spacings; 2D: the finer spacing swept, the coarser one at 3 spacings
    # only (on the square lattice the error is the constants' lattice
    # error, the same at both spacings)
    infls = (None, "constant", "inverse", "tupek", "gaussian")
    for dim, lattices, coarse, fine in ((3, ("sc", "fcc"), 1e-3, 5e-4), (2, ("sq", "hex"), 5e-4, 2.5e-4)):
        for lattice in lattices:
            for spacing, ratios, kinds in ((coarse, (2.5, 3.0, 4.0) if dim == 3 else (3.0,), infls),
                                           (fine, (3.0, 4.0) if dim == 3 else (2.5, 3.0, 4.0, 6.0),
                                            infls[:3] if dim == 3 else infls)):
                for ratio in ratios:
                    if BOX <= 2.2 * ratio * spacing * (1.6 if lattice == "fcc" else 1.0):
                        continue
                    if dim == 3 and spacing == fine and lattice == "fcc" and ratio > 3:
                        continue
                    add(style="pd/bond", dim=dim, lattice=lattice, ratio=ratio, spacing=spacing)
                    for infl in kinds[1:]:
                        add(style="pd/ordinary", dim=dim, lattice=lattice, ratio=ratio, spacing=spacing,
                            influence=infl)
    for style in ("pd/bond", "pd/ordinary"):
        for dtf in (0.25, 0.9):
            add(style=style, dim=3, ratio=3.0, spacing=1e-3, dt_fraction=dtf)
    return out


# ---------------------------------------------------------------- geometry

def lattice_constant(lattice, spacing):
    """LAMMPS's lattice constant for a volume (area) per site spacing^dim."""
    return {"sc": spacing, "sq": spacing, "fcc": spacing * 4.0 ** (1.0 / 3.0),
            "hex": spacing * math.sqrt(2.0 / math.sqrt(3.0))}[lattice]


def cells(lattice, a):
    """Conventional cells per side filling the box, and the cell sides."""
    side = {"sc": (a, a, a), "fcc": (a, a, a), "sq": (a, a), "hex": (a, math.sqrt(3.0) * a)}[lattice]
    return [max(1, round(BOX / s)) for s in side], side


def settings(case):
    c = dict(DEFAULTS)
    c.update({k: v for k, v in case.items() if v is not None or k == "influence"})
    c["lattice"] = {"square": "sq"}.get(c["lattice"], c["lattice"])
    dims = {"sq": 2, "hex": 2, "sc": 3, "fcc": 3}
    if "lattice" in case and "dim" not in case:
        c["dim"] = dims[c["lattice"]]
    elif dims[c["lattice"]] != c["dim"]:
        c["lattice"] = "sc" if c["dim"] == 3 else "sq"
    return c


def poisson(c):
    if c["style"] == "pd/bond":
        return 1.0 / 3.0 if c["dim"] == 2 else 0.25    # plane stress in 2D
    return NU_ORDINARY


# ---------------------------------------------------------------- the field

def modes(c, lengths):
    """A few smooth modes: wave numbers -1, 0 or 1 per direction (the
    longest waves of the box: k delta = 1.2 at delta = 3 mm), random
    directions, amplitudes and phases (seeded)."""
    rng = random.Random(c["seed"])
    speed = math.sqrt(E / RHO)
    out = []
    for _ in range(4):
        m = [0, 0, 0]
        while not any(m):
            m = [rng.randint(-1, 1) if d < c["dim"] else 0 for d in range(3)]
        k = [2.0 * math.pi * m[d] / lengths[d] if d < c["dim"] else 0.0 for d in range(3)]
        n = [rng.gauss(0, 1) if d < c["dim"] else 0.0 for d in range(3)]
        norm = math.sqrt(sum(x * x for x in n))
        amp = STRAIN * speed * rng.uniform(0.5, 1.0)
        out.append((k, [amp * x / norm for x in n], rng.uniform(0, 2 * math.pi)))
    return out


def velocity_commands(field, dim):
    terms = [[], [], []]
    for k, a, phi in field:
        arg = f"({k[0]!r}*x+{k[1]!r}*y+{k[2]!r}*z+{phi!r})"
        for d in range(3):
            if a[d]:
                terms[d].append(f"{a[d]!r}*sin{arg}")
    lines = [f"variable v{'xyz'[d]} atom {'+'.join(terms[d]) or '0.0'}" for d in range(3)]
    vz = "v_vz" if dim == 3 else "NULL"
    return "\n".join(lines) + f"\nvelocity all set v_vx v_vy {vz} units box\n"


# ---------------------------------------------------------------- LAMMPS

def deck(c, run_part):
    a = lattice_constant(c["lattice"], c["spacing"])
    n, side = cells(c["lattice"], a)
    dim = c["dim"]
    horizon = c["ratio"] * c["spacing"] * SHELL
    vol = c["spacing"] ** 3 if dim == 3 else c["spacing"] ** 2 * THICKNESS
    lat = {"sq": "sq", "hex": "hex", "sc": "sc", "fcc": "fcc"}[c["lattice"]]
    region = (f"0 {n[0]} 0 {n[1]} 0 {n[2]}" if dim == 3 else f"0 {n[0]} 0 {n[1]} -0.5 0.5")
    s = ["units si", f"dimension {dim}", "boundary p p p", "atom_style peri", "atom_modify map array",
         pdeck.NEIGHBOR.format(skin=repr(pdeck.SKIN * c["spacing"])).rstrip("\n"),
         f"lattice {lat} {a!r}", f"region box block {region}", "create_box 1 box", "create_atoms 1 box",
         f"set group all density {RHO!r}", f"set group all volume {vol!r}"]
    plane = f" plane stress thickness {THICKNESS}" if dim == 2 else ""
    quad = f" quadrature {c['quadrature']}"    # always named: pd/bond's default is partial
    if c["style"] == "pd/bond":
        s.append(f"pair_style pd/bond{plane}{quad}")
        s.append(f"pair_coeff * * pmb E {E!r} horizon {horizon!r}")
    else:
        infl = f" influence {c['influence']}" if c.get("influence") else ""
        s.append(f"pair_style pd/ordinary{plane}{infl}{quad}")
        s.append(f"pair_coeff * * E {E!r} nu {NU_ORDINARY!r} horizon {horizon!r} m {c['order']!r}")
    if dim == 2:
        s.append("fix 2d all enforce2d")
    lengths = [n[d] * side[d] if d < dim else 0.0 for d in range(3)]
    return "\n".join(s) + "\n" + run_part, lengths, horizon


def run_lmp(lmp, workdir, name, script):
    path = os.path.join(workdir, name)
    with open(path, "w") as f:
        f.write(script)
    p = subprocess.run([lmp, "-in", name, "-echo", "none", "-screen", "none", "-log", name + ".log"],
                       cwd=workdir, capture_output=True, text=True, timeout=3600)
    log = open(path + ".log").read() if os.path.exists(path + ".log") else ""
    if p.returncode != 0:
        err = [l for l in (log + p.stdout + p.stderr).splitlines() if "ERROR" in l]
        raise RuntimeError(f"lmp failed on {path}: {err[-1] if err else p.returncode}")
    return log


_stable = {}


def stable_dt(c, lmp, workdir):
    """The package's stable-step estimate of the case (cached: dt does not
    change it)."""
    key = tuple(sorted((k, str(v)) for k, v in c.items() if k not in ("dt_fraction", "seed")))
    if key not in _stable:
        log = run_lmp(lmp, workdir, "in.estimate", deck(c, "fix 1 all nve\nrun 0\n")[0])
        m = re.search(r"stable time step estimate \(MS07 eq\. 43\) (\S+),", log)
        if not m:
            raise RuntimeError("q_waves: no stable time step estimate in the log")
        _stable[key] = float(m.group(1))
    return _stable[key]


def read_dump(path):
    lines = open(path).read().splitlines()
    start = next(i for i, l in enumerate(lines) if l.startswith("ITEM: ATOMS"))
    rows = {}
    for l in lines[start + 1:]:
        w = l.split()
        if w:
            rows[int(w[0])] = [float(v) for v in w[1:]]
    return [rows[i] for i in sorted(rows)]


# ---------------------------------------------------------------- pd_exact

def run_exact(pd_exact, workdir, c, model, sites, lengths, horizon, time, tag):
    """pd_exact on the sites (x, v per site, no displacement); returns
    [(u, v)] in the same order."""
    fields = os.path.join(workdir, f"fields.{tag}")
    out = os.path.join(workdir, f"exact.{tag}")
    with open(fields, "w") as f:
        for r in sites:
            f.write(f"{r[0]!r} {r[1]!r} {r[2]!r} 0 0 0 {r[3]!r} {r[4]!r} {r[5]!r}\n")
    a = lattice_constant(c["lattice"], c["spacing"])
    n, _ = cells(c["lattice"], a)
    lines = [f"lattice {c['lattice']}", f"n {' '.join(map(str, n[:c['dim']]))}", f"spacing {a!r}",
             f"horizon {horizon!r}", f"model {model}", f"E {E!r}", f"nu {poisson(c)!r}",
             f"density {RHO!r}", f"time {time!r}", f"fields {fields}", f"output {out}"]
    if c["dim"] == 2:
        lines += ["plane stress", f"thickness {THICKNESS}"]
    if c["style"] == "pd/ordinary" and c.get("influence"):
        lines.append(f"influence {c['influence']}")
    lines.append(f"quadrature {c['quadrature']}")
    if c.get("directional") is False:
        lines.append("directional_correction no")
    inp = os.path.join(workdir, f"in.exact.{tag}")
    with open(inp, "w") as f:
        f.write("\n".join(lines) + "\n")
    p = subprocess.run([pd_exact, inp], capture_output=True, text=True, timeout=3600)
    if p.returncode != 0:
        raise RuntimeError(f"pd_exact failed on {inp}: {p.stderr.strip()}")
    rows = [list(map(float, l.split())) for l in open(out) if l.strip() and not l.startswith("#")]
    worst = re.search(r"worst (\S+)", p.stdout)
    return [(r[3:6], r[6:9]) for r in rows], float(worst.group(1)) if worst else math.nan


def rel_l2(a, b):
    num = sum((x - y) ** 2 for ra, rb in zip(a, b) for x, y in zip(ra, rb))
    den = sum(y * y for rb in b for y in rb)
    return math.sqrt(num / den) if den > 0 else math.nan


def measure(case, lmp, pd_exact, workdir):
    """Run one case; the errors, the cost and what they were measured on."""
    c = settings(case)
    os.makedirs(workdir, exist_ok=True)
    est = stable_dt(c, lmp, workdir)
    _, lengths, horizon = deck(c, "")
    time = CROSSINGS * lengths[0] / math.sqrt(E / RHO)
    steps = max(1, math.ceil(time / (c["dt_fraction"] * est)))
    dt = time / steps
    field = modes(c, lengths)
    run = (velocity_commands(field, c["dim"]) + "fix 1 all nve\n" + f"timestep {dt!r}\n" +
           "write_dump all custom dump.0 id x y z vx vy vz modify sort id format float %.17g\n" +
           "thermo 1000000\n" + f"run {steps}\n" +
           "write_dump all custom dump.1 id x y z vx vy vz modify sort id format float %.17g\n")
    script, lengths, horizon = deck(c, run)
    log = run_lmp(lmp, workdir, "in.waves", script)
    loop = re.search(r"Loop time of (\S+) on \d+ procs for (\d+) steps with (\d+) atoms", log)
    first, last = read_dump(os.path.join(workdir, "dump.0")), read_dump(os.path.join(workdir, "dump.1"))
    u_lmp, v_lmp = [], []
    for r0, r1 in zip(first, last):
        u = []
        for d in range(3):
            du = r1[d] - r0[d]
            if d < c["dim"]:
                du -= lengths[d] * round(du / lengths[d])    # periodic images
            u.append(du)
        u_lmp.append(u)
        v_lmp.append(r1[3:6])
    model = "pmb" if c["style"] == "pd/bond" else "ordinary"
    exact, worst = run_exact(pd_exact, workdir, c, model, first, lengths, horizon, time, "lattice")
    classical, _ = run_exact(pd_exact, workdir, c, "classical", first, lengths, horizon, time, "classical")
    natoms = int(loop.group(3)) if loop else len(first)
    return {
        "phase_error": rel_l2(u_lmp, [u for u, _ in classical]),
        "time_error": rel_l2(u_lmp, [u for u, _ in exact]),
        "velocity_time_error": rel_l2(v_lmp, [v for _, v in exact]),
        "lattice_vs_classical": rel_l2([u for u, _ in exact], [u for u, _ in classical]),
        "seconds": float(loop.group(1)) if loop else math.nan,
        "particle_steps": natoms * steps,
        "steps": steps, "dt": dt, "stable_dt": est, "atoms": natoms,
        "moduli_error": worst,
    }
