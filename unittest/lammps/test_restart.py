"""Restart continuation (issue 2): 'run 100' twice in one process, and
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
# A restart file whose bond record has another format tag (as one written
# by an older or newer build) is refused by name, not misread.
magic = struct.pack("<d", 20261201.2)
raw = open(f"{d}/restart.{tag}", "rb").read()
check("the bond record carries its format tag once", raw.count(magic) == 1)
open(f"{d}/restart.old", "wb").write(replace_exact(raw, magic, struct.pack("<d", 20250101.0)))
out, _ = run("read_restart restart.old\nrun 0\n", d, expect_error=True)
check("another format is an ERROR that says so", "in another format than this build reads" in out)
finish()
