"""Interface fracture energy: 'fail stretch Gc' and 'fail energy
Gc' on a line between two types give the bonds between them their own G_c.

Two halves of one material (types 1 below, 2 above a plane along the
lattice) are pulled apart quasi-statically: the upper half moves rigidly
in small increments, each followed by one force evaluation ('run 0'), so
only the bonds that cross the plane stretch and break. Three runs each:
  A  one G_c everywhere (G_int);
  B  bulk G_c = 10 G_int, the interface 'pair_coeff 1 2 ... Gc G_int';
  C  bulk G_c = 10 G_int, the interface mixed (its types' mean).
B must release exactly what A releases (same bonds, same critical values:
the pair's G_c, not the bulk's), and about G_int per unit area: within
-25%/+35%, the lattice calibration being exact only on average over crack
orientations (0.91-1.15 measured for a plane along the lattice)
plus the overshoot of the finite increments. C releases about 10 times
more (the bulk's). For 3D and 2D (plane stress and strain), both laws and
the influence functions the energy law allows in 2D."""
import itertools
from lmptest import *

d = workdir()
h = SPACING
G_INT, E, NU = 50.0, 1e9, 0.25
NX, NZ = 8, 10
STEPS, DZ = 150, 2e-7


def scene(two_d, style, fail, gc_bulk, interface, dz):
    if two_d:
        head = f"""units si
dimension 2
boundary p s p
atom_style peri
atom_modify map array
lattice sq {h}
region box block 0 {NX} 0 {NZ} -0.5 0.5
create_box 2 box
create_atoms 1 box
set group all volume {h * h * 1e-3}
region upper block INF INF {NZ / 2 - 0.25} INF INF INF
"""
        shift = f"0 {dz} 0"
    else:
        head = f"""units si
boundary p p s
atom_style peri
atom_modify map array
lattice sc {h}
region box block 0 {NX} 0 {NX} 0 {NZ}
create_box 2 box
create_atoms 1 box
set group all volume {h ** 3}
region upper block INF INF INF INF {NZ / 2 - 0.25} INF
"""
        shift = f"0 0 {dz}"
    material = "pmb E" if style.startswith("pd/bond") else "E"
    nu = "" if style.startswith("pd/bond") else f" nu {NU}"
    return head + f"""set group all density 1000
set region upper type 2
group upper region upper
pair_style {style}
pair_coeff * * {material} {E}{nu} horizon {3.0001 * h} fail {fail} Gc {gc_bulk}
{interface}
compute frac all pd/fracture
thermo_style custom step c_frac[2] c_frac[3]
thermo_modify format float %.15g
run 0
variable k loop {STEPS}
label again
displace_atoms upper move {shift} units box
run 0
next k
jump SELF again
"""


cases = [  # (label, 2D?, pair style, law)
    ("3D pd/ordinary energy (influence inverse)", False, "pd/ordinary", "energy"),
    ("3D pd/ordinary stretch", False, "pd/ordinary", "stretch"),
    # point quadrature: the bonds counted below are the lattice's within the horizon
    ("3D pd/bond stretch", False, "pd/bond quadrature point", "stretch"),
    ("2D plane stress pd/ordinary energy (constant)", True, "pd/ordinary plane stress thickness 1e-3", "energy"),
    ("2D plane stress pd/ordinary energy (tupek)", True,
     "pd/ordinary plane stress thickness 1e-3 influence tupek", "energy"),
    ("2D plane strain pd/ordinary stretch", True, "pd/ordinary plane strain thickness 1e-3", "stretch"),
]
for label, two_d, style, law in cases:
    area = NX * h * (1e-3 if two_d else NX * h)
    # pd/bond: a line between types is a whole bond definition (stiffness too)
    material = f"pmb E {E} " if style.startswith("pd/bond") else ""
    line = f"pair_coeff 1 2 {material}horizon {3.0001 * h} fail {law} Gc {G_INT}"
    released = {}
    # C's bonds need sqrt(10) times the separation: larger increments (its check is rough)
    for name, gc_bulk, interface, dz in (("A", G_INT, "", DZ), ("B", 10 * G_INT, line, DZ),
                                         ("C", 10 * G_INT, "", 4 * DZ)):
        out, rows = run(scene(two_d, style, law, gc_bulk, interface, dz), d)
        released[name] = (rows[-1]["c_frac[2]"], rows[-1]["c_frac[3]"])
    (ea, na), (eb, nb), (ec, nc) = released["A"], released["B"], released["C"]
    # every bond across the plane: per column of atoms, the family's extent across it
    dims = 2 if two_d else 3
    family = [v for v in itertools.product(range(-3, 4), repeat=dims) if 0 < sum(c * c for c in v) <= 9.0006]
    crossing = NX ** (dims - 1) * sum(v[-1] for v in family if v[-1] > 0)
    check(f"{label}: the separation breaks every bond across the plane ({crossing}), and only those",
          na == nb == nc == crossing, f"{na:.0f}, {nb:.0f}, {nc:.0f}")
    check_le(f"{label}: the interface's G_c releases what one material of that G_c releases",
             abs(eb - ea) / ea, 1e-9, "same bonds, same critical values")
    g = ea / area / G_INT
    check(f"{label}: released energy per area is the interface's G_c", 0.75 <= g <= 1.35,
          f"{g:.3f} G_int; lattice calibration and increment overshoot")
    check(f"{label}: the mixed interface releases the bulk's (about 10x)", 6.0 <= ec / ea <= 14.0, f"{ec / ea:.2f}")
finish()
