"""The bond loops' two ways give the same forces, to the bit (issue 13).

A row of bonds goes either through the vectorized first pass and the
scalar scatter, or bond by bond: on steps that tally energy and virial,
and for rows with a broken or breaking bond. Both must do the same
arithmetic in the same order. Each case runs twice from the same start,
once with the energy tallied on every step (every row bond by bond) and
once on the last step only (rows in two passes, except those with broken
bonds), and compares positions, velocities and forces after 60 steps as
text with 17 digits: they must be identical. Bonds break during the runs
(checked), so rows of both kinds meet in the second run; partial
quadrature gives rows of more than one chunk (64 bonds); two atom types
and random velocities (0.6 m/s) make every bond different.
"""
from lmptest import *

d = workdir()

CASES = {
    # pd/bond, partial quadrature (125 bonds owned per atom: two chunks)
    "pd/bond stretch": ("pair_style pd/bond\n"
                        "pair_coeff * * pmb K 14.9e9 horizon 0.0015001 fail stretch 0.0004\n"),
    "pd/ordinary m 1/2 energy": ("pair_style pd/ordinary\n"
                                 "pair_coeff * * K 14.9e9 G 8.94e9 horizon 0.0015001 m 0.5 "
                                 "fail energy Gc 0.2\n"),
    # PERI's rule: its note (each atom's next s0) in the scalar pass
    "pd/bond legacy PERI's rule": ("pair_style pd/bond legacy\n"
                                   "pair_coeff * * pmb K 14.9e9 horizon 0.0015001 "
                                   "fail legacy 0.0005 0.25\n"),
    "pd/ordinary m 0 stretch": ("pair_style pd/ordinary\n"
                                "pair_coeff * * K 14.9e9 G 8.94e9 horizon 0.0015001 m 0 "
                                "fail stretch 0.0004\n"),
}


def deck(pair, every, tag):
    return f"""units si
boundary p p p
atom_style peri
atom_modify map array
lattice sc 0.0005
region box block 0 8 0 8 0 8
create_box 2 box
create_atoms 1 box
set group all density 2200
set group all volume 1.25e-10
set group all type/fraction 2 0.3 77
variable vx atom normal(0,0.6,4928)
variable vy atom normal(0,0.6,4929)
variable vz atom normal(0,0.6,4930)
velocity all set v_vx v_vy v_vz
{pair}
fix 1 all nve
timestep 1.0e-8
thermo {every}
thermo_style custom step pe press
run 60
write_dump all custom dump.{tag} id x y z vx vy vz fx fy fz modify format float %.17g sort id
run 0
"""


for name, pair in CASES.items():
    tag = re.sub(r"[^A-Za-z0-9]+", "_", name)
    dumps, broken = [], []
    for every in (1, 60):
        out, _ = run(deck(pair, every, f"{tag}.{every}"), d, name=f"in.{tag}.{every}")
        dumps.append(os.path.join(d, f"dump.{tag}.{every}"))
        broken.append(int(log_value(out, r"pd/bonds: \d+ bonds kept, (\d+) of them broken")))
    total = int(log_value(out, r"pd/bonds: (\d+) bonds kept"))
    check(f"{name}: some bonds broke during the run, not all (so rows go both ways)",
          0 < broken[1] < total / 2, f"{broken[1]} of {total} broken")
    check(f"{name}: the same bonds broke with the energy tallied every step", broken[0] == broken[1],
          f"{broken[0]} vs {broken[1]}")
    same = open(dumps[0]).read() == open(dumps[1]).read()
    check(f"{name}: positions, velocities and forces identical to the bit", same,
          "" if same else f"max relative difference {max_rel_diff(read_dump(dumps[0]), read_dump(dumps[1])):.3g}")

finish()
