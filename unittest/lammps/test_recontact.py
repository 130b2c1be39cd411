"""Crack faces push only when they touch.

A PMMA plate (plane stress, spacing 1 mm, horizon 4 mm), periodic along x,
is cut across its mid-line by fix pd/precrack. Broken bonds resist
compression only once their two particles are within the contact distance
(r_i + r_j, one spacing: pd/contact's), as MS07's short-range force.
- An open gap: two rows are missing from the reference configuration (a
  notch 2 mm wide, nearest rows 3 mm apart, cut across), and the upper half
  slides along x at 10 m/s. With the default rule the lower half feels
  nothing: its momentum stays 0 (to round-off) after 20 us. The old rule
  ('recontact any': any compressed broken bond pushes, up to the horizon)
  drags it along: measured at more than 1 m/s.
- Faces pressed together: the lower half strikes the upper one at 20 m/s
  across the closed cut; the rows on either side stay more than half a
  spacing apart (no interpenetration) and the upper half is pushed.
"""
from lmptest import *

d = workdir()
h, DELTA = 1e-3, 4.0001e-3


def plate(rule, gap_rows, vx_upper, vy_lower, steps):
    top = 20 + gap_rows
    cut = 9.5 + 0.5 * gap_rows
    return f"""units si
dimension 2
boundary p s p
atom_style peri
atom_modify map array
lattice sq {h}
region box block 0 30 0 {top} -0.5 0.5
create_box 1 box
region solid block INF INF {cut - 0.5 * gap_rows} INF INF INF side out
region upper block INF INF {cut + 0.5 * gap_rows} INF INF INF
region body union 2 solid upper
create_atoms 1 region body
set group all density 1180
set group all volume {h * h * 1e-3}
group upper region upper
group lower subtract all upper
pair_style pd/ordinary plane stress thickness 1e-3 {rule}
pair_coeff * * E 3.5e9 nu 0.35 horizon {DELTA} m 0.5
fix cut all pd/precrack segment -1 {cut * h} 1 {cut * h}
compute vlow lower reduce ave vx vy
compute vup upper reduce ave vx vy
compute ytop lower reduce max y
compute ybot upper reduce min y
variable gap equal c_ybot-c_ytop
fix 1 all nve
fix 2d all enforce2d
timestep 5e-8
run 0
velocity upper set {vx_upper} 0 0 units box
velocity lower set 0 {vy_lower} 0 units box
thermo_style custom step c_vlow[1] c_vlow[2] c_vup[2] v_gap
thermo_modify format float %.15g
thermo 10
run {steps}
"""


# 20 us = 400 steps of 50 ns (about 0.2 of the stable step)
out, rows = run(plate("", 2, 10.0, 0.0, 400), d)
near = max(abs(r["c_vlow[1]"]) for r in rows)
check("the default rule is 'near' (logged)", "broken bonds push once their particles touch (recontact near)" in out)
check("the notch is there: the nearest rows start 3 spacings apart", abs(rows[0]["v_gap"] - 3 * h) < 1e-12,
      f"{rows[0]['v_gap'] / h:.6f}")
check_le("an open 2 mm gap: the lower half stays at rest while the upper slides at 10 m/s", near, 1e-9,
         "no force crosses the gap; round-off")
out, rows = run(plate("recontact any", 2, 10.0, 0.0, 400), d)
far = max(abs(r["c_vlow[1]"]) for r in rows)
check("... the old rule ('recontact any') drags it along across the gap", far > 1.0, f"{far:.3g} m/s")

out, rows = run(plate("", 0, 0.0, 20.0, 400), d)
gap = min(r["v_gap"] for r in rows)
check("faces pressed together (20 m/s): the rows stay more than half a spacing apart", gap > 0.5 * h,
      f"closest {gap / h:.3f} spacings")
check("... and the struck half is pushed", max(r["c_vup[2]"] for r in rows) > 1.0,
      f"{max(r['c_vup[2]'] for r in rows):.3g} m/s")
finish()
