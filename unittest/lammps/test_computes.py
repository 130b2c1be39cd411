"""compute pd/atom and pd/damage (issue 2).

A uniform dilatation s of the periodic block stretches every bond by exactly
s, so the dilatation is 3 s at every atom and the energy density K theta^2/2
(LPS, discretely normalized: exact, not a lattice approximation). Deleting
one atom takes one partner of equal volume from each of its 122 neighbors:
their damage is 1/122 exactly, and the lost partners are counted."""
from lmptest import *

d = workdir()
s = 1e-4
for style in ["pd/ordinary", "pd/bond"]:
    script = block(10) + PAIRS[style] + f"""compute pd all pd/atom dilatation energy
compute dmg all pd/damage
compute thmin all reduce min c_pd[1]
compute thmax all reduce max c_pd[1]
compute emin all reduce min c_pd[2]
compute emax all reduce max c_pd[2]
compute dmax all reduce max c_dmg
thermo_style custom step c_thmin c_thmax c_emin c_emax c_dmax
thermo_modify format float %.15g
run 0
change_box all x scale {1 + s} y scale {1 + s} z scale {1 + s} remap
run 0
"""
    out, rows = run(script, d)
    r = rows[-1]
    check_le(f"{style}: dilatation is 3 s at every atom", max(abs(r["c_thmin"] - 3 * s), abs(r["c_thmax"] - 3 * s)) / (3 * s),
             1e-9, "round-off")
    check_le(f"{style}: damage of an intact body is 0", r["c_dmax"], 0.0)
    if style == "pd/ordinary":
        want = 0.5 * BULK * (3 * s) ** 2
        err = max(abs(r["c_emin"] - want), abs(r["c_emax"] - want)) / want
        check_le(f"{style}: energy density K theta^2/2 at every atom", err, 1e-9, "round-off")

script = block(10) + PAIRS["pd/bond"] + """compute dmg all pd/damage
compute dmax all reduce max c_dmg
compute dsum all reduce sum c_dmg
run 0
group gone id 555
delete_atoms group gone compress no
thermo_style custom step c_dmax c_dsum f_PD_BONDS
thermo_modify format float %.15g
run 0
"""
out, rows = run(script, d)
r = rows[-1]
check_le("damage of a neighbor of a deleted atom is 1/122", abs(r["c_dmax"] - 1 / 122) * 122, 1e-12)
check_le("total damage is 122 x 1/122", abs(r["c_dsum"] - 1.0), 1e-12)
check("lost partners are counted: all 122 bonds of the deleted atom, whichever end stored them",
      r["f_PD_BONDS"] == 122, f"{r['f_PD_BONDS']:g}")
# delete_atoms renumbers atoms by default: the stored partner tags would then
# name other atoms, which must be refused, not silently used
out, _ = run(replace_exact(script, " compress no", ""), d, expect_error=True)
check("renumbered atoms (delete_atoms compress yes) are refused", "atom IDs changed since the bond families" in out)
finish()
