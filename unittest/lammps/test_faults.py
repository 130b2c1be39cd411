"""Faults end in a clear ERROR, not NaN, a crash or a lost message.

- Blow-ups: at 5x and 50x the stable step the guard stops the run within a
  few steps with an ERROR that names an atom, its position and the time
  step against the stable estimate (before: NaN output, then a LAMMPS bin
  or lost-atom error). A precompressed plate with m = 0 at 1.4x the
  setup's estimate (1.9x its current state's) grows geometrically: the
  guard names the kinetic energy's growth and fix pd/timestep long before
  any particle is fast; at 1.0x (above the current estimate too, but
  stable: the estimate is a bound) it runs on. A rigid translation 2x
  faster than the guard's speed limit is no fault. Two particles pushed onto each other with m = 0
  (log strain: infinite force) name the bond's two atoms.
- A damaged restart file is an ERROR, not a segfault or a different run:
  partner IDs or bond counts overwritten, one bit of a bond's length (the
  sign that marks it broken: a change of the damage only) or of a field,
  a byte of the global record's fracture totals. The package's records
  carry checksums.
- An ERROR raised on rank 0 alone (a missing material file) reaches
  log.lammps, on 1 and 2 ranks, with the output redirected.
"""
import os
import re
import struct
import subprocess
from lmptest import *

d = workdir()
H = HORIZON


def estimate(out):
    return log_value(out, r"stable time step estimate \(MS07 eq. 43\) ([0-9.eE+-]+)")


out, _ = run(block(8) + PAIRS["pd/ordinary"] + "run 0\n", d)
dt0 = estimate(out)
check("the stable estimate is logged", dt0 > 0, f"{dt0:.3g}")
for factor in (5, 50):
    out, rows = run(block(8) + PAIRS["pd/ordinary"] + ROUGH_VELOCITY + "fix 1 all nve\n" +
                    f"timestep {factor * dt0}\nthermo 1\nrun 400\n", d, expect_error=True)
    errors = [l for l in out.splitlines() if l.startswith("ERROR")]
    ok = errors and "the run is unstable at step" in errors[0] and "times the setup's stable estimate" in errors[0] and ": reduce it" in errors[0]
    check(f"{factor}x the stable step: the guard's ERROR names the atom and the time step", bool(ok),
          errors[0][:160] if errors else out[-300:])
    check(f"{factor}x: no NaN reached the thermo output", "nan" not in out.lower().replace("nanosec", ""))
    at = log_value(out, r"the run is unstable at step (\d+)")
    check_le(f"{factor}x: stopped within 60 steps", at, 60)

# a slow blow-up: a plate compressed 20% (m = 0 stiffens it), at rest but
# for round-off forces, above the current state's stable step
PLATE = """units si
dimension 2
boundary p p p
atom_style peri
atom_modify map array
lattice sq 0.0005
region box block 0 16 0 16 -0.5 0.5
create_box 1 box
create_atoms 1 box
set group all density 7800
set group all volume 2.5e-10
pair_style pd/ordinary plane stress thickness 0.001
pair_coeff * * E 200e9 nu 0.3 horizon 0.0015001 m 0
run 0
change_box all x scale 0.8 y scale 0.8 remap
fix 1 all nve
thermo 100
thermo_style custom step ke pe
"""
out, _ = run(PLATE, d)
dt_plate = estimate(out)
out, _ = run(PLATE + f"timestep {1.4 * dt_plate!r}\nrun 2000\n", d, expect_error=True)
errors = [l for l in out.splitlines() if l.startswith("ERROR")]
m = re.search(r"unstable at step (\d+): the kinetic energy grew .* times the stable estimate of the current state", errors[0]) \
    if errors else None
check("1.4x the estimate, compressed, m = 0: the guard names the energy's growth and the current state's step",
      bool(m) and "fix pd/timestep" in errors[0], errors[0][:240] if errors else out[-300:])
# (the speed limit alone stopped this run at step 47)
check_le("... within 20 steps", int(m.group(1)) if m else 1e9, 20)
out, rows = run(PLATE + f"timestep {1.0 * dt_plate!r}\nrun 2000\n", d)
check("1.0x the estimate, compressed (above the current estimate, stable): the run completes",
      "ERROR" not in out and rows and rows[-1]["Step"] == 2000 and rows[-1]["KinEng"] < 1e-12,
      f"ke {rows[-1]['KinEng'] if rows else None}")

# a rigid translation at 3e4 m/s: 1.5 mm, 2x the guard's limit of half a
# horizon, per step (LAMMPS reneighbors every step)
out, rows = run(block(8) + PAIRS["pd/ordinary"] + "neigh_modify every 1 delay 0 check yes\n"
                "velocity all set 3e4 0 0 units box\nfix 1 all nve\ntimestep 5e-8\nthermo 10\n"
                "thermo_style custom step ke pe\nrun 50\n", d, expect_error=True)
check("a rigid translation 2x faster than the speed limit is no fault", "ERROR" not in out and rows and
      rows[-1]["Step"] == 50, out[out.find("ERROR"):][:200])

# two particles pushed onto each other, log strain (m = 0): log(0)
squeeze = block(6, "s s s") + replace_exact(PAIRS["pd/ordinary"], "m 0.5", "m 0") + \
    "group one id 1\nvelocity one set 1e6 1e6 1e6 units box\nfix 1 all nve\n" \
    f"timestep {SPACING / 1e6}\nthermo 1\nrun 3\n"
check("the squeeze deck uses m = 0", " m 0\n" in squeeze)
out, _ = run(squeeze, d, expect_error=True)
errors = [l for l in out.splitlines() if l.startswith("ERROR")]
m = re.search(r"bond (\d+)-(\d+) has length 0", errors[0]) if errors else None
check("a zero-length bond with m = 0 is an ERROR naming both atoms (atom 1 and its diagonal neighbour)",
      bool(m) and "1" in m.groups(), errors[0][:240] if errors else out[-300:])

# --- a damaged restart file ---------------------------------------------------
run(block(8) + PAIRS["pd/ordinary"] + "run 0\nwrite_restart good.restart\n", d)
raw = bytearray(open(f"{d}/good.restart", "rb").read())
# atom 1's stored bonds: its partner tags are 8-byte integers stored in
# doubles; the first record of the form [count, own tag 1, ...] after the
# header is atom 1's. Overwrite its first partner tag with a huge ID.
one = struct.pack("<q", 1)
def family_volume_at(i):
    # after count and tag, the fields: dissipated, family_volume, weighted_volume, build_volume
    return struct.unpack("<d", raw[i + 24:i + 32])[0]


# (any byte offset: newer LAMMPS versions do not align the per-atom records)
count_tag = [i for i in range(0, len(raw) - 48) if raw[i + 8:i + 16] == one and
             0 < struct.unpack("<q", raw[i:i + 8])[0] < 200 and abs(family_volume_at(i) / (122 * VOLUME) - 1) < 1e-9]
check("atom 1's bond record is found in the restart file (once)", len(count_tag) == 1, f"{len(count_tag)}")
at = count_tag[-1]
bad = bytearray(raw)
BOND = at + 48        # the first bond, after count, tag and the four fields: partner tag, length
bad[BOND:BOND + 8] = struct.pack("<q", 10 ** 9)
open(f"{d}/bad_tag.restart", "wb").write(bad)
bad = bytearray(raw)
bad[at:at + 8] = struct.pack("<q", 10 ** 7)           # more bonds than the tables hold
open(f"{d}/bad_count.restart", "wb").write(bad)
bad = bytearray(raw)
bad[at:at + 8] = struct.pack("<q", struct.unpack("<q", raw[at:at + 8])[0] - 1)   # one bond short of its record
open(f"{d}/bad_length.restart", "wb").write(bad)
bad = bytearray(raw)
bad[BOND + 15] ^= 0x80        # the sign bit of the first bond's length: the bond marked broken
open(f"{d}/bad_broken.restart", "wb").write(bad)
bad = bytearray(raw)
bad[at + 24] ^= 0x01          # the last bit of the family volume
open(f"{d}/bad_field.restart", "wb").write(bad)
# the global record: its tag, then 8-byte fields; 'dissipated' is the 14th
tag = raw.find(b"PDBONDS\0")
check("the bond store's global record is found in the restart file", tag > 0 and raw.find(b"PDBONDS\0", tag + 1) < 0)
bad = bytearray(raw)
bad[tag + 8 * 13 + 3] ^= 0x10
open(f"{d}/bad_total.restart", "wb").write(bad)
ATOM = "atoms arrived with a bond record that fails its checksum"
for name, message in (("bad_tag", ATOM), ("bad_count", ATOM), ("bad_length", ATOM), ("bad_broken", ATOM),
                      ("bad_field", ATOM), ("bad_total", "the restart file's bond record fails its checksum")):
    for ranks in (1, 2):
        out, _ = run(f"read_restart {name}.restart\nrun 0\n", d, ranks=ranks, expect_error=True)
        crashed = any(s in out for s in ("Segmentation", "signal 11", "core dumped"))
        check(f"damaged restart ({name}, {ranks} rank(s)): an ERROR, no crash",
              message in out and not crashed, out.strip().splitlines()[-1][:160] if out.strip() else "")
out, _ = run("read_restart good.restart\nrun 0\n", d)
check("the undamaged restart file is read", "ERROR" not in out and "bonds kept" in out)

# --- an ERROR on one rank reaches the log -------------------------------------
deck = block(6) + f"pair_style pd/ordinary\npair_coeff * * file nosuch.pd PMMA horizon {H}\n"
open(f"{d}/in.nofile", "w").write(deck)
for ranks in (1, 2):
    log = f"{d}/log.nofile{ranks}"
    cmd = [LMP, "-in", "in.nofile", "-log", log, "-screen", "none"]
    if ranks > 1:
        cmd = ["mpirun", "-np", str(ranks)] + cmd
    subprocess.run(cmd, cwd=d, capture_output=True, text=True, env=MPI_ENV, timeout=300)
    text = open(log).read() if os.path.exists(log) else ""
    check(f"a missing material file: the ERROR is in log.lammps ({ranks} rank(s))",
          "ERROR: Pair pd/ordinary coeff file: cannot open 'nosuch.pd'" in text)
finish()
