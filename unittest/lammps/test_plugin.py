"""The package as a plugin: a plain LAMMPS (PLUGIN and PERI
packages, shared library, none of our styles compiled in) runs our styles
after 'plugin load pdext.so'.

- Without the plugin, pair_style pd/bond is unknown to it (so what runs
  below is the plugin's).
- Parity: pd/bond legacy from the plugin reproduces the plain LAMMPS's own
  peri/pmb to 1e-10 relative (round-off of differently ordered sums, as in
  test_parity.py).
- Restart: 'run 100', write_restart, a new process that loads the plugin,
  read_restart, 'run 100' ends where 'run 100' twice in one process ends,
  bitwise.
"""
import os
import lmptest
from lmptest import *

PLAIN = os.path.abspath(os.environ.get("PDEXT_PLAIN_LMP", "../../build/plain-lammps/lmp"))
PLUGIN = os.path.abspath(os.environ.get("PDEXT_PLUGIN", "../../build/pdext.so"))
check("the plain LAMMPS and the plugin exist", os.path.exists(PLAIN) and os.path.exists(PLUGIN), f"{PLAIN}, {PLUGIN}")
COMPILED = lmptest.LMP    # build/lmp: the package compiled in
lmptest.LMP = PLAIN
d = workdir()
LOAD = f"plugin load {PLUGIN}\n"

out, _ = run(block(8) + PAIRS["pd/bond legacy"], d, expect_error=True)
check("without the plugin the plain LAMMPS does not know pd/bond", "Unrecognized pair style 'pd/bond'" in out)
# every pd/ style the compiled-in lmp lists (lmp -h), not a list typed here
import subprocess  # noqa: E402
helptext = subprocess.run([COMPILED, "-h"],
                          capture_output=True, text=True).stdout
listed, kind = [], None
for line in helptext.splitlines():
    for k in ("Pair", "Fix", "Compute"):
        if line.startswith(f"* {k} styles"):
            kind = k.lower()
            break
    else:
        if line.startswith("* "):
            kind = None
        elif kind:
            listed += [(kind, w) for w in line.split() if w.startswith("pd/")]
check("lmp -h lists the package's pair, fix and compute styles", len({k for k, _ in listed}) == 3 and len(listed) >= 10,
      f"{len(listed)}: {listed}")
out, _ = run(LOAD + "plugin list\n", d)
missing = [f"{k} {n}" for k, n in listed if f"{k} style plugin {n}" not in out]
check(f"the plugin registers every one of them ({len(listed)})", listed and not missing, f"missing: {missing}")

STEPS = ROUGH_VELOCITY + "fix 1 all nve\ntimestep 1.0e-7\nthermo 100\n"
out, _ = run(LOAD + block(8) + STEPS + PAIRS["pd/bond legacy"] + "fix ts all pd/timestep\nrun 20\n", d)
check("the plugin's fix pd/timestep sets the step in the plain LAMMPS",
      re.search(r"pd/timestep: step 0 \(run start\): dt 1e-07 -> \S+ \(stable", out) is not None, out[-400:])
out, _ = run(LOAD + block(8) + STEPS + f"pair_style pd/corr model elastic\npair_coeff * * E 1e9 nu 0.25 "
             f"horizon {HORIZON}\nrun 20\n", d)
check("the plugin's pd/corr runs in the plain LAMMPS", "pd/corr: extended (T14 4.2) correspondence, model elastic" in out, out[-400:])
final = {}
for style in ("peri/pmb", "pd/bond legacy"):
    tag = style.replace(" ", "_").replace("/", "_")
    run(LOAD + block(12) + STEPS + PAIRS[style] + "run 200\n" + DUMP.format(file="final." + tag), d)
    final[style] = read_dump(f"{d}/final.{tag}")
check_le("plugin pd/bond legacy reproduces the plain LAMMPS's peri/pmb",
         max_rel_diff(final["peri/pmb"], final["pd/bond legacy"]), 1e-10, "round-off of differently ordered sums")

run(LOAD + block(12) + STEPS + PAIRS["pd/bond legacy"] + "run 100\nrun 100\n" + DUMP.format(file="one"), d)
run(LOAD + block(12) + STEPS + PAIRS["pd/bond legacy"] + "run 100\nwrite_restart half.restart\n", d)
out, _ = run(LOAD + "read_restart half.restart\nfix 1 all nve\nrun 100\n" + DUMP.format(file="restarted"), d)
diff = max_rel_diff(read_dump(f"{d}/one"), read_dump(f"{d}/restarted"))
check("restart with the plugin: the run continues bitwise", diff == 0.0, f"max rel diff {diff:.3g}")
finish()
