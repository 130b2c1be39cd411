"""compute pd/atom and pd/damage.

A uniform dilatation s of the periodic block stretches every bond by exactly
s, so the dilatation is 3 s at every atom and the energy density K theta^2/2
(LPS, discretely normalized: exact, not a lattice approximation). Deleting
one atom takes one partner of equal volume from each of its 122 neighbors:
their damage is 1/122 exactly, and the lost partners are counted.

Declared per-atom fields: compute pd/atom lists the bond store's
fields by name. The weighted volume of an atom of the periodic block is the
lattice sum of its family, and the dissipated energy per atom sums to
compute pd/fracture's total. The store's migrate+restart fields keep their
values when atoms cross between two processors and through a restart
file, which names each field and its width: a file that disagrees is an
ERROR that names the field."""
import struct
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

# An intact body that moves, is re-sorted and re-neighboured, on 1 and 2
# ranks: its intact sums then add the same volumes in another order than
# the reference (1 - intact / reference read +-1.4e-15 before the compute
# snapped round-off), and a damage > 0 test must not see a crack.
script = block(10) + PAIRS["pd/bond"] + """atom_modify sort 10 0.0
velocity all create 1e20 4928 dist gaussian
fix 1 all nve
timestep 1e-8
neighbor 0.0001 bin
neigh_modify every 1 delay 0 check no
compute dmg all pd/damage
compute dmin all reduce min c_dmg
compute dmax all reduce max c_dmg
run 0 post no
thermo_style custom step c_dmin c_dmax f_PD_BONDS
thermo_modify format float %.17g
thermo 20
run 100
"""
for ranks in (1, 2):
    out, rows = run(script, d, ranks=ranks)
    check(f"moving intact body on {ranks} rank(s): 100 steps, no bond lost (an elastic pair breaks none)",
          len(rows) == 6 and all(r["f_PD_BONDS"] == 0 for r in rows), str(rows[-1]))
    worst = max(max(abs(r["c_dmin"]), abs(r["c_dmax"])) for r in rows)
    check(f"moving intact body on {ranks} rank(s): damage is exactly 0 after sorting and reneighboring",
          worst == 0.0, f"{worst:g}")

# point quadrature: the 122 lattice neighbours within the horizon
script = block(10) + replace_exact(PAIRS["pd/bond"], "pair_style pd/bond", "pair_style pd/bond quadrature point") + """compute dmg all pd/damage
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

# --- declared fields by name ------------------------------------------------
# Every atom of the periodic block has a complete family: its weighted
# volume (pd/ordinary, default influence delta/|xi| in 3D) and family volume
# are the sums over the lattice points within the horizon.
points = [(a, b, c) for a in range(-3, 4) for b in range(-3, 4) for c in range(-3, 4)
          if 0 < SPACING * math.sqrt(a * a + b * b + c * c) <= HORIZON]
want_weighted = sum(HORIZON / (SPACING * math.sqrt(a * a + b * b + c * c)) * VOLUME for a, b, c in points)
want_family = len(points) * VOLUME
script = block(10) + PAIRS["pd/ordinary"] + """compute pd all pd/atom weighted_volume family_volume dilatation
compute wv all pd/atom weighted_volume
compute wmin all reduce min c_pd[1]
compute wmax all reduce max c_pd[1]
compute wvmax all reduce max c_wv
compute fmin all reduce min c_pd[2]
compute fmax all reduce max c_pd[2]
thermo_style custom step c_wmin c_wmax c_wvmax c_fmin c_fmax
thermo_modify format float %.17g
run 0
"""
out, rows = run(script, d)
r = rows[-1]
err = max(abs(r["c_wmin"] - want_weighted), abs(r["c_wmax"] - want_weighted)) / want_weighted
check_le(f"weighted_volume of every atom is the lattice sum over its {len(points)} partners", err, 1e-12,
         "round-off of a sum of 122 terms")
check("a single width-1 field is a per-atom vector with the same values", r["c_wvmax"] == r["c_wmax"],
      f"{r['c_wvmax']!r} vs {r['c_wmax']!r}")
err = max(abs(r["c_fmin"] - want_family), abs(r["c_fmax"] - want_family)) / want_family
check_le("family_volume of every atom is 122 V", err, 1e-12)
out, _ = run(block(6) + PAIRS["pd/ordinary"] + "compute pd all pd/atom dissipated nosuchfield\n", d,
             expect_error=True)
check("an unknown field is an ERROR that lists the available ones",
      "unknown field 'nosuchfield'; available: energy, dissipated, family_volume, weighted_volume, dilatation" in out,
      out[out.find("ERROR"):][:200])

# A body that keeps breaking bonds while drifting across the boundary of
# the two processors (along z) and the periodic boundary: neighbor skin
# 0.2 spacings, so atoms are exchanged every ten steps or so.
BREAKING = block(12) + """neighbor 1e-4 bin
variable vx atom 2*sin(12.9898*id)
variable vy atom 2*sin(78.233*id)
variable vz atom 2*sin(37.719*id)
velocity all set v_vx v_vy v_vz units box
velocity all set NULL NULL 40.0 sum yes units box
pair_style pd/bond
""" + f"pair_coeff * * pmb K {BULK} horizon {HORIZON} fail stretch 1e-3\n"
OUTPUT = """compute pd all pd/atom dissipated weighted_volume family_volume
compute frac all pd/fracture
compute dsum all reduce sum c_pd[1]
compute fsum all reduce sum c_frac
thermo 50
thermo_style custom step c_frac[1] c_dsum c_frac[3] c_fsum
thermo_modify format float %.17g
"""
FIELDS_DUMP = "write_dump all custom {file} id proc c_pd[1] c_pd[2] c_pd[3] c_frac modify sort id format float %.17g\n"
STEPS = "fix 1 all nve\ntimestep 1.0e-7\n"
out, rows = run(BREAKING + OUTPUT + STEPS + "run 0\n" + FIELDS_DUMP.format(file="f.start") + "run 100\n" +
                FIELDS_DUMP.format(file="f.mid") + "write_restart f.restart\nrun 100\n" +
                FIELDS_DUMP.format(file="f.end"), d, ranks=2)
start, mid, end = (read_dump(f"{d}/f.{w}") for w in ("start", "mid", "end"))
moved = sum(1 for k in start if start[k][0] != end[k][0])
check("atoms moved between the two processors", moved > 100, f"{moved} of {len(start)} atoms changed processor")
check("the reference volumes migrate with their atoms: unchanged to the last bit",
      all(end[k][2:4] == start[k][2:4] for k in start))
r = rows[-1]
check_le("the per-atom dissipated energy sums to compute pd/fracture's total after migrations",
         abs(r["c_dsum"] / r["c_frac[1]"] - 1), 1e-12, "round-off of the sum")
half, full = sum(v[1] for v in mid.values()), sum(v[1] for v in end.values())
check("energy was dissipated in both halves of the run (the values carried are not trivially zero)",
      0 < half < full, f"{half:.4g} then {full:.4g}")
check("compute pd/atom dissipated is compute pd/fracture's per-atom value",
      all(end[k][1] == end[k][4] for k in end) and max(v[1] for v in end.values()) > 0)
# the same, continued from the restart file written half-way
READ = "read_restart f.restart\nneighbor 1e-4 bin\n" + OUTPUT + "fix 1 all nve\n"
out, rows2 = run(READ + "run 0\n" + FIELDS_DUMP.format(file="f.read") + "run 100\n" +
                 FIELDS_DUMP.format(file="f.end2"), d, ranks=2)
read, end2 = read_dump(f"{d}/f.read"), read_dump(f"{d}/f.end2")
check("after read_restart the per-atom fields are those written (dissipated, volumes)",
      all(read[k][1:4] == mid[k][1:4] for k in mid))
diff = max(abs(end2[k][1] - end[k][1]) for k in end) / max(abs(end[k][1]) for k in end)
check_le("the restarted run dissipates per atom as the unsplit run", diff, 1e-9,
         "summation order differs after the file redistributes the atoms")
check("and keeps the reference volumes", all(end2[k][2:4] == end[k][2:4] for k in end))
check_le("the sum matches the total after the restart", abs(rows2[-1]["c_dsum"] / rows2[-1]["c_frac[1]"] - 1), 1e-12)

# The global record names each restart field and its width: a file that
# disagrees with this build is refused by the field's name (the edited
# record resealed with its checksum, as a build that wrote it would).
raw = open(f"{d}/f.restart", "rb").read()
flags = 2 | 4 | 8    # MIGRATE | RESTART | OUTPUT
entry = struct.pack("<qqq", 1, flags, len("weighted_volume")) + b"weighted_volume"
check("the restart file lists the field by name and width", raw.count(entry) == 1)
open(f"{d}/f.wide", "wb").write(reseal_bond_record(
    replace_exact(raw, entry, struct.pack("<qqq", 2, flags, 15) + b"weighted_volume")))
out, _ = run("read_restart f.wide\nrun 0\n", d, expect_error=True)
check("a field of another width is an ERROR naming it",
      "per-atom field 'weighted_volume' has width 2 in the restart file, 1 in this build" in out,
      out[out.find("ERROR"):][:200])
open(f"{d}/f.renamed", "wb").write(reseal_bond_record(
    replace_exact(raw, struct.pack("<q", 10) + b"dissipated", struct.pack("<q", 10) + b"dissipatex")))
out, _ = run("read_restart f.renamed\nrun 0\n", d, expect_error=True)
check("fields are read by name, not by position: a file without 'dissipated' is an ERROR naming it",
      "restart file carries no per-atom field 'dissipated'" in out, out[out.find("ERROR"):][:200])
out, _ = run("read_restart f.restart\nrun 0\n", d)
check("resealing an unedited file leaves it as written (the test's checksum is the package's)",
      reseal_bond_record(raw) == raw)
finish()
