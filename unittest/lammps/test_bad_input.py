"""Bad input gets a LAMMPS ERROR line that names what is wrong,
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
# a NUL byte before the material: C text would end there, and the
# material would seem missing
open(f"{d}/nul.pd", "wb").write(b"# materials\n\0\nmaterial glass\n  density 2500\n  E 70e9\n  nu 0.2\nend\n")
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
     replace_exact(block(6), f"set group all volume {VOLUME}\n", "") + f"pair_style pd/bond\npair_coeff * * pmb K 1e9 horizon {H}\n" + RUN,
     "is not larger than the particle spacing 1"),
    ("two atoms at one reference position",
     block(8) + f"create_atoms 1 single 2 2 2\nset group all density {DENSITY}\nset group all volume {VOLUME}\n"
     f"pair_style pd/bond\npair_coeff * * pmb K 1e9 horizon {H}\n" + RUN,
     "two atoms share a reference position"),
    ("an atom with zero volume", DATA + f"pair_style pd/bond\npair_coeff * * pmb K 1e9 horizon {H}\n" + RUN,
     "some atoms have zero volume"),
    ("atom style without volume",
     "units si\natom_style atomic\nlattice sc 5e-4\nregion b block 0 4 0 4 0 4\ncreate_box 1 b\ncreate_atoms 1 box\n"
     f"mass 1 1.0\npair_style pd/bond\npair_coeff * * pmb K 1e9 horizon {H}\n" + RUN,
     "requires an atom style with per-atom volume"),
    ("no atom map", replace_exact(block(6), "atom_modify map array\n", "") +
     f"pair_style pd/bond\npair_coeff * * pmb K 1e9 horizon {H}\n" + RUN, "requires an atom map"),
    ("newton off", "newton off\n" + block(6) + f"pair_style pd/bond\npair_coeff * * pmb K 1e9 horizon {H}\n" + RUN,
     "needs 'newton on'"),
    ("unknown pair_style keyword", block(6) + "pair_style pd/bond legacyy\n", "unknown keyword 'legacyy'"),
    ("unknown pair_coeff keyword", block(6) + f"pair_style pd/bond\npair_coeff * * pmb K 1e9 horizon {H} s00 1\n",
     "unknown keyword 's00'"),
    ("s0 without a failure law", block(6) + f"pair_style pd/bond\npair_coeff * * pmb K 1e9 horizon {H} s0 1\n",
     "'s0' needs a failure law: 'fail stretch"),
    ("negative critical stretch", block(6) + f"pair_style pd/bond\npair_coeff * * pmb K 1e9 horizon {H} fail stretch -0.01\n",
     "critical stretch s0 must be positive"),
    ("critical stretch spelled nan", block(6) + f"pair_style pd/bond\npair_coeff * * pmb K 1e9 horizon {H} fail stretch nan\n",
     "'fail stretch' takes a critical stretch s0, got 'nan'"),
    ("critical stretch a word", block(6) + f"pair_style pd/bond\npair_coeff * * pmb K 1e9 horizon {H} fail stretch x\n",
     "'fail stretch' takes a critical stretch s0, got 'x'"),
    ("zero G_c", block(6) + f"pair_style pd/ordinary\npair_coeff * * E 1e9 nu 0.3 horizon {H} fail energy Gc 0\n",
     "Gc must be positive"),
    ("energy law on bond-based", block(6) + f"pair_style pd/bond\npair_coeff * * pmb K 1e9 horizon {H} fail energy Gc 10\n",
     "'fail energy' needs a material with per-bond energies"),
    ("energy law on classical correspondence", block(6) + f"pair_style pd/corr strain classical model elastic\npair_coeff * * E 1e9 nu 0.3 horizon {H} fail energy Gc 10\n",
     "'fail energy' needs a material with per-bond energies"),
    ("pd/corr: two types with different m", block(6).replace("create_box 1 box", "create_box 2 box") +
     f"set type 1 type/fraction 2 0.5 1\npair_style pd/corr model elastic\n"
     f"pair_coeff 1 1 E 1e9 nu 0.3 horizon {H} m 0\npair_coeff 2 2 E 1e9 nu 0.3 horizon {H} m -1\nrun 0\n",
     "all types need the same strain order m"),
    ("pd/corr without a model", block(6) + f"pair_style pd/corr\npair_coeff * * E 1e9 nu 0.3 horizon {H}\n",
     "'model' missing"),
    ("pd/corr model elastic given a yield stress", block(6) + f"pair_style pd/corr model elastic\npair_coeff * * E 1e9 nu 0.3 horizon {H} yield 1e6\n",
     "yield (initial yield stress) is not used by model elastic"),
    ("pd/corr j2 without a yield stress", block(6) + f"pair_style pd/corr model j2\npair_coeff * * E 1e9 nu 0.3 horizon {H}\n",
     "model j2 needs yield"),
    ("pd/corr negative stabilization", block(6) + f"pair_style pd/corr model elastic stabilization -1\npair_coeff * * E 1e9 nu 0.3 horizon {H}\n",
     "stabilization -1: expected a coefficient >= 0"),
    ("failure on microplastic bonds", block(6) + f"pair_style pd/bond\npair_coeff * * microplastic K 1e9 horizon {H} yield_stretch 1e-3 fail stretch 0.01\n",
     "failure of microplastic bonds is not supported"),
    ("energy law with a divergent G_c integral", PLATE + f"pair_style pd/ordinary plane stress thickness 1e-3 influence inverse\n"
     f"pair_coeff * * E 1e9 nu 0.3 horizon {H} fail energy Gc 10\nset group all volume 2.5e-10\n" + RUN,
     "'fail energy profile opening' with influence inverse in 2D: the G_c integral diverges"),
    ("minimize with bond failure", block(8) + f"pair_style pd/ordinary\npair_coeff * * E 1e9 nu 0.3 horizon {H} fail stretch 0.01\n"
     "min_modify dmax 1e-6\nminimize 1e-10 0 10 100\n",
     "is not supported (line search trial states would break or yield bonds); for quasi-static loading use fix"),
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
    ("legacy without a lattice", replace_exact(DATA, "zero.data", "ok.data") +
     f"pair_style pd/bond legacy\npair_coeff * * pmb K 1e9 horizon {H}\n" + RUN, "need the lattice spacing"),
]

# Every numeric input finite and in range, every key a line cannot
# use refused, material files checked, messages that say what is wrong.
open(f"{d}/inf.pd", "w").write("material glass\n  density 2500\n  E inf\n  nu 0.2\nend\n")
open(f"{d}/twice.pd", "w").write("material glass\n  density 2500\n  E 7e10\n  nu 0.2\n  E 7e10\nend\n")
open(f"{d}/block2.pd", "w").write("material glass\n  E 7e10\n  nu 0.2\nend\nmaterial glass\n  E 1e9\nend\n")
open(f"{d}/long.pd", "w").write("material glass\n  E 7e10\n  nu 0.2\n# " + "x" * 600 + " E 1e6\n  density -1\nend\n")
TWO_TYPES = ("units si\nboundary s s s\natom_style peri\natom_modify map array\nlattice sc 5e-4\n"
             "region b block 0 4 0 4 0 4\ncreate_box 2 b\ncreate_atoms 1 box\nset group all volume 1.25e-10\n"
             "set group all density 1000\n")
ORD = "pair_style pd/ordinary\npair_coeff * * "


def overflow(key, text="1e400"):
    """Our ERROR names the key; LAMMPS 19Nov2024 refuses a number out of
    double's range itself while reading it, naming the value: either says
    what is wrong."""
    return (f"'{key}' must be a finite number",
            f"Floating point number {text} in input script or data file is out of range")


BOND = "pair_style pd/bond\npair_coeff * * pmb "
OK_ORD = f"E 1e9 nu 0.25 horizon {H}"
CONTACT = "pair_style pd/contact\npair_coeff * * "
JC = ("pair_style pd/corr model johnson_cook\npair_coeff * * E 72e9 nu 0.343 yield 250e6 jc_B 365e6 jc_n 0.04 "
      f"horizon {H} ")
cases += [
    # overflow, inf, nan, words: LAMMPS refuses words and nan/inf spelled out,
    # we refuse what overflows to inf (1e400), by the key's name
    ("K overflows", block(6) + BOND + f"K 1e400 horizon {H}\n", overflow("K")),
    ("micromodulus overflows", block(6) + BOND + f"c 1e400 horizon {H}\n", overflow("c")),
    ("E overflows", block(6) + ORD + f"E 1e400 nu 0.25 horizon {H}\n", overflow("E")),
    ("E spelled inf", block(6) + ORD + f"E inf nu 0.25 horizon {H}\n", "inf"),
    ("E spelled nan", block(6) + ORD + f"E nan nu 0.25 horizon {H}\n", "nan"),
    ("E a word", block(6) + ORD + f"E glass nu 0.25 horizon {H}\n", "glass"),
    ("G overflows", block(6) + ORD + f"K 1e9 G 1e400 horizon {H}\n", overflow("G")),
    ("nu overflows", block(6) + ORD + f"E 1e9 nu -1e400 horizon {H}\n", overflow("nu", "-1e400")),
    ("horizon overflows", block(6) + ORD + "E 1e9 nu 0.25 horizon 1e400\n", overflow("horizon")),
    ("m overflows", block(6) + ORD + f"{OK_ORD} m 1e400\n", overflow("m")),
    ("s0 overflows", block(6) + ORD + f"{OK_ORD} fail stretch 1e400\n", overflow("s0")),
    ("Gc overflows", block(6) + ORD + f"{OK_ORD} fail energy Gc 1e400\n", overflow("Gc")),
    ("stretch Gc overflows", block(6) + ORD + f"{OK_ORD} fail stretch Gc 1e400\n", overflow("Gc")),
    ("legacy s00 overflows", block(6) + f"pair_style pd/bond legacy\npair_coeff * * pmb K 1e9 horizon {H} fail legacy 1e400 0.25\n",
     overflow("s00")),
    ("thickness overflows", PLATE + "pair_style pd/ordinary plane stress thickness 1e400\n",
     ("thickness must be a positive finite number, got '1e400'", overflow("thickness")[1])),
    ("thickness negative", PLATE + "pair_style pd/ordinary plane stress thickness -1e-3\n",
     "thickness must be a positive finite number"),
    ("thickness a word", PLATE + "pair_style pd/ordinary plane stress thickness thick\n", "thick"),
    ("E so large the micromodulus overflows", block(6) + BOND + f"E 1e300 horizon {H}\n",
     "the inputs give c = inf"),
    ("Gc so small s0 underflows to 0", block(6) + ORD + f"{OK_ORD} fail stretch Gc 1e-320\n",
     ("Gc = 1e-320 is below the smallest normal number", overflow("Gc", "1e-320")[1])),
    ("contact stiffness overflows", block(6) + CONTACT + "stiffness 1e400\n",
     ("stiffness must be a positive finite number, got '1e400'", overflow("stiffness")[1])),
    ("contact distance overflows", block(6) + CONTACT + "stiffness 1e20 distance 1e400\n",
     ("distance must be a positive finite number", overflow("distance")[1])),
    ("friction overflows", block(6) + "pair_style pd/contact friction 1e400\n",
     ("friction coefficient must be a finite number >= 0, got '1e400'", overflow("friction")[1])),
    ("friction negative", block(6) + "pair_style pd/contact friction -0.1\n",
     "friction coefficient must be a finite number >= 0"),
    ("pre-crack coordinate overflows", block(6) + ORD + f"{OK_ORD}\nfix c all pd/precrack patch 0 0 1e400 1 0 0 0 1 0\n",
     ("coordinate '1e400' must be a finite number", overflow("x")[1])),
    ("pre-crack of zero area", block(6) + ORD + f"{OK_ORD}\nfix c all pd/precrack patch 0 0 0 1e-3 0 0 2e-3 0 0\n",
     "the crack has zero area"),
    ("pre-crack of zero length", PLATE + "pair_style pd/ordinary plane stress thickness 1e-3\n"
     f"pair_coeff * * {OK_ORD}\nfix c all pd/precrack segment 1e-3 1e-3 1e-3 1e-3\n", "the crack has zero length"),
    ("pre-crack segment in 3D", block(6) + ORD + f"{OK_ORD}\nfix c all pd/precrack segment 0 0 1e-3 1e-3\n",
     "'segment' is for 2D"),
    ("pre-crack with a missing value", block(6) + ORD + f"{OK_ORD}\nfix c all pd/precrack patch 0 0 0 1 0 0 0 1\n",
     "Illegal fix pd/precrack command"),
    # keys a line cannot use
    ("a key given twice", block(6) + ORD + f"E 1e9 E 2e9 nu 0.25 horizon {H}\n", "'E' is given twice on one line"),
    ("horizon and nobond", TWO_TYPES + ORD + f"{OK_ORD}\npair_coeff 1 2 horizon {H} nobond\n",
     "'horizon' is given twice on one line"),
    ("nobond on a type's own line", TWO_TYPES + ORD + f"{OK_ORD}\npair_coeff 1 1 nobond\n",
     "'nobond' (horizon 0) is for a line between two types"),
    ("nobond with a failure law", TWO_TYPES + ORD + f"{OK_ORD}\npair_coeff 1 2 nobond fail stretch 0.01\n",
     "a 'nobond' line (horizon 0) takes no 'fail'"),
    ("alpha without the legacy law", block(6) + ORD + f"{OK_ORD} fail stretch 0.01 alpha 0.25\n",
     "'alpha' belongs to 'fail legacy"),
    ("Gc with the legacy law", block(6) + f"pair_style pd/bond legacy\npair_coeff * * pmb K 1e9 horizon {H} "
     "fail legacy 0.001 0.25 Gc 10\n", "not to 'fail legacy <s00> <alpha>'"),
    ("energy law profile unknown", block(6) + ORD + f"{OK_ORD} fail energy Gc 10 profile sharp\n",
     "'fail energy profile sharp': expected 'opening' or 'uniform'"),
    ("energy law profile missing", block(6) + ORD + f"{OK_ORD} fail energy Gc 10 profile\n",
     "'fail energy profile (nothing)': expected 'opening' or 'uniform'"),
    ("energy law with two profiles", TWO_TYPES + "pair_style pd/ordinary\n"
     f"pair_coeff 1 1 E 1e9 nu 0.3 horizon {H} fail energy Gc 10\n"
     f"pair_coeff 2 2 E 1e9 nu 0.3 horizon {H} fail energy Gc 10 profile uniform\n" + RUN,
     "'fail energy' takes one profile for all type pairs: 2 2 has uniform, 1 1 has opening"),
    ("s0 with the energy law", block(6) + ORD + f"{OK_ORD} fail energy Gc 10 s0 0.01\n",
     "'s0' belongs to 'fail stretch <s0>"),
    ("s0 and Gc together", block(6) + ORD + f"{OK_ORD} fail stretch 0.01 Gc 10\n",
     "takes s0 or 'Gc <Gc>', not both"),
    ("Gc without a failure law", block(6) + ORD + f"{OK_ORD} Gc 10\n", "'Gc' needs a failure law"),
    ("'fail' without a law", block(6) + ORD + f"{OK_ORD} fail\n", "'fail' needs a law"),
    ("'fail legacy' missing alpha", block(6) + f"pair_style pd/bond legacy\npair_coeff * * pmb K 1e9 horizon {H} fail legacy 0.001\n",
     "'fail legacy' needs s00 and alpha"),
    ("legacy law without the legacy style", block(6) + BOND + f"K 1e9 horizon {H} fail legacy 0.001 0.25\n",
     "needs the 'legacy' pair style keyword"),
    ("'Gc' missing its value", block(6) + ORD + f"{OK_ORD} fail stretch Gc\n", "keyword 'Gc' needs a value"),
    ("energy law on an interface without any G_c", TWO_TYPES + ORD + f"{OK_ORD}\npair_coeff 1 2 horizon {H} fail energy\n" + RUN,
     "'fail energy' needs 'Gc <Gc>' here, or both types' own G_c"),
    ("two failure laws", TWO_TYPES + "pair_style pd/ordinary\n"
     f"pair_coeff 1 1 {OK_ORD} fail stretch 0.01\npair_coeff 2 2 {OK_ORD} fail energy Gc 10\n" + RUN,
     "one failure law for all type pairs"),
    ("a material on pd/bond's pmb line for pd/ordinary", block(6) + ORD + f"pmb {OK_ORD}\n", "unknown keyword 'pmb'"),
    ("horizon missing", block(6) + ORD + "E 1e9 nu 0.25\n", "horizon missing or not positive"),
    # style settings
    ("recontact mode unknown", block(6) + "pair_style pd/ordinary recontact sideways\n",
     "'recontact sideways': expected near, any or none"),
    ("recontact without a mode", block(6) + "pair_style pd/ordinary recontact\n", "expected near, any or none"),
    ("plane neither stress nor strain", PLATE + "pair_style pd/ordinary plane shear thickness 1e-3\n",
     "'plane shear': expected stress or strain"),
    ("surface correction not yes or no", block(6) + "pair_style pd/ordinary surface_correction maybe\n",
     "surface_correction 'maybe': expected yes or no"),
    ("the old influence name gauss", block(6) + "pair_style pd/ordinary influence gauss\n",
     "unknown influence function 'gauss'"),
    ("influence without a name (or taken by hybrid)", block(6) + "pair_style pd/ordinary influence\n",
     "'influence' needs a name (constant, inverse, lps, tupek, gaussian)"),
    ("legacy in 2D", PLATE + "pair_style pd/ordinary legacy plane stress thickness 1e-3\n"
     f"pair_coeff * * {OK_ORD}\nset group all volume 2.5e-10\nset group all density 1000\n" + RUN,
     "legacy reproduces peri/lps, which is 3D"),
    ("legacy with m != 1/2", block(6) + f"pair_style pd/ordinary legacy\npair_coeff * * {OK_ORD} m 0\nlattice sc 5e-4\n" + RUN,
     "which is m = 0.5"),
    ("two pd/ material styles under hybrid", TWO_TYPES + "pair_style hybrid pd/ordinary pd/bond\n"
     f"pair_coeff 1 1 pd/ordinary {OK_ORD}\npair_coeff 2 2 pd/bond pmb K 1e9 horizon {H}\n"
     f"pair_coeff 1 2 pd/ordinary horizon {H}\n" + RUN, "one pd/ material style per simulation"),
    # material files
    ("too few material names", TWO_TYPES + f"pair_style pd/ordinary\npair_coeff * * file {MATERIALS} PMMA horizon {H}\n",
     "expected 2 material names (one per atom type, NULL for a type without), but type 2's is the keyword 'horizon'"),
    ("two material names for one type", block(6) + f"pair_style pd/ordinary\npair_coeff * * file {MATERIALS} PMMA PMMA horizon {H}\n",
     "more material names than the 1 atom type: 'PMMA' follows type 1's"),
    ("no material names", block(6) + f"pair_style pd/ordinary\npair_coeff * * file {MATERIALS}\n",
     "expected a path and 1 material names"),
    ("file on a single type pair", block(6) + f"pair_style pd/ordinary\npair_coeff 1 1 file {MATERIALS} PMMA\n",
     "use 'pair_coeff * * file"),
    ("material file missing", block(6) + f"pair_style pd/ordinary\npair_coeff * * file nosuch.pd PMMA horizon {H}\n",
     "cannot open 'nosuch.pd'"),
    ("material file with a NUL byte", block(6) + f"pair_style pd/ordinary\npair_coeff * * file nul.pd glass horizon {H}\n",
     "coeff file 'nul.pd': a NUL byte on line 2 (byte 13): not a text file, or a damaged one"),
    ("material file value inf", block(6) + f"pair_style pd/ordinary\npair_coeff * * file inf.pd glass horizon {H}\n",
     "must be a finite number"),
    ("material file key twice", block(6) + f"pair_style pd/ordinary\npair_coeff * * file twice.pd glass horizon {H}\n",
     "given twice"),
    ("material block twice", block(6) + f"pair_style pd/ordinary\npair_coeff * * file block2.pd glass horizon {H}\n",
     "glass defined twice (lines 1 and 5)"),
    ("a long comment line is one line (the line after it is read)",
     block(6) + f"pair_style pd/ordinary\npair_coeff * * file long.pd glass horizon {H}\n", "line 5: density"),
    ("a horizon longer than the box (before: LAMMPS's bin error)", block(6, "s s s") + ORD + "E 1e9 nu 0.25 horizon 10\n" + RUN,
     "horizon 10 is longer than the whole box"),
    # other styles and misuse
    ("compute pd/fracture with arguments", block(6) + ORD + f"{OK_ORD}\ncompute f all pd/fracture total\n",
     "takes no arguments"),
    ("fix pd/bonds by hand", block(6) + "fix mine all pd/bonds noweights history 0\n", "do not define it by hand"),
    ("fix pd/timestep with fix dt/reset", block(8) + ORD + f"{OK_ORD}\nfix 1 all nve\nfix ts all pd/timestep\n"
     "fix dt all dt/reset 1 NULL NULL 1e-5 units box\nrun 0\n", "both set the time step: unfix one of them"),
    ("minimize with Johnson-Cook (plastic)", block(8) + JC + "\nminimize 1e-10 1e-10 10 100\n",
     "minimize with bond failure or plasticity is not supported"),
    ("pd/contact unknown coefficient", block(6) + CONTACT + "stiffnes 1e20\n", "unknown keyword 'stiffnes'"),
    # quadrature (pair_pd.cpp)
    ("unknown quadrature", block(6) + "pair_style pd/bond quadrature gauss\n",
     "'quadrature gauss': expected point or partial"),
    ("quadrature without a name", block(6) + "pair_style pd/ordinary quadrature\n",
     "'quadrature ': expected point or partial"),
    ("partial quadrature with legacy", block(6) + "pair_style pd/bond legacy quadrature partial\n",
     "'quadrature partial' and 'legacy' do not go together"),
    ("partial quadrature with legacy (other order)", block(6) + "pair_style pd/ordinary quadrature partial legacy\n",
     "'quadrature partial' and 'legacy' do not go together"),
    # one rank's error (LAMMPS's own error->one) reaches the output too
    ("plain hybrid with a type pair left unset", TWO_TYPES + "pair_style hybrid pd/ordinary pd/contact\n"
     f"pair_coeff 1 1 pd/ordinary {OK_ORD}\npair_coeff 2 2 pd/contact stiffness 1e20\n" + RUN,
     "All pair coeffs are not set"),
    ("a subnormal modulus (its stable step is inf)", block(6) + BOND + f"K 1e-320 horizon {H}\n",
     "K = 1e-320 is below the smallest normal number"),
    ("'fail legacy' with a negative s00 (breaks every bond at once)", block(6) +
     f"pair_style pd/bond legacy\npair_coeff * * pmb K 1e9 horizon {H} fail legacy -0.0005 0.25\n",
     "'fail legacy' s00 = -0.0005 must be positive"),
    ("Johnson-Cook d2 without d1 (no damage: d2 unused)", block(6) + JC + "d2 0.1\n",
     "d2 (Johnson-Cook damage d2) is used only with d1"),
    ("Johnson-Cook Dc without d1", block(6) + JC + "Dc 0.5\n", "Dc (critical damage"),
    ("Johnson-Cook d1 0 (a zero fracture strain)", block(6) + JC + "d1 0\n",
     "the fracture strain d1 + d2 = 0 must be positive"),
    ("Johnson-Cook taylor_quinney without T_melt", block(6) + JC + "taylor_quinney 0.8\n",
     "taylor_quinney (fraction of plastic work turned into heat) is used only with T_melt"),
    ("pd/contact legacy with friction", block(8) + f"pair_style hybrid/overlay pd/bond legacy pd/contact legacy friction 0.2\n"
     f"pair_coeff * * pd/bond pmb K 1e9 horizon {H}\npair_coeff * * pd/contact\ncomm_modify vel yes\n" + RUN,
     "has no friction"),
]

# Restart files of each pd/ style (families built by 'run 0'), read back
# with another style, model or setting: refused by name, never continued
# with state dropped or misread.
RESTARTS = {
    "j2": f"pair_style pd/corr model j2\npair_coeff * * E 1e9 nu 0.3 yield 1e6 horizon {H}\n",
    "elastic": f"pair_style pd/corr model elastic\npair_coeff * * E 1e9 nu 0.3 horizon {H}\n",
    "ordinary": f"pair_style pd/ordinary\npair_coeff * * {OK_ORD}\n",
    "bond": f"pair_style pd/bond\npair_coeff * * pmb K 1e9 horizon {H}\n",
}
for name, pair in RESTARTS.items():
    run(block(6, "s s s") + pair + f"run 0\nwrite_restart {name}.restart\n", d)


def restart(name, after):
    return f"read_restart {name}.restart\n{after}fix 1 all nve\ntimestep 1e-8\nrun 1\n"


CORR = "pair_style pd/corr model "
CORR_OK = f"E 1e9 nu 0.3 horizon {H}"
TS = block(8) + ORD + f"{OK_ORD}\nfix 1 all nve\ntimestep 1e-8\n"
FRAG = block(6) + ORD + f"{OK_ORD}\ncompute frag all pd/fragments "
cases += [
    # pd/corr: model names, constants of another model, settings
    ("pd/corr unknown model", block(6) + CORR + "plastic\n",
     "model 'plastic': expected elastic, neohookean, j2 or johnson_cook"),
    ("pd/corr model name in capitals", block(6) + CORR + "J2\n", "model 'J2': expected elastic"),
    ("pd/corr model without a name", block(6) + "pair_style pd/corr model\n", "'model' needs a value"),
    ("pd/corr elastic given a hardening modulus", block(6) + CORR + f"elastic\npair_coeff * * {CORR_OK} hardening 1e8\n",
     "hardening (linear hardening modulus) is not used by model elastic"),
    ("pd/corr neohookean given a yield stress", block(6) + CORR + f"neohookean\npair_coeff * * {CORR_OK} yield 1e6\n",
     "yield (initial yield stress) is not used by model neohookean"),
    ("pd/corr j2 given a Johnson-Cook constant", block(6) + CORR + f"j2\npair_coeff * * {CORR_OK} yield 1e6 jc_B 1e8\n",
     "jc_B (Johnson-Cook hardening stress B) is not used by model j2"),
    ("pd/corr johnson_cook without jc_B", block(6) + CORR + f"johnson_cook\npair_coeff * * {CORR_OK} yield 1e6 jc_n 0.1\n",
     "model johnson_cook needs jc_B"),
    ("pd/corr johnson_cook T_melt below T_room", block(8) + JC + "T_melt 200 heat_capacity 900\n",
     "T_melt 200 must exceed T_room"),
    ("pd/corr plane stress with j2", PLATE + CORR + f"j2 plane stress thickness 1e-3\npair_coeff * * {CORR_OK} yield 1e6\n"
     "set group all volume 2.5e-10\nset group all density 1000\n" + RUN,
     "plane stress needs model elastic (the j2 law"),
    ("pd/corr plane stress with johnson_cook", PLATE + CORR + "johnson_cook plane stress thickness 1e-3\n"
     f"pair_coeff * * {CORR_OK} yield 1e6 jc_B 1e8 jc_n 0.1\nset group all volume 2.5e-10\nset group all density 1000\n" + RUN,
     "plane stress needs model elastic (the johnson_cook law"),
    ("pd/corr unknown strain", block(6) + CORR + "elastic strain nonlocal\n",
     "strain 'nonlocal': expected classical or extended"),
    ("pd/corr strain without a value", block(6) + CORR + "elastic strain\n", "'strain' needs a value"),
    ("pd/corr stabilization a word", block(6) + CORR + "elastic stabilization some\n", "some"),
    ("pd/corr stabilization overflows", block(6) + CORR + "elastic stabilization 1e400\n", overflow("stabilization")),
    ("pd/corr stabilization without a value", block(6) + CORR + "elastic stabilization\n", "'stabilization' needs a value"),
    ("pd/corr unknown influence", block(6) + CORR + "elastic influence cubic\n", "unknown influence function 'cubic'"),
    ("pd/corr with legacy", block(6) + CORR + f"elastic legacy\npair_coeff * * {CORR_OK}\n" + RUN,
     "has no legacy PERI counterpart: drop 'legacy'"),
    # fix pd/timestep: each keyword's bad values
    ("pd/timestep every 0", TS + "fix ts all pd/timestep every 0\n", "every must be a step count >= 1, got '0'"),
    ("pd/timestep every a word", TS + "fix ts all pd/timestep every often\n", "often"),
    ("pd/timestep safety 0", TS + "fix ts all pd/timestep safety 0\n", "safety must be a fraction in (0, 1], got '0'"),
    ("pd/timestep safety above 1", TS + "fix ts all pd/timestep safety 1.5\n", "safety must be a fraction in (0, 1], got '1.5'"),
    ("pd/timestep travel negative", TS + "fix ts all pd/timestep travel -0.1\n",
     "travel must be a fraction of the spacing >= 0 (0: no limit), got '-0.1'"),
    ("pd/timestep min 0", TS + "fix ts all pd/timestep min 0\n", "min must be a time step > 0, got '0'"),
    ("pd/timestep max negative", TS + "fix ts all pd/timestep max -1e-7\n", "max must be a time step > 0, got '-1e-7'"),
    ("pd/timestep max overflows", TS + "fix ts all pd/timestep max 1e400\n",
     ("max must be a time step > 0, got '1e400'", overflow("max")[1])),
    ("pd/timestep min above max", TS + "fix ts all pd/timestep min 1e-6 max 1e-7\n", "min 1e-06 exceeds max 1e-07"),
    ("pd/timestep grow 1", TS + "fix ts all pd/timestep grow 1\n", "grow must be a factor > 1, got '1'"),
    ("pd/timestep unknown keyword", TS + "fix ts all pd/timestep often 5\n",
     "unknown keyword 'often' (every, safety, travel, min, max, grow)"),
    ("pd/timestep keyword without a value", TS + "fix ts all pd/timestep safety\n", "'safety' needs a value"),
    ("pd/timestep on a group", TS + "group low id < 10\nfix ts low pd/timestep\n", "use group all, not 'low'"),
    ("pd/timestep without a pd/ pair style", block(8) + f"pair_style peri/pmb\npair_coeff * * 1e20 {H} 1.0 0.0\n"
     "fix 1 all nve\nfix ts all pd/timestep\nrun 0\n", "needs a pd/ material pair style"),
    # quadrature and recontact on every material style
    ("quadrature in capitals", block(6) + "pair_style pd/ordinary quadrature Partial\n",
     "'quadrature Partial': expected point or partial"),
    ("pd/corr quadrature without a name", block(6) + CORR + "elastic quadrature\n", "expected point or partial"),
    ("pd/bond recontact a number", block(6) + "pair_style pd/bond recontact 1\n", "'recontact 1': expected near, any or none"),
    ("pd/corr recontact without a mode", block(6) + CORR + "elastic recontact\n", "expected near, any or none"),
    # fix pd/precrack
    ("pre-crack of an unknown shape", block(6) + ORD + f"{OK_ORD}\nfix c all pd/precrack disk 0 0 0 1e-3\n",
     "Illegal fix pd/precrack command: expected 'segment"),
    ("pre-crack patch in 2D", PLATE + "pair_style pd/ordinary plane stress thickness 1e-3\n"
     f"pair_coeff * * {OK_ORD}\nfix c all pd/precrack patch 0 0 0 1e-3 0 0 0 1e-3 0\n", "'patch' is for 3D"),
    ("pre-crack coordinate a word", block(6) + ORD + f"{OK_ORD}\nfix c all pd/precrack patch 0 0 x 1e-3 0 0 0 1e-3 0\n",
     ("coordinate 'x' must be a finite number", "instead of 'x'")),
    ("pre-crack outside the box", block(6) + ORD + f"{OK_ORD}\nfix c all pd/precrack patch 1 1 1 1e-3 0 0 0 1e-3 0\n" + RUN,
     "the crack lies outside the simulation box"),
    # compute pd/fragments
    ("pd/fragments unknown keyword", FRAG + "size 3\n", "unknown keyword 'size' (min_atoms, bins, range)"),
    ("pd/fragments min_atoms 0", FRAG + "min_atoms 0\n", "min_atoms must be an integer >= 1"),
    ("pd/fragments bins 0", FRAG + "bins 0\n", "bins must be an integer from 1 to"),
    ("pd/fragments range lo 0", FRAG + "range 0 1\n", "range lo must be a finite mass > 0"),
    ("pd/fragments range hi below lo", FRAG + "range 1 0.5\n", "range hi must be a finite mass > lo = 1"),
    ("pd/fragments range missing hi", FRAG + "range 1\n", "'range' needs"),
    # restarts read with another style, model or setting
    ("a pd/corr elastic restart continued with model j2",
     restart("elastic", CORR + f"j2\npair_coeff * * {CORR_OK} yield 1e6\n"),
     "the restart file carries no per-atom field 'plastic_strain'"),
    ("a bond store made by hand without the weights pd/ordinary needs",
     block(8) + "fix PD_BONDS all pd/bonds noweights history 0\n" + ORD + f"{OK_ORD}\n" + RUN,
     "Pair pd/ordinary: the bond store PD_BONDS has bonds with no weights and 0 history values, this style "
     "needs weights and 0"),
    ("set volume after the families were built", block(8) + ORD + f"{OK_ORD}\nrun 0\n"
     "set atom 5 volume 2e-10\nfix 1 all nve\ntimestep 1e-8\nrun 1\n",
     "the volume of 1 atom changed since the bond families were built (e.g. atom 5:"),
    ("a pd/corr j2 restart continued with model elastic",
     restart("j2", CORR + f"elastic\npair_coeff * * {CORR_OK}\n"),
     "the restart file carries per-atom field 'plastic_strain' (width 1), which pair style pd/corr does not keep"),
    ("a pd/corr j2 restart continued with johnson_cook", restart("j2", JC + "\n"),
     "the restart file carries no per-atom field 'corr_increment'"),
    ("a pd/corr restart continued with pd/ordinary", restart("j2", ORD + f"{OK_ORD}\n"),
     "restart file bonds carry 3 history values, the pair style now needs 0"),
    ("a pd/bond restart continued with pd/ordinary", restart("bond", ORD + f"{OK_ORD}\n"),
     "Pair pd/ordinary: the bond families were built for other pair settings"),
    ("a pd/ordinary restart continued with pd/bond", restart("ordinary", BOND + f"K 1e9 horizon {H}\n"),
     "Pair pd/bond: the bond families were built for other pair settings"),
    ("a pd/bond pmb restart continued with microplastic bonds",
     restart("bond", f"pair_style pd/bond\npair_coeff * * microplastic K 1e9 horizon {H} yield_stretch 1e-3\n"),
     "restart file bonds carry 0 history values, the pair style now needs 1"),
    ("a pd/ordinary restart continued with another influence function",
     restart("ordinary", "pair_style pd/ordinary influence gaussian\n"), "the bond families were built for other pair settings"),
    ("a pd/ordinary restart continued without the directional correction",
     restart("ordinary", "pair_style pd/ordinary directional_correction no\n"),
     "the bond families were built for other pair settings"),
]
# every case on 1 and 2 ranks: the ERROR must reach the output either way
for ranks in (1, 2):
    for what, script, message in cases:
        out, _ = run(script, d, ranks=ranks, expect_error=True)
        errors = [l for l in out.splitlines() if l.startswith("ERROR")]
        crashed = any(s in out for s in ("Segmentation", "signal 11", "Aborted", "core dumped"))
        accepted = message if isinstance(message, tuple) else (message,)
        check(f"{what} ({ranks} rank{'s' if ranks > 1 else ''}): ERROR names it",
              bool(errors) and any(m in errors[0] for m in accepted) and not crashed,
              errors[0][:200] if errors else out.strip().splitlines()[-1][:200] if out.strip() else "no output")
check(f"the catalogue has at least 150 cases ({len(cases)})", len(cases) >= 150)
finish()
