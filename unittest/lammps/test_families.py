"""The bond families as built (fix pd/bonds, fix_pd_bonds_build.cpp): the
same bonds as an independent brute-force search over all pairs.

Jittered simple cubic blocks (positions written here, so the reference
positions x0 are irregular and no pair sits on the horizon) are read on 2
and 3 ranks; before the first run all atoms are moved 2.6 spacings, across
the periodic boundary, plus a random 0.3 spacing, so current and reference
positions differ and x0 lies outside the box for some atoms. Point
quadrature: a pair is a bond iff its minimum-image reference distance is
at most the horizon. Each atom's bond count (family_volume / volume, both
ends) must equal the brute-force count, atom by atom, in
  - an orthogonal box, periodic in x and y, fixed in z, 2 ranks,
  - a tilted box (xy, xz, yz), periodic, 3 ranks.
The rows of the bond tables are as long as the most bonds one atom
stores, each bond at the end from which it points up (brute force too).
Partial quadrature with two types (horizons 3 and 4 spacings) has no
simple brute force: its bond count, per-type line and the histogram of
bonds per atom are the values of the neighbor-list build that preceded
the cell build (29 Sep 2021 LAMMPS, commit 5dcf657); which end stores a
bond has changed since, and with it the longest row."""
import random
import re
from collections import Counter
from lmptest import *

A, HORIZON, VOLUME = SPACING, 0.0015001, 1.25e-10
d = workdir()


def lattice(n, seed, tilt=(0.0, 0.0, 0.0)):
    """n^3 jittered sites (lattice units), in a box of n spacings, tilted by
    tilt = (xy, xz, yz) spacings; z keeps a margin for a fixed boundary."""
    rng = random.Random(seed)
    xy, xz, yz = tilt
    sites = []
    for k in range(n):
        for j in range(n):
            for i in range(n):
                u = [c + 0.5 + 0.3 * (rng.random() - 0.5) for c in (i, j, k)]
                sites.append(((u[0] + xy * u[1] / n + xz * u[2] / n) * A, (u[1] + yz * u[2] / n) * A, u[2] * A))
    return sites


def write_data(path, sites, n, tilt=None, types=None):
    with open(path, "w") as f:
        f.write(f"jittered block\n\n{len(sites)} atoms\n{2 if types else 1} atom types\n\n")
        f.write(f"0 {n * A!r} xlo xhi\n0 {n * A!r} ylo yhi\n0 {n * A!r} zlo zhi\n")
        if tilt:
            f.write(" ".join(repr(t * A) for t in tilt) + " xy xz yz\n")
        f.write("\nAtoms\n\n")
        for k, (x, y, z) in enumerate(sites):
            t = types(x) if types else 1
            f.write(f"{k + 1} {t} {VOLUME!r} 2200.0 {x!r} {y!r} {z!r}\n")


def minimum_image(dx, dy, dz, n, periodic, tilt):
    """The image convention of LAMMPS's Domain::minimum_image (z, y, x)."""
    L = n * A
    xy, xz, yz = (t * A for t in tilt)
    h = L / 2
    if periodic[2]:
        while abs(dz) > h:
            s = 1 if dz < 0 else -1
            dz, dy, dx = dz + s * L, dy + s * yz, dx + s * xz
    if periodic[1]:
        while abs(dy) > h:
            s = 1 if dy < 0 else -1
            dy, dx = dy + s * L, dx + s * xy
    if periodic[0]:
        while abs(dx) > h:
            dx += L if dx < 0 else -L
    return dx, dy, dz


def stored_at_first(dx, dy, dz):
    """Whether a bond is stored at the end it points away from: its
    reference vector points up (z, then y, then x; fix pd/bonds doc)."""
    for c in (dz, dy, dx):
        if c != 0.0:
            return c > 0.0
    raise ValueError("coincident atoms")


def brute_force(sites, n, periodic, tilt):
    """Bonds of each atom (by ID) over all pairs, and how many each stores."""
    count = [0] * (len(sites) + 1)
    stored = [0] * (len(sites) + 1)
    h2 = HORIZON * HORIZON
    for a in range(len(sites)):
        xa, ya, za = sites[a]
        for b in range(a + 1, len(sites)):
            xb, yb, zb = sites[b]
            dx, dy, dz = minimum_image(xb - xa, yb - ya, zb - za, n, periodic, tilt)
            if dx * dx + dy * dy + dz * dz <= h2:
                count[a + 1] += 1
                count[b + 1] += 1
                stored[a + 1 if stored_at_first(dx, dy, dz) else b + 1] += 1
    return count, stored


MOVE = (f"displace_atoms all move {2.6 * A!r} {-0.4 * A!r} 0.0 units box\n"
        f"displace_atoms all random {0.3 * A!r} {0.3 * A!r} {0.3 * A!r} 4711 units box\n")
COUNTS = ("compute fam all pd/atom family_volume\ncompute vol all property/atom vfrac\n"
          "dump d all custom 1 {file} id c_fam c_vol\ndump_modify d sort id format float %.17g\n"
          "run 0\n")


def bonds_per_atom(path):
    return {k: v[0] / v[1] for k, v in read_dump(path).items()}


def families(tag, sites, n, boundary, ranks, tilt=(0.0, 0.0, 0.0), pair=None, types=None):
    write_data(f"{d}/{tag}.data", sites, n, tilt if any(tilt) else None, types)
    pair = pair or f"pair_style pd/bond quadrature point\npair_coeff * * pmb K 14.9e9 horizon {HORIZON}\n"
    out, _ = run(f"units si\nboundary {boundary}\natom_style peri\natom_modify map array\n"
                 f"read_data {tag}.data\n" + MOVE + pair + COUNTS.format(file=f"{tag}.counts"), d, ranks=ranks)
    return out, bonds_per_atom(f"{d}/{tag}.counts")


for tag, n, boundary, ranks, tilt in [("orthogonal", 12, "p p f", 2, (0.0, 0.0, 0.0)),
                                      ("tilted", 10, "p p p", 3, (2.5, -1.5, 1.0))]:
    sites = lattice(n, seed=17 + n, tilt=tilt)
    out, got = families(tag, sites, n, boundary, ranks, tilt)
    want, stored = brute_force(sites, n, [c == "p" for c in boundary.split()], tilt)
    wrong = [k for k in got if abs(got[k] - want[k]) > 1e-9]
    check(f"{tag} box, {ranks} ranks: every atom has the bonds of the brute-force search",
          not wrong, f"{len(wrong)} of {len(got)} atoms differ" + (
              f", e.g. atom {wrong[0]}: {got[wrong[0]]:.3f} built, {want[wrong[0]]} brute force" if wrong else ""))
    total = log_value(out, r"pd/bonds: (\d+) bonds, ")
    check(f"{tag} box: the logged bond count is the brute-force count", total == sum(want) / 2,
          f"{total:.0f} logged, {sum(want) // 2} brute force")
    longest = log_value(out, r"up to (\d+) owned per atom")
    check(f"{tag} box: the rows are as long as the most bonds an atom stores (the end a bond points "
          "away from, upwards)", longest == max(stored), f"{longest:.0f} logged, {max(stored)} brute force")
    hist = Counter(round(v) for v in got.values())
    print(f"  {tag}: bonds per atom (count: atoms) {dict(sorted(hist.items()))}")
    check(f"{tag} box: jitter gives a spread of family sizes (the test sees irregular families)", len(hist) > 5)

# perfect lattices: bonds on a plane of z (2D: a line of y) are ties that
# the exact reference vector decides, so every atom stores half its family
for dim, deck, plane, modulus in [(3, block(8), "", "K 14.9e9"),
                                  (2, plate(12), " plane stress thickness 1e-3", "E 72e9")]:
    r = HORIZON / SPACING
    span = range(-3, 4)
    family = sum(1 for i in span for j in span for k in (span if dim == 3 else [0])
                 if 0 < i * i + j * j + k * k <= r * r)
    out, _ = run(deck + f"pair_style pd/bond quadrature point{plane}\npair_coeff * * pmb {modulus} horizon {HORIZON}\n"
                 "run 0\n", d, ranks=2)
    per_atom, longest = log_value(out, r"([\d.]+) bonds per atom \("), log_value(out, r"up to (\d+) owned per atom")
    check(f"{dim}D lattice, 2 ranks: every atom stores half of its {family} bonds", per_atom == family
          and longest == family // 2, f"{per_atom:.2f} bonds per atom, up to {longest:.0f} stored per atom")

# partial quadrature, two types: the values of the neighbor-list build
sites = lattice(12, seed=29)
out, got = families("partial", sites, 12, "p p f", 2, types=lambda x: 1 if x < 6 * A else 2,
                    pair="pair_style pd/ordinary quadrature partial\n"
                    f"pair_coeff 1 1 K 14.9e9 G 9e9 horizon {HORIZON} m 0.5\n"
                    f"pair_coeff 2 2 K 10e9 G 6e9 horizon {4.0001 * A!r} m 0.5\n")
# per-atom bond counts c_id: sum c, sum id c, sum c^2 (exact integers)
counts = {k: round(v) for k, v in got.items()}
fingerprint = (sum(counts.values()), sum(k * c for k, c in counts.items()), sum(c * c for c in counts.values()))
OLD = {"bonds": 283842, "fingerprint": (567684, 490992501, 199246792),
       "types": "pd/bonds: bonds per atom by type: type 1 268.39; type 2 388.65; bonds between types: 1-2 101004;"}
total = log_value(out, r"pd/bonds: (\d+) bonds, ")
check("partial quadrature, 2 types: bonds as the neighbor-list build made them", total == OLD["bonds"],
      f"{total:.0f} bonds")
types = re.search(r"pd/bonds: bonds per atom by type:.*", out)
check("partial quadrature, 2 types: bonds per atom by type as before", types and types.group(0) == OLD["types"],
      types.group(0) if types else "no line")
check("partial quadrature, 2 types: each atom's bond count as before (sums of c, id c, c^2 over atoms)",
      fingerprint == OLD["fingerprint"], str(fingerprint))
finish()
