"""Conservation: linear momentum to round-off and no energy drift
for an elastic vibration, 2000 steps at half the stable time step.

Velocity Verlet does not conserve KE + PE exactly: for a linear system it
conserves E~ = KE + PE - dt^2/8 sum |f|^2 / rho (per unit volume, as the
energies here), and KE + PE oscillates about it by O((omega dt)^2). The test
tracks E~, so the 1e-6 bound is on real drift: a force that is not minus the
gradient of the reported energy, or a time-step error, shows as drift."""
import os
from lmptest import *

d = workdir()
L = 16 * SPACING
# long longitudinal and shear waves plus a uniform drift (momentum test)
WAVES = f"""variable vx atom 0.3+0.5*sin(2*PI*x/{L})
variable vy atom -0.2+0.5*sin(2*PI*x/{L})
variable vz atom 0.1+0.3*sin(2*PI*y/{L})
velocity all set v_vx v_vy v_vz units box
"""
MONITOR = """compute f all property/atom fx fy fz
variable f2 atom (c_f[1]^2+c_f[2]^2+c_f[3]^2)/mass
compute f2 all reduce sum v_f2
variable shadow equal etotal-dt*dt/8*c_f2
variable px equal mass(all)*vcm(all,x)
variable py equal mass(all)*vcm(all,y)
variable pz equal mass(all)*vcm(all,z)
thermo_style custom step ke pe etotal v_shadow v_px v_py v_pz
thermo_modify format float %.15g
"""

# the nonlinear solid (m = 0, constants from the material file) as well
MATERIALS = os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../potentials/materials.pd")
PAIRS["pd/ordinary m=0 PMMA"] = (f"pair_style pd/ordinary\npair_coeff * * file {MATERIALS} PMMA "
                                 f"horizon {HORIZON} m 0\n")
# extended correspondence (hyperelastic: Hencky's solid at m = 0), copper
# from the file (its yield and hardening are not used by model elastic)
PAIRS["pd/corr extended copper"] = (f"pair_style pd/corr model elastic\npair_coeff * * file "
                                    f"{MATERIALS} OFHC_copper horizon {HORIZON}\n")
for style in ["pd/bond", "pd/ordinary", "pd/ordinary m=0 PMMA", "pd/corr extended copper"]:
    out, _ = run(block(16) + PAIRS[style] + "run 0\n", d)
    dt_stable = log_value(out, r"stable time step estimate \(MS07 eq. 43\) ([0-9.eE+-]+)")
    dt = 0.5 * dt_stable
    out, rows = run(block(16) + WAVES + PAIRS[style] + MONITOR +
                    f"fix 1 all nve\ntimestep {dt!r}\nthermo 20\nrun 2000\n", d)
    e0 = rows[0]["v_shadow"]
    drift = max(abs(r["v_shadow"] - e0) for r in rows) / e0
    swing = max(abs(r["TotEng"] - rows[0]["TotEng"]) for r in rows) / e0
    print(f"{style}: dt = {dt:.4g} (half of {dt_stable:.4g}); KE+PE swings {swing:.2e}, E~ drifts {drift:.2e}")
    check_le(f"{style}: energy drift over 2000 steps at dt = stable/2", drift, 1e-6,
             "geometric nonlinearity at strain 2e-4; measured ~3e-10")
    if "PMMA" in style:
        # the file's E = 3.5 GPa, nu = 0.35 (T14 6.2.1) become the 3D constants
        lam, mu = 3.5e9 * 0.35 / (1.35 * 0.3), 3.5e9 / 2.7
        check_le("material file: lambda_bar = lambda - mu",
                 abs(log_value(out, r"lambda_bar ([0-9.eE+-]+)") / (lam - mu) - 1), 1e-3, "4 digits in the log")
        check_le("material file: mu_bar = 5 mu / 2",
                 abs(log_value(out, r"mu_bar ([0-9.eE+-]+)") / (2.5 * mu) - 1), 1e-3, "4 digits in the log")
    pscale = max(abs(rows[0][k]) for k in ("v_px", "v_py", "v_pz"))
    pdev = max(abs(r[k] - rows[0][k]) for r in rows for k in ("v_px", "v_py", "v_pz")) / pscale
    check_le(f"{style}: linear momentum conserved", pdev, 1e-12, "equal and opposite bond forces")

# Microplastic bonds yield under the same rough waves: kinetic + elastic +
# plastic work (compute pair pd/bond, first extra value) is conserved up to
# the O(dt^2) error of Verlet with a return map. Measured over the same time
# at two steps: the deviation must fall 4x per halving (second order), and
# be under 1% at the smaller step.
def microplastic_balance(dt):
    steps = int(round(5e-5 / dt))
    script = block(16) + ROUGH_VELOCITY + f"""pair_style pd/bond
pair_coeff * * microplastic K {BULK} horizon {HORIZON} yield_stretch 1e-4
compute plastic all pair pd/bond
compute frac all pd/fracture
compute peratom all reduce sum c_frac
variable total equal etotal+c_plastic[1]
thermo_style custom step ke pe c_plastic[1] v_total c_frac[1] c_frac[2] c_peratom
thermo_modify format float %.15g
fix 1 all nve
timestep {dt}
thermo {steps // 20}
run {steps}
"""
    _, rows = run(script, d)
    e0 = rows[0]["v_total"]
    last = rows[-1]
    # plastic work in compute pd/fracture: the sum of the per-atom densities
    # is value 1, and with equal volumes V times it is value 2 (joules)
    books = max(abs(last["c_peratom"] / last["c_frac[1]"] - 1),
                abs(VOLUME * last["c_frac[1]"] / last["c_frac[2]"] - 1))
    return last["c_plastic[1]"] / e0, max(abs(r["v_total"] - e0) for r in rows) / e0, books


work, dev1, books = microplastic_balance(5e-8)
check_le("microplastic: per-atom, density-sum and joule plastic work agree", books, 1e-12, "round-off")
_, dev2, _ = microplastic_balance(2.5e-8)
print(f"microplastic: plastic work {work:.2f} of the initial energy; balance deviation {dev1:.2e} at dt, "
      f"{dev2:.2e} at dt/2")
check("microplastic: bonds yield (plastic work > 10% of the energy)", work > 0.1)
check_le("microplastic: energy balance error is second order in dt", abs(dev1 / dev2 - 4), 1.0, "ratio 4 +- 1")
check_le("microplastic: kinetic + elastic + plastic work conserved at dt/2", dev2, 0.01)
finish()
