"""Short-range contact: two elastic blocks that were
never bonded (their gap exceeds the horizon) collide at 2 x 20 m/s.

pd/contact (hybrid/overlay with pd/ordinary) pushes particles closer than
their contact distance (the spacing, from the volumes) apart with equal and
opposite forces: momentum is conserved to round-off, the elastic rebound
conserves kinetic + elastic energy within 1% (velocity Verlet at 0.15 of
the stable step; the contact spring is 15 c), and the facing surfaces never
come closer than 90% of the contact distance. Without pd/contact the same
blocks pass through each other, so the test can fail. 1 and 2 ranks agree."""
import math
from lmptest import *

d = workdir()


def blocks(pairs, steps=3000, ranks=1, data=None, dump="", vy=0.0):
    atoms = (f"read_data {data}\n" if data else
             "region box block -1 17 0 8 0 8\ncreate_box 2 box\nregion a block 0 5 INF INF INF INF\n"
             "region b block 10 15 INF INF INF INF\ncreate_atoms 1 region a\ncreate_atoms 2 region b\n")
    return f"""units si
boundary s p p
atom_style peri
atom_modify map array
lattice sc {SPACING}
{atoms}group a type 1
group b type 2
set group all density 1180
set group all volume {VOLUME}
{pairs}
velocity a set 20 {vy} 0 units box
velocity b set -20 {-vy} 0 units box
variable vya equal vcm(a,y)
variable py equal mass(all)*vcm(all,y)
variable gap equal bound(b,xmin)-bound(a,xmax)
variable px equal mass(all)*vcm(all,x)
variable pa equal mass(a)*vcm(a,x)
{ENERGY_JOULES}fix 1 all nve
timestep 2e-8
thermo 50
thermo_style custom step c_KEJ c_PEJ v_etot v_gap v_px v_pa v_vya v_py
thermo_modify format float %.15g
run {steps}
{dump}"""


# unwrapped coordinates: restart re-wraps atoms into the periodic y and z
UNWRAPPED = replace_exact(DUMP, "id x y z", "id xu yu zu")
CONTACT = (f"pair_style hybrid/overlay pd/ordinary pd/contact\n"
           f"pair_coeff * * pd/ordinary E 3.5e9 nu 0.25 horizon {HORIZON}\npair_coeff * * pd/contact\n")
out, rows = run(blocks(CONTACT, dump=DUMP.format(file="one")), d)
e0, p0 = rows[0]["v_etot"], rows[0]["v_pa"]
gap_min = min(r["v_gap"] for r in rows)
print(f"contact: smallest gap {gap_min:.4g} m (contact distance {SPACING}), final energy "
      f"{rows[-1]['v_etot'] / e0 - 1:+.2e}, block momentum {rows[-1]['v_pa'] / p0:+.3f} of initial")
check("the blocks rebound (block A's momentum reversed)", rows[-1]["v_pa"] < -0.5 * p0)
check_le("momentum conserved", max(abs(r["v_px"]) for r in rows) / abs(p0), 1e-12, "equal and opposite forces")
check_le("energy conserved through the rebound", max(abs(r["v_etot"] / e0 - 1) for r in rows), 0.01,
         "Verlet at 0.15 of the stable step")
check("no interpenetration: the gap stays above 0.9 contact distance", gap_min > 0.9 * SPACING, f"{gap_min:.4g}")
check("the contact list is short (its own cutoff, not the horizon)",
      log_value(out, r"pd/contact: list cutoff ([0-9.eE+-]+)") < HORIZON + 0.0010001)

_, rows = run(blocks(f"pair_style pd/ordinary\npair_coeff * * E 3.5e9 nu 0.25 horizon {HORIZON}\n", steps=4000), d)
check("without pd/contact the blocks pass through each other", min(r["v_gap"] for r in rows) < 0)

run(blocks(CONTACT, steps=0).split("group a")[0] + "write_data two.data\n", d)
finals = {}
for ranks in (1, 2):
    run(blocks(CONTACT, steps=2600, data="two.data", dump=UNWRAPPED.format(file=f"r{ranks}")), d, ranks=ranks)
    finals[ranks] = read_dump(f"{d}/r{ranks}")
check_le("1 and 2 ranks end at the same positions", max_rel_diff(finals[1], finals[2]), 1e-10, "round-off")

# restart as the faces touch (step 2450 of 2600): the bond families, broken state
# and the sub-styles' settings come from the file; pair_style hybrid keeps
# no coefficients in restart files (LAMMPS), so the pair_coeff lines return
run(blocks(CONTACT, steps=2450, data="two.data", dump="write_restart mid.restart\n"), d)
run("read_restart mid.restart\n" + CONTACT.split("\n", 1)[1] + "fix 1 all nve\nrun 150\n" +
    UNWRAPPED.format(file="split"), d)
check_le("a restart as the faces touch continues as the unsplit run",
         max_rel_diff(finals[1], read_dump(f"{d}/split")), 1e-12, "round-off after re-sorting")

# Coulomb friction (Peridigm-style) in an oblique collision: it slows the
# sliding of the faces (block A's tangential velocity), conserves momentum,
# and dissipates. (Without friction the sliding is not untouched either: the
# faces are rows of particles, whose contact normals tilt as they pass.)
slide = {}
for mu in (0.0, 0.5):
    style = replace_exact(CONTACT, "pd/ordinary pd/contact\n", f"pd/ordinary pd/contact friction {mu}\n") if mu else CONTACT
    _, rows = run("comm_modify vel yes\n" + blocks(style, vy=10.0), d)
    slide[mu] = rows[-1]["v_vya"] / rows[0]["v_vya"]
    if mu:
        check_le("friction: momentum conserved", max(abs(r["v_px"]) + abs(r["v_py"]) for r in rows) / abs(p0),
                 1e-12, "equal and opposite")
        check("friction dissipates (kinetic + elastic energy drops by > 1%)", rows[-1]["v_etot"] < 0.99 * rows[0]["v_etot"])
print(f"tangential velocity kept: {slide[0.0]:.3f} without friction, {slide[0.5]:.3f} with mu = 0.5")
check("friction removes tangential motion that frictionless contact keeps",
      slide[0.5] < 0.5 * slide[0.0], f"{slide[0.5]:.3f} vs {slide[0.0]:.3f}")

bad = [("negative stiffness", "pair_style pd/contact\npair_coeff * * stiffness -1\n", "stiffness must be a positive finite number"),
       ("negative contact distance", "pair_style pd/contact\npair_coeff * * stiffness 1e20 distance -1e-4\n",
        "distance must be a positive finite number"),
       ("legacy contact without a legacy material",
        replace_exact(CONTACT, "pd/ordinary pd/contact\n", "pd/ordinary pd/contact legacy\n") + "run 0\n", "pd/contact legacy needs"),
       ("contact alone without stiffness", "pair_style pd/contact\npair_coeff * *\nrun 0\n",
        "without a pd/ material style"),
       ("unknown keyword", "pair_style pd/contact\npair_coeff * * friction 0.3\n", "unknown keyword 'friction'"),
       ("friction without ghost velocities", "pair_style pd/contact friction 0.3\npair_coeff * * stiffness 1e20\nrun 0\n",
        "'comm_modify vel yes'")]
for what, pairs, message in bad:
    out, _ = run(blocks(pairs, steps=0).split("velocity a")[0] + pairs, d, expect_error=True)
    check(f"bad input, {what}: ERROR names it", message in out)
# Default stiffness of unlike types: 15 times each type's PMB-equivalent
# micromodulus (3D: 12 E / (pi delta^4)), and their harmonic mean for the
# pair, not a value from the pair's horizon (here 'nobond': the bodies
# share no bonds).
UNLIKE = (f"pair_style hybrid/overlay pd/ordinary pd/contact\n"
          f"pair_coeff * * pd/ordinary E 3.5e9 nu 0.25 horizon {HORIZON}\n"
          f"pair_coeff 2 2 pd/ordinary E 70e9 nu 0.25 horizon {HORIZON}\n"
          f"pair_coeff 1 2 pd/ordinary nobond\npair_coeff * * pd/contact\n")
out, _ = run(blocks(UNLIKE, steps=0), d)
c11, c12, c22 = (log_value(out, rf"stiffness c_s.* {p} ([0-9.e+]+)") for p in ("1-1", "1-2", "2-2"))
expected = [15 * 12 * e / (math.pi * HORIZON ** 4) for e in (3.5e9, 70e9)]
check_le("default stiffness of a type: 15 x 12 E / (pi delta^4)",
         max(abs(c11 / expected[0] - 1), abs(c22 / expected[1] - 1)), 1e-5, "6 digits in the log")
check_le("unlike types: the harmonic mean of their own values", abs(c12 / (2 * c11 * c22 / (c11 + c22)) - 1), 1e-5,
         "the softer body sets it; not from the pair's horizon")

# pd/contact alone, stiffness given for each type only: the unset 1 2 pair
# takes the mean of the two (LAMMPS-style mixing), no ERROR.
out, _ = run(blocks("pair_style pd/contact\npair_coeff 1 1 stiffness 1e22\npair_coeff 2 2 stiffness 3e22\n",
                    steps=0), d)
check_le("pd/contact alone: an unset pair mixes the given values",
         abs(log_value(out, r"stiffness c_s.* 1-2 ([0-9.e+]+)") / 2e22 - 1), 1e-12)
finish()
