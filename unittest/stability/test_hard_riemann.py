"""Hard case 1: the peridynamic Riemann problem of T14 5.3
(examples/riemann-2d: two halves of a 2D bar meet, m = 0) at 1200 and
2000 m/s, up to the same simulated time at the example's fixed step
(2e-7 s, 0.06 of the setup estimate) and at 0.8 of the setup estimate and with fix pd/timestep. The fixed
step shows where it fails; the adaptive one must keep every criterion of
hardcase.py. Reduced: 3 spacings per horizon (7,200 particles), 60 us;
full (PDEXT_VALIDATE=1): T14's 5 (20,000 particles), 100 us."""
from hardcase import *

d = scene_dir()
deck = open(os.path.join(HERE, "../../examples/riemann-2d/in.riemann")).read()
deck = sub_exact(r"^dump.*\n", "", deck, count=2, flags=re.M)   # dump and dump_modify
deck = sub_exact(r"^thermo_style.*\n", "include ${energy}\nvariable work equal 0.0\ninclude ${thermo}\n"
                 "dump frames all custom ${dumps} ${frames} id x y z\n"
                 "dump_modify frames sort id format float %.10g\n"
                 "variable now equal time\nfix stop all halt 10 v_now > ${tmax} error soft\n"
                 "${adapt}\n", deck, flags=re.M)
deck = sub_exact(r"^timestep +2.0e-7\n", "timestep ${dt}\n", deck, flags=re.M)
deck = sub_exact(r"^thermo +50\n", "thermo 10\n", deck, flags=re.M)
deck = sub_exact(r"^print.*\n", "", deck, flags=re.M)    # its summary reads computes after the run
deck = sub_exact(r"^velocity +left set 1200", "velocity left set ${v}", deck, flags=re.M)
deck = sub_exact(r"^velocity +right set -1200", "velocity right set -${v}", deck, flags=re.M)
nh, tmax = (5, 1e-4) if FULL else (3, 6e-5)
h = 0.05 / nh
TOL, APART = 0.01, 0.2
for v in (1200, 2000):
    base = {"m": 0, "v": v, "nh": nh, "tag": "t", "energy": "energy.in", "thermo": "thermo.in", "tmax": tmax,
            "steps": 100000, "dumps": 25, "dt": 2e-7}
    fixed = outcome(*run_scene(deck, d, dict(base, adapt="", steps=int(tmax / 2e-7)), f"fixed{v}")[:3],
                    0.050005, h, TOL, APART)
    print(f"SCENE riemann {v} m/s: fixed dt 2e-7: {'stable' if fixed['stable'] else 'UNSTABLE'}: {describe(fixed)}")
    # the step a user would take from the setup's estimate: 0.8 of it
    est = log_value(fixed["out"], r"stable time step estimate \(MS07 eq. 43\) ([0-9.eE+-]+)")
    user = outcome(*run_scene(deck, d, dict(base, adapt="", steps=int(tmax / (0.8 * est)) + 1,
                                          dt=0.8 * est), f"user{v}")[:3], 0.050005, h, TOL, APART)
    print(f"SCENE riemann {v} m/s: fixed dt {0.8 * est:.3g} (0.8 of the setup estimate): "
          f"{'stable' if user['stable'] else 'UNSTABLE'}: {describe(user)}")
    out, rows, frames, wall = run_scene(deck, d, dict(base, adapt=ADAPTIVE), f"adaptive{v}")
    r = outcome(out, rows, frames, 0.050005, h, TOL, APART)
    check_reached(f"riemann {v} m/s", r, tmax)
    assess(f"riemann {v} m/s", r, TOL, APART, wall)
finish()
