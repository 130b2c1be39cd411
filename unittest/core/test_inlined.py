"""Every per-bond hook is inlined into the bond kernels (nm on libpdcore.a).

The bond loops (pd_bond_loop.h) call a material's and a law's hooks per
bond; each is declared PD_INLINE. A hook that the compiler leaves out of
line costs a call per bond and the kernel's vector code: pd/ordinary's m = 0
strain, out of line as strain_log.constprop.2.isra.0, made make demo 1.5x
slower and no other test noticed. In the objects that instantiate kernels,
a local function is therefore a kernel instantiation (<material>_<law>_<three
digits: failing, weight mode, tally>), a pass instantiation (pd/ordinary's
dilatation_<strain>[_kept][_failing]), a function the core keeps out of
line on purpose (declared PD_NOINLINE: a rarely taken branch, under its own
name) or nothing: an out-of-line hook, or a compiler clone (.isra,
.constprop, .part), fails here."""
import glob
import os
import re
import subprocess
import sys

nm, library = sys.argv[1], sys.argv[2]
KERNEL = re.compile(r"^[a-z0-9]+(_[a-z]+)+_[0-9]{3}$")
PASS = re.compile(r"^dilatation_[a-z]+(_kept)?(_failing)?$")
CORE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../src/PERIDYNAMICS_EXT/core")
OUT_OF_LINE = {m.group(1) for path in glob.glob(os.path.join(CORE, "*.h"))
               for m in re.finditer(r"^PD_NOINLINE\s+\w+\s+(\w+)\(", open(path).read(), re.M)}
listing = subprocess.run([nm, "-A", library], capture_output=True, text=True, check=True).stdout
kernels, strays, symbols = 0, [], []
for line in listing.splitlines():
    w = line.split()
    if len(w) == 3 and w[1] in "tT":
        symbols.append((w[0].split(":")[-2], w[1], w[2]))
kernel_objects = {o for o, kind, name in symbols if kind == "t" and KERNEL.match(name)}
for o, kind, name in symbols:
    if o not in kernel_objects or kind != "t":
        continue
    if KERNEL.match(name):
        kernels += 1
    elif not PASS.match(name) and name not in OUT_OF_LINE:
        strays.append(f"{o}: {name}")

failed = 0
def check(what, ok, detail=""):
    global failed
    failed += not ok
    print(f"{'PASS' if ok else 'FAIL'} {what}  ({detail})")

check("the kernel objects are found (pd_bond_based, pd_ordinary, pd_corr)",
      len(kernel_objects) >= 3, ", ".join(sorted(kernel_objects)))
check("they instantiate the kernels (materials x laws x weight modes x tally)", kernels >= 400, f"{kernels}")
check("the core's out-of-line functions are found (PD_NOINLINE)", "pd_chunk_atom_virial" in OUT_OF_LINE,
      ", ".join(sorted(OUT_OF_LINE)))
check("no function besides the kernels in them: every hook inlined, no clone", not strays, "; ".join(strays))
sys.exit(1 if failed else 0)
