"""Quantity 6: the kink angle of a crack at initiation under mode II and
mixed mode, against the classical criterion of each failure law.

A square PMMA plate (plane stress, 1 mm thick), 2a wide, with a straight
pre-crack (fix pd/precrack) along y = 0 from beyond its left edge to its
centre, the tip at the origin, half a spacing from the nearest rows and
columns of atoms (the lattice is shifted so). The outer layer of the
plate, one horizon deep, is the grip; it follows the displacement of the
linear-elastic crack-tip field (the K-field boundary condition; plane
stress, kappa = (3 - nu) / (1 + nu), mu and nu those of the model: nu =
1/3 for pd/bond)

  u = K_I/(2mu) sqrt(r/2pi) f_I(theta) + K_II/(2mu) sqrt(r/2pi) f_II(theta)

about the tip in the reference configuration, which sets the mode mix
exactly (K_II/K_I) and its scale by G = (K_I^2 + K_II^2)/E. Load steps:
G grows from 0.5 G_c by 0.05 G_c per step; each step moves every atom by
the increment of the K-field (the grips exactly, the inside as the
relaxation's first guess: moving the grips alone by a finite step
strains the bonds at the grip's edge by the whole step, which breaks
them before the inside follows) and relaxes the inside to equilibrium
with fix pd/adr (relative residual 1e-4), until new damage reaches 4
horizons from the tip. Broken bonds never push (`recontact none`): the
criteria assume traction-free crack faces, and sliding faces must not
drag each other.

Dynamic loading ('load': 'dynamic'): after the same first step, K grows
at a constant rate, G from 0.5 to 3 G_c (K by 1.03 K_c) in 'crossings'
(40) times the time a bar wave takes across the plate, the grips moving
at the field's rate and the inside by its equations of motion (fix nve
at fix pd/timestep's step), until the same reach. How slow is slow
enough (pd/ordinary energy, 4 spacings, a/h = 50): -66.7, -67.9 and
-68.2 deg at 20, 40 and 80 crossings, against -68.4 quasi-static.

Sign convention: K_II > 0 moves the upper face (y > 0) in +x relative
to the lower one; angles are counter-clockwise from +x, the direction of
the pre-crack, so the maximum tangential stress (MTS, Erdogan-Sih) kink
solves K_I sin(theta) + K_II (3 cos(theta) - 1) = 0 on the side of
negative theta: -70.53 deg for pure mode II (K_I = 0), -53.13 deg for
K_II/K_I = 1. The maximum energy release rate criterion gives 75-77 deg
in magnitude for pure mode II (Hussain-Pu-Underwood 1974: 75.2 deg;
Wu 1978 and others up to 77 deg).

Which criterion a failure law follows: the energy law breaks bonds by
their energy, the stretch law by their strain. A critical stretch is a
strain criterion, and its classical counterpart is the maximum
tangential strain (Chang 1981): the kink where the hoop strain
eps_tt = (sigma_tt - nu sigma_rr) / E (plane stress) is largest, which
depends on nu: -63.6 deg for pure mode II and -49.7 deg for K_II/K_I = 1
at nu = 1/3 (pd/bond's plane stress). The error is measured against the
law's own criterion: MTS for the energy law, the maximum tangential
strain for the stretch law; both angles are reported.

The measured angle: the atoms whose damage grew by at least 0.2 since
the pre-crack was cut, the atoms beside the new crack (square lattice, 3
spacings: an atom half a spacing from a straight crack along the rows
loses 39% of its bonds, one and a half spacings away 21%, two and a half
4%), at 1 to 4 horizons from the tip (inside one horizon the atoms are
damaged by the pre-crack's own tip in every direction; the first few
horizons are the initiation the criteria speak of, farther out the path
turns as it meets the grips' field). theta is the direction of the
principal axis of their second moments (weights: the damage growth)
about their weighted centroid, oriented away from the tip: a
straight-line fit, which needs no position of the peridynamic tip (known
only to within a spacing or two: the new crack starts a spacing or so
ahead of the cut's end and below it, which turns a line drawn from the
tip by some 5-10 deg at 2 horizons). The direction from the tip to the
centroid is reported too (theta_tip). Error: |theta - theta_criterion|
in degrees.

On a lattice plate the path is decided by near-ties between bonds: a
change of the bond weights at round-off, or every particle moved by a
millionth of a spacing, moves the angle by several degrees at 4
spacings and a/h = 100-200. One run is one sample of that scatter: the
full sweep runs three such perturbed copies ('perturb') of the 4-, 5-
and 6-spacing plates, and the recommendation counts them with the plate."""
import math
import os
import deck

NAME = "kink"
PRIMARY = "err"
TITLE = "Crack kink angle at initiation (mode II, mixed) against the classical criteria"
ERROR_UNIT = "degrees from the law's criterion (MTS or the maximum tangential strain)"
TARGETS = (10.0, 5.0, 3.0, 2.0, 1.0)     # degrees: the report's recommendation targets
COST = "wall"
H = 5.0e-4              # spacing (m)
THRESHOLD = 0.2         # damage growth that marks an atom beside the new crack
R_IN, R_OUT, R_STOP = 1.0, 4.0, 4.0     # horizons from the tip
G0, DG, NSTEPS = 0.5, 0.05, 120         # load: G/G_c at step 1, per step, most steps
G_END, CROSSINGS = 3.0, 40      # dynamic load: G/G_c at the ramp's end, its time in wave crossings
TOL = 1e-4
# one load step: the grips' increment of the K-field, relaxed by fix pd/adr
# (fix halt ends the run at TOL)
LOAD_STEP = "displace_atoms all move v_dx v_dy 0 units box\nrun 50000\nrun 0 post no\n"


def mts_angle(ratio):
    """The MTS kink angle (deg) for K_II/K_I = ratio (inf: pure mode II),
    K_II > 0: the root of K_I sin t + K_II (3 cos t - 1) = 0 that
    maximises the hoop stress, t = 2 atan((K_I - sqrt(K_I^2 + 8 K_II^2)) / (4 K_II))."""
    ki, kii = (0.0, 1.0) if math.isinf(ratio) else (1.0, ratio)
    return math.degrees(2 * math.atan((ki - math.sqrt(ki * ki + 8 * kii * kii)) / (4 * kii)))


def hoop(t, ki, kii):
    """(sigma_rr, sigma_tt) of the Williams field at angle t, times sqrt(2 pi r)."""
    srr = 0.25 * (ki * (5 * math.cos(t / 2) - math.cos(1.5 * t)) + kii * (-5 * math.sin(t / 2) + 3 * math.sin(1.5 * t)))
    stt = 0.25 * (ki * (3 * math.cos(t / 2) + math.cos(1.5 * t)) - 3 * kii * (math.sin(t / 2) + math.sin(1.5 * t)))
    return srr, stt


def strain_angle(ratio, nu):
    """The maximum tangential strain kink angle (deg, plane stress) for
    K_II/K_I = ratio: the largest sigma_tt - nu sigma_rr, by a scan in
    0.1 deg steps refined by golden sections."""
    ki, kii = (0.0, 1.0) if math.isinf(ratio) else (1.0, ratio)
    f = lambda t: (lambda s: s[1] - nu * s[0])(hoop(t, ki, kii))
    t0 = max((math.radians(k / 10) for k in range(-1799, 1800)), key=f)
    a, b, g = t0 - math.radians(0.1), t0 + math.radians(0.1), (math.sqrt(5) - 1) / 2
    for _ in range(60):
        c, d = b - g * (b - a), a + g * (b - a)
        a, b = (a, d) if f(c) > f(d) else (c, b)
    return math.degrees(0.5 * (a + b))


def criterion(case):
    """(name, angle) of the criterion the case's failure law follows."""
    ratio = ratio_of(case)
    if case["law"] == "stretch":
        return "max strain", strain_angle(ratio, deck.poisson(case))
    return "MTS", mts_angle(ratio)


def cases(mode):
    """smoke: pure mode II, pd/ordinary energy, a/h = 25 and 50 (the
    recommendation takes two resolutions; about 10 s); short:
    pure mode II, square lattice, 3 spacings at a/h = 25 and 50 and 4
    spacings at a/h = 50, pd/ordinary energy and pd/bond stretch (about
    40 s); full: also a/h = 100 at 3 and 4 spacings, 200 at 4, K_II/K_I =
    1 at 4 spacings and a/h = 50, 100 and 200, hex at 5 spacings and a/h =
    100 and 200, and, at a/h = 25, hex, three jittered plates and
    K_II/K_I = 1, the energy law's uniform profile at 4 spacings, a/h =
    100 and 200, and three copies of each law's 4-spacing plates at a/h =
    100 and 200, mode II and K_II/K_I = 1, perturbed by 1e-6 spacings;
    with three such copies each, at a/h = 100 and 200: the stretch law's
    5-spacing plate, the energy law's 6-spacing plate in both modes, and
    both dynamically loaded in mode II; three jittered plates of each law
    at 6 spacings, a/h = 100 and 200 (about 2.8 hours of runs, 85
    minutes on two cores)."""
    if mode == "smoke":
        return [{"style": "pd/ordinary", "law": "energy", "lattice": "square", "ratio": 3, "n": n, "mix": "II"}
                for n in (25, 50)]
    out = []
    laws = (("pd/ordinary", "energy"), ("pd/bond", "stretch"))
    for style, law in laws:
        for n in ((25, 50) if mode == "short" else (25, 50, 100)):
            out.append({"style": style, "law": law, "lattice": "square", "ratio": 3, "n": n, "mix": "II"})
        # at 3 spacings the stretch law's path follows the square lattice's
        # diagonal; at 4 it converges to its criterion
        # (a/h = 200: the path converged to 3 degrees, about 4 minutes each)
        for n in ((50,) if mode == "short" else (50, 100, 200)):
            out.append({"style": style, "law": law, "lattice": "square", "ratio": 4, "n": n, "mix": "II"})
    if mode == "full":
        for style, law in laws:
            for n in (50, 100, 200):
                out.append({"style": style, "law": law, "lattice": "square", "ratio": 4, "n": n, "mix": 1.0})
            # at 3 and 4 spacings the hexagonal lattice's path is not converged
            for n in (100, 200):
                out.append({"style": style, "law": law, "lattice": "hex", "ratio": 5, "n": n, "mix": "II"})
            out.append({"style": style, "law": law, "lattice": "hex", "ratio": 3, "n": 25, "mix": "II"})
            # three arrangements: one jittered plate is one sample of the path's scatter
            for seed in (4711, 1, 2):
                out.append({"style": style, "law": law, "lattice": "square-jitter", "ratio": 3, "n": 25, "mix": "II",
                            "seed": seed})
            out.append({"style": style, "law": law, "lattice": "square", "ratio": 3, "n": 25, "mix": 1.0})
        for n in (100, 200):
            out.append({"style": "pd/ordinary", "law": "energy", "profile": "uniform", "lattice": "square", "ratio": 4,
                        "n": n, "mix": "II"})
        # the stretch law at 5 spacings, where its mode II path holds to 3
        # degrees over the copies too (the energy law's does not: 5.8)
        for n in (100, 200):
            for seed in (None, 1, 2, 3):
                case = {"style": "pd/bond", "law": "stretch", "lattice": "square", "ratio": 5, "n": n, "mix": "II"}
                out.append(case if seed is None else dict(case, perturb=1e-6, seed=seed))
        # the energy law at 6 spacings, where its path holds to 3 degrees
        # of MTS in both modes over the copies
        for mix in ("II", 1.0):
            for n in (100, 200):
                for seed in (None, 1, 2, 3):
                    case = {"style": "pd/ordinary", "law": "energy", "lattice": "square", "ratio": 6, "n": n,
                            "mix": mix}
                    out.append(case if seed is None else dict(case, perturb=1e-6, seed=seed))
        # the jittered plates at 6 spacings: no lattice direction to lock on
        for style, law in laws:
            for n in (100, 200):
                for seed in (4711, 1, 2):
                    out.append({"style": style, "law": law, "lattice": "square-jitter", "ratio": 6, "n": n,
                                "mix": "II", "seed": seed})
        # dynamic loading (slow: G from 0.5 to 3 G_c in 40 wave crossings) at
        # the settings that hold to 3 degrees quasi-static
        for style, law, ratio in (("pd/bond", "stretch", 5), ("pd/ordinary", "energy", 6)):
            for n in (100, 200):
                for seed in (None, 1, 2, 3):
                    case = {"style": style, "law": law, "lattice": "square", "ratio": ratio, "n": n, "mix": "II",
                            "load": "dynamic"}
                    out.append(case if seed is None else dict(case, perturb=1e-6, seed=seed))
        # the 4-spacing plates perturbed by 1e-6 spacings: the path's
        # scatter under a change no measurement of the plate could see
        for style, law in laws:
            for mix in ("II", 1.0):
                for n in (100, 200):
                    for seed in (1, 2, 3):
                        out.append({"style": style, "law": law, "lattice": "square", "ratio": 4, "n": n, "mix": mix,
                                    "perturb": 1e-6, "seed": seed})
    return out


def ratio_of(case):
    return math.inf if case["mix"] == "II" else float(case["mix"])


def group(case):
    return "mode II" if case["mix"] == "II" else f"K_II/K_I {case['mix']:g}"


def family(case):
    return curve(case) + (f" perturbed {case['perturb']:g}" if "perturb" in case else "") + \
        (f" seed {case['seed']}" if "seed" in case else "")


def curve(case):
    """The plots' curve: a plate's perturbed copies and a jittered plate's
    seeds are points of it, not curves of their own."""
    return f"{case['style']} {case['law']}{deck.profile_words(case)} {case['lattice']} a/h {case['n']}" + \
        (" dynamic" if case.get("load") == "dynamic" else "")


def crossings(case):
    """The dynamic ramp's time in wave crossings of the plate."""
    return case.get("crossings", CROSSINGS)


def setting(case):
    """The measured setting as deck keys, the plate's size as a comment."""
    checked = f" or more (its path checked against {case['checked']})" if case.get("checked") else ""
    load = (f"; dynamic: G grows from 0.5 to 3 G_c in {crossings(case)} wave crossings of the plate"
            if case.get("load") == "dynamic" else "")
    return dict(case, h=H, recontact="none", note=f"crack length {case['n']} spacings{checked}{load}")


# A path within this of one of the plate's lattice directions (square:
# every 45 degrees, hex: every 30) follows the lattice, not a criterion:
# the hexagonal lattice at 5 spacings sends both laws along -61.0, the
# uniform profile the square lattice's columns at -89.7.
LOCKED = 1.5
LATTICE_STEP = {"square": 45.0, "hex": 30.0}


def locked(case, theta):
    """Whether a kink angle lies along one of its plate's lattice directions."""
    step = LATTICE_STEP[deck.base_lattice(case["lattice"])]
    return abs(theta - step * round(theta / step)) < LOCKED


def trusted(points):
    """The points the recommendation may pick, (cost, error, row): a
    setting (a case but its crack length and seed) measured at a/h = n and
    2n, with the worst of its errors at both (over every seed) and of the
    angle's move between them as its error, and the cost of its run at n;
    copies of a lattice plate perturbed by a millionth of a spacing count
    as its seeds; a setting whose path runs along a lattice direction at
    either resolution (locked) is none. A single run is not a
    recommendation: at 4 spacings the perturbed copies of one plate
    scatter by 2-10 degrees, and one jittered plate is one sample of a
    10-22 degree scatter; a setting without its next resolution measured
    has not shown that its path converged."""
    by = {}
    for c, e, r in points:
        key = tuple(sorted((k, str(v)) for k, v in r["case"].items() if k not in ("n", "seed", "perturb")))
        by.setdefault(key, {}).setdefault(r["case"]["n"], []).append((c, e, r))
    out = []
    for runs in by.values():
        for n, here in runs.items():
            there = runs.get(2 * n)
            if not there or any(locked(p[2]["case"], p[2]["metrics"]["theta"]) for p in here + there):
                continue
            move = max(abs(a[2]["metrics"]["theta"] - b[2]["metrics"]["theta"]) for a in here for b in there)
            err = max([p[1] for p in here + there] + [move])
            row = next((p[2] for p in here if "perturb" not in p[2]["case"]), here[0][2])
            case = dict(row["case"])
            if "perturb" in case:    # (only perturbed copies measured: the plate is the setting)
                del case["perturb"], case["seed"]
            out.append((max(p[0] for p in here), err, dict(row, case=dict(case, checked=2 * n))))
    return out


def plate(case):
    """The deck: plate, pre-crack, K-field grips, load steps; writes
    kink.dump (reference positions and damage growth) at the end."""
    h, n, lattice = H, case["n"], case["lattice"]
    mat = deck.material()
    E, gc = mat["E"], mat["Gc"]
    nu = deck.poisson(case)
    mu = E / (2 * (1 + nu))
    kappa = (3 - nu) / (1 + nu)
    ratio = ratio_of(case)
    ci, cii = (0.0, 1.0) if math.isinf(ratio) else (1 / math.hypot(1, ratio), ratio / math.hypot(1, ratio))
    kc = math.sqrt(E * gc)              # plane stress: G = K^2 / E
    half = n * h                        # crack length = plate half-width
    delta = case["ratio"] * h
    # the rows and columns of atoms half a spacing off the crack line and
    # the tip (square: cell h x h; hex: rows a sqrt(3)/2 apart)
    origin = {"square": "0.5 0.5 0.0", "hex": "0.25 0.25 0.0"}[deck.base_lattice(lattice)]
    text = deck.header(lattice, h, "s s p").rstrip("\n") + f" origin {origin}\n"
    text += (f"region box block {-half!r} {half!r} {-half!r} {half!r} {-0.5 * h!r} {0.5 * h!r} units box\n"
             "create_box 1 box\ncreate_atoms 1 box\n")
    # a lattice plate perturbed by a millionth of a spacing: how far the
    # path moves under a change no measurement of the plate could see
    shaken = lattice + "-jitter" if case.get("perturb") else lattice
    text += deck.jitter(shaken, h, "s s p", seed=case.get("seed", 4711), amplitude=case.get("perturb", 0.2))
    text += f"set group all density {mat['density']}\nset group all volume {deck.volume(lattice, h)!r}\n"
    text += deck.pair_lines(dict(case, recontact="none"), h, fail=deck.fail_words(case, gc))
    text += f"fix crack all pd/precrack segment {-2 * half!r} 0.0 {1e-3 * h!r} 0.0\n"
    inner = half - delta
    text += (f"region inner block {-inner!r} {inner!r} {-inner!r} {inner!r} INF INF units box\n"
             "group inner region inner\ngroup grips subtract all inner\n"
             "compute dmg all pd/damage\n"
             "run 0\n"                          # bonds built and cut, undeformed
             # reference positions and the pre-crack's damage
             "fix ref all store/state 0 x y c_dmg\n"
             "variable X atom f_ref[1]\nvariable Y atom f_ref[2]\n"
             "variable r atom sqrt(v_X*v_X+v_Y*v_Y)\nvariable t atom atan2(v_Y,v_X)\n"
             f"variable a atom sqrt(v_r/(2*PI))/{2 * mu!r}\n"
             "variable c atom cos(0.5*v_t)\nvariable s atom sin(0.5*v_t)\n"
             # the K-field (Williams) per unit K_I and K_II, plane stress
             f"variable uxI atom v_a*v_c*({kappa - 1!r}+2*v_s*v_s)\n"
             f"variable uyI atom v_a*v_s*({kappa + 1!r}-2*v_c*v_c)\n"
             f"variable uxII atom v_a*v_s*({kappa + 1!r}+2*v_c*v_c)\n"
             f"variable uyII atom -v_a*v_c*({kappa - 1!r}-2*v_s*v_s)\n"
             f"variable K equal sqrt({G0!r}+{DG!r}*(v_k-1))*{kc!r}\n"
             f"variable dK equal v_K-sqrt({G0!r}+{DG!r}*(v_k-2))*{kc!r}*(v_k>1)\n"
             f"variable dx atom v_dK*({ci!r}*v_uxI+{cii!r}*v_uxII)\n"
             f"variable dy atom v_dK*({ci!r}*v_uyI+{cii!r}*v_uyII)\n"
             "variable dd atom c_dmg-f_ref[3]\n"
             f"variable far atom v_r*(v_dd>={THRESHOLD!r})\n"
             "compute reach all reduce max v_far\n"
             f"fix adr inner pd/adr tol {TOL!r}\nfix 2d all enforce2d\n"
             "variable res equal f_adr[1]\n"
             f"fix halt all halt 1 v_res < {TOL!r} error continue message no\n"
             "thermo_style custom step f_adr[1] c_reach\nthermo 5000\n")
    final = "write_dump all custom kink.dump id f_ref[1] f_ref[2] v_dd modify format float %.10g\n"
    if case.get("load") == "dynamic":
        return text + ramp(case, delta, ci, cii, kc, E, mat["density"]) + final
    text += (f"variable k loop {NSTEPS}\n"
             "label step\n" + LOAD_STEP +
             f"print \"KINK $k $(v_K/{kc!r}:%.4f) $(c_reach/{delta!r}:%.3f) $(f_adr[5]) $(f_adr[1]:%.2e)\"\n"
             f"if \"$(c_reach) > {R_STOP * delta!r}\" then \"jump SELF done\"\n"
             "next k\njump SELF step\n"
             "label done\n")
    return text + final


def ramp(case, delta, ci, cii, kc, E, rho):
    """The dynamic load: step 1 as the quasi-static one (the K-field at G0,
    relaxed), then K grows at a constant rate, G from G0 to G_END in
    'crossings' times the time a bar wave takes across the plate; the grips
    follow the K-field at its rate, the inside the equations of motion (fix
    nve, the step from fix pd/timestep), until new damage reaches R_STOP
    horizons from the tip."""
    span = crossings(case) * 2 * case["n"] * H / math.sqrt(E / rho)
    k0, k1 = math.sqrt(G0) * kc, math.sqrt(G_END) * kc
    kdot = (k1 - k0) / span
    row = f"$(v_Kt/{kc!r}:%.4f) $(c_reach/{delta!r}:%.3f) $(step) 0"
    return ("variable k equal 1\n" + LOAD_STEP +
            "unfix halt\nunfix adr\nvelocity all set 0 0 0\n"
            "variable t0 equal $(time)\n"
            f"variable Kt equal {k0!r}+{kdot!r}*(time-v_t0)\n"
            f"print \"KINK 1 {row}\"\n"
            # the grips at the K-field's rate: no force on them, their
            # velocity kept (fix move would forbid fix pd/timestep)
            f"variable gvx atom {kdot!r}*({ci!r}*v_uxI+{cii!r}*v_uxII)\n"
            f"variable gvy atom {kdot!r}*({ci!r}*v_uyI+{cii!r}*v_uyII)\n"
            "velocity grips set v_gvx v_gvy 0 units box\n"
            "fix grip grips setforce 0 0 0\n"
            "fix nve all nve\nfix ts all pd/timestep\n"
            f"variable done equal (c_reach>{R_STOP * delta!r})+(time>v_t0+{span!r})\n"
            "fix stop all halt 200 v_done > 0.5 error continue message no\n"
            f"fix rows all print 200 \"KINK 2 {row}\" screen yes\n"
            "thermo_style custom step time dt c_reach\nthermo 2000\n"
            "run 100000000\n"
            f"print \"KINK 3 {row}\"\n")


def read_dump(path):
    rows, inside = [], False
    for line in open(path):
        if line.startswith("ITEM: ATOMS"):
            inside = True
            continue
        if inside and line.strip():
            w = line.split()
            rows.append((float(w[1]), float(w[2]), float(w[3])))
    return rows


def angles(rows, delta):
    """(theta, theta_tip, atoms): the line fit and the direction from the tip,
    in degrees, over the atoms of the new crack 1-4 horizons from the tip."""
    pts = [(x, y, d) for x, y, d in rows if d >= THRESHOLD and R_IN * delta <= math.hypot(x, y) <= R_OUT * delta]
    if len(pts) < 3:
        return None, None, len(pts)
    w = sum(p[2] for p in pts)
    cx, cy = sum(p[0] * p[2] for p in pts) / w, sum(p[1] * p[2] for p in pts) / w
    sxx = sum(p[2] * (p[0] - cx) ** 2 for p in pts)
    syy = sum(p[2] * (p[1] - cy) ** 2 for p in pts)
    sxy = sum(p[2] * (p[0] - cx) * (p[1] - cy) for p in pts)
    phi = 0.5 * math.atan2(2 * sxy, sxx - syy)          # principal axis, modulo 180 deg
    ex, ey = math.cos(phi), math.sin(phi)
    if ex * cx + ey * cy < 0:                           # pointing away from the tip
        ex, ey = -ex, -ey
    return math.degrees(math.atan2(ey, ex)), math.degrees(math.atan2(cy, cx)), len(pts)


def measure(case, lmp, workdir):
    delta = case["ratio"] * H
    out, t = deck.run(lmp, plate(case), workdir, name="in.kink")
    steps = deck.printed(out, "KINK")
    if not steps or float(steps[-1][2]) <= R_STOP:
        raise RuntimeError(f"no crack growth to {R_STOP} horizons after {len(steps)} load steps"
                           + (f" (G/G_c {float(steps[-1][1]) ** 2:.3f}, reach {steps[-1][2]} horizons)" if steps else ""))
    rows = read_dump(os.path.join(workdir, "kink.dump"))
    theta, theta_tip, count = angles(rows, delta)
    if theta is None:
        raise RuntimeError(f"only {count} atoms of new crack 1-4 horizons from the tip")
    # the load step of initiation: the first with new damage anywhere
    first = next((s for s in steps if float(s[2]) > 0), steps[-1])
    mts = mts_angle(ratio_of(case))
    _, ref = criterion(case)
    iters = int(float(steps[-1][3]))
    return {"err": abs(theta - ref), "theta": theta, "theta_tip": theta_tip, "theta_mts": mts,
            "theta_criterion": ref, "err_tip": abs(theta_tip - ref), "atoms": count,
            "G_init": float(first[1]) ** 2, "G_final": float(steps[-1][1]) ** 2, "load_steps": len(steps),
            "iterations": iters, "seconds": sum(t["loop"]), "particle_steps": len(rows) * iters, "wall": t["wall"]}


def note(rows):
    ok = [r for r in rows if r.get("metrics")]
    if not ok:
        return ""
    lines = ["Kink angle (deg; counter-clockwise from the pre-crack's direction, K_II > 0), measured "
             "by the line fit and from the tip, against the failure law's criterion (the energy law: "
             "MTS; the stretch law: maximum tangential strain) and MTS; G/G_c (plane stress, K-field) "
             "at the first new damage:", "",
             "| setting | mix | theta | theta_tip | criterion | theta - criterion | MTS | G_init/G_c | run time (s) |",
             "|---|---|---|---|---|---|---|---|---|"]
    for r in ok:
        m = r["metrics"]
        name, ref = criterion(r["case"])
        lines.append(f"| {r['family']} ratio {r['case']['ratio']} | {group(r['case'])} | {m['theta']:.1f} | "
                     f"{m['theta_tip']:.1f} | {name} {ref:.1f} | {m['theta'] - ref:+.1f} | "
                     f"{m['theta_mts']:.1f} | {m['G_init']:.2f} | {m['wall']:.0f} |")
    return "\n".join(lines)
