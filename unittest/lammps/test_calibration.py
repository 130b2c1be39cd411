"""Each family calibrated on itself (core/pd_calibration.h).

On an irregular arrangement (positions moved by up to 0.25 spacings, volumes
+-30%) every interior particle's weighted volume is its own: a uniform
dilatation then gives pd/ordinary the classical energy density at every
particle, exactly (the dilatation is N sum w eps V with N = d / m of the same
family; +-eps averaged, so the error left is of order eps^2 = 1e-8), for
every strain order m. Normalized by one family for all (the largest), the
same particles were 10-12% soft.

The extended correspondence's strain is exact on any family (every atom,
every mode), and pd/bond's micromodulus, calibrated on the type's median
family, gives the body's mean dilatation energy to within the sampling of
its atoms (it was 2.4-2.8% soft with the continuum's micromodulus and
point quadrature).

On a lattice the interior atoms share one family and atoms near a free
surface take it too (no renormalization at surfaces, T14 6.1.3); with
surface_correction yes each atom takes its own. The calibration is of the
reference family: pre-cracked bonds (kept as broken) do not change it, and
it is the same on 1 and 2 ranks. The energy law's threshold is calibrated
on each family's own failure moment: separating a jittered plate releases
G_c to within the square lattice's own orientation error.

pd/ordinary's critical stretch from G_c is calibrated on the family too
(its weighted volume, the moment sum w V |xi| and the bond energy's
moduli, with the dilatation's share of the released energy on the family's
own crossing bonds): separating the hexagonal (2D) and simple cubic (3D) lattices
across planes at 0, 22.5 and 45 degrees and off every lattice plane
releases G_c within 4% (measured 0.999 .. 1.017 and 0.992 .. 1.009; the
bond-based formula it replaces gave 0.95 .. 0.97 and 0.53 .. 0.58)."""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "..", "tools", "accuracy"))
from lmptest import LMP, check, check_le, finish, read_dump, run, workdir  # noqa: E402
import deck  # noqa: E402
import q_constants  # noqa: E402
import q_fracture  # noqa: E402

H = 1.0e-3
E0 = 1.0e-4


def jittered(lattice, boundary, body, seed=4711, volumes=0.3):
    """A lattice body, its atoms moved by up to 0.25 spacings and given
    volumes +-volumes about the lattice's, as the reference configuration."""
    dims = deck.dims_of(lattice)
    V = deck.volume(lattice, H)
    a = 0.25 * H
    z = "0.0" if dims == 2 else repr(a)
    return (deck.header(lattice, H, boundary) + body +
            f"displace_atoms all random {a!r} {a!r} {z} {seed} units box\n"
            "write_data jitter.data\nclear\n" + deck.header(lattice, H, boundary) + "read_data jitter.data\n"
            f"set group all density {deck.material()['density']}\n"
            f"variable vr atom {V!r}*(1+{volumes!r}*(2*random(0,1,{seed + 1})-1))\nset group all volume v_vr\n")


def strain_errors(style, lattice, mode="dilatation", m=None, ranks=1, volumes=0.3, side=8, copies=1):
    """Per-atom energy density of a uniform strain (+-E0, averaged) over
    the classical one, minus 1, on a jittered periodic block (repeated
    'copies' times along each axis); and the dump's rows (id: energy,
    family_share, calibrated_volume)."""
    dims = deck.dims_of(lattice)
    case = {"style": style, "lattice": lattice, "ratio": 3, "quadrature": "point"}
    if m is not None:
        case["m"] = m
    text, _, lengths = deck.periodic_block(lattice, H, side * H)
    body = text[text.index("region box"):text.index("set group all density")]
    d = workdir()
    # the arrangement on one rank (its random numbers depend on the ranks), run on any
    repeat = f"replicate {copies} {copies} {copies if dims == 3 else 1}\n" if copies > 1 else ""
    run(jittered(lattice, "p p p", body, volumes=volumes) + repeat + "write_data body.data\n", d, name="in.body")
    deck_text = deck.header(lattice, H, "p p p") + "read_data body.data\n" + deck.pair_lines(case, H)
    deck_text += ("compute pa all pe/atom\ncompute fa all pd/atom family_share calibrated_volume\n"
                  "thermo_style custom step pe\nrun 0\n")
    e = q_constants.modes(dims)[mode]
    for sign in (1, -1):
        deck_text += q_constants.box_change([[sign * x for x in r] for r in e], [copies * x for x in lengths])
        deck_text += (f"dump dd all custom 1 dump.{sign} id c_pa c_fa[1] c_fa[2]\n"
                      "dump_modify dd format float %.17g\nrun 0 post no\nundump dd\n")
    run(deck_text, d, ranks=ranks)
    lam, mu = deck.classical_lame(case)
    tr = sum(e[i][i] for i in range(3))
    w_cl = lam / 2 * tr * tr + mu * sum(e[i][j] ** 2 for i in range(3) for j in range(3))
    plus, minus = read_dump(os.path.join(d, "dump.1")), read_dump(os.path.join(d, "dump.-1"))
    errors = [0.5 * (plus[k][0] + minus[k][0]) / w_cl - 1 for k in plus]
    return errors, plus


for lattice in ("sc", "square"):
    for m in (0.5, 0, -1):
        errors, atoms = strain_errors("pd/ordinary", lattice, m=m)
        check_le(f"{lattice} jittered, m = {m}: every atom's dilatation energy is classical",
                 max(abs(x) for x in errors), 1e-6, "own-family normalization; +-eps leaves O(eps^2)")
        check(f"{lattice} jittered, m = {m}: every atom is interior (share 1)",
              all(v[1] == 1.0 for v in atoms.values()), f"{len(atoms)} atoms")
    for mode in ("dilatation", "shear_xy"):
        errors, _ = strain_errors("pd/corr", lattice, mode)
        check_le(f"{lattice} jittered, pd/corr extended, {mode}: every atom's energy is classical",
                 max(abs(x) for x in errors), 1e-6, "its strain tensor is exact on any family")
    # pd/bond: one scale per type (the median interior family's); single atoms
    # scatter with their families, the body's mean is the input's
    errors, _ = strain_errors("pd/bond", lattice)
    mean = sum(errors) / len(errors)
    stderr = math.sqrt(sum((x - mean) ** 2 for x in errors) / (len(errors) - 1) / len(errors))
    check_le(f"{lattice} jittered, pd/bond: mean dilatation energy is classical", abs(mean), 3 * stderr,
             f"micromodulus calibrated on the median family; 3 standard errors of {len(errors)} atoms' scatter")

# equal volumes: jittered families may share a volume (a count of partners),
# and the arrangement is still irregular (not a lattice's one family)
# (square, 900 atoms, constant influence: several atoms have the most partners)
errors, atoms = strain_errors("pd/ordinary", "square", m=0.5, volumes=0.0, side=29)
check_le(f"square jittered, equal volumes, {len(atoms)} atoms: every atom's dilatation energy is classical",
         max(abs(x) for x in errors), 1e-6, "told from a lattice by its moment sum V |xi|")
# ... and in 3D with the default inverse influence, whose weighted moment
# w V |xi| = delta V is a count of partners; a jittered motif repeated
# 2 x 2 x 2 (its 8 copies share every moment: not a lattice either)
errors, atoms = strain_errors("pd/ordinary", "sc", m=0.5, volumes=0.0, side=7, copies=2)
check_le(f"sc jittered motif repeated, equal volumes, inverse influence, {len(atoms)} atoms: every atom's "
         "dilatation energy is classical", max(abs(x) for x in errors), 1e-6,
         "told from a lattice by the unweighted moment and the share of atoms at the largest")

# the same calibration on 2 ranks
_, one = strain_errors("pd/ordinary", "sc", m=0.5)
_, two = strain_errors("pd/ordinary", "sc", m=0.5, ranks=2)
diff = max(abs(one[k][2] - two[k][2]) / one[k][2] for k in one)
check_le("calibrated volumes on 2 ranks equal 1 rank's", diff, 1e-12, "medians by bisection are rank-independent")


def lattice_block(extra_settings="", precrack=""):
    """A free sc block, 12 spacings wide: interior, surface, and its shares."""
    text = (deck.header("sc", H, "s s s") + f"region box block 0 12 0 12 0 12\ncreate_box 1 box\n"
            "create_atoms 1 box\n" + f"set group all density {deck.material()['density']}\n"
            f"set group all volume {H ** 3!r}\n")
    text += deck.pair_lines({"style": "pd/ordinary", "lattice": "sc", "ratio": 3}, H, fail="fail energy Gc 400")
    if extra_settings:
        text = text.replace("quadrature point", "quadrature point " + extra_settings)
    text += precrack
    text += ("compute fa all pd/atom family_share calibrated_volume weighted_volume\n"
             "dump dd all custom 1 dump.fam id x y z c_fa[1] c_fa[2] c_fa[3]\n"
             "dump_modify dd format float %.17g\nrun 0\n")
    d = workdir()
    out, _ = run(text, d)
    return read_dump(os.path.join(d, "dump.fam")), out


atoms, out = lattice_block()
inner = [v for v in atoms.values() if all(3 * H - 1e-9 <= c <= 9 * H + 1e-9 for c in v[:3])]
outer = [v for v in atoms.values() if any(c < 2 * H + 1e-9 or c > 10 * H - 1e-9 for c in v[:3])]
volumes = {v[4] for v in atoms.values()}
interior = max(abs(v[5] / next(iter(volumes)) - 1) for v in inner)
check("lattice: every atom is calibrated on the interior family (surfaces not renormalized)",
      len(volumes) == 1 and interior < 1e-12,
      f"{len(volumes)} distinct calibrated volumes; interior weighted volumes within {interior:.1e} of it")
check("lattice: interior atoms take their own family, surface atoms the complete one",
      all(v[3] == 1.0 for v in inner) and all(v[3] == 0.0 for v in outer) and len(outer) > 0,
      f"{len(inner)} interior, {len(outer)} within 2 spacings of a face")

corrected, _ = lattice_block("surface_correction yes")
own = max(abs(v[4] / v[5] - 1) for v in corrected.values())
check_le("surface_correction yes: every atom its own weighted volume", own, 1e-12,
         f"{len({round(v[4] / H ** 3, 6) for v in corrected.values()})} distinct values")

cracked, _ = lattice_block(precrack="fix cut all pd/precrack patch 0 0.00601 0 0.012 0 0 0 0 0.012\n")
check("a pre-cracked family keeps its calibration (of the reference family)",
      all(cracked[k][3] == atoms[k][3] and cracked[k][4] == atoms[k][4] for k in atoms))


def separation(case, orientations):
    """q_fracture's separation of one case at the given orientations:
    {orientation: G / G_c}."""
    saved = q_fracture.ORIENTATIONS
    q_fracture.ORIENTATIONS = orientations
    try:
        res = q_fracture.measure(case, LMP, workdir())
    finally:
        q_fracture.ORIENTATIONS = saved
    return {k[2:]: v for k, v in res.items() if k.startswith("G_")}


# pd/ordinary, fail stretch Gc: the accuracy report's separation across
# lattice planes and off them (lattice orientation error 1-3%, the
# dilatation's share of the release estimated in the continuum)
for lattice, orientations in (("hex", ("0", "22.5", "45", "r1", "r2", "r3")), ("sc", ("0", "22.5", "45", "r1"))):
    case = {"style": "pd/ordinary", "law": "stretch", "lattice": lattice, "ratio": 3, "r": 0.004,
            "quadrature": "point"}
    gs = separation(case, orientations)
    check_le(f"pd/ordinary fail stretch Gc, {lattice}: G / G_c at every orientation within 4%",
             max(abs(v - 1) for v in gs.values()), 0.04, ", ".join(f"{k}: {v:.3f}" for k, v in gs.items()))

# ... in plane strain, where the bond moduli's lambda / mu is 0.67 (PMMA;
# 0.04 in plane stress), the dilatation's share of the release counts: on
# the family's own crossing bonds it is 0.244 at 3 spacings, the continuum's
# 0.20 made plane strain release 2-7% more than plane stress at every
# orientation (1.025 against 0.979 along the rows, 1.036-1.047 as ratios).
# The share is calibrated as the orientation average: across a plane of
# atoms the lattice's own share differs (0.995 against 0.978 along the rows)
case = {"style": "pd/ordinary", "law": "stretch", "lattice": "square", "ratio": 3, "r": 0.004, "quadrature": "point"}
stress = separation(case, ("0", "45", "r1"))
strain = separation(dict(case, plane="plane strain"), ("0", "45", "r1"))
check_le("pd/ordinary fail stretch Gc, square: plane strain releases what plane stress does (2.5% at each "
         "orientation)", max(abs(strain[k] / stress[k] - 1) for k in stress), 0.025,
         ", ".join(f"{k}: {strain[k]:.3f} / {stress[k]:.3f}" for k in stress))
check_le("... and G_c within 3% at each", max(abs(v - 1) for v in strain.values()), 0.03)

# pd/bond's critical stretch on jittered hexagonal bands (three seeds):
# calibrated on the median of the complete families, those of atoms whose
# partners all keep theirs. Taken over every atom of share 1, which
# includes those that lost up to the tolerance (25% here) of their family
# to the band's faces, the median was low and the bands released 5-7% too
# much. A band's G samples its crossing bonds (at a window of 12 lattice
# windows: standard deviation 1.4% over 10 seeds, mean 1.003; the
# accuracy tool's windows are 48 now, its three seeds 1.003-1.006): the
# mean of three within 2%, each within 2%
case = {"style": "pd/bond", "law": "stretch", "lattice": "hex", "ratio": 3, "r": 0.004, "quadrature": "point"}
g = list(separation(case, ("jitter", "jitter2", "jitter3")).values())
check_le("pd/bond fail stretch Gc, jittered hex bands: mean G / G_c of three seeds within 2%",
         abs(sum(g) / len(g) - 1), 0.02, ", ".join(f"{v:.3f}" for v in g))
check_le("... each within 2%", max(abs(v - 1) for v in g), 0.02)

# the energy law on jittered plates (positions +-0.25 spacings, volumes
# +-30%, three seeds), separated across a plane off the lattice the
# particles came from. Across the plane between their former rows, which
# no particle crosses, each crossing pair counted by its lattice
# separation along n, not its own: the energy law, whose release is
# weighted to short bonds, then released 1.053-1.078 G_c on the hexagonal
# lattice (the lattice itself: 1.008). Measured (48 lattice windows):
# square 0.982-1.004, hexagonal 0.994-1.017: each seed within 2.5%
for lattice in ("square", "hex"):
    case = {"style": "pd/ordinary", "law": "energy", "lattice": lattice, "ratio": 3, "r": 0.004,
            "quadrature": "point"}
    g = list(separation(case, ("jitter", "jitter2", "jitter3")).values())
    check_le(f"energy law on jittered {lattice} plates: mean G / G_c of three seeds within 3%",
             abs(sum(g) / len(g) - 1), 0.03, ", ".join(f"{x:.3f}" for x in g))
    check_le("... each within 2.5%", max(abs(x - 1) for x in g), 0.025)

# The energy law's profile across a plane of atoms at 3 spacings (with the
# directional correction): the opening profile (T14 eq. 6.3), whose
# release leans on the short bonds that lie in the plane, released 0.921
# (sc) and 0.954 (square) G_c; the uniform one 0.976 and 0.975. Both are
# calibrated on the orientation average, so the uniform one must lift the
# plane by 1.5 points or more and bring it within 3%.
for lattice in ("sc", "square"):
    case = {"style": "pd/ordinary", "law": "energy", "lattice": lattice, "ratio": 3, "r": 0.004,
            "quadrature": "point"}
    opening = separation(case, ("0",))["0"]
    uniform = separation(dict(case, profile="uniform"), ("0",))["0"]
    check_le(f"energy law, profile uniform, {lattice}: a plane of atoms releases G_c within 3%", abs(uniform - 1),
             0.03, f"{uniform:.3f}")
    check_le("... 1.5 points or more above the opening profile", opening - uniform, -0.015,
             f"opening {opening:.3f}")

# the profile is a coefficient: kept in restart files with the rest
body = deck.header("sc", H, "p p p") + "region b block 0 8 0 8 0 8\ncreate_box 1 b\ncreate_atoms 1 box\n" + \
    f"set group all density 1180\nset group all volume {H ** 3!r}\n"
d = workdir()
first, _ = run(body + f"pair_style pd/ordinary\npair_coeff * * E 3.5e9 nu 0.35 horizon {3.0001 * H!r} "
               "fail energy Gc 400 profile uniform\nrun 0\nwrite_restart profile.restart\n", d)
again, _ = run("read_restart profile.restart\nrun 0\n", d)
line = [x for x in first.splitlines() if "fail energy, profile" in x]
check("profile uniform: the setup report names it, and read_restart restores it (the same beta)",
      len(line) == 1 and "profile uniform" in line[0] and line[0] in again.splitlines(),
      line[0] if line else "no line")
finish()
