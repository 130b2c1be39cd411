"""fix pd/timestep: the adaptive stable time step.

A free 10^3 block of the nonlinear solid m = -1 is given a uniform inward
velocity: it compresses by about 15%, stiffens (its bonds' tangent grows like
stretch^(2m-2)), and rebounds. The fix must shrink the step as it stiffens
and let it grow back, naming the cause; kinetic + elastic energy must stay
as well kept as at a fixed step; the run must not depend on the rank count
or on a restart in between."""
import re
from lmptest import *

d = workdir()
N = 10
BODY = block(N, "s s s") + f"""pair_style pd/ordinary
pair_coeff * * K {BULK} G {SHEAR} horizon {HORIZON} m -1
variable c equal {N * SPACING / 2}
variable vx atom -1.6e5*(x-v_c)
variable vy atom -1.6e5*(y-v_c)
variable vz atom -1.6e5*(z-v_c)
velocity all set v_vx v_vy v_vz units box
""" + ENERGY_JOULES + """fix 1 all nve
timestep 1.0e-8
thermo_style custom step dt v_etot c_KEJ c_PEJ
thermo 10
thermo_modify format float %.15g
"""
# travel 0: the stiffness alone sets the step here (the travel limit, on by
# default, is tested in unittest/stability)
ADAPT = "fix ts all pd/timestep every 10 travel 0\n"
CHANGE = re.compile(r"pd/timestep: step (\d+)(?: \(run start\))?: dt (\S+) -> (\S+) \(stable (\S+), limited by ([a-z]+)")


def changes(out):
    return [(int(s), float(a), float(b), float(st), why) for s, a, b, st, why in CHANGE.findall(out)]


def energy_spread(rows):
    e = [r["v_etot"] for r in rows]
    return (max(e) - min(e)) / e[0]


out, rows = run(BODY + ADAPT + "run 600\n" + DUMP.format(file="one"), d)
ch = changes(out)
print("\n".join(f"  step {s}: {a:.4g} -> {b:.4g} (stable {st:.4g}, {why})" for s, a, b, st, why in ch))
first = ch[0]
check("the run starts at the step the state allows: safety 0.8 of the stable one, a band of 1.1 below it",
      first[0] == 0 and abs(first[2] - 0.8 * first[3] / 1.1) < 1e-5 * first[2], f"{first}")
smallest = min(b for _, _, b, _, _ in ch)
check("the step shrinks as the block stiffens in compression (by more than 1.3x)",
      smallest < first[2] / 1.3, f"{first[2]:.4g} -> {smallest:.4g}")
check("... and the log names compression as the cause", any(w == "compression" for *_, w in ch))
grew = [c for c in ch[1:] if c[2] > c[1]]
check("the step grows back as the block rebounds", len(grew) > 0, f"{len(grew)} increases")
check("every step the fix set is below safety x stable of its check", all(b <= 0.8 * st * (1 + 1e-12) for _, _, b, st, _ in ch))
summary = re.search(r"pd/timestep: this run: (\d+) checks, (\d+) changes of the step \(limited by ([^)]*)\); "
                    r"step (\S+) \.\. (\S+)", out)
check("the run ends with a summary: as many changes as lines, the causes, the range of the step",
      summary is not None and int(summary.group(2)) == len(ch) and "compression" in summary.group(3) and
      abs(float(summary.group(4)) - smallest) <= 1e-5 * smallest, summary.group(0) if summary else "no summary")
dts = [r["Dt"] for r in rows]
check("thermo reports the changing step", min(dts) < 0.8 * max(dts), f"{min(dts):.3g} .. {max(dts):.3g}")
spread = energy_spread(rows)
# at a fixed step equal to the largest the fix used, the same span of time:
# velocity Verlet's energy error is O(dt^2) and bounded; changing the step
# must not add a drift of its own
largest = max(dts)
span = sum(r["Dt"] for r in rows[:-1]) * 10
_, fixed_rows = run(BODY + f"timestep {largest!r}\nrun {int(span / largest)}\n", d)
fixed_spread = energy_spread(fixed_rows)
check_le("kinetic + elastic energy across the changes of step: spread over the run (relative)", spread,
         1.5 * fixed_spread, f"fixed largest step {largest:.3g}: {fixed_spread:.3g}")

# 2 ranks: the same changes, the same energies (the stiffness sums only add
# in another order)
out2, rows2 = run(BODY + ADAPT + "run 600\n", d, ranks=2)
ch2 = changes(out2)
same_steps = [c[0] for c in ch] == [c[0] for c in ch2]
dt_diff = max(abs(a[2] - b[2]) / a[2] for a, b in zip(ch, ch2)) if same_steps else math.inf
check("2 ranks change the step at the same steps, to the same value (1e-10)", same_steps and dt_diff < 1e-10,
      f"{len(ch)} vs {len(ch2)} changes, max rel diff {dt_diff:.3g}")
e_diff = abs(rows2[-1]["v_etot"] - rows[-1]["v_etot"]) / rows[-1]["v_etot"]
check_le("2 ranks: the same final energy", e_diff, 1e-9, "round-off of sums in another order")

# restart between two checks (step 255): the continued run keeps the step
# and the check schedule of the uninterrupted one
run(BODY + ADAPT + "run 255\nwrite_restart restart.ts\n", d)
out3, _ = run("read_restart restart.ts\n" + ENERGY_JOULES + "fix 1 all nve\n" + ADAPT +
              "thermo 10\nrun 345\n" + DUMP.format(file="two"), d)
after = [c for c in ch if c[0] > 255]
ch3 = changes(out3)
check("after a restart between checks the step is not retaken at the run start",
      all(c[0] > 255 for c in ch3), f"{ch3[:1]}")
check("... and changes at the same steps to the same values", [(c[0], c[2]) for c in ch3] == [(c[0], c[2]) for c in after],
      f"{len(ch3)} vs {len(after)} changes")
diff = max_rel_diff(read_dump(f"{d}/one"), read_dump(f"{d}/two"))
check_le("the restarted run ends at the same positions", diff, 1e-12,
         "the stiffness sums add ghosts in the restarted run's order: the step moves by round-off")

# input checks: each ERROR names the argument and says what is expected
for args, msg in [("every 0", "every must be a step count >= 1, got '0'"),
                  ("safety 1.5", "safety must be a fraction in (0, 1], got '1.5'"),
                  ("travel -1", "travel must be a fraction of the spacing >= 0"),
                  ("grow 1", "grow must be a factor > 1, got '1'"),
                  ("min 2e-8 max 1e-8", "min 2e-08 exceeds max 1e-08"),
                  ("speed 3", "unknown keyword 'speed' (every, safety, travel, min, max, grow)"),
                  ("safety", "'safety' needs a value")]:
    bad, _ = run(BODY + f"fix ts all pd/timestep {args}\nrun 0\n", d, expect_error=True)
    check(f"ERROR for 'fix pd/timestep {args}'", "ERROR" in bad and msg in bad, bad[-300:] if msg not in bad else "")
bad, _ = run(BODY + "group half id <= 500\nfix ts half pd/timestep\nrun 0\n", d, expect_error=True)
check("ERROR for a group other than all", "use group all, not 'half'" in bad)
bad, _ = run(BODY + "fix ts all pd/timestep min 1e-6\nrun 100\n", d, expect_error=True)
check("ERROR when the stable step falls below min", "is below min 1e-06" in bad and "the run would be unstable" in bad)
bad, _ = run(BODY + "fix ts all pd/timestep\nfix dt all dt/reset 1 NULL NULL 1e-5 units box\nrun 0\n", d,
             expect_error=True)
check("ERROR when fix dt/reset also sets the step", "both set the time step" in bad and "fix dt (dt/reset)" in bad)

# A step that shrinks by orders of magnitude says so: one particle sent off
# at 1e6 m/s, whose travel limit (0.05 spacings per step) is 2.5e-11 s,
# some 4000x below the block's stable step. Warned at 100x and at each
# further 10x: here once (the step stays above 1e-4 of the first)
FAST = block(N, "s s s") + f"""pair_style pd/ordinary
pair_coeff * * K {BULK} G {SHEAR} horizon {HORIZON}
group fast id 555
velocity fast set 1e6 0 0 units box
fix 1 all nve
fix ts all pd/timestep every 10
timestep 1.0e-8
run 20
"""
out, _ = run(FAST, d)
warned = [l for l in out.splitlines() if "times below the material's stable step" in l]
check("a step that falls 100x below the material's stable step is a WARNING naming the cause",
      len(warned) == 1 and "limited by travel" in warned[0], warned[0][:200] if warned else "none")
# A slowly changing state does not change the step at each check: a 2D
# plate pulled apart (its allowed step creeping up by hairs) logged 300
# changes of the step to itself in 3000 steps before the band's lower end
# had its slack
PULL = plate(40, "s s p").replace(f"density {DENSITY}", "density 1180") + f"""pair_style pd/ordinary plane stress thickness 1e-3
pair_coeff * * E 3.5e9 nu 0.35 horizon 1.5e-3
velocity all ramp vy -4 4 y 0 {40 * SPACING} units box
fix 1 all nve
fix 2d all enforce2d
fix ts all pd/timestep
run 3000
"""
out, _ = run(PULL, d)
ch = changes(out)
check("a plate pulled apart: the step is set at the run start and changes only by more than the slack (1%)",
      1 <= len(ch) <= 5 and all(max(a / b, b / a) > 1.01 for _, a, b, _, _ in ch[1:]),
      f"{len(ch)} changes, first {[(s, a, b) for s, a, b, _, _ in ch[:3]]}")
out, _ = run(FAST.replace("velocity fast set 1e6 0 0", "velocity fast set 1 0 0"), d)
check("... and a step that stays is not", "times below the material's stable step" not in out)
finish()
