"""The crack-kink example (examples/crack-kink/in.kink) at a coarse
setting: horizon 3 spacings, crack 25 spacings (about 2 s a run).

- Quasi-static and dynamic loading, pure mode II and K_II = K_I: each run
  grows a new crack to 4 horizons from the tip and prints its angle.
- The deck's own fit (LAMMPS reductions of the damage growth's second
  moments) is the accuracy sweep's (tools/accuracy/q_kink.py, on the
  positions and damage growth the deck dumps): the same angle to 1e-6
  degrees; the maximum tangential stress angle it prints is q_kink's to
  0.01 degrees.
- Physics: the crack turns to the side the criterion says, within 12
  degrees of it. At 3 spacings and a crack of 25 the accuracy sweep
  measures the energy law 7-8 degrees short of MTS in mode II and 1.6
  off at K_II = K_I; one run is one sample of the lattice's near-ties
  (a few degrees at 4 spacings), so the bound is not tighter.
- A wrong variable is refused with an ERROR that names it."""
import os
import re
import sys
from lmptest import *

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "../../tools/accuracy"))
import q_kink

DECK = open(os.path.join(HERE, "../../examples/crack-kink/in.kink")).read()
N, M, H = 25, 3, 5.0e-4
LINE = r"KINK angle ([-0-9.]+) degrees \(maximum tangential stress ([-0-9.]+)\)"

for load in ("quasistatic", "dynamic"):
    for psi, ratio in ((90, float("inf")), (45, 1.0)):
        d = workdir()
        out, _ = run(DECK, d, as_is=True, variables={"n": N, "m": M, "psi": psi, "load": load, "images": 0,
                                                     "dump": 1})
        m = re.search(LINE, out)
        name = f"{load}, psi {psi}"
        check(f"{name}: the deck prints the kink angle", m is not None, out[-300:] if m is None else "")
        if m is None:
            continue
        theta, mts = float(m.group(1)), float(m.group(2))
        fit, _, atoms = q_kink.angles(q_kink.read_dump(os.path.join(d, "kink.dump")), M * H)
        print(f"  {name}: {theta} degrees (MTS {mts}), sweep's fit {fit:.4f} over {atoms} atoms")
        check_le(f"{name}: the deck's fit is the sweep's (degrees)", abs(theta - fit), 1e-6 + 0.005,
                 "printed to 2 decimals")
        check_le(f"{name}: the printed MTS angle is the criterion's (degrees)", abs(mts - q_kink.mts_angle(ratio)),
                 0.01)
        check(f"{name}: turns to the criterion's side", theta < 0.0, f"{theta}")
        check_le(f"{name}: within 12 degrees of MTS", abs(theta - q_kink.mts_angle(ratio)), 12.0,
                 "3 spacings, a/h 25: the sweep's 7-8 degrees, one sample of the near-ties")
for bad, named in (({"load": "static"}, "-var load static"), ({"psi": 0}, "-var psi 0"),
                   ({"n": 8}, "-var n 8")):
    out, _ = run(DECK, workdir(), as_is=True, expect_error=True, variables=dict(bad, images=0))
    check(f"refused: {named}", f"ERROR: {named}" in out, "" if f"ERROR: {named}" in out else out[-300:])
finish()
