"""The material contract: every material pair style registered in the binary
(every pair style named pd/..., except pd/contact, which is not a
material) passes these checks, for every variant its contract deck
unittest/lammps/contract/<style, / replaced by _>.in gives (the format is
described at the top of contract/pd_bond.in). A registered material
without a deck is a FAIL naming it, so a new material cannot skip the
contract; a deck for a style the binary does not register is a FAIL too
(it would go untested).

Per variant (SI units, simple cubic / square lattice of spacing A,
horizon 3 spacings, all volumes equal):
  1. energy gradient: on a free block with random displacements of 1% of
     a spacing, the force density on a few atoms (corner, edge, face,
     interior) is minus the central finite difference of pe (a sum of
     energy densities: with equal volumes V, F_k = -d(V pe)/dx_k, so the
     force density f_k = F_k / V = -d(pe)/dx_k);
  2. objectivity: the deformed block rotated rigidly by 30 degrees about
     a skew axis has the same pe and the rotated forces;
  3. momentum: on that deformed block sum f = 0 and sum (x - c) x f = 0;
  4. uniform strain: in a periodic block, an isotropic expansion, an
     isochoric stretch along the axes, a simple shear xy and a uniaxial
     strain along x give pe / atoms = 1/2 eps:C:eps and the stress of the
     virial sigma = C:eps, with C of E and the deck's nu for the deck's
     model, each of the three modes (dilatation, shear along the lattice
     axes, simple shear) scaled by the lattice error the style's own setup
     report predicts for it; to 0.3%, so that a material 1% off in any
     constant fails, and an error the report does not predict fails;
  5. restart: 40 steps with a rough velocity field and a drift across the
     periodic boundaries, split by write_restart / read_restart in a new
     process at step 20, end where the uninterrupted run ends;
  6. rank invariance: the uninterrupted run on 2 MPI ranks ends where it
     ends on 1.

Negative checks: PDEXT_CONTRACT_BREAK=<name> perturbs the test or its
input so that a check must FAIL, to confirm that each check can fail:
fd_sign (the finite difference with the wrong sign: check 1), rotation
(the expected rotation 1 degree off: check 2's forces), nonrigid (a
deformation of 1e-4 of the displacements added to the rotation: check 2's
pe and forces), momentum (an external force on one atom, 1e-6 of the
force densities: check 3), classical (the classical law with nu + 0.02:
check 4), stiff (the material 1% stiffer than the classical law the test
compares it with: E of the decks 1.01 E: check 4), restart (one more step after read_restart: check 5), ranks (a
time step 1e-8 longer on 2 ranks: check 6), no_deck (the decks looked
for in an empty folder: the discovery)."""
import math
import os
import re
import subprocess
import time
from collections import namedtuple
from fractions import Fraction
from lmptest import *

T0 = time.time()
HERE = os.path.dirname(os.path.abspath(__file__))
DECKS = os.path.join(HERE, "contract")
BREAK = os.environ.get("PDEXT_CONTRACT_BREAK", "")
BREAKS = {"", "fd_sign", "rotation", "nonrigid", "momentum", "classical", "stiff", "restart", "ranks",
          "no_deck"}
if BREAK not in BREAKS:
    raise SystemExit(f"PDEXT_CONTRACT_BREAK={BREAK!r}: expected one of {sorted(BREAKS - {''})}")

# Material and lattice (SI). E and nu are those the decks get as ${E} and
# ${nu}; a deck whose material has a fixed Poisson's ratio says which.
A = 5.0e-4              # lattice spacing
DELTA = 3.0002 * A      # horizon: 3 spacings (just above, so that the bonds at 3A exist)
YOUNG, POISSON = 20.0e9, 0.3
RHO = 2200.0
THICK = 1.0e-3          # 2D plate thickness
DT = 5.0e-8             # about 0.4-0.5 of the stable step estimates of all variants
VARS = {"E": YOUNG, "nu": POISSON, "delta": DELTA, "thickness": THICK}
# The largest lattice error of a modulus the setup report may predict: a
# material whose moduli are off by more than this at delta = 3 spacings
# does not meet the contract.
MAX_LATTICE_ERROR = 0.15

# A variant of a deck: the style, its name, the model (3d, plane stress,
# plane strain), the Poisson's ratio of the material the lines define and
# the pair_style / pair_coeff lines.
Variant = namedtuple("Variant", "style name model nu deck")

# ----------------------------------------------------------------------
# Discovery: the material styles of the binary, and their decks.


def registered_pair_styles():
    p = subprocess.run([LMP, "-h"], capture_output=True, text=True, env=MPI_ENV, timeout=120)
    text = p.stdout
    m = re.search(r"^\* Pair styles:\s*\n(.*?)^\* ", text, re.S | re.M)
    if not m:
        raise RuntimeError(f"no '* Pair styles:' section in '{LMP} -h'")
    return m.group(1).split()


def deck_path(style):
    folder = DECKS if BREAK != "no_deck" else os.path.join(DECKS, "nonexistent")
    return os.path.join(folder, style.replace("/", "_") + ".in")


def parse_deck(style, path):
    """The Variants of a contract deck; a malformed deck
    raises ValueError (a typo must not drop a variant silently)."""
    variants, cur = [], None
    for number, raw in enumerate(open(path).read().splitlines(), 1):
        line = raw.strip()
        where = f"{os.path.basename(path)}:{number}"
        m = re.match(r"#\s*(variant|model|nu|tolerance)\s*:\s*(.*?)\s*$", line)
        if m and m.group(1) == "variant":
            cur = {"name": m.group(2), "model": None, "nu": None, "lines": []}
            variants.append(cur)
        elif m and m.group(1) == "tolerance":
            raise ValueError(f"{where}: no '# tolerance:' line: the uniform-strain check takes the lattice "
                             "error the style's setup report predicts")
        elif m:
            if cur is None or cur["lines"]:
                raise ValueError(f"{where}: '{m.group(1)}:' belongs right after a '# variant:' line")
            cur[m.group(1)] = m.group(2)
        elif not line or line.startswith("#"):
            continue
        elif cur is None:
            raise ValueError(f"{where}: a command before the first '# variant:' line")
        else:
            cur["lines"].append(line)
    out = []
    for v in variants:
        what = f"{os.path.basename(path)}, variant '{v['name']}'"
        if v["model"] not in ("3d", "plane stress", "plane strain"):
            raise ValueError(f"{what}: model must be 3d, plane stress or plane strain, not {v['model']!r}")
        if v["nu"] is None:
            raise ValueError(f"{what}: no '# nu:' line")
        try:
            nu = POISSON if v["nu"] == "${nu}" else float(Fraction(v["nu"]))
        except (ValueError, ZeroDivisionError):
            raise ValueError(f"{what}: '# nu:' must be a number, a fraction or ${{nu}}, not {v['nu']!r}")
        styles = [l.split()[1] for l in v["lines"] if l.split()[0] == "pair_style" and len(l.split()) > 1]
        if styles != [style]:
            raise ValueError(f"{what}: needs exactly one 'pair_style {style} ...' line, has {styles}")
        out.append(Variant(style, v["name"], v["model"], nu, "\n".join(v["lines"]) + "\n"))
    if not out:
        raise ValueError(f"{os.path.basename(path)}: no '# variant:' block")
    return out


styles = registered_pair_styles()
materials = sorted(s for s in styles if s.startswith("pd/") and s != "pd/contact")
print(f"registered material styles: {' '.join(materials)}")
check("discovery finds pd/bond and pd/ordinary among the registered pair styles",
      "pd/bond" in materials and "pd/ordinary" in materials, " ".join(materials))
for path in sorted(set(f for f in os.listdir(DECKS) if f.endswith(".in")) -
                   {os.path.basename(deck_path(m)) for m in materials}):
    check(f"contract/{path} belongs to a registered material style", False,
          f"the binary registers {' '.join(materials)}: the deck would go untested")
cases = []
for style in materials:
    path = deck_path(style)
    ok = os.path.exists(path)
    check(f"{style} has a contract deck", ok,
          "" if ok else f"{style} is registered but has no contract deck "
                        f"(unittest/lammps/contract/{os.path.basename(path)})")
    if ok:
        try:
            cases += parse_deck(style, path)
        except ValueError as err:
            check(f"{style}: its contract deck is well formed", False, str(err))

# ----------------------------------------------------------------------
# Geometry and helpers.


def two_d(model):
    return model != "3d"


def volume(model):
    return A * A * THICK if two_d(model) else A ** 3


def geometry(model, n, free):
    """n lattice points per side: free (shrink-wrapped) or periodic."""
    lo, hi = (-0.5, n - 0.5) if free else (0, n)
    if two_d(model):
        return (f"units si\ndimension 2\nboundary {'s s p' if free else 'p p p'}\natom_style peri\n"
                f"atom_modify map array\nlattice sq {A}\nregion box block {lo} {hi} {lo} {hi} -0.5 0.5\n"
                f"create_box 1 box\ncreate_atoms 1 box\nset group all density {RHO}\n"
                f"set group all volume {volume(model)!r}\n")
    return (f"units si\nboundary {'s s s' if free else 'p p p'}\natom_style peri\natom_modify map array\n"
            f"lattice sc {A}\nregion box block {lo} {hi} {lo} {hi} {lo} {hi}\ncreate_box 1 box\n"
            f"create_atoms 1 box\nset group all density {RHO}\nset group all volume {volume(model)!r}\n")


def rough(amplitude, model, kind):
    """An atom-style field depending on atom IDs only (the same on any rank
    count): 'displace_atoms all move' or 'velocity all set' of it."""
    z = "0.0" if two_d(model) else "v_rz"
    field = (f"variable rx atom {amplitude!r}*sin(12.9898*id)\n"
             f"variable ry atom {amplitude!r}*sin(78.233*id)\n"
             f"variable rz atom {amplitude!r}*sin(37.719*id)\n")
    if kind == "displace":
        return field + f"displace_atoms all move v_rx v_ry {z} units box\n"
    return field + f"velocity all set v_rx v_ry {z} units box\n"


def dump(name, unwrapped=False):
    cols = "id xu yu zu fx fy fz" if unwrapped else "id x y z fx fy fz"
    return f"write_dump all custom {name} {cols} modify sort id format float %.17g\n"


def printed(out, tag):
    """Values of the lines 'tag v1 v2 ...' that print wrote (each once: a
    print line appears on the screen only)."""
    rows = []
    for line in out.splitlines():
        w = line.split()
        if w and w[0] == tag:
            rows.append(w[1:])
    return rows


def norm(v):
    return math.sqrt(sum(c * c for c in v))


def rotation(axis, degrees):
    """Right-handed rotation matrix (Rodrigues), as displace_atoms rotate."""
    k = [c / norm(axis) for c in axis]
    c, s = math.cos(math.radians(degrees)), math.sin(math.radians(degrees))
    K = [[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]]
    return [[c * (i == j) + s * K[i][j] + (1 - c) * k[i] * k[j] for j in range(3)] for i in range(3)]


def matvec(R, v):
    return [sum(R[i][j] * v[j] for j in range(3)) for i in range(3)]


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def lame(model, nu):
    """(lambda, mu) of the classical law for in-plane (2D) or 3D strains."""
    mu = YOUNG / (2 * (1 + nu))
    if model == "plane stress":
        return YOUNG * nu / (1 - nu * nu), mu
    return YOUNG * nu / ((1 + nu) * (1 - 2 * nu)), mu


d = workdir()
# the data files of the dynamics (restart and rank) runs, written on one
# rank: atom IDs from create_atoms depend on the rank count
run(geometry("3d", 8, free=False) + "write_data block.data\n" +
    "clear\n" + geometry("plane stress", 12, free=False) + "write_data plate.data\n", d, name="in.data")

# ----------------------------------------------------------------------
# The checks, per variant.

H_FD = 1e-6 * A         # finite-difference step
ROT_AXIS, ROT_DEG = (1.0, 2.0, 3.0), 30.0
RESULTS = []


def statics(v, tag):
    """Checks 1-3 on a free (shrink-wrapped) block, in one LAMMPS process."""
    label = f"{v.style} [{v.name}]"
    dims = 2 if two_d(v.model) else 3
    n = 10 if dims == 2 else 7
    # atoms by lattice site (create_atoms on one rank numbers them x
    # fastest, then y, then z): corner, edge, face, centre (the 3D centre
    # has a complete family at n = 7); in 2D corner, edge, two interior
    picks = [(0, 0, 0), (3, 0, 0), (2, 3, 0), (3, 3, 3)] if dims == 3 else \
        [(0, 0, 0), (4, 0, 0), (4, 5, 0), (5, 5, 0)]
    ids = [1 + i + n * j + n * n * k for i, j, k in picks]
    centre = [(n - 1) / 2 * A] * 2 + [(n - 1) / 2 * A if dims == 3 else 0.0]
    axis = ROT_AXIS if dims == 3 else (0.0, 0.0, 1.0)
    s = geometry(v.model, n, free=True) + v.deck + (MOMENTUM_BREAK if BREAK == "momentum" else "")
    s += "thermo_style custom step pe\nrun 0\n"               # the families, from the lattice
    s += rough(0.01 * A, v.model, "displace")                 # strains ~1e-2: nonlinear terms count
    s += "run 0 post no\n" + dump(f"deformed.{tag}")
    for a in ids:
        s += f"group g{a} id {a}\n"
        for c in range(dims):
            step = ["0"] * 3
            for sign, move in (("+", H_FD), ("-", -2 * H_FD), ("back", H_FD)):
                step[c] = repr(move)
                s += f"displace_atoms g{a} move {' '.join(step)} units box\n"
                if sign != "back":
                    s += f'run 0 post no\nprint "FD {a} {c} {sign} $(pe:%.17g)"\n'
    s += "run 0 post no\n" + dump(f"unrotated.{tag}") + 'print "PE1 $(pe:%.17g)"\n'
    s += (f"displace_atoms all rotate {centre[0]!r} {centre[1]!r} {centre[2]!r} "
          f"{axis[0]} {axis[1]} {axis[2]} {ROT_DEG} units box\n")
    if BREAK == "nonrigid":
        s += ("variable nx atom 1e-4*v_rx\nvariable ny atom 1e-4*v_ry\n"
              "displace_atoms all move v_nx v_ny 0.0 units box\n")
    s += "run 0 post no\n" + dump(f"rotated.{tag}") + 'print "PE2 $(pe:%.17g)"\n'
    out, _ = run(s, d, variables=VARS, name=f"in.statics.{tag}")

    # 1. energy gradient
    D = read_dump(f"{d}/deformed.{tag}")
    for a, p in zip(ids, picks):
        if any(abs(D[a][q] - p[q] * A) > 0.1 * A for q in range(dims)):
            raise RuntimeError(f"atom {a} is not at lattice site {p}: the test's ID numbering broke")
    pe = {(int(w[0]), int(w[1]), w[2]): float(w[3]) for w in printed(out, "FD")}
    worst = 0.0
    for a in ids:
        grad = [(pe[(a, c, "+")] - pe[(a, c, "-")]) / (2 * H_FD) for c in range(dims)]
        if BREAK == "fd_sign":
            grad = [-g for g in grad]
        f = D[a][3:3 + dims]
        worst = max(worst, norm([fi + gi for fi, gi in zip(f, grad)]) / norm(f))
    # Central differences with h = 1e-6 spacings: truncation ~ (h/A)^2 =
    # 1e-12 (the energy varies on the scale of a spacing), round-off ~
    # 1e-16 pe / (h |f|) ~ 1e-9 here (measured 2e-10 to 8e-10). 1e-6 is far
    # above both, and far below what a force that is not the energy's
    # gradient gives (a missing or extra term is off by O(1)).
    check_le(f"{label}: force = -d(pe)/dx (central differences, {len(ids)} atoms)", worst, 1e-6,
             "FD truncation (h/A)^2 and round-off 1e-16 pe/(h |f|)")
    RESULTS.append((label, "gradient", (worst,)))

    # 2. objectivity
    B, Rd = read_dump(f"{d}/unrotated.{tag}"), read_dump(f"{d}/rotated.{tag}")
    R = rotation(axis, ROT_DEG + (1.0 if BREAK == "rotation" else 0.0))
    pe1, pe2 = float(printed(out, "PE1")[0][0]), float(printed(out, "PE2")[0][0])
    xerr = max(norm([p - q for p, q in zip(matvec(R, [B[a][i] - centre[i] for i in range(3)]),
                                           [Rd[a][i] - centre[i] for i in range(3)])]) for a in B)
    xscale = max(norm([B[a][i] - centre[i] for i in range(3)]) for a in B)
    ferr = max(norm([p - q for p, q in zip(matvec(R, B[a][3:6]), Rd[a][3:6])]) for a in B)
    fscale = max(norm(B[a][3:6]) for a in B)
    # The atoms went where the test's rotation puts them (else the next two
    # checks would compare against another rotation): round-off of x only.
    check_le(f"{label}: atoms rotated as the test expects ({ROT_DEG} degrees)", xerr / xscale, 1e-14,
             "round-off of x")
    # Rotating rounds the positions by 1e-16 |x|, the strains by 1e-16 |x| /
    # A ~ 1e-15 against strains of 1e-2: pe and forces agree to ~1e-13
    # (measured 3e-15 to 8e-15 and 7e-14 to 1.1e-13). A term that is not
    # objective (one that uses x or Y components, not bond lengths and
    # directions) is off by O(1).
    check_le(f"{label}: pe unchanged by a rigid rotation", abs(pe2 - pe1) / pe1, 1e-9, "round-off")
    check_le(f"{label}: forces rotate with the body", ferr / fscale, 1e-9, "round-off, relative to max |f|")
    RESULTS.append((label, "objectivity: pe, f", (abs(pe2 - pe1) / pe1, ferr / fscale)))

    # 3. momentum: all volumes are equal, so the sums of force densities
    # are the sums of forces over V
    fsum, tsum, fabs, tabs = [0.0] * 3, [0.0] * 3, 0.0, 0.0
    c0 = [sum(D[a][i] for a in D) / len(D) for i in range(3)]
    for a in D:
        f = D[a][3:6]
        r = [D[a][i] - c0[i] for i in range(3)]
        fsum = [p + q for p, q in zip(fsum, f)]
        tsum = [p + q for p, q in zip(tsum, cross(r, f))]
        fabs += norm(f)
        tabs += norm(r) * norm(f)
    # Each bond adds equal and opposite force densities along Y to its two
    # ends (V_i = V_j): both sums vanish to round-off, ~1e-16 relative
    # (measured 1e-18 to 8e-17); 1e-10 as in the rank and parity tests.
    check_le(f"{label}: sum of forces is zero", norm(fsum) / fabs, 1e-10, "round-off, relative to sum |f|")
    check_le(f"{label}: sum of torques about the centroid is zero", norm(tsum) / tabs, 1e-10,
             "round-off, relative to sum |x - c| |f|")
    RESULTS.append((label, "momentum: force, torque", (norm(fsum) / fabs, norm(tsum) / tabs)))


# PDEXT_CONTRACT_BREAK=momentum: an external force density on one atom,
# 1e-6 of the force densities of the deformed block (~1e11 N/m^3), as a
# style that loses a small part of one reaction would give
MOMENTUM_BREAK = "variable kick atom (id==1)*1.0e5\nfix kick all addforce v_kick 0.0 0.0\n"

# Uniform strains: engineering strains of the box edges (xx, yy, zz) and
# the tilt xy over the box's height (a simple shear, the tensor strain
# eps_xy is half of it), small enough that the finite-strain terms
# (relative O(1e-4)) are far below the check's tolerance.
E0 = 1.0e-4
STRAINS = {3: {"isotropic": (E0, E0, E0, 0.0), "isochoric": (E0, -E0 / 2, -E0 / 2, 0.0),
               "simple shear xy": (0.0, 0.0, 0.0, E0), "uniaxial x": (E0, 0.0, 0.0, 0.0)},
           2: {"isotropic": (E0, E0, 0.0, 0.0), "isochoric": (E0, -E0, 0.0, 0.0),
               "simple shear xy": (0.0, 0.0, 0.0, E0), "uniaxial x": (E0, 0.0, 0.0, 0.0)}}
# The three modes the setup report gives the lattice error of, in its words
MODES = ("dilatation", "shear along the lattice axes", "simple shear xy")
# Measured against predicted: the report rounds each error to 0.1
# percentage point (up to 5e-4 off), and the finite-strain terms at E0 add
# up to 3.5e-4 (the correspondence styles' virial stress). A constant 1%
# off moves W and sigma by 1e-2: 3e-3 catches it in every mode.
TOL_PREDICTED = 3.0e-3


def predicted_errors(out, label):
    """The lattice error of each mode (MODES) in the setup report, or
    zeros where it says the constants are exact; None when it says
    neither (a material must report its accuracy)."""
    if re.search(r": type 1: constants exact under uniform strain", out):
        return (0.0, 0.0, 0.0)
    m = re.search(r": type 1: lattice error of the constants on .*?: dilatation ([-+0-9.]+)%, "
                  r"shear along the lattice axes ([-+0-9.]+)%, simple shear xy ([-+0-9.]+)%", out)
    return tuple(float(x) / 100.0 for x in m.groups()) if m else None


def classical_response(model, nu, e, errors):
    """pe per atom and the stress (xx yy zz xy xz yz) of the classical law
    at strain e = (exx, eyy, ezz, tilt xy), each mode's modulus scaled by
    1 + its error: dilatation (the in-plane trace in 2D), the deviatoric
    strain along the axes, the shear xy. The three are orthogonal
    eigenspaces of any cubic (square) stiffness, so W and sigma are the sums
    of their parts."""
    dims = 2 if two_d(model) else 3
    lam, mu = lame(model, nu)
    mean = sum(e[:dims]) / dims
    exy = e[3] / 2
    dev = [e[i] - mean if i < dims else 0.0 for i in range(3)]
    w = [(lam * dims + 2 * mu) * dims * mean * mean / 2, mu * sum(x * x for x in dev), 2 * mu * exy * exy]
    sig = [[(lam * dims + 2 * mu) * mean if i < dims else 0.0 for i in range(3)] + [0.0] * 3,
           [2 * mu * x for x in dev] + [0.0] * 3,
           [0.0] * 3 + [2 * mu * exy, 0.0, 0.0]]
    scale = [1 + x for x in errors]
    return (sum(k * x for k, x in zip(scale, w)),
            [sum(k * part[c] for k, part in zip(scale, sig)) for c in range(6)])


def classical(v, tag):
    """Check 4 on a periodic (triclinic) block: all families complete."""
    label = f"{v.style} [{v.name}]"
    dims = 2 if two_d(v.model) else 3
    n = 12 if dims == 2 else 8      # the box must be longer than two horizons
    L = n * A
    s = geometry(v.model, n, free=False) + "change_box all triclinic\n" + v.deck
    s += ("compute pv all pressure NULL virial\n"
          "thermo_style custom step pe vol c_pv[1] c_pv[2] c_pv[3] c_pv[4] c_pv[5] c_pv[6]\nrun 0\n")
    for key, e in STRAINS[dims].items():
        s += "change_box all " + " ".join(f"{q} final 0 {L * (1 + e[i])!r}" for i, q in enumerate("xyz"[:dims]))
        s += f" xy final {L * e[3]!r} remap units box\nrun 0 post no\n"
        s += f'print "STRAIN {key.replace(" ", "_")} $(pe:%.17g) $(vol:%.17g) ' + \
             " ".join(f"$(c_pv[{i}]:%.17g)" for i in range(1, 7)) + '"\n'
    # PDEXT_CONTRACT_BREAK=stiff: the decks' material 1% stiffer than the
    # law it is compared with
    variables = dict(VARS, E=YOUNG * 1.01) if BREAK == "stiff" else VARS
    out, _ = run(s, d, variables=variables, name=f"in.classical.{tag}")
    errors = predicted_errors(out, label)
    check(f"{label}: the setup report gives the lattice error of the constants", errors is not None,
          "no 'lattice error of the constants' or 'constants exact' line for type 1")
    if errors is None:
        return
    check_le(f"{label}: predicted lattice error of the moduli ({', '.join(MODES)})",
             max(abs(x) for x in errors), MAX_LATTICE_ERROR, "the contract's bound at 3 spacings")
    natoms = n ** dims
    nu = v.nu + (0.02 if BREAK == "classical" else 0.0)
    rows = printed(out, "STRAIN")
    if len(rows) != len(STRAINS[dims]):
        raise RuntimeError(f"{label}: {len(rows)} strain states printed")
    for w in rows:
        key = w[0].replace("_", " ")
        e = STRAINS[dims][key]
        pe, vol, p = float(w[1]), float(w[2]), [float(x) for x in w[3:9]]
        w_cl, sig_cl = classical_response(v.model, nu, e, (0.0, 0.0, 0.0))
        w_pr, sig_pr = classical_response(v.model, nu, e, errors)
        # the virial is -P vol (LAMMPS's vol: the area in 2D; the volume is
        # unchanged by the shear); the Cauchy stress is the virial over the
        # current volume of the material, N V det F (V = area x thickness
        # in 2D); in 2D the in-plane components (the virial has no zz)
        jac = (1 + e[0]) * (1 + e[1]) * (1 + e[2])
        sig = [-x * vol / (natoms * volume(v.model) * jac) for x in p]
        if dims == 2:
            sig[2] = 0.0
        w_err = abs(pe / natoms / w_pr - 1)
        s_err = norm([x - y for x, y in zip(sig, sig_pr)]) / norm(sig_pr)
        print(f"  {key}: W = {pe / natoms:.6g} (classical {w_cl:.6g}, with the predicted lattice error "
              f"{w_pr:.6g}); sigma = {' '.join(f'{x:.5g}' for x in sig)} (predicted "
              f"{' '.join(f'{x:.5g}' for x in sig_pr)})")
        check_le(f"{label}: {key} strain: pe / atoms = 1/2 eps:C:eps, C with the predicted lattice error",
                 w_err, TOL_PREDICTED, "report's rounding and finite strain")
        check_le(f"{label}: {key} strain: virial stress = C:eps, C with the predicted lattice error", s_err,
                 TOL_PREDICTED, "report's rounding and finite strain, relative to |sigma|")
        RESULTS.append((label, f"uniform {key}: W, sigma", (w_err, s_err)))

def dynamics(v, tag):
    """Checks 5 (restart) and 6 (ranks) on a periodic block in motion."""
    label = f"{v.style} [{v.name}]"
    dims = 2 if two_d(v.model) else 3
    # a small skin: reneighboring (and exchange between ranks) every few
    # steps; restart files do not keep these settings
    neigh = f"neighbor {0.4 * A!r} bin\nneigh_modify every 1 delay 0 check yes\n"
    head = ("units si\n" + ("dimension 2\n" if dims == 2 else "") +
            "boundary p p p\natom_style peri\natom_modify map array\n" + neigh +
            f"read_data {'plate' if dims == 2 else 'block'}.data\n")
    # random displacements of 1% of a spacing, rough velocities (strains
    # grow by ~1e-3 in 40 steps), and a drift of 0.8 spacings across the
    # periodic boundaries and the subdomains
    motion = rough(0.01 * A, v.model, "displace") + rough(0.5, v.model, "velocity") + \
        "velocity all set 200.0 NULL " + ("-100.0" if dims == 3 else "NULL") + " sum yes units box\n"
    steps = "fix 1 all nve\ntimestep {dt}\nthermo 10\nthermo_style custom step ke pe\n"
    final = 'print "END $(ke:%.17g) $(pe:%.17g)"\n'

    def whole(dump_name, dt=DT):
        return head + v.deck + motion + steps.format(dt=repr(dt)) + "run 40\n" + dump(dump_name, True) + final

    out1, _ = run(whole(f"one.{tag}"), d, variables=VARS, name=f"in.one.{tag}")
    run(head + v.deck + motion + steps.format(dt=repr(DT)) + f"run 20\nwrite_restart restart.{tag}\n", d,
        variables=VARS, name=f"in.half.{tag}")
    # no pair_style, pair_coeff or timestep after read_restart: the file carries them
    out2, _ = run(f"read_restart restart.{tag}\n" + neigh + "fix 1 all nve\nthermo 10\nthermo_style custom step ke pe\n"
                  f"run {21 if BREAK == 'restart' else 20}\n" + dump(f"two.{tag}", True) + final, d,
                  variables=VARS, name=f"in.two.{tag}")
    out3, _ = run(whole(f"ranks.{tag}", DT * (1 + 1e-8) if BREAK == "ranks" else DT), d, ranks=2,
                  variables=VARS, name=f"in.ranks.{tag}")

    def compare(other, out):
        """Largest differences from the uninterrupted 1-rank run: positions
        (unwrapped) relative to max |x|, forces relative to max |f|, ke and
        pe relative."""
        a, b = read_dump(f"{d}/one.{tag}"), read_dump(f"{d}/{other}")
        if set(a) != set(b):
            return math.inf, math.inf, math.inf
        ex = max(abs(a[i][q] - b[i][q]) for i in a for q in range(3)) / max(abs(a[i][q]) for i in a for q in range(3))
        ef = max(abs(a[i][q] - b[i][q]) for i in a for q in range(3, 6)) / \
            max(abs(a[i][q]) for i in a for q in range(3, 6))
        e1 = [float(x) for x in printed(out1, "END")[0]]
        e2 = [float(x) for x in printed(out, "END")[0]]
        return ex, ef, max(abs(x - y) / abs(x) for x, y in zip(e1, e2))

    # 5. restart. The continued run adds the same terms, some in another
    # order (the atoms are re-sorted when the new run sets up): round-off,
    # amplified little over 20 stable steps. Positions, ke and pe: 1e-12
    # (measured up to 4.4e-16 and 2.4e-14). Forces are sums of bond terms
    # that each respond to the bond's extension (~5e-6 m): a difference of
    # one ulp in a position (~1e-18 m) changes them by ~2e-13 of the
    # largest (measured up to 3.3e-13), hence 1e-11. A coefficient, bond or
    # history value that the file does not restore is off by far more.
    ex, ef, ee = compare(f"two.{tag}", out2)
    check_le(f"{label}: restart at step 20: the same positions at step 40", ex, 1e-12,
             "round-off, relative to max |x|")
    check_le(f"{label}: restart at step 20: the same forces at step 40", ef, 1e-11,
             "round-off of 1 ulp in x against extensions ~5e-6 m, relative to max |f|")
    check_le(f"{label}: restart at step 20: the same ke and pe at step 40", ee, 1e-12, "round-off")
    RESULTS.append((label, "restart: x, f, ke/pe", (ex, ef, ee)))
    # 6. ranks: ghost forces summed in another order (as test_mpi.py;
    # measured up to 5.5e-16, 3.8e-13, 3.6e-14)
    check(f"{label}: 2 ranks ran, and atoms migrated between them (reneighborings > 0)",
          "on 2 procs" in out3 and log_value(out3, r"Neighbor list builds = (\d+)") > 0)
    ex, ef, ee = compare(f"ranks.{tag}", out3)
    check_le(f"{label}: 2 ranks: the same positions as 1 rank", ex, 1e-10, "round-off of reordered sums")
    check_le(f"{label}: 2 ranks: the same forces as 1 rank", ef, 1e-10, "round-off of reordered sums")
    check_le(f"{label}: 2 ranks: the same ke and pe as 1 rank", ee, 1e-10, "round-off of reordered sums")
    RESULTS.append((label, "2 ranks: x, f, ke/pe", (ex, ef, ee)))


for number, v in enumerate(cases):
    tag = f"{v.style.replace('/', '_')}.{number}"
    print(f"--- {v.style} [{v.name}] ({v.model}, nu = {v.nu:.6g})")
    for part in (statics, classical, dynamics):
        try:
            part(v, tag)
        except RuntimeError as err:     # LAMMPS stopped (its output is printed): the next part
            check(f"{v.style} [{v.name}]: {part.__name__} runs", False, str(err))

print("measured, per variant:")
for label, what, values in RESULTS:
    print(f"  {label:44s} {what:32s} " + " ".join(f"{x:.3g}" for x in values))
print(f"contract test: {len(cases)} variants of {len(materials)} material styles, {time.time() - T0:.1f} s")
finish()
