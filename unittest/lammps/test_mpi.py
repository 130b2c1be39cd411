"""Rank-count invariance: 1, 2 and 4 MPI ranks give the same final
positions to 1e-10 relative. Atoms come from one data file (IDs from
create_atoms depend on the rank count); a drift of 200 m/s carries them
across subdomains (exchange of atoms with their bonds) while bonds span
subdomain boundaries all the time. Differences are round-off from summing
ghost forces in another order."""
from lmptest import *

d = workdir()
run(block(16) + "write_data block.data\n", d)
run(plate(40) + "write_data plate.data\n", d)
for style in ["pd/bond legacy", "pd/ordinary", "pd/ordinary 2D m=0"]:
    tag = style.replace(" ", "_").replace("/", "_").replace("=", "")
    two_d = "2D" in style
    MOTION = replace_exact(ROUGH_VELOCITY, "v_vz", "0.0" if two_d else "v_vz") + \
        f"velocity all set 200.0 NULL {0.0 if two_d else -100.0} sum yes units box\n"
    final = {}
    for ranks in (1, 2, 4):
        script = (("dimension 2\n" if two_d else "") +
                  "units si\nboundary p p p\natom_style peri\natom_modify map array\n" +
                  f"read_data {'plate' if two_d else 'block'}.data\n" +
                  ("lattice sc 0.0005\n" if "legacy" in style else "") +
                  MOTION + PAIRS[style] + "fix 1 all nve\ntimestep 1.0e-7\nthermo 100\nrun 200\n" +
                  DUMP.format(file=f"final.{tag}.{ranks}"))
        out, _ = run(script, d, ranks=ranks)
        final[ranks] = read_dump(f"{d}/final.{tag}.{ranks}")
        if ranks == 4:
            check(f"{style}: atoms migrated between ranks (reneighborings > 0)",
                  log_value(out, r"Neighbor list builds = (\d+)") > 0)
    for ranks in (2, 4):
        check_le(f"{style}: {ranks} ranks match 1 rank", max_rel_diff(final[1], final[ranks]), 1e-10,
                 "round-off of reordered sums")
finish()
