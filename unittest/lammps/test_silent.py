"""Nothing silent: set-ups that used to run quietly wrong.

- Bonds per atom are reported per type; a type without bonds (a horizon
  below the real spacing: wrong lattice, volume or units) is an ERROR; two
  types that touch but share no bonds get a WARNING unless 'nobond' says so;
  so do a failing type and one that does not fail when only the mixing
  rules bond them (an impactor glued to its target), unless a pair_coeff
  I J line names their bonds ('nobond' or an interface).
- The bond families survive a run with another pair style (pair_style none).
- A restart written before the first run keeps fix pd/precrack's cut.
- A 'run 0' loop with displace_atoms (quasi-static loading) books every bond
  it breaks, as the same loading with 'run 1' does.
- pd/ordinary under hybrid/overlay with a type it has no coefficients for
  (a contact-only impactor): finite constants and energy, not NaN.
- An influence function that vanishes at the horizon (tupek) with partial
  cells beyond it makes no zero-weight bonds, which a failure law would
  "break" at once.
- pd/corr's stabilization, a penalty without an energy, says at setup that
  the energy is not conserved.
- 'unfix PD_BONDS' after bonds broke, then a run: an ERROR (a new store
  would build the families again and heal every broken bond).
"""
from lmptest import *

d = workdir()
H = HORIZON

# --- bonds per atom -------------------------------------------------------
# simple cubic, horizon 3 spacings: 122 lattice points within it (periodic)
out, _ = run(block(8) + PAIRS["pd/ordinary"] + "run 0\n", d)
check("bonds per atom by type are logged (122 in a periodic sc block)",
      "pd/bonds: bonds per atom by type: type 1 122.00;" in out)
sparse = replace_exact(block(6), f"lattice sc {SPACING}", "lattice sc 0.002")
check("the sparse deck really has a 4x larger spacing", "lattice sc 0.002" in sparse)
out, _ = run(sparse + PAIRS["pd/ordinary"] + "run 0\n", d, expect_error=True)
check("a body without bonds (spacing 0.002, horizon 0.0015) is an ERROR naming the type",
      "ERROR: Fix pd/bonds: atoms of type 1 have 0.00 bonds on average" in out)
lj = replace_exact(block(6), "units si", "units lj")
out, _ = run(lj + PAIRS["pd/ordinary"] + "run 0\n", d, expect_error=True)
check("an SI deck under units lj (no bonds) is an ERROR", "atoms of type 1 have 0.00 bonds on average" in out)

# two types side by side: lower half type 1, upper half type 2
TWO = replace_exact(block(8), "create_box 1 box", "create_box 2 box") + \
    f"region upper block INF INF INF INF 4 INF\nset region upper type 2\n"
out, _ = run(TWO + f"pair_style pd/ordinary\npair_coeff * * E 1e9 nu 0.25 horizon {H}\n"
             f"pair_coeff 1 2 horizon {0.5 * SPACING}\nrun 0\n", d)
check("two touching types with a horizon below the spacing: a WARNING names the pair",
      "WARNING: Fix pd/bonds: types 1 and 2 touch" in out and "pair_coeff 1 2 nobond" in out)
out, _ = run(TWO + f"pair_style pd/ordinary\npair_coeff * * E 1e9 nu 0.25 horizon {H}\n"
             "pair_coeff 1 2 nobond\nrun 0\n", d)
check("'nobond' keeps them apart without a warning, and the log says 0 bonds between them",
      "bonds between types: 1-2 0;" in out and "WARNING: Fix pd/bonds" not in out)
out, _ = run(TWO + f"pair_style pd/ordinary\npair_coeff * * E 1e9 nu 0.25 horizon {H}\nrun 0\n", d)
check("mixed types bond across the interface (the count is logged)",
      "bonds between types: 1-2" in out and "bonds between types: 1-2 0;" not in out)

# an elastic impactor (type 2) within a horizon of a breaking target (type 1)
GLUED = TWO + f"pair_style pd/ordinary\npair_coeff 1 1 E 1e9 nu 0.25 horizon {H} fail stretch s0 0.01\n" \
    f"pair_coeff 2 2 E 2e9 nu 0.25 horizon {H}\n"
out, _ = run(GLUED + "run 0\n", d)
check("a failing and an elastic type bonded by the mixing rules alone: a WARNING with the count and 'nobond'",
      re.search(r"WARNING: Fix pd/bonds: types 1 and 2 share \d+ bonds that no 'pair_coeff 1 2' line names", out)
      is not None and "'pair_coeff 1 2 nobond'" in out)
for line, what in (("pair_coeff 1 2 nobond", "'nobond'"), (f"pair_coeff 1 2 horizon {H}", "a named interface")):
    out, _ = run(GLUED + line + "\nrun 0\n", d)
    check(f"... {what} says what is meant: no warning", "pd/bonds: bonds per atom" in out
          and "WARNING: Fix pd/bonds" not in out)

# --- bonds near half a periodic box ----------------------------------------
# A bond that reaches past half the periodic box jumps to another image at
# the next reneighboring, and its energy with it. In a box of 7 spacings
# (horizon 3, half the skin 1) a lattice bond of 3 spacings is within half
# the skin of half the box: a WARNING; in 8 spacings it is not.
out, _ = run(block(7) + PAIRS["pd/ordinary"] + "run 0\n", d)
check("bonds within half the skin of half the periodic box: a WARNING with their count",
      re.search(r"WARNING: Fix pd/bonds: at step 0 \d+ bonds span nearly half the periodic box", out) is not None)
out, _ = run(block(8) + PAIRS["pd/ordinary"] + "run 0\n", d)
check("... none in a box of 8 spacings", "span nearly half the periodic box" not in out)
# a 2D plate as the docs lay it out: z periodic and one spacing thick, the
# default skin (1 mm in SI) larger than that period; its bonds lie in the plane
out, _ = run(plate(12) + f"pair_style pd/ordinary plane stress thickness 1e-3\n"
             f"pair_coeff * * E 1e9 nu 0.25 horizon {H}\nrun 0\n", d)
check("a 2D plate one spacing thick in a periodic z: no warning about half the box",
      "pd/bonds: bonds per atom" in out and "span nearly half the periodic box" not in out)

# --- pair_style none between runs -----------------------------------------
MOVE = ROUGH_VELOCITY + "fix 1 all nve\ntimestep 1e-8\ncompute dmg all pd/damage\n" \
    "compute dmax all reduce max c_dmg\ncompute frac all pd/fracture\n" \
    "thermo_style custom step pe c_dmax c_frac[4]\nthermo_modify format float %.15g\n"
out, rows = run(block(8) + PAIRS["pd/ordinary"] + MOVE + "run 10\npair_style none\nrun 5\n" +
                PAIRS["pd/ordinary"] + "run 10\n", d)
r = rows[-1]
check("a run with pair_style none keeps every bond: no damage, no lost partner",
      r["c_dmax"] < 1e-12 and r["c_frac[4]"] == 0.0, f"damage {r['c_dmax']:.3g} (round-off), lost {r['c_frac[4]']}")
check("... the log says the families were kept", "the bond families are kept unchanged" in out)
check("... and the material acts again afterwards (elastic energy)", r["PotEng"] > 0.0, f"{r['PotEng']:.3g}")

# --- a restart before the first run keeps the pre-crack ---------------------
PATCH = f"fix cut all pd/precrack patch {-3 * SPACING} {-3 * SPACING} {4.5 * SPACING} " \
    f"{16 * SPACING} 0 0 0 {16 * SPACING} 0\n"
out, rows = run(block(10) + PAIRS["pd/ordinary"] + PATCH + "thermo_style custom step f_cut\nrun 0\n", d)
direct = rows[-1]["f_cut"]
run(block(10) + PAIRS["pd/ordinary"] + PATCH + "write_restart early.restart\n", d)
out, rows = run("read_restart early.restart\ncompute dmg all pd/damage\ncompute dsum all reduce sum c_dmg\n"
                "thermo_style custom step c_dsum\nthermo_modify format float %.15g\nrun 0\n", d)
saved = log_value(out, r"pd/bonds: (\d+) bonds cut by the pre-cracks saved in the restart file")
check(f"a restart written before the first run keeps the cut ({direct:.0f} bonds)", saved == direct and direct > 0,
      f"{saved} vs {direct}")
check_le("... and the damage is that of the cut (2 x cut / 122)", abs(rows[-1]["c_dsum"] - 2 * direct / 122), 1e-9)

# --- breaks in a re-evaluated step are booked ---------------------------------
# A bar stretched in 12 increments, each followed by one force evaluation:
# 'run 0' (the step does not advance) must book what 'run 1' books.
def stretched(evaluate):
    return block(12, "s s s") + f"""pair_style pd/ordinary
pair_coeff * * E 1e9 nu 0.25 horizon {H} fail stretch 0.002
compute frac all pd/fracture
thermo_style custom step c_frac[2] c_frac[3]
thermo_modify format float %.15g
run 0
variable k loop 12
label again
displace_atoms all ramp x 0 {0.0006 * SPACING * 12} x 0 {SPACING * 12} units box
{evaluate}
next k
jump SELF again
run 0
"""


out0, rows0 = run(stretched("run 0"), d, name="in.run0")
out1, rows1 = run(stretched("run 1"), d, name="in.run1")
b0, b1 = rows0[-1]["c_frac[3]"], rows1[-1]["c_frac[3]"]
e0, e1 = rows0[-1]["c_frac[2]"], rows1[-1]["c_frac[2]"]
check("the loading breaks bonds", b1 > 100, f"{b1:.0f}")
check("a 'run 0' loop books the same broken bonds as 'run 1'", b0 == b1, f"{b0:.0f} vs {b1:.0f}")
check_le("... and the same dissipated energy", abs(e0 - e1) / e1, 1e-12, "same bonds, same states")

# --- data files ------------------------------------------------------------------
out, _ = run(block(8) + PAIRS["pd/ordinary"] + "run 0\nwrite_data cracked.data\n", d)
check("write_data after the families exist: a WARNING says what a data file loses",
      "WARNING: Fix pd/bonds: write_data does not store the bond families" in out)
out, _ = run("units si\nboundary p p p\natom_style peri\natom_modify map array\nread_data cracked.data\n"
             + PAIRS["pd/ordinary"] + "run 0\n", d)
check("... and the file still reads (the note is a comment in its header)", "pd/bonds: bonds per atom by type" in out
      and "# PERIDYNAMICS_EXT: no bond families" in open(f"{d}/cracked.data").read())

# --- lost partners, whatever the rank count --------------------------------------
# A block flies out of a fixed box (position-based velocities: the same
# motion on any rank count, although create_atoms numbers atoms by rank and
# so decides which end stores each bond). Every intact bond whose atom left
# is lost, counted once, whichever end stored it.
FLY = f"""units si
{{procs}}
boundary f f f
atom_style peri
atom_modify map array
lattice sc {SPACING}
region box block 0 12 0 12 0 12
create_box 1 box
region inner block 3 9 3 9 3 9
create_atoms 1 region inner
set group all density 2200
set group all volume {VOLUME}
pair_style pd/bond
pair_coeff * * pmb K 14.9e9 horizon {H}
variable phase atom x*7e3+y*3e4+z*1e5
variable vx atom 300+5*sin(12.9898*v_phase)
variable vy atom 5*sin(78.233*v_phase)
variable vz atom 5*sin(37.719*v_phase)
velocity all set v_vx v_vy v_vz units box
fix 1 all nve
timestep 2e-8
compute frac all pd/fracture
variable n equal count(all)
thermo_style custom step v_n c_frac[4]
thermo_modify lost ignore
run 600
"""
counts = {}
for procs, ranks in (("", 1), ("processors 2 1 1", 2), ("processors 1 2 1", 2)):
    out, rows = run(FLY.format(procs=procs), d, ranks=ranks)
    counts[procs or "1 rank"] = (rows[-1]["v_n"], rows[-1]["c_frac[4]"])
values = list(counts.values())
check("atoms leave the box (the same on every layout)", values[0][0] < 343 and len(set(v[0] for v in values)) == 1,
      str(counts))
check("lost partners: the same count on 1 rank and on 2 ranks split either way",
      len(set(v[1] for v in values)) == 1 and values[0][1] > 0, str(counts))
# ... and across a restart, with bonds breaking meanwhile: the counts the
# restart file carries (intact bonds at the last mapping, breaks since) give
# the same lost and broken counts as the unbroken run, on 1 and 2 ranks
SPLIT = block(10).replace("atom_modify map array", "atom_modify map hash") + PAIRS["pd/ordinary"].replace(
    "m 0.5\n", "m 0.5 fail stretch 0.001\n") + """run 0
group gone id 555
delete_atoms group gone compress no
velocity all ramp vx -5 5 x 0 0.005 units box
fix 1 all nve
timestep 1e-7
compute frac all pd/fracture
thermo_style custom step c_frac[3] c_frac[4]
run 50
write_restart split.restart
run 50
"""
check("the split deck breaks bonds and deletes an atom", "fail stretch 0.001" in SPLIT and "map hash" in SPLIT)
for ranks in (1, 2):
    _, rows = run(SPLIT, d, ranks=ranks)
    whole = (rows[-1]["c_frac[3]"], rows[-1]["c_frac[4]"])
    _, rows = run("read_restart split.restart\nfix 1 all nve\ncompute frac all pd/fracture\n"
                  "thermo_style custom step c_frac[3] c_frac[4]\nrun 50\n", d, ranks=ranks)
    restarted = (rows[-1]["c_frac[3]"], rows[-1]["c_frac[4]"])
    check(f"{ranks} rank(s): broken and lost counts continue across a restart (122 lost: the deleted atom's)",
          whole == restarted and whole[1] == 122 and whole[0] > 0, f"{whole} vs {restarted}")
# --- another sub-style's type under hybrid/overlay ------------------------
# type 2: one atom far above the block, pd/contact only; pd/ordinary has no
# coefficients for it (its energy and constants used to be NaN)
LONE = (f"units si\nboundary p p p\natom_style peri\natom_modify map array\nlattice sc {SPACING}\n"
        "region box block 0 8 0 8 0 16\ncreate_box 2 box\nregion body block 0 8 0 8 0 8\n"
        f"create_atoms 1 region body\ncreate_atoms 2 single 4 4 12\nset group all density {DENSITY}\n"
        f"set group all volume {VOLUME}\n")
HYB = (f"pair_style hybrid/overlay pd/ordinary pd/contact\npair_coeff 1 1 pd/ordinary E 1e9 nu 0.25 horizon {H}\n"
       "pair_coeff * * pd/contact stiffness 1e20\nvelocity all create 1e-3 7 dist gaussian\nfix 1 all nve\n"
       "timestep 1e-8\nthermo 5\nrun 10\n")
out, rows = run(LONE + HYB, d)
check("the lone atom is there", "Created 1 atoms" in out and "Loop time of" in out)
check("pd/ordinary under hybrid/overlay with a contact-only type: finite energy at every step",
      rows and all(math.isfinite(r["E_pair"]) and r["E_pair"] > 0.0 for r in rows), str([r["E_pair"] for r in rows][:3]))
check("... and its setup report prints no NaN (constants of its own types only)",
      "nan" not in " ".join(l for l in out.splitlines() if l.startswith("pd/")).lower())

# --- zero-weight bonds ----------------------------------------------------
# tupek's influence (1 - r/delta)^2 is 0 at the horizon; partial cells reach
# past it. At rest with the energy law nothing may break.
TUPEK = block(8) + (f"pair_style pd/ordinary influence tupek quadrature partial\n"
                    f"pair_coeff * * E 1e9 nu 0.25 horizon {H} fail energy Gc 100\n"
                    "compute f all pd/fracture\ncompute dmg all pd/damage\ncompute dmax all reduce max c_dmg\n"
                    "thermo_style custom step pe c_f[3] c_dmax\nfix 1 all nve\ntimestep 1e-8\nrun 5\n")
out, rows = run(TUPEK, d)
check("tupek + partial + energy law at rest: no bond breaks and no damage",
      rows and rows[-1]["c_f[3]"] == 0 and rows[-1]["c_dmax"] == 0.0,
      f"broken {rows[-1]['c_f[3]']:.0f}, damage {rows[-1]['c_dmax']:.3g}" if rows else "no thermo")
# --- stabilization: no energy, so a WARNING ---------------------------------
CORR = block(8) + f"pair_style pd/corr model elastic stabilization 0.1\npair_coeff * * E 1e9 nu 0.25 horizon {H}\nrun 0\n"
out, _ = run(CORR, d)
check("pd/corr stabilization: a WARNING that the energy is not conserved",
      "WARNING: Pair pd/corr: stabilization 0.1 is a penalty force without an energy" in out)
out, _ = run(CORR.replace(" stabilization 0.1", ""), d)
check("... and none without it", "penalty force without an energy" not in out)
# --- the bond store removed after fracture ----------------------------------
UNFIX = block(8) + (f"pair_style pd/bond\npair_coeff * * pmb K 1e9 horizon {H} fail stretch 0.001\n"
                    "velocity all ramp vx -5 5 x 0 0.004 units box\nfix 1 all nve\ntimestep 1e-8\n"
                    "compute f all pd/fracture\nthermo_style custom step c_f[3]\nrun 100\n")
out, rows = run(UNFIX, d)
check("the deck breaks bonds", rows and rows[-1]["c_f[3]"] > 0, f"{rows[-1]['c_f[3]']:.0f}" if rows else "")
out, _ = run(UNFIX + "unfix PD_BONDS\nrun 10\n", d, expect_error=True)
check("unfix of the bond store after fracture, then a run: an ERROR instead of healed bonds",
      "ERROR: Pair pd/bond: the bond store PD_BONDS was removed after it held the bond families" in out)
finish()
