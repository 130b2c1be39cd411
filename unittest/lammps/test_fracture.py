"""Fracture: T14's energy failure law in a pre-cracked 2D strip.

A PMMA strip (plane stress, E = 3.5 GPa, nu = 0.35, G_c = 400 J/m^2) 60 mm
x 20 mm, pre-cracked from the left edge to 15 mm on its mid-line
(fix pd/precrack), is stretched uniformly (eps_yy) and held by grips one
horizon deep: the energy release rate of a long strip, W H, is 1.3 G_c.
The crack runs; the crack tip is the rightmost atom whose damage (MS07 eq.
25, from the broken bonds) exceeds 0.3.

- Fracture energy: dissipated energy / (new crack length x thickness) is G_c
  within 10% at two resolutions (spacing 0.5 and 0.25 mm, horizon 3
  spacings). beta is calibrated on the lattice; measured: -4.1% and -0.6%
  (+0.7% at both while broken bonds pushed at any length; now they push
  only once their particles touch). The same strip as a 3D slab (periodic
  through 8 layers): +0.1% at 0.5 mm (was +1.2%).
- Energy balance: kinetic + elastic + dissipated (joules) stays within 1% of
  the initial elastic energy (measured 0.02-0.04%). A bond that fails
  releases the energy it holds at that step and acts there with half its
  force, so that the two half-kicks around the step carry it up to that
  step: the balance is second order in dt. The bond-based strip (critical
  stretch) shows the order: 3.5e-4, 9.1e-5, 2.5e-5 at dt = 0.35, 0.18, 0.09
  of the stable step (a bond dropped whole, as before: 8.4e-3, 4.4e-3,
  2.3e-3, first order); the check asks for a ratio above 3 per halving.
- 1 and 2 ranks break the same bonds; a run split in two runs, or by a
  restart, continues with the same broken bonds, dissipated energy and
  positions (to round-off: the step at the split is evaluated twice, and
  bonds that broke in it act with half their force both times)."""
import math
import os
from lmptest import *

d = workdir()
E, NU, GC, H_STRIP, L_STRIP = 3.5e9, 0.35, 400.0, 0.02, 0.06
STRAIN = math.sqrt(2 * 1.3 * GC / (E / (1 - NU ** 2) * H_STRIP))


def strip(h, steps, dt, extra="", setup="", dumps="", data=None):
    atoms = (f"read_data {data}\n" if data else
             f"region box block 0 {round(L_STRIP / h)} 0 {round(H_STRIP / h)} -0.5 0.5\n"
             "create_box 1 box\ncreate_atoms 1 box\n")
    return f"""units si
dimension 2
boundary s s p
atom_style peri
atom_modify map array
lattice sq {h}
{atoms}set group all density 1180
set group all volume {h * h * 1e-3}
pair_style pd/ordinary plane stress thickness 1e-3
pair_coeff * * E {E} nu {NU} horizon {3.0001 * h} m 0.5 fail energy Gc {GC}
fix crack all pd/precrack segment -0.001 {H_STRIP / 2 + 0.5 * h} 0.015 {H_STRIP / 2 + 0.5 * h}
region top block INF INF {round(H_STRIP / h) - 3} INF INF INF
region bot block INF INF INF 3 INF INF
group top region top
group bot region bot
group grips union top bot
group free subtract all grips
compute dmg all pd/damage
compute frac all pd/fracture
variable tipx atom x*(c_dmg>0.3)
compute tip all reduce max v_tipx
{ENERGY_JOULES}variable total equal c_KEJ+c_PEJ+c_frac[2]
{setup}
run 0
displace_atoms all ramp y {-STRAIN * H_STRIP / 2} {STRAIN * H_STRIP / 2} y 0 {H_STRIP} units box
velocity all set 0 0 0 units box
fix hold grips setforce 0 0 0
fix 1 free nve
fix 2d all enforce2d
thermo_style custom step c_KEJ c_PEJ c_frac[2] v_total c_frac[3] c_tip
thermo_modify format float %.17g
timestep {dt}
thermo {max(steps // 8, 1)}
{extra}
run {steps}
{dumps}"""


def slab(h, steps, dt):
    """The strip as a 3D slab, periodic through 8 layers: plane strain far
    ahead of the crack, so W = (lambda + 2 mu) eps^2 / 2 sets the strain for
    the same G = 1.3 G_c; the pre-crack is a patch through the thickness."""
    lam, mu = E * NU / ((1 + NU) * (1 - 2 * NU)), E / (2 * (1 + NU))
    eps3 = math.sqrt(2 * 1.3 * GC / ((lam + 2 * mu) * H_STRIP))
    lz = 8 * h
    s = replace_exact(replace_exact(strip(h, steps, dt), "dimension 2\n", ""), "fix 2d all enforce2d\n", "")
    s = replace_exact(replace_exact(s, f"lattice sq {h}", f"lattice sc {h}"), "-0.5 0.5", "0 8")
    s = replace_exact(s, f"set group all volume {h * h * 1e-3}", f"set group all volume {h ** 3}")
    s = replace_exact(s, "pair_style pd/ordinary plane stress thickness 1e-3", "pair_style pd/ordinary")
    s = replace_exact(s, f"segment -0.001 {H_STRIP / 2 + 0.5 * h} 0.015 {H_STRIP / 2 + 0.5 * h}",
                  f"patch -0.001 {H_STRIP / 2 + 0.5 * h} {-3 * h} 0.016 0 0 0 0 {lz + 6 * h}")
    s = replace_exact(s, f"{-STRAIN * H_STRIP / 2} {STRAIN * H_STRIP / 2}", f"{-eps3 * H_STRIP / 2} {eps3 * H_STRIP / 2}")
    return s, lz


def crack_run(h, dt, steps, three_d=False):
    script, thickness = slab(h, steps, dt) if three_d else (strip(h, steps, dt), 1e-3)
    _, rows = run(script, d)
    tip0, tip = rows[0]["c_tip"], rows[-1]["c_tip"]
    g = rows[-1]["c_frac[2]"] / ((tip - tip0) * thickness)
    balance = max(abs(r["v_total"] - rows[0]["v_total"]) for r in rows) / rows[0]["v_total"]
    return g, tip - tip0, balance, rows[-1]["c_frac[3]"]


for h, dt in [(5e-4, 2.5e-8), (2.5e-4, 1.25e-8)]:
    g, grown, balance, nbroken = crack_run(h, dt, int(round(6e-5 / dt)))
    print(f"spacing {h}: crack grew {grown * 1e3:.1f} mm, {nbroken:.0f} bonds broken, "
          f"G = {g:.1f} J/m^2, energy balance {balance:.2e}")
    check("crack grows by more than 10 horizons", grown > 10 * 3 * h)
    check_le(f"spacing {h}: dissipated energy per new crack area within 10% of G_c", abs(g / GC - 1), 0.10,
             "lattice-calibrated beta; off-plane damage")
    if h == 5e-4:
        check_le("kinetic + elastic + dissipated conserved within 1%", balance, 0.01, "second-order breaking step")

# order of the energy balance in dt: the bond-based strip with the critical
# stretch, the same crack at three time steps
balances = []
for dt in (1e-7, 5e-8, 2.5e-8):
    s = strip(5e-4, int(round(6e-5 / dt)), dt)
    s = replace_exact(s, "pair_style pd/ordinary plane", "pair_style pd/bond plane")
    s = replace_exact(s, f"pair_coeff * * E {E} nu {NU} horizon {3.0001 * 5e-4} m 0.5 fail energy Gc {GC}",
                  f"pair_coeff * * pmb E {E} horizon {3.0001 * 5e-4} fail stretch Gc {GC}")
    _, rows = run(s, d)
    balances.append(max(abs(r["v_total"] - rows[0]["v_total"]) for r in rows) / rows[0]["v_total"])
print("bond-based strip, energy balance at dt = 1e-7, 5e-8, 2.5e-8: " + ", ".join(f"{b:.2e}" for b in balances))
check("energy balance converges at second order in dt (ratio > 3 per halving)",
      all(a > 3 * b for a, b in zip(balances, balances[1:])),
      " ".join(f"{a / b:.2f}" for a, b in zip(balances, balances[1:])))

# 3D slab: spacing 0.5 mm in make test (140 s on one core), 0.4 mm with
# make validate (PDEXT_VALIDATE=1). At 1 mm (horizon 3 mm, a third of the
# half-height of the strip) it dissipates 16-20% too much: the horizon must
# be small against the specimen, as in 2D.
for h, dt in [(5e-4, 2.5e-8)] + ([(4e-4, 2e-8)] if os.environ.get("PDEXT_VALIDATE") else []):
    g, grown, balance, nbroken = crack_run(h, dt, int(round(6e-5 / dt)), three_d=True)
    print(f"3D slab, spacing {h}: crack grew {grown * 1e3:.1f} mm, {nbroken:.0f} bonds broken, "
          f"G = {g:.1f} J/m^2, energy balance {balance:.2e}")
    check("3D: crack grows by more than 10 horizons", grown > 10 * 3 * h)
    check_le(f"3D slab, spacing {h}: dissipated energy per new crack area within 10% of G_c",
             abs(g / GC - 1), 0.10, "lattice-calibrated beta")

# rank count and restart: a short coarse run, atoms from one data file
# (IDs from create_atoms depend on the rank count)
STEPS, DT = 800, 2.5e-8
dump = DUMP.format(file="{name}")
run(strip(5e-4, 0, DT).split("pair_style")[0] + "write_data strip.data\n", d)
# (and the energy law's uniform profile, whose calibration is per atom too)
uniform = {}
for ranks in (1, 2):
    s = replace_exact(strip(5e-4, STEPS, DT, dumps=dump.format(name=f"u{ranks}"), data="strip.data"),
                      f"fail energy Gc {GC}", f"fail energy Gc {GC} profile uniform")
    uniform[ranks] = run(s, d, ranks=ranks)[1][-1]
finals = {}
for ranks in (1, 2):
    _, rows = run(strip(5e-4, STEPS, DT, dumps=dump.format(name=f"r{ranks}"), data="strip.data"), d, ranks=ranks)
    finals[ranks] = rows[-1]
for what, f, name in (("", finals, "r"), (", profile uniform", uniform, "u")):
    check(f"1 and 2 ranks break the same number of bonds{what}", f[1]["c_frac[3]"] == f[2]["c_frac[3]"] > 0,
          f"{f[1]['c_frac[3]']:.0f} vs {f[2]['c_frac[3]']:.0f}")
    check_le(f"1 and 2 ranks dissipate the same energy{what}", abs(f[1]["c_frac[2]"] / f[2]["c_frac[2]"] - 1), 1e-9,
             "round-off")
    check_le(f"1 and 2 ranks end at the same positions{what}",
             max_rel_diff(read_dump(f"{d}/{name}1"), read_dump(f"{d}/{name}2")), 1e-10)
check("the profiles break different bonds (the uniform one is used)", uniform[1]["c_frac[3]"] != finals[1]["c_frac[3]"],
      f"{uniform[1]['c_frac[3]']:.0f} vs {finals[1]['c_frac[3]']:.0f}")

# a run split in two in one process: the second run's first evaluation
# repeats the step at which the first ended, bonds that broke there included
run(strip(5e-4, STEPS // 2, DT, dumps=f"run {STEPS // 2}\n" + dump.format(name="split"), data="strip.data"), d)
check_le("two runs end as one run (breaking step replayed)",
         max_rel_diff(read_dump(f"{d}/r1"), read_dump(f"{d}/split")), 1e-12, "round-off")

run(strip(5e-4, STEPS // 2, DT, dumps="write_restart half.restart\n", data="strip.data"), d)
out, rows = run(f"""read_restart half.restart
fix hold grips setforce 0 0 0
fix 1 free nve
fix 2d all enforce2d
fix crack all pd/precrack segment -0.001 {H_STRIP / 2 + 2.5e-4} 0.015 {H_STRIP / 2 + 2.5e-4}
compute frac all pd/fracture
thermo_style custom step c_frac[2] c_frac[3]
thermo_modify format float %.17g
run {STEPS // 2}
""" + dump.format(name="restarted"), d)
check("restart: the same broken bonds", rows[-1]["c_frac[3]"] == finals[1]["c_frac[3]"],
      f"{rows[-1]['c_frac[3]']:.0f} vs {finals[1]['c_frac[3]']:.0f}")
# round-off only: read_restart re-sorts the atoms, so sums run in another order
check_le("restart: the same dissipated energy", abs(rows[-1]["c_frac[2]"] / finals[1]["c_frac[2]"] - 1), 1e-12)
check_le("restart: the same positions", max_rel_diff(read_dump(f"{d}/r1"), read_dump(f"{d}/restarted")), 1e-12)
finish()
