"""Pre-cracks: fix pd/precrack breaks exactly the bonds whose
reference segment crosses the crack, on any rank count, and they stay
broken across a restart.

A periodic simple-cubic block of 10^3 atoms (horizon 3 spacings) is cut by
a patch in the plane z = 4.5 spacings that spans the box and the periodic
images a bond can reach (3 spacings either side): every column of
atoms then loses sum over the family of the bond vectors' z extent (in
layers, xi_z > 0) bonds, 10 x 10 columns in all. Each cut bond takes one
equal-volume partner from both its ends: the MS07 damage summed over the
atoms is 2 x cut / 122."""
import itertools
from lmptest import *

d = workdir()
family = [v for v in itertools.product(range(-3, 4), repeat=3) if 0 < sum(c * c for c in v) <= 9.0006]
expected = 100 * sum(v[2] for v in family if v[2] > 0)
h = SPACING
PATCH = f"fix cut all pd/precrack patch {-3 * h} {-3 * h} {4.5 * h} {16 * h} 0 0 0 {16 * h} 0\n"
script = block(10) + PAIRS["pd/ordinary"] + PATCH + """compute dmg all pd/damage
compute wdmg all pd/damage weighted
compute dsum all reduce sum c_dmg
compute wmax all reduce max c_wdmg
compute frac all pd/fracture
thermo_style custom step f_cut c_dsum c_wmax c_frac[3] c_frac[4]
thermo_modify format float %.15g
run 0
write_restart cut.restart
"""
for ranks in (1, 2):
    out, rows = run(script, d, ranks=ranks)
    r = rows[-1]
    check(f"{ranks} rank(s): the patch cuts {expected} bonds", r["f_cut"] == expected, f"{r['f_cut']:.0f}")
check_le("damage sums to 2 x cut / 122", abs(r["c_dsum"] - 2 * expected / 122), 1e-9)
check("weighted damage (T14 eq. 6.12) is between 0 and 1", 0 < r["c_wmax"] < 1, f"{r['c_wmax']:.3f}")
check("pre-cut bonds are not counted as fracture", r["c_frac[3]"] == 0)
check("pre-cut bonds are not counted as lost partners", r["c_frac[4]"] == 0, f"{r['c_frac[4]']:.0f}")
out, rows = run("""read_restart cut.restart
compute dmg all pd/damage
compute dsum all reduce sum c_dmg
thermo_style custom step c_dsum
thermo_modify format float %.15g
run 0
""", d)
check_le("the cut survives a restart", abs(rows[-1]["c_dsum"] - 2 * expected / 122), 1e-9)
# The group: only bonds with both ends in it are cut. Half the block
# (columns x < 5 spacings, periodic in x) keeps the bonds that cross the
# patch from or to the other half.
half = 10 * sum(v[2] * sum(1 for ix in range(5) if (ix + v[0]) % 10 < 5) for v in family if v[2] > 0)
out, rows = run(block(10) + PAIRS["pd/ordinary"] + f"region half block INF {4.5 * h} INF INF INF INF units box\n"
                "group half region half\n" + replace_exact(PATCH, "fix cut all", "fix cut half")
                + "thermo_style custom step f_cut\nrun 0\n", d)
check(f"a group cuts only its own bonds ({half} of {expected})", rows[-1]["f_cut"] == half, f"{rows[-1]['f_cut']:.0f}")
out, _ = run(block(10) + PAIRS["pd/ordinary"] + "fix cut all pd/precrack patch 1 1 1 0.1 0 0 0 0.1 0\n", d,
             expect_error=True)
check("a crack outside the box is an ERROR", "the crack lies outside the simulation box" in out)
finish()
