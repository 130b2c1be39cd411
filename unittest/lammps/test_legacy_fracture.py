"""Parity with legacy PERI on a scene that breaks (issue 5): LAMMPS's own
examples/peri decks (a sphere at 100 m/s shattering a cylinder, 3487
particles), run with peri/pmb and peri/lps and with
'pair_style hybrid/overlay pd/bond|pd/ordinary legacy pd/contact legacy'
with 'fail legacy s00 alpha' (PERI's critical-stretch rule) in one binary.

Measured: the damage fields are identical atom by atom through step 900
(mean damage 0.376 with PMB, 0.167 with LPS); positions start equal to
round-off (1e-16 m) and the difference grows about tenfold every 100 steps
as the target shatters (a bond just at its threshold breaks in one run and
not the other once the difference is large enough): 5e-8 m (PMB) and 7e-8 m
(LPS) at step 900, when the first bonds differ shortly after (step 1000: 96
and 69 of 3487 atoms differ by a bond or two). Tolerance: identical damage
and positions within 5e-7 m (1e-4 of the cylinder's radius) at step 900.

The same with alpha 0 (PMB): every atom's s0 is then s00 and the law takes
no notes of the bonds (its log line says so); the damage must again be
PERI's, atom by atom."""
import os
import re
from lmptest import *

d = workdir()
src = os.environ.get("PDEXT_LAMMPS_SRC", os.path.expanduser("~/.cache/pdext/lammps-src"))
DECK_DUMP = ("dump fin all custom 900 final.${tag} id x y z c_1\n"
             "dump_modify fin sort id format float %.17g\nrun 900\n")


def deck(name, pd_pair=None, alpha=None):
    s = open(os.path.join(src, "examples/peri", name)).read()
    s = sub_exact(r"^run\s+1000", DECK_DUMP, s, flags=re.M)
    if alpha is not None:
        s = sub_exact(r"^(pair_coeff\s+\* \* \S+ \S+ \S+) 0.25$", rf"\1 {alpha}", s, flags=re.M)
    if pd_pair:
        s = sub_exact(r"^pair_style.*\n", "", s, flags=re.M)
        s = sub_exact(r"^pair_coeff.*\n", pd_pair, s, flags=re.M)
        s = replace_exact(s, "compute         1 all damage/atom", "compute         1 all pd/damage")
    return s


def last_snapshot(path):
    lines = open(path).read().splitlines()
    start = max(i for i, l in enumerate(lines) if l.startswith("ITEM: ATOMS"))
    return {int(l.split()[0]): [float(v) for v in l.split()[1:]] for l in lines[start + 1:] if l.strip()}


PMB = ("pair_style hybrid/overlay pd/bond legacy pd/contact legacy\n"
       "pair_coeff * * pd/bond pmb c 1.6863e22 horizon 0.0015001 fail legacy 0.0005 {alpha}\n"
       "pair_coeff * * pd/contact\n")
cases = {
    "PMB": ("in.peri.pmb", PMB.format(alpha=0.25), None),
    "LPS": ("in.peri.lps", "pair_style hybrid/overlay pd/ordinary legacy pd/contact legacy\n"
            "pair_coeff * * pd/ordinary K 14.9e9 G 14.9e9 horizon 0.0015001 fail legacy 0.0005 0.25\n"
            "pair_coeff * * pd/contact\n", None),
    "PMB alpha 0": ("in.peri.pmb", PMB.format(alpha=0.0), 0.0),
}
for name, (file, pair, alpha) in cases.items():
    run(deck(file, alpha=alpha), d, variables={"tag": "legacy"}, name="in.legacy")
    out, _ = run(deck(file, pair, alpha), d, variables={"tag": "pd"}, name="in.pd")
    check(f"{name}: the law says whether every atom's s0 is s00",
          ("every atom's s0 is s00" in out) == (alpha == 0.0))
    a, b = last_snapshot(f"{d}/final.legacy"), last_snapshot(f"{d}/final.pd")
    mean = sum(v[3] for v in a.values()) / len(a)
    same_damage = all(a[k][3] == b[k][3] for k in a)
    dpos = max(abs(a[k][c] - b[k][c]) for k in a for c in range(3))
    print(f"{name}: mean damage {mean:.4f}, largest position difference {dpos:.2e} m")
    check(f"{name}: the target is shattering (mean damage > 0.1)", mean > 0.1)
    check(f"{name}: identical damage fields after 900 steps", same_damage)
    check_le(f"{name}: positions agree after 900 steps", dpos, 5e-7, "round-off grown tenfold per 100 steps")
finish()
