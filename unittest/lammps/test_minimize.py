"""Quasi-static bar: 'minimize' solves a bar stretched by 0.1%
between two grips (3 layers each, held by fix setforce); Young's modulus is
the grip force over the cross-section divided by the strain between two
interior sections, 10 spacings apart.

Without surface correction (the default; T14 6.1.3) atoms within a horizon
of a free surface are softer, so a thin bar is softer than the input E by a
share that goes as horizon / width. Two widths (9 and 13 atoms) show that
scaling, and their Richardson extrapolation to an infinite width must give
the input E within 2% (the lattice error of the moduli, THEORY.md, is below
that). The energy and forces are consistent, or minimize would stop early
(the line search needs the gradient of the reported energy)."""
import re
from lmptest import *

d = workdir()
E_IN = 3.5e9


def bar_script(width, order, extra="", dmax="min_modify dmax 1e-5"):
    return f"""units si
boundary s s s
atom_style peri
atom_modify map array
lattice sc 5e-4
region b block 0 40 0 {width - 1} 0 {width - 1}
create_box 1 b
create_atoms 1 box
set group all density 1180
set group all volume 1.25e-10
pair_style pd/ordinary {extra}
pair_coeff * * E {E_IN} nu 0.35 horizon 0.0015001 m {order}
region left block INF 2.5 INF INF INF INF units lattice
region right block 37.5 INF INF INF INF INF units lattice
group left region left
group right region right
region sa block 14.5 15.5 INF INF INF INF units lattice
region sb block 24.5 25.5 INF INF INF INF units lattice
group sa region sa
group sb region sb
run 0
displace_atoms all ramp x 0.0 2e-5 x 0.0 0.02 units box
fix l left setforce 0 0 0
fix r right setforce 0 0 0
variable eps equal (xcm(sb,x)-xcm(sa,x))/(10*5e-4)-1
variable sig equal f_l[1]*1.25e-10/({width * width}*2.5e-7)
variable E equal v_sig/v_eps
min_style cg
{dmax}
minimize 1e-15 0 5000 100000
print "RESULT $(v_E:%.10g)"
"""


def bar(width, order, extra=""):
    out, _ = run(bar_script(width, order, extra), d)
    return log_value(out, r"RESULT ([0-9.eE+-]+)"), log_value(out, r"force evaluations = \d+ (\d+)")


# LAMMPS's default line-search step (0.1 length units: 10 cm here) tears
# bonds; that must stop the run with advice, not silently lose bonds
out, _ = run(bar_script(9, 0.5, dmax=""), d, expect_error=True)
check("minimize with the default dmax stops with advice", "limit the line search step with 'min_modify dmax'" in out)

e9, n9 = bar(9, 0.5)
e13, n13 = bar(13, 0.5)
e_inf = (13 * e13 - 9 * e9) / (13 - 9)
print(f"E(9 wide) = {e9:.4g} ({e9 / E_IN - 1:+.2%}), E(13 wide) = {e13:.4g} ({e13 / E_IN - 1:+.2%}), "
      f"extrapolated {e_inf:.4g} ({e_inf / E_IN - 1:+.2%}); force evaluations {n9:.0f}, {n13:.0f}")
check_le("extrapolated Young's modulus within 2% of the input", abs(e_inf / E_IN - 1), 0.02,
         "lattice error of the moduli")
ratio = (1 - e13 / E_IN) / (1 - e9 / E_IN)
check_le("surface softening scales as 1/width (ratio of deficits 9/13 = 0.69)", abs(ratio - 9 / 13), 0.05)
e9_log, _ = bar(9, 0.0)
check_le("m = 0 gives the same small-strain modulus as m = 1/2 (0.1% strain)", abs(e9_log / e9 - 1), 1e-2,
         "the strain measures differ at O(strain) = 0.1%, times a geometric factor")

# pd/corr elastic keeps no state that a trial step could change (its
# per-bond data are reference vectors, its plastic state is per atom): the
# line search is safe and minimize must be accepted (it refused it as
# "plasticity") and lower the energy; 300 iterations, a quarter of the way
corr = bar_script(9, 0).replace(f"pair_style pd/ordinary \npair_coeff * * E {E_IN} nu 0.35 horizon 0.0015001 m 0",
                                f"pair_style pd/corr model elastic\npair_coeff * * E {E_IN} nu 0.35 horizon 0.0015001")
corr = corr.replace("minimize 1e-15 0 5000 100000", "minimize 1e-15 0 300 100000")
check("the pd/corr bar deck", "pd/corr model elastic" in corr and "minimize 1e-15 0 300" in corr)
out, _ = run(corr, d, expect_error=True)
energies = re.search(r"Energy initial, next-to-last, final = \n\s*(\S+)\s+(\S+)\s+(\S+)", out)
check("pd/corr elastic: minimize is accepted and lowers the energy by more than a third",
      "ERROR" not in out and energies is not None and float(energies.group(3)) < float(energies.group(1)) / 1.5,
      energies.group(0).split("=")[-1].strip() if energies else next((l for l in out.splitlines() if "ERROR" in l), ""))
finish()
