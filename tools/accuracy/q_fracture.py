"""Quantity 3: fracture energy released across a plane, by orientation.

A band of material around a plane (normal n at 0, 22.5 and 45 degrees to
the lattice x axis, in the xy plane; and at 0 degrees in a jittered
arrangement, every particle moved by up to 0.2 spacings) is separated
quasi-statically: its two halves move apart rigidly along n (fix move),
the opening growing geometrically by a factor 1 + r per step from 1e-3
spacings to 1.05 horizons, by which every bond across the plane has
broken. The energy the bonds dissipated (compute pd/fracture, per atom,
summed over a window of the plane 2 horizons away from the band's ends;
where the plane has rows of atoms, the window holds whole rows, else it
is three times longer, 36 spacings or 12 horizons; the jittered
arrangement's window is three times longer too, 37 rows: its G is a mean
over the atoms' offsets, and one arrangement's 13 rows scattered it by
+-5%)
divided by the window's area is compared with G_c (PMMA, 400 J/m^2),
for `fail stretch Gc` and `fail energy Gc`. A bond breaks in the first
step its stretch (or energy) exceeds the critical one, at most a factor
1 + r past it: the release is biased up by about r (0.4%).

The band is 2 horizons + 1 spacing thick on each side, so every atom
whose bonds cross the plane has its complete family. 3D: periodic along
z (the plane contains z). Error: worst orientation, |G / G_c - 1|."""
import math
import deck

NAME = "fracture"
PRIMARY = "err"
TITLE = "Fracture energy released across a plane (worst of 4 orientations)"
ORIENTATIONS = ("0", "22.5", "45", "jitter")
H = 5.0e-4


def cases(mode):
    """smoke: one 2D case; short: square at 3 and 4 spacings, sc at 3;
    full: square at 2.5-5 spacings, hex at 3-5, sc at 3 (pd/bond also
    at 4), with pd/ordinary's stretch law in 2D (3D at 3 spacings costs
    about half a minute per case). Opening steps of 0.4% in every mode:
    their bias (about +0.4%) is below the smallest target."""
    if mode == "smoke":
        return [{"style": "pd/bond", "law": "stretch", "lattice": "square", "ratio": 3, "r": 0.004, "quadrature": "point"}]
    ratios = {"short": {"square": [3, 4], "sc": [3]},
              "full": {"square": [2.5, 3, 4, 5], "hex": [3, 4, 5], "sc": [3, 4]}}[mode]
    out = []
    for lattice, rs in ratios.items():
        for style, law, infl in (("pd/bond", "stretch", None), ("pd/ordinary", "energy", None),
                                 ("pd/ordinary", "energy", "constant" if deck.dims_of(lattice) == 3 else "tupek"),
                                 ("pd/ordinary", "stretch", None)):
            if (mode == "short" or deck.dims_of(lattice) == 3) and style == "pd/ordinary" and law == "stretch":
                continue
            for ratio in rs:
                if deck.dims_of(lattice) == 3 and infl:
                    continue        # 3D: the default influence
                if mode == "full" and ratio > 3 and lattice == "sc" and style != "pd/bond":
                    continue
                c = {"style": style, "law": law, "lattice": lattice, "ratio": ratio, "r": 0.004, "quadrature": "point"}
                if infl:
                    c["influence"] = infl
                out.append(c)
    return out


def QUADRATURE(case):
    """Partial-volume copies of every case but the 3D ones beyond 3
    spacings (a minute each)."""
    return deck.dims_of(case["lattice"]) == 2 or case["ratio"] == 3


def group(case):
    return f"{deck.dims_of(case['lattice'])}D"


def family(case):
    return " ".join(str(case[k]) for k in ("style", "law", "lattice", "influence", "quadrature") if case.get(k))


def row_spacing(lattice, theta, a):
    """Distances between the planes of atoms normal to n and to t (the
    plane's normal and its direction in the xy plane), or None where the
    orientation has no such rows (22.5 degrees, hex at 45)."""
    if theta in ("0", "jitter"):
        return {"sc": (a, a), "square": (a, a), "fcc": (a / 2, a / 2),
                "hex": (a / 2, a * math.sqrt(3) / 2)}[lattice]
    if theta == "45" and lattice != "hex":
        p = a / math.sqrt(2) / (2 if lattice == "fcc" else 1)
        return p, p
    return None, None


def separation(case, theta, h=H):
    """The deck for one orientation; returns (text, window area, steps)."""
    lattice = case["lattice"] + ("-jitter" if theta == "jitter" else "")
    dims = deck.dims_of(lattice)
    ang = 0.0 if theta == "jitter" else math.radians(float(theta))
    n, t = (math.cos(ang), math.sin(ang)), (-math.sin(ang), math.cos(ang))
    delta = case["ratio"] * h
    a = deck.LATTICES[deck.base_lattice(lattice)][2] * h
    # the plane halfway between two planes of atoms, and a window that
    # holds a whole number of atom rows along the plane (its edges halfway
    # between rows): otherwise the window's count of atoms, not the
    # physics, sets the result (one row too many in 12 is +8%)
    p_n, p_t = row_spacing(deck.base_lattice(lattice), theta, a)
    c0 = 0.5 * p_n if p_n else 0.37 * a
    B = 2 * delta + h
    W = max(12 * h, 4 * delta) * (3 if theta == "jitter" else 1)
    if p_t:
        W = (2 * math.ceil(W / (2 * p_t)) + 1) * p_t
    else:
        W *= 3          # no rows: a longer window averages the atoms' offsets to its edges
    T = W / 2 + 2 * delta + h
    # periodic along z: longer than twice the bonds' reach (the horizon, and
    # with partial-volume quadrature half a cell diagonal more)
    nz = math.ceil(2 * (delta + h) / a) + 1
    lz = nz * a
    ext = B + T + abs(c0) + a
    zr = f"{-0.5 * a!r} {0.5 * a!r}" if dims == 2 else f"0 {lz!r}"
    mat = deck.material()
    text = deck.header(lattice, h, "s s p")
    text += f"region box block {-ext!r} {ext!r} {-ext!r} {ext!r} {zr} units box\ncreate_box 1 box\n"

    def plane(name, s_n, s_t, sign_n, sign_t):
        px, py = s_n * n[0] + s_t * t[0], s_n * n[1] + s_t * t[1]
        nx, ny = sign_n * n[0] + sign_t * t[0], sign_n * n[1] + sign_t * t[1]
        return f"region {name} plane {px!r} {py!r} 0 {nx!r} {ny!r} 0 units box\n"
    text += plane("p1", c0 - B, 0, 1, 0) + plane("p2", c0 + B, 0, -1, 0)
    text += plane("p3", 0, -T, 0, 1) + plane("p4", 0, T, 0, -1)
    text += "region band intersect 4 p1 p2 p3 p4\ncreate_atoms 1 region band\n"
    text += deck.jitter(lattice, h, "s s p")
    text += f"set group all density {mat['density']}\nset group all volume {deck.volume(lattice, h)!r}\n"
    text += deck.pair_lines(case, h, fail=f"fail {case['law']} Gc {mat['Gc']}")
    text += plane("upper", c0, 0, 1, 0)
    text += "group up region upper\ngroup lo subtract all up\n"
    u0, umax = 1e-3 * h, 1.05 * delta
    steps = math.ceil(math.log(umax / u0) / math.log(1 + case["r"]))
    text += (f"variable u equal {u0!r}*exp({math.log(1 + case['r'])!r}*elapsed)\n"
             f"variable dxu equal {0.5 * n[0]!r}*v_u\nvariable dyu equal {0.5 * n[1]!r}*v_u\n"
             f"variable dxl equal {-0.5 * n[0]!r}*v_u\nvariable dyl equal {-0.5 * n[1]!r}*v_u\n"
             "fix mu up move variable v_dxu v_dyu NULL NULL NULL NULL\n"
             "fix ml lo move variable v_dxl v_dyl NULL NULL NULL NULL\n")
    # the window: atoms within W/2 of the middle along the plane (all
    # volumes are equal: energy = V x the sum of dissipated densities)
    text += plane("w1", 0, -W / 2, 0, 1) + plane("w2", 0, W / 2, 0, -1)
    text += "region win intersect 2 w1 w2\ngroup win region win\n"
    text += ("compute frac all pd/fracture\ncompute gwin win reduce sum c_frac\n"
             "thermo_style custom step v_u c_frac[2] c_frac[3] c_gwin\nthermo_modify format float %.15g\n"
             f"thermo {steps}\ntimestep 1e-9\n")
    text += f"run {steps}\n"
    text += 'print "FRAC $(c_gwin:%.17g) $(c_frac[3]:%.17g) $(atoms)"\n'
    area = W * (lz if dims == 3 else deck.THICK)
    return text, area, steps


def measure(case, lmp, workdir):
    gc = deck.material()["Gc"]
    res, worst, secs, psteps, wall = {}, 0.0, 0.0, 0, 0.0
    for theta in ORIENTATIONS:
        text, area, steps = separation(case, theta)
        out, t = deck.run(lmp, text, workdir, name=f"in.fracture.{theta}")
        row = deck.printed(out, "FRAC")[-1]
        g = float(row[0]) * deck.volume(case["lattice"], H) / area / gc
        res[f"G_{theta}"] = g
        worst = max(worst, abs(g - 1))
        secs += sum(t["loop"])
        wall += t["wall"]
        psteps += int(float(row[2])) * steps
    res["err"] = worst
    res["seconds"], res["particle_steps"], res["wall"] = secs, psteps, wall
    return res


def note(rows):
    ok = [r for r in rows if r.get("metrics")]
    if not ok:
        return ""
    lines = ["Released energy per unit area / G_c, by orientation of the plane to the lattice:", "",
             "| setting | ratio | " + " | ".join(ORIENTATIONS) + " |", "|---|---|" + "---|" * len(ORIENTATIONS)]
    for r in ok:
        lines.append(f"| {r['family']} | {r['case']['ratio']} | " +
                     " | ".join(f"{r['metrics'][f'G_{o}']:.3f}" for o in ORIENTATIONS) + " |")
    return "\n".join(lines)
