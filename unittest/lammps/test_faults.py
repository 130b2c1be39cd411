"""Faults end in a clear ERROR, not NaN, a crash or a lost message.

- Blow-ups: at 5x and 50x the stable step the guard stops the run within a
  few steps with an ERROR that names an atom, its position and the time
  step against the stable estimate (before: NaN output, then a LAMMPS bin
  or lost-atom error). Two particles pushed onto each other with m = 0
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
    ok = errors and "the run is unstable at step" in errors[0] and "times the stable estimate" in errors[0]
    check(f"{factor}x the stable step: the guard's ERROR names the atom and the time step", bool(ok),
          errors[0][:160] if errors else out[-300:])
    check(f"{factor}x: no NaN reached the thermo output", "nan" not in out.lower().replace("nanosec", ""))
    at = log_value(out, r"the run is unstable at step (\d+)")
    check_le(f"{factor}x: stopped within 60 steps", at, 60)

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
    # after count and tag, the fields: dissipated, family_volume, weighted_volume
    return struct.unpack("<d", raw[i + 24:i + 32])[0]


# (any byte offset: newer LAMMPS versions do not align the per-atom records)
count_tag = [i for i in range(0, len(raw) - 48) if raw[i + 8:i + 16] == one and
             0 < struct.unpack("<q", raw[i:i + 8])[0] < 200 and abs(family_volume_at(i) / (122 * VOLUME) - 1) < 1e-9]
check("atom 1's bond record is found in the restart file (once)", len(count_tag) == 1, f"{len(count_tag)}")
at = count_tag[-1]
bad = bytearray(raw)
bad[at + 40:at + 48] = struct.pack("<q", 10 ** 9)   # after count, tag and the three fields
open(f"{d}/bad_tag.restart", "wb").write(bad)
bad = bytearray(raw)
bad[at:at + 8] = struct.pack("<q", 10 ** 7)           # more bonds than the tables hold
open(f"{d}/bad_count.restart", "wb").write(bad)
bad = bytearray(raw)
bad[at:at + 8] = struct.pack("<q", struct.unpack("<q", raw[at:at + 8])[0] - 1)   # one bond short of its record
open(f"{d}/bad_length.restart", "wb").write(bad)
bad = bytearray(raw)
bad[at + 47] ^= 0x80          # the sign bit of the first bond's length: the bond marked broken
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
