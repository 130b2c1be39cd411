"""Bad input gets a LAMMPS ERROR line that names what is wrong (issue 2),
never a crash, a NaN or a silent default."""
from lmptest import *
import os

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
open(f"{d}/bad.pd", "w").write("material glass\n  density 2500\n  E -70e9  # sign slip\n  nu 0.2\nend\n")
MATERIALS = os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../potentials/materials.pd")
PLATE = ("units si\ndimension 2\nboundary p p p\natom_style peri\natom_modify map array\nlattice sq 5e-4\n"
         "region b block 0 10 0 10 -0.5 0.5\ncreate_box 1 b\ncreate_atoms 1 box\n")
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
    ("unknown pair_coeff keyword", block(6) + f"pair_style pd/bond\npair_coeff * * pmb K 1e9 horizon {H} s00 1\n",
     "unknown keyword 's00'"),
    ("s0 without a failure law", block(6) + f"pair_style pd/bond\npair_coeff * * pmb K 1e9 horizon {H} s0 1\n",
     "s0 needs 'fail stretch'"),
    ("negative critical stretch", block(6) + f"pair_style pd/bond\npair_coeff * * pmb K 1e9 horizon {H} fail stretch -0.01\n",
     "critical stretch s0 must be positive"),
    ("zero G_c", block(6) + f"pair_style pd/ordinary\npair_coeff * * E 1e9 nu 0.3 horizon {H} fail energy Gc 0\n",
     "Gc must be positive"),
    ("energy law on bond-based", block(6) + f"pair_style pd/bond\npair_coeff * * pmb K 1e9 horizon {H} fail energy Gc 10\n",
     "'fail energy' needs a state-based material"),
    ("failure on microplastic bonds", block(6) + f"pair_style pd/bond\npair_coeff * * microplastic K 1e9 horizon {H} yield_stretch 1e-3 fail stretch 0.01\n",
     "failure of microplastic bonds is not supported"),
    ("energy law with a divergent G_c integral", PLATE + f"pair_style pd/ordinary plane stress thickness 1e-3 influence inverse\n"
     f"pair_coeff * * E 1e9 nu 0.3 horizon {H} fail energy Gc 10\nset group all volume 2.5e-10\n" + RUN,
     "the G_c integral diverges"),
    ("minimize with bond failure", block(8) + f"pair_style pd/ordinary\npair_coeff * * E 1e9 nu 0.3 horizon {H} fail stretch 0.01\n"
     "min_modify dmax 1e-6\nminimize 1e-10 0 10 100\n", "minimize with bond failure or plasticity is not supported"),
    ("unknown failure law", block(6) + f"pair_style pd/ordinary\npair_coeff * * E 1e9 nu 0.3 horizon {H} fail bending 3\n",
     "unknown failure law 'bending'"),
    ("pd/ordinary without G", block(6) + f"pair_style pd/ordinary\npair_coeff * * K 1e9 horizon {H}\n",
     "G missing"),
    ("pd/ordinary negative K", block(6) + f"pair_style pd/ordinary\npair_coeff * * K -1e9 G 1e9 horizon {H}\n",
     "K must be positive"),
    ("pd/ordinary order out of range", block(6) + f"pair_style pd/ordinary\npair_coeff * * K 1e9 G 1e9 horizon {H} m 2\n",
     "strain order m = 2 is outside"),
    ("pd/ordinary unknown influence", block(6) + "pair_style pd/ordinary influence cubic\n",
     "unknown influence function 'cubic'"),
    ("nu at 1/2", block(6) + f"pair_style pd/ordinary\npair_coeff * * E 1e9 nu 0.5 horizon {H}\n",
     "are not an isotropic elastic material"),
    ("pd/ordinary material on a line between types",
     "units si\nboundary s s s\natom_style peri\natom_modify map array\nlattice sc 5e-4\n"
     "region b block 0 4 0 4 0 4\ncreate_box 2 b\ncreate_atoms 1 box\n"
     f"pair_style pd/ordinary\npair_coeff * * E 1e9 nu 0.3 horizon {H}\npair_coeff 1 2 E 7e10 horizon {H}\n",
     "'E' belongs on a type's own line"),
    ("nu at -1", block(6) + f"pair_style pd/ordinary\npair_coeff * * E 1e9 nu -1 horizon {H}\n",
     "are not an isotropic elastic material"),
    ("K and E together", block(6) + f"pair_style pd/ordinary\npair_coeff * * E 1e9 K 1e9 G 1e9 horizon {H}\n",
     "give the elastic constants as K and G or as E and nu"),
    ("bond-based with nu != 1/4", block(6) + f"pair_style pd/bond\npair_coeff * * pmb E 1e9 nu 0.3 horizon {H}\n",
     "bond-based elasticity has Poisson's ratio 0.25"),
    ("2D without plane and thickness", PLATE + "pair_style pd/ordinary\n", "needs 'plane stress' or 'plane strain'"),
    ("2D without thickness", PLATE + "pair_style pd/ordinary plane stress\n", "and 'thickness <t>'"),
    ("2D option in 3D", block(6) + "pair_style pd/ordinary plane stress thickness 1e-3\n", "'plane' is a 2D option"),
    ("3D-only option in 2D", PLATE + f"pair_style pd/bond plane stress thickness 5e-4\npair_coeff * * pmb K 1e9 horizon {H}\n",
     "K is a 3D option"),
    ("microplastic without yield stretch", block(6) + f"pair_style pd/bond\npair_coeff * * microplastic E 1e9 horizon {H}\n",
     "microplastic needs a positive yield_stretch"),
    ("material missing from the file", block(6) + f"pair_style pd/ordinary\npair_coeff * * file {MATERIALS} unobtainium horizon {H}\n",
     "material unobtainium is not in the file"),
    ("material file value without units sense", block(6) + f"pair_style pd/ordinary\npair_coeff * * file bad.pd glass horizon {H}\n",
     "E = -7e+10 must be positive"),
    ("strain order missing its value", block(6) + f"pair_style pd/ordinary\npair_coeff * * E 1e9 nu 0.2 horizon {H} m\n",
     "keyword 'm' needs a value"),
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
