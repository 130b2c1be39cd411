"""The per-atom virial: compute stress/atom.

Uniform strain: the periodic simple cubic block stretched by (1, -0.4,
0.25) x 1e-6 along x, y, z. Every atom's stress/atom over its volume must
be the classical stress lambda tr(e) I + 2 mu e, all six components, on 1
and 2 ranks, for pd/bond (nu = 1/4: lambda = mu), pd/ordinary and pd/corr
(G = 0.4 K: lambda and mu apart), to 1e-5 of the largest component: the
directional correction makes pd/bond's and pd/ordinary's constants on this
lattice exact to 1e-7, pd/corr's are exact, and the stretch is linear in
the strain to 1e-6 of it. A per-atom virial off by its sign, by half, or
missing the ghosts' shares that compute stress/atom brings home from the
neighbouring rank fails.

The same strain of a free block (its surfaces make the atoms differ):
atoms at places mirrored through its centre must carry the same
stress/atom to 1e-9 (the displacements are 1e-6 of the positions, whose
round-off is 1e-16 of them), whichever end of a bond its half list made
the bond's owner: every tensor put onto the owner fails by 0.6.

Contact: two blocks collide (pd/contact with pd/bond, hybrid/overlay,
1 and 2 ranks); while their faces touch, the per-atom virials of both
styles sum to the global virial times the volume (negated: stress/atom is
a stress times a volume) to 1e-12 of the largest component (the same
pairs' tensors summed in another order). pd/bond's loop is checked the
same way, with bonds breaking, for every material, in test_kernels.py."""
from lmptest import *

d = workdir()
STRAIN = (1e-6, -0.4e-6, 0.25e-6)
G_CORR = 0.4 * BULK
STYLES = {
    # pmb: nu = 1/4, lambda = mu = 3/5 K
    "pd/bond": (PAIRS["pd/bond"], 0.6 * BULK, 0.6 * BULK),
    "pd/ordinary": (f"pair_style pd/ordinary\npair_coeff * * K {BULK} G {G_CORR} horizon {HORIZON}\n",
                    BULK - 2 * G_CORR / 3, G_CORR),
    "pd/corr": (f"pair_style pd/corr strain classical model elastic\n"
                f"pair_coeff * * K {BULK} G {G_CORR} horizon {HORIZON}\n", BULK - 2 * G_CORR / 3, G_CORR),
}
NAMES = ("xx", "yy", "zz", "xy", "xz", "yz")


def stress_deck(pair):
    reduce = "".join(f"variable s{n} atom c_sa[{c + 1}]/c_vf\ncompute lo{n} all reduce min v_s{n}\n"
                     f"compute hi{n} all reduce max v_s{n}\n" for c, n in enumerate(NAMES))
    keys = " ".join(f"c_lo{n} c_hi{n}" for n in NAMES)
    return block(8) + pair + f"""compute vf all property/atom vfrac
compute sa all stress/atom NULL virial
{reduce}thermo_style custom step {keys}
thermo_modify format float %.17g
run 0
change_box all x scale {1 + STRAIN[0]!r} y scale {1 + STRAIN[1]!r} z scale {1 + STRAIN[2]!r} remap
run 0
"""


for style, (pair, lam, mu) in STYLES.items():
    tr = sum(STRAIN)
    want = [lam * tr + 2 * mu * e for e in STRAIN] + [0.0, 0.0, 0.0]
    scale = max(abs(w) for w in want)
    for ranks in (1, 2):
        _, rows = run(stress_deck(pair), d, ranks=ranks)
        r = rows[-1]
        worst = max(max(abs(r[f"c_lo{n}"] - w), abs(r[f"c_hi{n}"] - w)) for n, w in zip(NAMES, want)) / scale
        check_le(f"{style}, {ranks} rank(s): stress/atom / V is the classical stress at every atom",
                 worst, 1e-5, f"constants exact to 1e-7, strain second order 1e-6 (sigma_xx {want[0]:.6g} Pa, "
                 f"atoms {r['c_loxx']:.6g} .. {r['c_hixx']:.6g})")

# a free block strained the same way: the owner of each bond (its half
# list's choice) must not show, so atoms at mirrored places (through the
# block's centre) carry the same stress/atom
for style in ("pd/bond", "pd/ordinary"):
    script = block(9, "s s s") + STYLES[style][0] + f"""run 0
variable ux atom x*{STRAIN[0]!r}
variable uy atom y*{STRAIN[1]!r}
variable uz atom z*{STRAIN[2]!r}
displace_atoms all move v_ux v_uy v_uz units box
compute sa all stress/atom NULL virial
# (a dump of the run, not write_dump after it: LAMMPS 6 Jan 2022 refuses a
# compute that no run invoked)
dump free all custom 1 free.dump id x y z c_sa[1] c_sa[2] c_sa[3] c_sa[4] c_sa[5] c_sa[6]
dump_modify free format float %.17g
run 0
"""
    run(script, d)
    atoms = list(read_dump(f"{d}/free.dump").values())
    lo = [min(a[c] for a in atoms) for c in range(3)]
    hi = [max(a[c] for a in atoms) for c in range(3)]
    cell = lambda p: tuple(round((p[c] - lo[c]) / (hi[c] - lo[c]) * 9) for c in range(3))
    at = {cell(a): a[3:] for a in atoms}
    top = max(abs(v) for a in atoms for v in a[3:])
    worst = max(abs(s - m) for k, v in at.items() for s, m in zip(v, at[tuple(9 - c for c in k)])) / top
    check_le(f"{style}, free block: stress/atom is the same at atoms mirrored through the centre "
             f"({len(atoms)} atoms)", worst, 1e-9, "each bond's tensor half to each end, whichever owns it")

COLLIDE = two_blocks() + f"""set group all density 1180
set group all volume {VOLUME}
pair_style hybrid/overlay pd/bond pd/contact
pair_coeff * * pd/bond pmb E 3.5e9 horizon {HORIZON}
pair_coeff * * pd/contact
velocity a set 20 0 0 units box
velocity b set -20 0 0 units box
compute sa all stress/atom NULL virial
compute ssa all reduce sum c_sa[1] c_sa[2] c_sa[3] c_sa[4] c_sa[5] c_sa[6]
compute vir all pressure NULL virial
compute ec all pair pd/contact
fix 1 all nve
timestep 2e-8
thermo 50
thermo_style custom step vol c_ec c_vir[1] c_vir[2] c_vir[3] c_vir[4] c_vir[5] c_vir[6] {" ".join(f"c_ssa[{c}]" for c in range(1, 7))}
thermo_modify format float %.17g
run 2600
"""

for ranks in (1, 2):
    _, rows = run(COLLIDE, d, ranks=ranks)
    touching = [r for r in rows if r["c_ec"] > 0]
    worst = 0.0
    for r in rows:
        glob = [r["Volume"] * r[f"c_vir[{c}]"] for c in range(1, 7)]
        top = max(abs(g) for g in glob)
        if top > 0:
            worst = max(worst, max(abs(r[f"c_ssa[{c}]"] + g) for c, g in zip(range(1, 7), glob)) / top)
    check(f"contact, {ranks} rank(s): the faces touch during the run (contact energy > 0)", len(touching) >= 3,
          f"{len(touching)} of {len(rows)} rows")
    check_le(f"contact, {ranks} rank(s): the per-atom virials sum to the global virial at each of "
             f"{len(rows)} rows", worst, 1e-12, "the same pairs' tensors summed in another order")

finish()
