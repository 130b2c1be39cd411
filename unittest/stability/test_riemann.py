"""Stability: the peridynamic Riemann problem of T14 5.3 at T14's
resolution (20,000 particles, 5 spacings per horizon), 100 microseconds.

T14's finding, both sides: the linear solid (m = 1/2) lets the two halves
interpenetrate (a left particle beyond the right half's leftmost one, and
particles closer than a third of the spacing), the log-strain solid (m = 0)
keeps them apart. Measured at 100 us: m = 1/2 overlaps by 0.07 m with 164
close particles; m = 0 stays 0.004 m apart with none."""
import os
import re
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../lammps"))
from lmptest import *

d = workdir()
deck = open(os.path.join(os.path.dirname(os.path.abspath(__file__)),
                         "../../examples/riemann-2d/in.riemann")).read()
deck = sub_exact(r"^dump.*\n", "", deck, count=2, flags=re.M)   # dump and dump_modify
result = {}
for m in (0.5, 0):
    out, rows = run(deck, d, variables={"m": m, "nh": 5, "steps": 500, "tag": "t"})
    result[m] = (log_value(out, r"overlap_m ([0-9.eE+-]+)"), log_value(out, r"close_particles ([0-9.eE+-]+)"))
    print(f"m = {m}: overlap {result[m][0]:+.4f} m, close particles {result[m][1]:.0f}")
check("m = 1/2: the halves interpenetrate (T14 fig. 5-3)", result[0.5][0] > 0 and result[0.5][1] > 10)
check("m = 0: the halves stay apart (T14 fig. 5-4)", result[0][0] < 0 and result[0][1] == 0)
finish()
