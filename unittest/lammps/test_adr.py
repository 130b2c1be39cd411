"""fix pd/adr: quasi-static loading by adaptive dynamic relaxation.

(1) An elastic strip pulled by its grips relaxes under fix pd/adr to the
    equilibrium that minimize finds, for a bond-based and a state-based
    solid, within a few iterations per spacing of its length (critical
    damping of the lowest mode), and its middle stretches as the grips do.
(2) 1 and 2 ranks give the same relaxed positions to round-off, bonds
    breaking and pd/contact under hybrid/overlay included.
(3) A run split by write_restart / read_restart mid-relaxation continues
    as the unsplit run, on 1 and 2 ranks; runs split by run commands end
    at the same equilibrium.
(4) A notched plate loaded in steps grows its crack under every failure
    law (stretch, energy with pd/contact under hybrid/overlay, legacy):
    bonds break only once the load is high enough, the dissipated energy
    is positive and grows, the load peaks and falls, every load step
    converges, nothing blows up.
Bad input stops with an ERROR that names it."""
import math

from lmptest import *

d = workdir()
H = 5e-4                      # spacing
PLATE_HEAD = f"""units si
dimension 2
boundary s s p
atom_style peri
atom_modify map array
neighbor 0.0001 bin
"""


def strip(pair, length=40, width=10):
    """A plane-stress strip with grips 3 spacings deep at both ends."""
    return PLATE_HEAD + f"""lattice sq {H}
region b block 0 {length} 0 {width} -0.5 0.5
create_box 1 b
create_atoms 1 box
set group all density 1180
set group all volume {H * H * 1e-3}
{pair}
region left block INF 2.5 INF INF INF INF units lattice
region right block {length - 2.5} INF INF INF INF INF units lattice
group left region left
group right region right
group grips union left right
group free subtract all grips
region sa block 14.5 15.5 INF INF INF INF units lattice
region sb block 24.5 25.5 INF INF INF INF units lattice
group sa region sa
group sb region sb
run 0
displace_atoms right move {{pull}} 0 0 units box
"""


ELASTIC = {
    "pd/bond": "pair_style pd/bond plane stress thickness 0.001\npair_coeff * * pmb E 3.5e9 horizon 0.0015001",
    "pd/ordinary": "pair_style pd/ordinary plane stress thickness 0.001\n"
                   "pair_coeff * * E 3.5e9 nu 0.35 horizon 0.0015001 m 0.5",
}
PULL = 2e-5                   # 0.11% between the grips
TOL = 1e-8
STRAIN = "variable eps equal (xcm(sb,x)-xcm(sa,x))/(10*{h})-1\n".format(h=H)

# ---------------------------------------------------------------- (1)
for name, pair in ELASTIC.items():
    base = strip(pair).replace("{pull}", str(PULL))
    adr = base + f"""fix adr free pd/adr
fix 2 all enforce2d
variable r equal f_adr[1]
fix halt all halt 1 v_r < {TOL} error continue
thermo 1000
run 20000
{STRAIN}print "RESULT $(step) $(f_adr[1]:%.6g) $(v_eps:%.12g)"
""" + DUMP.format(file="adr.dump")
    out, _ = run(adr, d)
    steps, res, eps_adr = (log_value(out, r"RESULT (\S+) \S+ \S+"), log_value(out, r"RESULT \S+ (\S+) \S+"),
                           log_value(out, r"RESULT \S+ \S+ (\S+)"))
    xa = read_dump(f"{d}/adr.dump")
    mini = base + f"""fix l grips setforce 0 0 0
fix 2 all enforce2d
min_style cg
min_modify dmax 1e-5
minimize 0 1e-14 40000 100000
{STRAIN}print "RESULT $(v_eps:%.12g)"
""" + DUMP.format(file="min.dump")
    out, _ = run(mini, d)
    eps_min = log_value(out, r"RESULT (\S+)")
    xm = read_dump(f"{d}/min.dump")
    # the grips are 36 spacings apart; the lowest mode of such a chain in
    # pseudo time (the stability bound puts the highest at 2) is
    # omega_1 = 2 sin(pi / 72), and critical damping reduces it by
    # exp(-omega_1 n): ln(1/tol) / omega_1 iterations, twice that for the
    # Gershgorin bound's margin over the highest true mode
    omega1 = 2 * math.sin(math.pi / 72)
    limit = 2 * math.log(1 / TOL) / omega1
    check_le(f"{name}: ADR reaches the relative residual {TOL:g} (critical damping of the lowest mode)",
             steps, limit, f"{steps:.0f} iterations, residual {res:.3g}")
    # e = K^-1 R: the residual over the reaction, times the ratio of the
    # largest to the lowest stiffness of the strip ((36 / pi)^2 in 1D)
    diff = max(abs(p - q) for k in xa for p, q in zip(xa[k], xm[k])) / PULL
    check_le(f"{name}: ADR positions equal minimize's, relative to the pull", diff,
             TOL * (36 / math.pi) ** 2, "residual x condition of the strip")
    check_le(f"{name}: the middle's strain equals minimize's", abs(eps_adr / eps_min - 1),
             TOL * (36 / math.pi) ** 2 * 36 / 10, "the same over the 10-spacing gauge")
    # the nominal strain of the free length: rigid grips hold the strip's
    # Poisson contraction at its ends, the free surfaces are softer (no
    # surface correction), so the middle stretches a few % off it
    nominal = PULL / (36 * H)
    check_le(f"{name}: the middle stretches as the grips do, within 5%", abs(eps_adr / nominal - 1), 0.05,
             f"strain {eps_adr:.5g} against {nominal:.5g}: end effects of rigid grips")

# ---------------------------------------------------------------- bad input
# each mistake stops with an ERROR that names it
base = strip(ELASTIC["pd/bond"]).replace("{pull}", str(PULL))
for what, deck, expect in (
        ("a safety factor below 1", "fix adr free pd/adr safety 0.5\nrun 10\n", "safety must be a factor >= 1"),
        ("an unknown keyword", "fix adr free pd/adr damping 0.1\nrun 10\n", "unknown keyword 'damping'"),
        ("a second integrator on the group", "fix 1 all nve\nfix adr free pd/adr\nrun 10\n",
         "integrates some of its atoms too"),
        ("fix pd/timestep next to it", "fix ts all pd/timestep\nfix adr free pd/adr\nrun 10\n",
         "runs in pseudo time, where fix ts (pd/timestep)"),
        ("no pd/ material", "pair_style zero 0.002\npair_coeff * *\nfix adr free pd/adr\nrun 10\n",
         "Fix pd/adr needs a pd/ material pair style")):
    out, _ = run(base + deck, d, expect_error=True)
    check(f"bad input: {what} is an ERROR that says so", "ERROR" in out and expect in out,
          next((l for l in out.splitlines() if "ERROR" in l), "no ERROR")[:160])

# ---------------------------------------------------------------- (2), (3), (4)
# A notched plate, 20 mm x 15 mm, a 5.75 mm pre-crack from the left edge at
# mid-height, grips 3 rows deep at top and bottom, opened in load steps.
run(PLATE_HEAD + f"""lattice sq {H}
region b block 0 40 0 30 -0.5 0.5
create_box 1 b
create_atoms 1 box
set group all density 1180
set group all volume {H * H * 1e-3}
write_data plate.data
""", d)

LAWS = {
    "stretch": "pair_style pd/bond plane stress thickness 0.001\n"
               "pair_coeff * * pmb E 3.5e9 horizon 0.0015001 fail stretch Gc 400\n",
    "energy + contact": "pair_style hybrid/overlay pd/ordinary plane stress thickness 0.001 pd/contact\n"
                        "pair_coeff * * pd/ordinary E 3.5e9 nu 0.35 horizon 0.0015001 fail energy Gc 400\n"
                        "pair_coeff * * pd/contact\n",
    "legacy": "lattice sq 5e-4\npair_style pd/bond legacy plane stress thickness 0.001\n"
              "pair_coeff * * pmb E 3.5e9 horizon 0.0015001 fail legacy 0.0103 0.25\n",
}


def notched(pair, steps, opening, run_cmd, extra=""):
    return PLATE_HEAD + f"""read_data plate.data
{pair}fix crack all pd/precrack segment -0.001 0.00775 0.00575 0.00775
region top block INF INF 0.0135 INF INF INF units box
region bot block INF INF INF 0.0015 INF INF units box
group top region top
group bot region bot
group grips union top bot
group free subtract all grips
compute frac all pd/fracture
compute dmg all pd/damage
variable tipx atom x*(c_dmg>0.3)
compute tip all reduce max v_tipx
compute vf all property/atom vfrac
variable fyv atom fy*c_vf
compute load top reduce sum v_fyv
compute dsp all displace/atom
compute moved all reduce max c_dsp[4]
run 0
fix adr free pd/adr
fix 2 all enforce2d
variable r equal f_adr[1]
thermo_style custom step f_adr[1] f_adr[2] f_adr[4] c_frac[2] c_frac[3] c_tip c_load c_moved
thermo 1000
{extra}
variable k loop {steps}
label loop
displace_atoms top move 0 {opening / 2} 0 units box
displace_atoms bot move 0 {-opening / 2} 0 units box
{run_cmd}
run 0 post no
print "LOADSTEP $k $(step) $(f_adr[1]:%.6g) $(f_adr[4]:%.8g) $(c_frac[2]:%.8g) $(c_frac[3]) $(c_tip:%.6g) $(c_load:%.8g) $(c_moved:%.6g)"
next k
jump SELF loop
"""


def loadsteps(out):
    rows = []
    for line in out.splitlines():
        w = line.split()
        if w[:1] == ["LOADSTEP"]:
            rows.append([float(v) for v in w[1:]])
    return rows


# (2) 1 and 2 ranks: the same iterations on both (600 per load step, to a
# residual near 1e-11), bonds breaking in the last load steps. Mid-way
# through a relaxation the two differ by more than round-off: the damping's
# quotient divides by velocities that pass through 0, which amplifies the
# round-off of the reordered sums (1e-9 in c_n after 30 iterations); the
# relaxation then converges to the same equilibrium. Where a crack runs in
# a load step, bonds break in the iterations' transient states and the
# rank count can change which (as it can in a dynamic run): the last load
# steps here break a few bonds at a time.
for law, steps in (("stretch", 10), ("energy + contact", 11)):
    tag = law.split()[0]
    script = notched(LAWS[law], steps, 5e-6, "run 600") + DUMP.format(file=f"ranks.{tag}.$n")
    final, rows = {}, {}
    for ranks in (1, 2):
        out, _ = run(script, d, ranks=ranks, variables={"n": ranks})
        final[ranks] = read_dump(f"{d}/ranks.{tag}.{ranks}")
        rows[ranks] = loadsteps(out)
    b1, b2 = rows[1][-1][5], rows[2][-1][5]
    check(f"{law}: bonds break in the rank comparison, the same number", b1 > 0 and b1 == b2,
          f"{b1:.0f} and {b2:.0f} bonds")
    worst = max(r[2] for r in rows[1] + rows[2])
    check_le(f"{law}: every load step relaxed before the comparison", worst, 1e-9,
             "the positions of an equilibrium are compared")
    check_le(f"{law}: 2 ranks match 1 rank", max_rel_diff(final[1], final[2]), 1e-10,
             "round-off of reordered ghost sums and global sums, times the strip's condition")

# (3) restart mid-relaxation: 8 load steps, 60 iterations into the 9th,
# write_restart; the rest of the 9th from the file against the unsplit run
law = "stretch"
first = notched(LAWS[law], 8, 5e-6, "run 150") + f"""displace_atoms top move 0 2.5e-6 0 units box
displace_atoms bot move 0 -2.5e-6 0 units box
run 60
"""
split1 = first + "write_restart adr.restart\n"
split2 = f"""read_restart adr.restart
neighbor 0.0001 bin
fix adr free pd/adr
fix 2 all enforce2d
thermo_style custom step f_adr[1] f_adr[2] f_adr[5]
run 90
""" + DUMP.format(file="split.dump")
whole = first + "thermo_style custom step f_adr[1] f_adr[2] f_adr[5]\nrun 90\n" + DUMP.format(file="whole.dump")
# and without the break: the 9th load step as one run, against 60 + 690,
# both to convergence. Mid-way they differ by more than round-off (2e-9 of
# the box after 60 + 90): the second run's setup sorts the atoms, which
# reorders the sums, and the damping amplifies that round-off (see (2)).
single = first.replace("run 60\n", "run 750\n") + DUMP.format(file="single.dump")
twice = first + "run 690\n" + DUMP.format(file="twice.dump")
run(single, d)
run(twice, d)
check_le(f"{law}: run 60 + run 690 ends where run 750 does", max_rel_diff(read_dump(f"{d}/twice.dump"),
         read_dump(f"{d}/single.dump")), 1e-10, "the relaxation carries on from run to run; round-off at convergence")
# the restart, on 1 and 2 ranks: both runs sort the atoms at the second
# run's setup and build the same ghosts, so the sums come in the same
# order (measured: identical to the bit); 1e-12 allows for round-off
for ranks in (1, 2):
    out_w, rows_w = run(whole, d, ranks=ranks)
    run(split1, d, ranks=ranks)
    out_s, rows_s = run(split2, d, ranks=ranks)
    diff = max_rel_diff(read_dump(f"{d}/whole.dump"), read_dump(f"{d}/split.dump"))
    check_le(f"{law}, {ranks} rank(s): a run split by write_restart/read_restart mid-relaxation continues as "
             "the unsplit run", diff, 1e-12, "the same sums in the same order")
    check(f"{ranks} rank(s): the restart keeps the iteration count and the damping",
          rows_w[-1]["f_adr[5]"] == rows_s[-1]["f_adr[5]"] and
          abs(rows_w[-1]["f_adr[2]"] - rows_s[-1]["f_adr[2]"]) <= 1e-6 * rows_w[-1]["f_adr[2]"],
          f"iterations {rows_w[-1]['f_adr[5]']:.0f} / {rows_s[-1]['f_adr[5]']:.0f}, "
          f"c {rows_w[-1]['f_adr[2]']:.6g} / {rows_s[-1]['f_adr[2]']:.6g}")

# (4) load steps to convergence; the crack grows through the plate. 14
# steps of 5 um opening: the first 7 stay below the critical load of the
# notch, the crack runs in the last ones and cuts the plate in two, after
# which the residual is taken relative to the load the plate carried.
NSTEPS, OPEN = 14, 5e-6
HALT = "fix halt all halt 1 v_r < 1e-4 error continue"
for law, pair in LAWS.items():
    out, _ = run(notched(pair, NSTEPS, OPEN, "run 5000", HALT), d)
    rows = loadsteps(out)
    check(f"{law}: {NSTEPS} load steps ran", len(rows) == NSTEPS and "ERROR" not in out,
          out[-300:] if len(rows) < NSTEPS else "")
    if len(rows) < NSTEPS:
        continue
    its = [b[1] - a[1] for a, b in zip([[0, 0]] + rows, rows)]
    check(f"{law}: every load step converges to 1e-4 within 5000 iterations",
          all(r[2] < 1e-4 for r in rows) and max(its) < 5000, f"iterations {[int(i) for i in its]}")
    broken = [r[5] for r in rows]
    dissipated = [r[4] for r in rows]
    load = [-r[7] for r in rows]    # the force the body pulls the top grip down with
    check(f"{law}: no bond breaks in the first load step (below the critical load)", broken[0] == 0)
    check(f"{law}: bonds break as the load grows, never fewer", broken[-1] > 0 and
          all(b >= a for a, b in zip(broken, broken[1:])), f"broken {broken}")
    check(f"{law}: the dissipated energy is positive and grows",
          dissipated[-1] > 0 and all(b >= a for a, b in zip(dissipated, dissipated[1:])),
          f"{dissipated[-1]:.4g} J")
    tip0 = rows[0][6]
    check(f"{law}: the crack tip advances by more than 5 mm from the notch", rows[-1][6] > tip0 + 5e-3,
          f"tip {tip0 * 1e3:.2f} -> {rows[-1][6] * 1e3:.2f} mm")
    check(f"{law}: the load rises, peaks and falls below half its peak as the crack cuts the plate",
          load[1] > load[0] > 0 and load[-1] < 0.5 * max(load), f"loads {[round(v, 2) for v in load]} N")
    # no blow-up: no particle moves farther than the grips did, with the
    # plate's Poisson contraction across its half-width at right angles
    # (nu x opening / height x 10 mm); fragments without bonds are held
    grip = NSTEPS * OPEN / 2
    contraction = 0.35 * NSTEPS * OPEN / 15e-3 * 10e-3
    check_le(f"{law}: no particle moves farther than the grips and the contraction", max(r[8] for r in rows),
             math.hypot(grip, contraction))
    print(f"{law}: load steps (step, residual, reference, dissipated J, broken, tip m, load N, largest move m):")
    for r in rows:
        print("   ", " ".join(f"{v:.5g}" for v in r))
finish()
