"""Restart continuation: 'run 100' twice in one process, and
'run 100', write_restart, a new process, read_restart, 'run 100', end at
bitwise the same positions on the same rank count. No lattice command and
no pair_style after the restart: the pair style, its coefficients, the
families and (legacy) the lattice spacing all come from the file."""
import struct
from lmptest import *

d = workdir()
# uniform drift so atoms cross the periodic boundary and get re-sorted
STEPS = "fix 1 all nve\ntimestep 1.0e-7\nthermo 50\n"
for style in ["pd/bond legacy", "pd/ordinary", "pd/ordinary 2D m=0"]:
    tag = style.replace(" ", "_").replace("/", "_").replace("=", "")
    body = plate(24) if "2D" in style else block(12)
    MOTION = replace_exact(ROUGH_VELOCITY, "v_vz", "0.0" if "2D" in style else "v_vz") + \
        "velocity all set 40.0 NULL NULL sum yes units box\n"
    run(body + MOTION + PAIRS[style] + STEPS + "run 100\nrun 100\n" + DUMP.format(file="one." + tag), d)
    first, _ = run(body + MOTION + PAIRS[style] + STEPS + f"run 100\nwrite_restart restart.{tag}\n", d)
    out, _ = run(f"read_restart restart.{tag}\nfix 1 all nve\nthermo 50\nrun 100\n" +
                 DUMP.format(file="two." + tag), d)
    # the restarted run reports the families it read, as many bonds as
    # were built (nothing breaks or is lost here), and builds none
    built = log_value(first, r"pd/bonds: (\d+) bonds, ")
    kept = log_value(out, r"pd/bonds: (\d+) bonds kept, 0 of them broken")
    check(f"{style}: after read_restart the families from the file are kept, all {built:.0f} bonds",
          built > 0 and kept == built, f"{kept:.0f} kept")
    check(f"{style}: and not rebuilt", "bonds per atom (each stored once)" in first and
          "bonds per atom (each stored once)" not in out)
    diff = max_rel_diff(read_dump(f"{d}/one.{tag}"), read_dump(f"{d}/two.{tag}"))
    check(f"{style}: restarted run ends at bitwise the same positions", diff == 0.0, f"max rel diff {diff:.3g}")
# The bond store's global record is versioned (pd_bonds_record.h): a tag,
# the version and the size of its fixed part come first. A record of
# another version, one whose fixed part has another size, or one from
# before versioning (whose first 8 bytes were the format tag 20261201.1)
# is refused by an ERROR that names what it found and what it expects,
# not misread.
TAG = b"PDBONDS\0"
raw = open(f"{d}/restart.{tag}", "rb").read()
check("the bond record carries its tag once", raw.count(TAG) == 1)
at = raw.index(TAG)
version, fixed = struct.unpack_from("<qq", raw, at + 8)
check("... then its version (2) and the size of its fixed part", version == 2 and fixed >= 32 and fixed % 8 == 0,
      f"version {version}, {fixed} bytes")
edits = {
    "newer": (raw[:at + 8] + struct.pack("<q", 3) + raw[at + 16:],
              "bond record is version 3; this build reads version 2 (the file was written by a newer"),
    "resized": (raw[:at + 16] + struct.pack("<q", fixed + 8) + raw[at + 24:],
                f"has a fixed part of {fixed + 8} bytes; this build expects {fixed} bytes for version 2"),
    "inconsistent": (raw[:at + 24] + struct.pack("<q", struct.unpack_from("<q", raw, at + 24)[0] + 24) +
                     raw[at + 32:], "the restart file's bond record is damaged (inconsistent counts)"),
    "unversioned": (raw[:at] + struct.pack("<d", 20261201.1) + raw[at + 8:],
                    "in an older format (format tag 20261201.1, before versioned records); this build "
                    "reads bond record version 2"),
}
for name, (data, message) in edits.items():
    open(f"{d}/restart.{name}", "wb").write(data)
    out, _ = run(f"read_restart restart.{name}\nrun 0\n", d, expect_error=True)
    check(f"a bond record {name}: an ERROR that says what it found (and expects)",
          message in out, out.strip().splitlines()[-1] if out.strip() else "no output")
finish()
