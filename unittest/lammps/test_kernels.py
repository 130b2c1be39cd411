"""The bond loops' two ways give the same forces, energy and virial, to
the bit.

A row of bonds goes either through the vectorized first pass and the scalar
scatter, or bond by bond: rows with a broken or breaking bond, and every
row with the test hook PDEXT_BOND_BY_BOND=1 (the force loop's and the
state-based sums' rows: pd/ordinary's dilatation, pd/corr's sums). Both
must do the same arithmetic in the same order. Each case runs six times
from the same start: bond by bond with the global energy, the pressure and
the per-atom energy (compute pe/atom) on every step; the same in two passes
(the tallies in the scalar one); the global tallies alone in two passes;
with thermo on the last step only; and with the per-atom virial (compute
stress/atom, each bond's tensor half to each end) on every step, chunked
and bond by bond. Positions, velocities and forces after 60 steps, as text
with 17 digits, must be identical, and so must the energy and virial
(compute pressure NULL virial: the pressure's kinetic part would hide it)
at every step of the runs tallied every step, and the sums of the per-atom
energies and of the per-atom virials, chunked and bond by bond. The
per-atom virials must sum to the global virial times the box volume
(negated: stress/atom is a stress times a volume) at every step, to
round-off: 1e-8 of the largest component, as the global virial sums x (x) F
over atoms whose positions are some 10^6 times their displacements (the
random velocities' stresses are small: the two sums differ by up to 4e-10
of it). test_atom_stress.py checks each atom's value. Bonds break (or,
microplastic, yield) during the runs (checked), so rows of both kinds meet;
partial quadrature gives rows of more than one chunk (64 bonds); two atom
types and random velocities (0.6 m/s) make every bond different.
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
    # alpha 0: from the second step the critical stretch's kernels, the
    # bond breaking after its force acted
    "pd/bond legacy PERI's rule alpha 0": ("pair_style pd/bond legacy\n"
                                           "pair_coeff * * pmb K 14.9e9 horizon 0.0015001 "
                                           "fail legacy 0.0005 0\n"),
    "pd/ordinary m 0 stretch": ("pair_style pd/ordinary\n"
                                "pair_coeff * * K 14.9e9 G 8.94e9 horizon 0.0015001 m 0 "
                                "fail stretch 0.0004\n"),
    # no bond breaks: rows whose bonds yield go bond by bond (the return
    # map), the others through the first pass with the plastic stretch read
    "pd/bond microplastic": ("pair_style pd/bond\n"
                             "pair_coeff * * pmb K 14.9e9 horizon 0.0015001\n"
                             "pair_coeff 1 1 microplastic K 14.9e9 horizon 0.0015001 "
                             "yield_stretch 0.0003\n"),
    # pd/corr: classical's force is not along the bond (its first pass
    # stores the force's components), extended's is
    "pd/corr classical stretch": ("pair_style pd/corr strain classical model elastic\n"
                                  "pair_coeff * * K 14.9e9 G 8.94e9 horizon 0.0015001 "
                                  "fail stretch 0.0004\n"),
    "pd/corr extended energy": ("pair_style pd/corr model elastic\n"
                                "pair_coeff * * K 14.9e9 G 8.94e9 horizon 0.0015001 "
                                "fail energy Gc 0.2\n"),
}
YIELDS = {"pd/bond microplastic"}


def deck(pair, every, tag, per_atom):
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
compute pa all pe/atom
compute spa all reduce sum c_pa
compute vir all pressure NULL virial
compute frac all pd/fracture
compute sa all stress/atom NULL virial
compute ssa all reduce sum c_sa[1] c_sa[2] c_sa[3] c_sa[4] c_sa[5] c_sa[6]
thermo {every}
thermo_style custom step vol pe c_vir[1] c_vir[2] c_vir[3] c_vir[4] c_vir[5] c_vir[6] c_frac[1]{EXTRA[per_atom]}
thermo_modify format float %.17g
run 60
write_dump all custom dump.{tag} id x y z vx vy vz fx fy fz modify format float %.17g sort id
run 0
"""


# the per-atom output each run prints with thermo
EXTRA = {None: "", "energy": " c_spa", "virial": "".join(f" c_ssa[{c}]" for c in range(1, 7))}

# (thermo every, per-atom output, bond by bond): bond by bond, tallied
# every step; chunked, the same; chunked, global tallies every step;
# chunked, tallied at the end; per-atom virial every step, chunked and
# bond by bond
RUNS = [(1, "energy", True), (1, "energy", False), (1, None, False), (60, None, False),
        (1, "virial", False), (1, "virial", True)]

for name, pair in CASES.items():
    tag = re.sub(r"[^A-Za-z0-9]+", "_", name)
    dumps, broken, tallies, per_atom_sums, dissipated, atom_virial_sums = [], [], [], [], [], []
    for every, per_atom, by_bond in RUNS:
        key = f"{tag}.{every}{'.atom' if per_atom else ''}{'.bond' if by_bond else ''}"
        MPI_ENV["PDEXT_BOND_BY_BOND"] = "1" if by_bond else "0"
        out, _ = run(deck(pair, every, key, per_atom), d, name=f"in.{key}")
        dumps.append(os.path.join(d, f"dump.{key}"))
        broken.append(int(log_value(out, r"pd/bonds: \d+ bonds kept, (\d+) of them broken")))
        # the timed run's thermo rows (before its Loop time line)
        rows = thermo(out.split("Loop time")[0])
        tallies.append([tuple(r[k] for k in ["PotEng"] + [f"c_vir[{c}]" for c in range(1, 7)])
                        for r in rows])
        dissipated.append(rows[-1]["c_frac[1]"])
        per_atom_sums.append([r["c_spa"] for r in rows] if per_atom == "energy" else None)
        if per_atom == "virial":
            atom_virial_sums.append([[r[f"c_ssa[{c}]"] for c in range(1, 7)] for r in rows])
            atom_virial = [(r["Volume"], [r[f"c_vir[{c}]"] for c in range(1, 7)],
                            [r[f"c_ssa[{c}]"] for c in range(1, 7)]) for r in rows]
    MPI_ENV.pop("PDEXT_BOND_BY_BOND")
    total = int(log_value(out, r"pd/bonds: (\d+) bonds kept"))
    if name in YIELDS:
        # (the plastic work of the return map: bonds yielded; pd/bond's
        # elastic type 2 and the mixed pairs never do, so rows go both ways)
        check(f"{name}: bonds yielded during the run, none broke", broken[2] == 0 and dissipated[2] > 0,
              f"{broken[2]} broken, dissipated {dissipated[2]}")
    else:
        check(f"{name}: some bonds broke during the run, not all (so rows go both ways)",
              0 < broken[2] < total / 2, f"{broken[2]} of {total} broken")
    check(f"{name}: the same energy dissipated in the four runs, to the bit", len(set(dissipated)) == 1,
          f"{dissipated}")
    check(f"{name}: the same bonds broke in the four runs", len(set(broken)) == 1, f"{broken}")
    texts = [open(p).read() for p in dumps]
    for r in (1, 2, 3, 4, 5):
        same = texts[0] == texts[r]
        check(f"{name}: positions, velocities and forces identical to the bit (run {r + 1} against "
              "bond by bond)", same,
              "" if same else f"max relative difference {max_rel_diff(read_dump(dumps[0]), read_dump(dumps[r])):.3g}")
    for r in (1, 2, 4, 5):
        check(f"{name}: energy and virial at each of the 61 steps identical to the bit (run {r + 1} "
              "against bond by bond)", len(tallies[0]) == 61 and tallies[0] == tallies[r],
              f"{len(tallies[0])} rows; first difference "
              f"{next(((a, b) for a, b in zip(tallies[0], tallies[r]) if a != b), None)}")
    check(f"{name}: the per-atom energies' sum at each step identical to the bit, chunked and bond by bond",
          len(per_atom_sums[0]) == 61 and per_atom_sums[0] == per_atom_sums[1],
          f"first difference {next(((a, b) for a, b in zip(per_atom_sums[0], per_atom_sums[1]) if a != b), None)}")
    check(f"{name}: the per-atom virials' sums at each step identical to the bit, chunked and bond by bond",
          len(atom_virial_sums[0]) == 61 and atom_virial_sums[0] == atom_virial_sums[1],
          f"first difference {next(((a, b) for a, b in zip(*atom_virial_sums) if a != b), None)}")
    # (the pressure is the virial over the volume: SI's pressure unit is 1)
    worst = max(max(abs(a + v * g) for g, a in zip(glob, atoms)) / max(abs(v * g) for g in glob)
                for v, glob, atoms in atom_virial)
    check(f"{name}: the per-atom virials sum to the global virial at each of the 61 steps (1e-8)",
          len(atom_virial) == 61 and worst < 1e-8, f"{len(atom_virial)} rows, worst relative difference {worst:.3g}")

finish()
