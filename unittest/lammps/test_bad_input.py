"""Bad input gets a LAMMPS ERROR line that names what is wrong (issue 2),
never a crash, a NaN or a silent default."""
from lmptest import *

d = workdir()
H = HORIZON
RUN = "fix 1 all nve\ntimestep 1e-7\nrun 10\n"

# a data file in which atom 7 has zero volume (the set command refuses 0)
run(block(8) + "write_data ok.data\n", d)
lines = open(f"{d}/ok.data").read().splitlines()
start = next(i for i, l in enumerate(lines) if l.startswith("Atoms")) + 2
for i in range(start, len(lines)):
    w = lines[i].split()
    if w and w[0] == "7":
        w[2] = "0.0"
        lines[i] = " ".join(w)
open(f"{d}/zero.data", "w").write("\n".join(lines) + "\n")
DATA = "units si\nboundary p p p\natom_style peri\natom_modify map array\nread_data zero.data\n"

cases = [
    ("pd/bond without modulus", block(6) + f"pair_style pd/bond\npair_coeff * * pmb horizon {H}\n",
     "give exactly one of 'c'"),
    ("pd/bond negative modulus", block(6) + f"pair_style pd/bond\npair_coeff * * pmb K -1e9 horizon {H}\n",
     "K must be positive"),
    ("pd/bond missing horizon", block(6) + "pair_style pd/bond\npair_coeff * * pmb K 1e9\n",
     "horizon missing or not positive"),
    ("pd/bond negative horizon", block(6) + "pair_style pd/bond\npair_coeff * * pmb K 1e9 horizon -1e-3\n",
     "horizon missing or not positive"),
    ("horizon below the spacing", block(6) + "pair_style pd/bond\npair_coeff * * pmb K 1e9 horizon 4e-4\n" + RUN,
     "is not larger than the particle spacing"),
    ("volume never set (PERI's default is 1)",
     block(6).replace(f"set group all volume {VOLUME}\n", "") + f"pair_style pd/bond\npair_coeff * * pmb K 1e9 horizon {H}\n" + RUN,
     "is not larger than the particle spacing 1"),
    ("an atom with zero volume", DATA + f"pair_style pd/bond\npair_coeff * * pmb K 1e9 horizon {H}\n" + RUN,
     "some atoms have zero volume"),
    ("atom style without volume",
     "units si\natom_style atomic\nlattice sc 5e-4\nregion b block 0 4 0 4 0 4\ncreate_box 1 b\ncreate_atoms 1 box\n"
     f"mass 1 1.0\npair_style pd/bond\npair_coeff * * pmb K 1e9 horizon {H}\n" + RUN,
     "requires an atom style with per-atom volume"),
    ("no atom map", block(6).replace("atom_modify map array\n", "") +
     f"pair_style pd/bond\npair_coeff * * pmb K 1e9 horizon {H}\n" + RUN, "requires an atom map"),
    ("newton off", "newton off\n" + block(6) + f"pair_style pd/bond\npair_coeff * * pmb K 1e9 horizon {H}\n" + RUN,
     "needs 'newton on'"),
    ("unknown pair_style keyword", block(6) + "pair_style pd/bond legacyy\n", "unknown keyword 'legacyy'"),
    ("unknown pair_coeff keyword", block(6) + f"pair_style pd/bond\npair_coeff * * pmb K 1e9 horizon {H} s0 1\n",
     "unknown keyword 's0'"),
    ("pd/ordinary without G", block(6) + f"pair_style pd/ordinary\npair_coeff * * K 1e9 horizon {H}\n",
     "G missing or not positive"),
    ("pd/ordinary negative K", block(6) + f"pair_style pd/ordinary\npair_coeff * * K -1e9 G 1e9 horizon {H}\n",
     "K missing or not positive"),
    ("pd/ordinary order out of range", block(6) + f"pair_style pd/ordinary\npair_coeff * * K 1e9 G 1e9 horizon {H} m 2\n",
     "strain order m = 2 is outside"),
    ("pd/ordinary unknown influence", block(6) + "pair_style pd/ordinary influence cubic\n",
     "unknown influence function 'cubic'"),
    ("legacy without a lattice", DATA.replace("zero.data", "ok.data") +
     f"pair_style pd/bond legacy\npair_coeff * * pmb K 1e9 horizon {H}\n" + RUN, "need the lattice spacing"),
]
for what, script, message in cases:
    out, _ = run(script, d, expect_error=True)
    errors = [l for l in out.splitlines() if l.startswith("ERROR")]
    crashed = any(s in out for s in ("Segmentation", "signal", "Aborted", "nan"))
    check(f"{what}: ERROR names it", bool(errors) and message in errors[0] and not crashed,
          errors[0] if errors else out.strip().splitlines()[-1] if out.strip() else "no output")
finish()
