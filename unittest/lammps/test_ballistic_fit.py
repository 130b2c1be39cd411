"""The ballistic-limit example's Lambert-Jonas fit recovers a known curve:
points of v_r = a (v^p - v_bl^p)^(1/p) (a = 0.8, p = 2, v_bl = 400 m/s)
at the example's impact velocities give back v_bl within 2 m/s (the
grid's resolution after six refinements of a 20 m/s bracket is far finer;
2 m/s is half a percent), p within 2% and a within 1%; with 3 m/s of noise
on each point v_bl stays within the bracket of the cases that stopped and
perforated. A case undecided at its time limit (through -1) is left out
of the fit and named. Needs no LAMMPS."""
import os
import random
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "../../examples/ballistic-limit"))
sys.path.insert(0, HERE)
import ballistic_limit as bl  # noqa: E402
from lmptest import check, check_le, finish  # noqa: E402

V = [200, 250, 300, 320, 340, 360, 380, 400, 420, 450, 500, 600, 700, 800, 1000, 1200]
exact = [(v, bl.model(v, 0.8, 2.0, 400.0)) for v in V]
a, p, vbl, rms, (lo, hi) = bl.fit(exact)
check("the bracket is the fastest stop and the slowest perforation (400, 420)", (lo, hi) == (400, 420), f"{lo}, {hi}")
check_le("v_bl recovered (m/s)", abs(vbl - 400.0), 2.0, "exact points")
check_le("p recovered (relative)", abs(p / 2.0 - 1), 0.02, "exact points")
check_le("a recovered (relative)", abs(a / 0.8 - 1), 0.01, "exact points")
check_le("rms of the residuals on exact points (m/s)", rms, 1.0, "the model fits itself")

rng = random.Random(7)
noisy = [(v, max(0.0, r + rng.uniform(-3, 3)) if r > 0 else 0.0) for v, r in exact]
a, p, vbl, rms, (lo, hi) = bl.fit(noisy)
check("with noise v_bl stays in its bracket", lo <= vbl <= hi, f"{vbl:.1f} in [{lo}, {hi}]")
check_le("... and the rms is that of the noise (m/s)", rms, 3.0, "uniform noise of +-3 m/s has rms 1.7")

try:
    bl.fit([(v, 0.0) for v in V])
    check("no perforation is refused with a message", False)
except SystemExit as e:
    check("no perforation is refused with a message", "no case perforated" in str(e), str(e))
with tempfile.NamedTemporaryFile("w", suffix=".csv", delete=False) as f:
    f.write("v,vres,through,broken,energy\n300,0,0,1,1\n340,0,-1,1,1\n320,12.5,1,1,1\n")
points, undecided = bl.read_cases(f.name)
os.unlink(f.name)
check("an undecided case is left out of the fit", points == [(300.0, 0.0), (320.0, 12.5)], str(points))
check("... and named", undecided == [340.0], str(undecided))
finish()
