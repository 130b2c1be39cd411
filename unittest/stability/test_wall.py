"""Hard case 2: a 2D PMMA plate into a rigid wall at 2000 m/s,
m = 0, bonds failing by energy, stiff contact (in.wall). At a fixed step
it blows up: at 2e-8 s (0.089 of the setup estimate, the step the
package was first tried with on this scene), and at half that it gains
energy (+21% in 30 us). With fix pd/timestep it must keep every criterion
of hardcase.py. The run at 2e-8 must end in the blow-up guard's ERROR
naming fix pd/timestep (the speed limit stops it at step 61; at 1e-8 the
energy grows without reaching the limit in 30 us). Reduced: 30 us;
full (PDEXT_VALIDATE=1): 80 us."""
from hardcase import *

d = scene_dir()
deck = open(os.path.join(HERE, "in.wall")).read()
tmax = 8e-5 if FULL else 3e-5
base = {"m": 0, "v": 2000, "tmax": tmax, "dumps": 100, "energy": "energy.in", "thermo": "thermo.in"}
H, HORIZON = 5e-4, 3.0001 * 5e-4
TOL, APART = 0.01, 0.5
for dt in (2e-8, 1e-8):
    fixed = outcome(*run_scene(deck, d, dict(base, adapt="", dt=dt), f"fixed{dt}")[:3], HORIZON, H, TOL, APART)
    print(f"SCENE wall 2000 m/s: fixed dt {dt}: {'stable' if fixed['stable'] else 'UNSTABLE'}: {describe(fixed)}")
    check(f"at the fixed step {dt} the scene blows up or gains energy (what the adaptive step must prevent)",
          not fixed["stable"], describe(fixed))
    # the blow-up is the guard's ERROR, which points to the adaptive step
    # and, the step being below the setup's estimate, to the stiffened
    # state, not a NaN or a lost-atoms error of LAMMPS
    if dt < 2e-8:
        continue
    check(f"at the fixed step {dt} the guard stops the run with an ERROR that names fix pd/timestep",
          fixed["error"] is not None and "unstable at step" in fixed["error"] and "fix pd/timestep" in fixed["error"]
          and "the state stiffened since" in fixed["error"],
          (fixed["error"] or describe(fixed))[:240])
out, rows, frames, wall = run_scene(deck, d, dict(base, adapt=ADAPTIVE, dt=2e-8), "adaptive")
r = outcome(out, rows, frames, HORIZON, H, TOL, APART)
check_reached("wall 2000 m/s", r, tmax)
check("wall 2000 m/s: the log names the contact springs or the compression as a limit",
      re.search(r"limited by (contact|compression)", out) is not None)
assess("wall 2000 m/s", r, TOL, APART, wall)
finish()
