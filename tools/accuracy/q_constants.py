"""Quantity 2: elastic constants under every uniform strain mode.

A periodic block (all families complete) is strained uniformly by
change_box ... remap, by +eps and by -eps (|eps| = 1e-4), then run 0.
The mean energy density of the two, pe / atoms, is compared with
1/2 eps:C:eps and half the difference of the two virial stresses with
C:eps: the terms of odd (energy) and even (stress) order in eps cancel, so
finite-strain terms are of relative order 1e-8, and an exact discrete
model (pd/corr) meets the classical constants to that order. C is
the classical constants of the material the pair lines
define (PMMA of potentials/materials.pd; bond-based: its fixed Poisson's
ratio). Modes: the axial strains, the shears (xy, xz, yz: simple shear by
box tilt), the 45-degree rotated shear of the xy plane (eps_xx = -eps_yy)
and the dilatation. pd/bond and pd/ordinary run with their default
directional correction (each family's fourth moment made isotropic:
exact on every lattice), and with `directional_correction no` for the
default influence function (curves `... directional no`: the lattice's
own anisotropy).

Cost: nve steps on the same block, after the strains (at least 20, and at
least 1e5 particle-steps, at most 2000 steps: a small 2D block needs many
steps for a Loop time above the timer's noise); seconds per particle-step
from that run's Loop time."""
import math
import deck

NAME = "constants"
PRIMARY = "err"
TITLE = "Elastic constants (worst mode, energy and stress)"
E0 = 1.0e-4
COST_STEPS = 20


def modes(dims):
    """name -> small strain tensor (symmetric, as [[...]])."""
    out = {}
    axes = "xyz"[:dims]
    for i, a in enumerate(axes):
        e = [[0.0] * 3 for _ in range(3)]
        e[i][i] = E0
        out[f"axial_{a}"] = e
    for i, j in ([(0, 1)] if dims == 2 else [(0, 1), (0, 2), (1, 2)]):
        e = [[0.0] * 3 for _ in range(3)]
        e[i][j] = e[j][i] = E0 / 2           # simple shear of E0: tensor shear E0 / 2
        out[f"shear_{axes[i]}{axes[j]}"] = e
    e = [[0.0] * 3 for _ in range(3)]
    e[0][0], e[1][1] = E0 / 2, -E0 / 2         # the xy shear of a frame turned by 45 degrees
    out["shear_45"] = e
    e = [[E0 if i == j and i < dims else 0.0 for j in range(3)] for i in range(3)]
    out["dilatation"] = e
    return out


def box_change(e, lengths):
    """change_box arguments for the strain e from the reference box."""
    dims = len(lengths)
    parts = [f"{'xyz'[i]} final 0 {lengths[i] * (1 + e[i][i])!r}" for i in range(dims)]
    # simple shear u_x = gamma y: tilt xy = gamma L_y, gamma = 2 eps_xy
    parts.append(f"xy final {2 * e[0][1] * lengths[1] * (1 + e[1][1])!r}")
    if dims == 3:
        parts.append(f"xz final {2 * e[0][2] * lengths[2]!r}")
        parts.append(f"yz final {2 * e[1][2] * lengths[2]!r}")
    return "change_box all " + " ".join(parts) + " remap units box\n"


def cases(mode):
    """full: where a curve is resolved by fewer points, fewer points
    (measured): pd/corr is exact at every ratio and on every lattice (3
    and 4 spacings), the jittered lattices and plane strain follow their
    regular and plane stress curves (fewer ratios, the default
    influence), and the three other influence functions are drawn at 3
    and 4 spacings only."""
    lat3 = ["sc"] if mode == "smoke" else (["sc", "fcc"] if mode == "short" else ["sc", "fcc", "sc-jitter"])
    lat2 = ["square"] if mode == "smoke" else (["square", "hex"] if mode == "short" else
                                               ["square", "hex", "square-jitter"])
    ratios = {"smoke": [3], "short": [3, 4, 6], "full": [2.5, 3, 4, 6]}[mode]
    infl = {"smoke": [None], "short": [None, "constant"], "full": [None, "constant", "lps", "gaussian", "tupek"]}[mode]
    out = []
    for style in ("pd/bond", "pd/ordinary", "pd/corr"):
        for lattice in lat3 + lat2:
            planes = ["3d"] if deck.dims_of(lattice) == 3 else (
                ["plane stress"] if mode == "smoke" else ["plane stress", "plane strain"])
            for plane in planes:
                for ratio in ratios:
                    # the second influence function: the other of the 3D (inverse) and
                    # 2D (constant) defaults
                    other = {"constant": "inverse"} if plane != "3d" else {}
                    for k, influence in enumerate([other.get(i, i) for i in infl] if style == "pd/ordinary" else [None]):
                        if mode == "smoke" and style != "pd/bond" and lattice != "sc":
                            continue
                        if mode == "short" and style == "pd/corr" and ratio > 4 and plane == "3d":
                            continue        # 10 s each, and exact at every ratio
                        if mode == "full" and not full_case(style, lattice, plane, ratio, k):
                            continue
                        c = {"style": style, "lattice": lattice, "ratio": ratio, "quadrature": "point"}
                        if plane != "3d":
                            c["plane"] = plane
                        if influence:
                            c["influence"] = influence
                        out.append(c)
                        # without the directional correction: the lattice's own anisotropy
                        if mode != "smoke" and style != "pd/corr" and k == 0:
                            out.append(dict(c, directional=False))
    return out


def full_case(style, lattice, plane, ratio, k):
    """Whether the full sweep measures a setting (k: the influence
    function's place, 0 the default, 1 the other one)."""
    if style == "pd/corr":
        return ratio in (3, 4) and (not lattice.endswith("-jitter") or ratio == 3)
    if lattice.endswith("-jitter") or plane == "plane strain":
        return k == 0 and ratio in (3, 4, 6)
    return k <= 1 or ratio in (3, 4)


def QUADRATURE(case):
    """Partial-volume copies of every case but pd/corr's beyond 3
    spacings (exact with either quadrature)."""
    return case["style"] != "pd/corr" or case["ratio"] == 3


def group(case):
    """Recommendations are made within a model: 3D, plane stress, plane strain."""
    return case.get("plane", "3d")


def family(case):
    """The curve a case belongs to: everything but the horizon ratio."""
    return " ".join(str(case[k]) for k in ("style", "lattice", "plane", "influence", "quadrature") if case.get(k)) + \
        (" directional no" if case.get("directional") is False else "")


def measure(case, lmp, workdir):
    h = 1.0e-3
    dims = deck.dims_of(case["lattice"])
    delta = case["ratio"] * h
    # longer than twice the bonds' reach (with partial quadrature: the
    # horizon and half a cell diagonal)
    text, natoms, lengths = deck.periodic_block(case["lattice"], h, 2 * (delta + h))
    V = deck.volume(case["lattice"], h)
    text += deck.pair_lines(case, h)
    text += ("compute pv all pressure NULL virial\n"
             "thermo_style custom step pe c_pv[1] c_pv[2] c_pv[3] c_pv[4] c_pv[5] c_pv[6]\nthermo_modify format float %.15g\nrun 0\n")
    ms = modes(dims)
    for name, e in ms.items():
        for sign in (1, -1):
            text += box_change([[sign * x for x in r] for r in e], lengths) + "run 0 post no\n"
            text += f'print "MODE {name} {sign} $(pe:%.17g) $(vol:%.17g) ' + \
                    " ".join(f"$(c_pv[{i}]:%.17g)" for i in range(1, 7)) + '"\n'
    zero = [[0.0] * 3 for _ in range(3)]
    text += box_change(zero, lengths)
    steps = max(COST_STEPS, min(2000, math.ceil(1e5 / natoms)))
    text += f"fix nve all nve\ntimestep 1e-9\nthermo {steps}\nrun {steps}\n"
    out, t = deck.run(lmp, text, workdir, name="in.constants")
    lam, mu = deck.classical_lame(case)
    res = {}
    worst = 0.0
    rows = {(r[0], int(r[1])): r[2:] for r in deck.printed(out, "MODE")}
    for name, e in ms.items():
        if (name, 1) not in rows or (name, -1) not in rows:
            raise RuntimeError(f"constants: mode {name} not printed")
        tr = sum(e[i][i] for i in range(3))
        w_cl = lam / 2 * tr * tr + mu * sum(e[i][j] ** 2 for i in range(3) for j in range(3))
        sig_cl = [lam * tr * (i == j) + 2 * mu * e[i][j] for i, j in ((0, 0), (1, 1), (2, 2), (0, 1), (0, 2), (1, 2))]
        pe, sig = 0.0, [0.0] * 6
        for sign in (1, -1):
            row = [float(x) for x in rows[(name, sign)]]
            jac = (1 + sign * e[0][0]) * (1 + sign * e[1][1]) * (1 + sign * e[2][2])
            pe += row[0] / 2
            sig = [s + sign * (-x * row[1] / (natoms * V * jac)) / 2 for s, x in zip(sig, row[2:8])]
        comps = [0, 1, 3] if dims == 2 else range(6)
        # weights of the off-diagonal components in the tensor norm
        wts = [1, 1, 1, 2, 2, 2]
        num = math.sqrt(sum(wts[k] * (sig[k] - sig_cl[k]) ** 2 for k in comps))
        den = math.sqrt(sum(wts[k] * sig_cl[k] ** 2 for k in comps))
        w_err = pe / natoms / w_cl - 1
        s_err = num / den
        res[f"W_{name}"] = w_err
        res[f"sigma_{name}"] = s_err
        worst = max(worst, abs(w_err), s_err)
    if len(res) != 2 * len(ms):
        raise RuntimeError(f"constants: {len(res) // 2} of {len(ms)} modes printed")
    res["err"] = worst
    res["seconds"] = t["loop"][-1]
    res["particle_steps"] = natoms * steps
    res["wall"] = t["wall"]
    res["natoms"] = natoms
    return res
