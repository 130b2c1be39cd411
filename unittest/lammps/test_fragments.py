"""compute pd/fragments: the connected components of the intact bonds.

Known pieces: a plate cut by two through cracks (fix pd/precrack) is three
fragments of 50, 100 and 150 particles; a strip periodic in x cut once is
one fragment that wraps through the boundary, cut twice two; a periodic 3D
block cut by two planes is two slabs, one of them wrapping. Random
breakage: random cracks, bonds broken by a random displacement field
(critical stretch) and a group that leaves atoms out, against a
brute-force union-find in Python over the bonds rebuilt from the lattice
with the same crossing and stretch tests. Each case runs on 1, 2 and 3
ranks, and the random one again after write_restart/read_restart, on other
rank counts. Every geometry is written once (one rank) as a data file, so
that atom IDs, and with them the fragment IDs (each fragment's smallest
atom ID), do not depend on the rank count.

Tolerances: fragment IDs, counts and atoms are integers and must be exact;
masses are sums of equal particle masses (at most 1600) added in another
order than k x m: relative 1e-12 covers that round-off (1600 x 1.1e-16)."""
import math
import random
from lmptest import *

d = workdir()
H = SPACING
THICK = 1e-3
MASS2D = DENSITY * H * H * THICK     # a plate particle: density x volume
MASS3D = DENSITY * VOLUME
MASS_TOL = 1e-12
PAIR2D = ("pair_style pd/bond plane stress thickness 1e-3 quadrature point\n"
          f"pair_coeff * * pmb E 3e9 horizon {HORIZON}{{fail}}\n")


def make_plate(name, nx, ny, boundary):
    """An nx x ny square-lattice plate (atom (i, j) at (i h, j h)) as a data file."""
    run(f"""units si
dimension 2
boundary {boundary}
atom_style peri
atom_modify map array
lattice sq {H}
region box block -0.25 {nx - 0.25} -0.25 {ny - 0.25} -0.5 0.5
create_box 1 box
create_atoms 1 box
set group all density {DENSITY}
set group all volume {H * H * THICK}
write_data {name}.data
""", d)


def read_head(name, boundary, dim=2, procs=""):
    return (f"units si\ndimension {dim}\nboundary {boundary}\natom_style peri\natom_modify map array\n"
            f"neighbor {0.2 * H} bin\n{procs}read_data {name}.data\n")


def fragments(script, tag, ranks=1, computes="compute fr all pd/fragments\n", ids="c_fr"):
    """Run 0 with the computes; returns the last thermo row and {id: [x, y, z, fragment IDs...]}."""
    script += computes + f"""thermo_style custom step c_fr[*]
thermo_modify format float %.17g
dump 1 all custom 1 {tag}.dump id x y z {ids}
dump_modify 1 format float %.17g
run 0
"""
    _, rows = run(script, d, ranks=ranks, name=f"in.{tag}")
    return rows[-1], read_dump(f"{d}/{tag}.dump")


def smallest_id(atoms, inside):
    """The fragment ID each atom should have: the smallest ID of the atoms for which inside(x, y, z)
    gives the same piece key."""
    first = {}
    for i, v in atoms.items():
        k = inside(*v[:3])
        first[k] = min(first.get(k, i), i)
    return {i: first[inside(*v[:3])] for i, v in atoms.items()}


def same_ids(atoms, want, col=3):
    bad = [i for i in want if atoms[i][col] != want[i]]
    return len(bad) == 0 and set(atoms) == set(want), f"{len(bad)} of {len(want)} atoms differ"


def check_mass(what, got, want):
    err = abs(got - want) / want if want else abs(got)
    check_le(what, err, MASS_TOL, "sums of equal masses in another order")


def segment(x1, y1, x2, y2):
    return f"segment {x1!r} {y1!r} {x2!r} {y2!r}"


# --- a plate cut by two through cracks: 5, 10 and 15 columns ------------------
make_plate("plate", 30, 10, "s s p")
CUTS = "".join(f"fix c{k} all pd/precrack {segment(x * H, -H, x * H, 11 * H)}\n" for k, x in enumerate((4.5, 14.5)))
head = read_head("plate", "s s p") + PAIR2D.format(fail="") + CUTS
piece = lambda x, y, z: (x > 4.5 * H) + (x > 14.5 * H)
for ranks in (1, 2, 3):
    r, atoms = fragments(head, f"plate{ranks}", ranks)
    where = f"plate, {ranks} rank(s)"
    check(f"{where}: 3 fragments of 50, 100, 150 particles",
          (r["c_fr[1]"], r["c_fr[5]"], r["c_fr[7]"]) == (3, 3, 150), str(r))
    check_mass(f"{where}: largest mass 150 m", r["c_fr[2]"], 150 * MASS2D)
    check_mass(f"{where}: mean mass 100 m", r["c_fr[3]"], 100 * MASS2D)
    check_mass(f"{where}: total mass 300 m", r["c_fr[4]"], 300 * MASS2D)
    check(f"{where}: no debris", r["c_fr[6]"] == 0.0)
    check(f"{where}: each atom's fragment ID is its piece's smallest atom ID", *same_ids(atoms, smallest_id(atoms, piece)))
# min_atoms, the mass distribution, a group
r, atoms = fragments(head, "plate_opts", computes="""compute fr all pd/fragments min_atoms 60 bins 4
compute x1 all pd/fragments range {lo!r} {hi!r} bins 2
compute x2 all pd/fragments range {lo!r} {hi2!r} bins 1
region left block INF {left!r} INF INF INF INF units box
group left region left
compute part left pd/fragments
""".format(lo=40 * MASS2D, hi=200 * MASS2D, hi2=120 * MASS2D, left=11.5 * H), ids="c_part")
check("min_atoms 60: 2 fragments counted, 3 in all", (r["c_fr[1]"], r["c_fr[5]"]) == (2, 3), str(r))
check_mass("min_atoms 60: the 50-particle piece is debris", r["c_fr[6]"], 50 * MASS2D)
check_mass("min_atoms 60: mean of the counted fragments 125 m", r["c_fr[3]"], 125 * MASS2D)
check("a group: its atoms get the smallest ID of their piece (columns 0-4, 5-11), the others 0",
      *same_ids(atoms, {i: (smallest_id(atoms, piece)[i] if v[0] < 11.5 * H else 0) for i, v in atoms.items()}))
# the arrays through thermo (one value each: c_ID[i][j])
arr = "".join(f" c_fr[{k}][{c}]" for k in (1, 2, 3, 4) for c in (1, 2, 3)) + \
      " c_x1[1][2] c_x1[2][2] c_x1[2][3] c_x2[1][2] c_x2[1][3] c_part[1] c_part[5] c_part[7]"
_, rows = run(head + """compute fr all pd/fragments bins 4
compute x1 all pd/fragments range {lo!r} {hi!r} bins 2
compute x2 all pd/fragments range {lo!r} {hi2!r} bins 1
region left block INF {left!r} INF INF INF INF units box
group left region left
compute part left pd/fragments
thermo_style custom step{arr}
thermo_modify format float %.17g
run 0
""".format(lo=40 * MASS2D, hi=200 * MASS2D, hi2=120 * MASS2D, left=11.5 * H, arr=arr), d)
r = rows[-1]
edges = [MASS2D * 300 ** ((k + 1) / 4) for k in range(4)]
check_le("bins 4, range auto: edges m (300 m / m)^(k/4)",
         max(abs(r[f"c_fr[{k + 1}][1]"] - edges[k]) / edges[k] for k in range(4)), 1e-14, "one pow per edge")
check("bins 4: cumulative counts 0 0 1 3 (50 m lies in (17.3 m, 72.1 m])",
      [r[f"c_fr[{k}][2]"] for k in (1, 2, 3, 4)] == [0, 0, 1, 3])
check_le("bins 4: cumulative mass fractions 0 0 1/6 1",
         max(abs(r[f"c_fr[{k}][3]"] - w) for k, w in zip((1, 2, 3, 4), (0, 0, 1 / 6, 1))), 1e-12)
check("range 40 m .. 200 m, 2 bins (upper edges 89 m, 200 m): counts 1 3",
      (r["c_x1[1][2]"], r["c_x1[2][2]"], r["c_x1[2][3]"]) == (1, 3, 1.0))
check("range 40 m .. 120 m, 1 bin: the 150 m piece is beyond it (2 counted, half the mass)",
      (r["c_x2[1][2]"], r["c_x2[1][3]"]) == (2, 0.5), f"{r['c_x2[1][2]']}, {r['c_x2[1][3]']}")
check("the group's compute: 2 fragments (50 and 70 particles)",
      (r["c_part[1]"], r["c_part[5]"], r["c_part[7]"]) == (2, 2, 70), str(r))

# --- a strip periodic in x, cut once and twice ---------------------------------
make_plate("strip", 30, 10, "p s p")
for ncut, want_n in ((1, 1), (2, 2)):
    cuts = "".join(f"fix c{k} all pd/precrack {segment(x * H, -H, x * H, 11 * H)}\n"
                   for k, x in enumerate((9.5, 19.5)[:ncut]))
    for ranks, procs in ((1, ""), (2, "processors 2 1 1\n"), (3, "processors 3 1 1\n")):
        r, atoms = fragments(read_head("strip", "p s p", procs=procs) + PAIR2D.format(fail="") + cuts,
                             f"strip{ncut}_{ranks}", ranks)
        where = f"periodic strip cut {ncut}x, {ranks} rank(s)"
        sizes = (300,) if ncut == 1 else (200, 100)
        check(f"{where}: {want_n} fragment(s) of {sizes} particles",
              (r["c_fr[1]"], r["c_fr[7]"]) == (want_n, sizes[0]), str(r))
        key = (lambda x, y, z: 0) if ncut == 1 else (lambda x, y, z: 9.5 * H < x < 19.5 * H)
        check(f"{where}: the piece through the boundary is one fragment (IDs)", *same_ids(atoms, smallest_id(atoms, key)))

# --- a periodic 3D block cut by two planes: slabs of 5 and 7 layers ------------
run(f"""units si
boundary p p p
atom_style peri
atom_modify map array
lattice sc {H}
region box block 0 8 0 8 0 12
create_box 1 box
create_atoms 1 box
set group all density {DENSITY}
set group all volume {VOLUME}
write_data block.data
""", d)
PATCHES = "".join(f"fix p{k} all pd/precrack patch {-3 * H!r} {-3 * H!r} {z * H!r} {14 * H!r} 0 0 0 {14 * H!r} 0\n"
                  for k, z in enumerate((3.5, 8.5)))
for ranks, procs in ((1, ""), (2, "processors 1 1 2\n")):
    r, atoms = fragments(read_head("block", "p p p", 3, procs) +
                         f"pair_style pd/bond quadrature point\npair_coeff * * pmb K {BULK} horizon {HORIZON}\n" + PATCHES,
                         f"block{ranks}", ranks)
    where = f"3D block, {ranks} rank(s)"
    check(f"{where}: 2 fragments, the larger (7 layers, through the boundary) 448 particles",
          (r["c_fr[1]"], r["c_fr[7]"]) == (2, 448), str(r))
    check_mass(f"{where}: total mass", r["c_fr[4]"], 768 * MASS3D)
    check(f"{where}: fragment IDs", *same_ids(atoms, smallest_id(atoms, lambda x, y, z: 3.5 * H < z < 8.5 * H)))

# --- random breakage against a brute-force union-find --------------------------
N = 40
S0 = 0.002
make_plate("random", N, N, "p s p")


def random_cracks(seed):
    """Cracks through the plate's height, which cross one another, and shorter ones; all more than a
    horizon from the periodic boundary (x = 0), where which end of a bond is cut would depend on the
    end that stores it."""
    rng = random.Random(seed)
    u = lambda lo, hi: rng.uniform(lo, hi) * H
    return ([(u(3.6, N - 3.6), -2 * H, u(3.6, N - 3.6), (N + 1) * H) for _ in range(5)] +
            [(u(3.6, N - 3.6), u(-2, N + 1), u(3.6, N - 3.6), u(-2, N + 1)) for _ in range(4)])


def random_body(cracks):
    return ("".join(f"fix c{k} all pd/precrack {segment(*c)}\n" for k, c in enumerate(cracks)) +
            # a displacement of +-1.2% of the spacing, random by atom ID: 45% of the bonds stretch past s0
            """variable hx atom sin(id*12.9898)*43758.5453
variable hy atom sin(id*78.233)*43758.5453
variable dx atom 1.2e-5*(v_hx-floor(v_hx)-0.5)
variable dy atom 1.2e-5*(v_hy-floor(v_hy)-0.5)
displace_atoms all move v_dx v_dy 0 units box
variable member atom (id%7)!=0
group part variable member
""" + PAIR2D.format(fail=f" fail stretch {S0}"))


def data_positions(name):
    lines = open(f"{d}/{name}.data").read().splitlines()
    start = next(i for i, l in enumerate(lines) if l.startswith("Atoms")) + 2
    box = {w[2][0]: (float(w[0]), float(w[1])) for w in (l.split() for l in lines[:start]) if len(w) == 4 and w[2].endswith("lo")}
    pos = {}
    for l in lines[start:]:
        w = l.split()
        if not w:
            break
        pos[int(w[0])] = (float(w[4]), float(w[5]))
    return box, pos


def orient(a, b, c):
    return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])


def crosses(p, q, c):
    """fix pd/precrack's test (core/pd_precrack.c): ends strictly on both sides, crossing on the segment."""
    a, b = (c[0], c[1]), (c[2], c[3])
    sp, sq = orient(a, b, p), orient(a, b, q)
    if not ((sp > 0 and sq < 0) or (sp < 0 and sq > 0)):
        return False
    sa, sb = orient(p, q, a), orient(p, q, b)
    return not ((sa > 0 and sb > 0) or (sa < 0 and sb < 0))


def oracle(atoms, members, cracks):
    """{id: smallest ID of its component} over intact bonds between members (0 for non-members), and
    the components' sizes, largest first. The bonds are rebuilt from the lattice (every pair within
    the horizon, periodic in x); a bond is broken if it crosses a crack (reference positions) or is
    stretched past S0 (positions of the dump)."""
    box, x0 = data_positions("random")
    length = box["x"][1] - box["x"][0]
    mi = lambda dx: dx - length * round(dx / length)
    at = {(round(x / H) % N, round(y / H)): i for i, (x, y) in x0.items()}
    reach = [(a, b) for a in range(-3, 4) for b in range(-3, 4) if (a, b) > (0, 0) and a * a + b * b <= 9]
    parent = {i: i for i in x0}

    def find(i):
        while parent[i] != i:
            parent[i] = parent[parent[i]]
            i = parent[i]
        return i
    for (ix, iy), i in at.items():
        for a, b in reach:
            j = at.get(((ix + a) % N, iy + b))
            if j is None or i not in members or j not in members:
                continue
            xi = (mi(x0[j][0] - x0[i][0]), x0[j][1] - x0[i][1])
            if any(crosses(x0[i], (x0[i][0] + xi[0], x0[i][1] + xi[1]), c) for c in cracks):
                continue
            y = (mi(atoms[j][0] - atoms[i][0]), atoms[j][1] - atoms[i][1])
            if math.hypot(*y) / math.hypot(*xi) - 1 > S0:
                continue
            ri, rj = find(i), find(j)
            parent[max(ri, rj)] = min(ri, rj)
    comp = {}
    for i in x0:
        if i in members:
            comp.setdefault(find(i), []).append(i)
    ids = {i: (min(comp[find(i)]) if i in members else 0) for i in x0}
    return ids, sorted((len(c) for c in comp.values()), reverse=True)


ARR = " ".join(f"c_frg[{k}][1] c_frg[{k}][2] c_frg[{k}][3]" for k in range(1, 7))


def random_run(tag, cracks, ranks=1, procs=""):
    """Fragments of all atoms (defaults) and of the group 'part' (min_atoms 3, 6 bins); the
    distribution also through fix ave/time, the fragments also as chunks."""
    script = read_head("random", "p s p", procs=procs) + random_body(cracks) + f"""compute fr all pd/fragments
compute frg part pd/fragments min_atoms 3 bins 6
compute ch all chunk/atom c_fr nchunk every compress yes
fix dist all ave/time 1 1 1 c_frg[1] c_frg[2] c_frg[3] mode vector file {tag}.dist
thermo_style custom step c_fr[*] c_frg[*] c_ch {ARR}
thermo_modify format float %.17g
dump 1 all custom 1 {tag}.dump id x y z c_fr c_frg
dump_modify 1 format float %.17g
run 0
write_restart {tag}.restart
"""
    _, rows = run(script, d, ranks=ranks, name=f"in.{tag}")
    return rows[-1], read_dump(f"{d}/{tag}.dump")


def check_random(where, r, atoms, cracks, group=True):
    want, sizes = oracle(atoms, set(atoms), cracks)
    counted = [s for s in sizes if s >= 2]
    check(f"{where}: fragment IDs equal the brute-force union-find's ({len(counted)} fragments, "
          f"{len(sizes) - len(counted)} single particles)", *same_ids(atoms, want))
    check(f"{where}: counts, largest, debris as the union-find's",
          (r["c_fr[1]"], r["c_fr[5]"], r["c_fr[7]"]) == (len(counted), len(sizes), sizes[0]), str(r))
    check_mass(f"{where}: largest mass", r["c_fr[2]"], MASS2D * sizes[0])
    check_mass(f"{where}: mean mass", r["c_fr[3]"], MASS2D * sum(counted) / len(counted))
    check_mass(f"{where}: debris mass", r["c_fr[6]"], MASS2D * (N * N - sum(counted)))
    if not group:
        return
    members = {i for i in atoms if i % 7 != 0}
    gwant, gsizes = oracle(atoms, members, cracks)
    counted = [s for s in gsizes if s >= 3]
    check(f"{where}: the group's fragment IDs (members only, 0 outside)", *same_ids(atoms, gwant, col=4))
    check(f"{where}: the group's counts (min_atoms 3: {len(counted)} of {len(gsizes)})",
          (r["c_frg[1]"], r["c_frg[5]"]) == (len(counted), len(gsizes)))
    lo, hi = MASS2D, MASS2D * len(members)
    edge = [lo * (hi / lo) ** ((k + 1) / 6) for k in range(6)]
    cum = [sum(1 for s in counted if s * MASS2D <= e * (1 + 1e-9)) for e in edge]
    frac = [sum(s for s in counted if s * MASS2D <= e * (1 + 1e-9)) / sum(counted) for e in edge]
    got = [r[f"c_frg[{k}][2]"] for k in range(1, 7)]
    check(f"{where}: cumulative counts on 6 log bins from one particle to the group's mass", got == cum,
          f"{got} vs {cum}")
    check_le(f"{where}: cumulative mass fractions",
             max(abs(r[f"c_frg[{k + 1}][3]"] - frac[k]) for k in range(6)), MASS_TOL)
    check_le(f"{where}: bin edges", max(abs(r[f"c_frg[{k + 1}][1]"] - edge[k]) / edge[k] for k in range(6)), 1e-14)
    return cum


# several random cases on one rank
for seed in (1, 2, 3, 4):
    cracks = random_cracks(seed)
    r, atoms = random_run(f"seed{seed}", cracks)
    cum = check_random(f"random breakage, seed {seed}", r, atoms, cracks)
    lines = [l.split() for l in open(f"{d}/seed{seed}.dist") if l.strip() and not l.startswith("#")][1:]
    check(f"seed {seed}: fix ave/time mode vector writes the 6 rows of the distribution",
          len(lines) == 6 and [float(w[2]) for w in lines] == cum, str(lines[:2]))
    check(f"seed {seed}: compute chunk/atom c_ID makes one chunk per fragment", r["c_ch"] == r["c_fr[5]"])
# one of them on 2 and 3 ranks, and through restart files
cracks = random_cracks(1)
results = {"random1": random_run("random1", cracks)[1]}
for tag, ranks, procs in (("random2", 2, "processors 2 1 1\n"), ("random3", 3, "processors 3 1 1\n"),
                          ("random3y", 3, "processors 1 3 1\n")):
    r, atoms = random_run(tag, cracks, ranks, procs)
    where = f"random breakage, {ranks} ranks ({procs.strip()})"
    check_random(where, r, atoms, cracks)
    check(f"{where}: every fragment ID as on 1 rank", all(atoms[i][3:] == results["random1"][i][3:] for i in atoms))
    results[tag] = atoms
# the bond store restarts: the same fragments on other rank counts, without the cracks' fixes
for written, ranks in (("random2", 1), ("random3", 3), ("random1", 2)):
    r, atoms = fragments(f"read_restart {written}.restart\n", f"restart_{written}_{ranks}", ranks)
    where = f"restart of {written} read on {ranks} rank(s)"
    check(f"{where}: every fragment ID as before",
          all(atoms[i][3] == results[written][i][3] for i in atoms) and set(atoms) == set(results[written]))
    check_random(where, r, atoms, cracks, group=False)

# --- bad input ----------------------------------------------------------------
BAD = read_head("plate", "s s p") + PAIR2D.format(fail="")
for args, message in [
    ("bins 0", "bins must be an integer from 1 to 100000, got '0'"),
    ("bins 2.5", "bins must be an integer from 1 to 100000, got '2.5'"),
    ("bins", "'bins' needs a value"),
    ("min_atoms 0", "min_atoms must be an integer >= 1"),
    ("min_atoms two", "min_atoms must be an integer >= 1 (the fewest atoms a counted fragment has), got 'two'"),
    ("range 0 1", "range lo must be a finite mass > 0"),
    ("range 1e-6 inf", "range hi must be a finite mass > lo = 1e-06, got 'inf'"),
    ("range 2 1", "range hi must be a finite mass > lo = 2, got '1'"),
    ("range 1 bins 3", "range hi must be a finite mass > lo = 1, got 'bins'"),
    ("range 1", "'range' needs two masses lo hi, or 'auto'"),
    ("colour 3", "unknown keyword 'colour' (min_atoms, bins, range)"),
]:
    out, _ = run(BAD + f"compute f all pd/fragments {args}\n", d, expect_error=True)
    errors = [l for l in out.splitlines() if l.startswith("ERROR")]
    check(f"bad input '{args}': ERROR names it", bool(errors) and message in errors[0], errors[0] if errors else out[-300:])
out, _ = run(read_head("block", "p p p", 3) + "pair_style peri/pmb\npair_coeff * * 1e20 0.0015001 1 0\n"
             "compute f all pd/fragments\nthermo_style custom step c_f[1]\nrun 0\n", d, expect_error=True)
check("without a pd/ pair style (no bond store): ERROR", "Compute pd/fragments needs a pd/ material pair style" in out,
      [l for l in out.splitlines() if l.startswith("ERROR")][:1])
finish()
