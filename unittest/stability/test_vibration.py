"""Hard case 7: a long elastic vibration (in.vibration). A
periodic 2D PMMA plate of 16 x 16 particles (plane stress) vibrates in two
standing waves of the box's longest wavelength, 10 m/s each (strains of
about 1%), with a little energy in every other mode, for 10^4 steps
(10^5 with PDEXT_VALIDATE=1): pd/ordinary with m = 1/2 and pd/bond (PMB),
each at a fixed step of 0.7 of the setup estimate and with fix
pd/timestep (which takes 0.73 of it: safety 0.8 over grow 1.1).

Velocity Verlet is symplectic: its energy error stays bounded, it
oscillates with the waves (1-2% of the energy at this step, (omega
dt)^2 / 4 for the longitudinal wave) but does not accumulate. The test
asserts that the drift, the mean energy over the last tenth of the run
minus that over the first tenth, is at most DRIFT times the oscillation
(largest minus smallest energy over the run). Measured: 6e-4 to 5e-3 of
the oscillation over 10^4 steps (a window of a tenth still holds part of
a slow beat of the waves), 4e-4 and less over 10^5 steps; DRIFT = 0.05
leaves a factor 10. The oscillation itself must stay below 5% of the
energy, and hardcase.assess() holds for the adaptive run with TOL = 0.05
(the energy starts at the bottom of its oscillation, so that assess()'s
growth is the oscillation: 1.4% and 1.9%)."""
from hardcase import *

d = scene_dir()
deck = open(os.path.join(HERE, "in.vibration")).read()
STEPS = 100000 if FULL else 10000
EVERY = 7    # thermo interval: odd, so that the samples do not lock onto the waves' periods
H, HORIZON = 5e-4, 3.0001 * 5e-4
TOL, APART = 0.05, 0.5
DRIFT = 0.05
ESTIMATE = r"stable time step estimate \(MS07 eq. 43\) ([0-9.eE+-]+)"


def scene(style, **kw):
    v = {"style": style, "n": 16, "amp": 10, "steps": STEPS, "every": EVERY, "dumps": STEPS // 20,
         "energy": "energy.in", "thermo": "thermo.in", "adapt": "", "dt": 1e-8}
    v.update(kw)
    return v


def energy_history(rows):
    """(drift, oscillation), both relative to the first energy."""
    e = [r["v_etot"] for r in rows]
    tenth = max(len(e) // 10, 1)
    drift = (sum(e[-tenth:]) - sum(e[:tenth])) / tenth
    return drift / e[0], (max(e) - min(e)) / e[0]


for style, model in (("ordinary", "pd/ordinary m=1/2"), ("bond", "pd/bond")):
    name = f"vibration {model}"
    out, rows, frames, wall = run_scene(deck, d, scene(style, adapt=ADAPTIVE), f"adaptive_{style}")
    est = log_value(out, ESTIMATE)
    runs = {"adaptive": (out, rows, frames, wall)}
    runs["fixed"] = run_scene(deck, d, scene(style, dt=0.7 * est), f"fixed_{style}")
    for kind, (out_k, rows_k, frames_k, wall_k) in runs.items():
        r = outcome(out_k, rows_k, frames_k, HORIZON, H, TOL, APART)
        drift, osc = energy_history(rows_k) if rows_k else (math.inf, math.inf)
        step = f"dt {rows_k[-1]['Dt']:.3g} ({rows_k[-1]['Dt'] / est:.2f} of the setup estimate)" if rows_k else ""
        what = f"{name}: {kind} {step}"
        print(f"SCENE {what}: {describe(r)}; energy oscillation {osc:.3g}, drift {drift:+.3g} of the energy "
              f"({abs(drift) / osc:.2g} of the oscillation); {wall_k:.1f} s wall")
        check(f"{what}: all {STEPS} steps run", r.get("steps") == STEPS, f"{r.get('steps', 0)} steps")
        check_le(f"{what}: energy oscillation (relative to the energy)", osc, 0.05,
                 "velocity Verlet's bounded error at this step")
        check_le(f"{what}: drift between the first and the last tenth, relative to the oscillation",
                 abs(drift) / osc, DRIFT, "a symplectic integrator does not accumulate energy error")
        if kind == "adaptive":
            assess(name, r, TOL, APART, wall_k)
        else:
            check(f"{what}: stable by hardcase.py's criteria", r["stable"], describe(r))
finish()
