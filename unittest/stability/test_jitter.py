"""Hard case 6: an irregular arrangement under impact. The plate
of in.wall with every particle moved by up to 0.25 spacings at random and
its volume varied by -30% .. +30% (so its stiffness sums, stable steps and
contact radii all differ), into the wall at 1000 m/s. The setup estimate
takes the irregular families into account; fix pd/timestep must keep every
criterion of hardcase.py through the impact. Reduced: 30 us; full
(PDEXT_VALIDATE=1): 80 us."""
from hardcase import *

d = scene_dir()
deck = open(os.path.join(HERE, "in.wall")).read()
deck = replace_exact(deck, "set             group all volume $(v_h*v_h*1e-3)\n",
                     "displace_atoms  all random $(0.25*v_h) $(0.25*v_h) 0.0 4711 units box\n"
                     "variable        vol atom v_h*v_h*1e-3*(1.0+0.3*sin(12.9898*id))\n"
                     "set             group all volume v_vol\n")
tmax = 8e-5 if FULL else 3e-5
base = {"m": 0, "v": 1000, "tmax": tmax, "dumps": 100, "energy": "energy.in", "thermo": "thermo.in"}
H, HORIZON = 5e-4, 3.0001 * 5e-4
# time integration error: measured 0.89-1.06% over four arrangements
# (seeds 4711-4714; 0.87-1.00% without the directional correction), a
# blow-up multiplies the energy; non-partners: the model itself lets them come
# close here (contact radii from the varied volumes leave gaps), and how
# close is chaotic: moving every particle by 1e-13 m moved the nearest
# approach from 0.007 to 0.065 spacings at a fixed 2e-9 s (15000 steps),
# and between 0.009 and 0.087 with the adaptive step; a change of
# round-off alone moved it from 0.032 to 0.009. So the bar is that no two
# particles meet (with contact 1000 times too weak: 0.000), not the
# lattice scenes' half spacing
TOL, APART = 0.015, 0.003
fixed = outcome(*run_scene(deck, d, dict(base, adapt="", dt=2e-8), "fixed")[:3], HORIZON, H, TOL, APART)
print(f"SCENE jitter 1000 m/s: fixed dt 2e-8: {'stable' if fixed['stable'] else 'UNSTABLE'}: {describe(fixed)}")
out, rows, frames, wall = run_scene(deck, d, dict(base, adapt=ADAPTIVE, dt=2e-8), "adaptive")
r = outcome(out, rows, frames, HORIZON, H, TOL, APART)
check_reached("jitter 1000 m/s", r, tmax)
assess("jitter 1000 m/s", r, TOL, APART, wall)
finish()
