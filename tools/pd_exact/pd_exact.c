/* pd_exact: the exact solution of the linearized peridynamic equation of
 * motion (pd/bond PMB, pd/ordinary) or of local elasticity on a periodic
 * lattice, for comparison with LAMMPS runs (README.md). */
#include "evolve.h"
#include "input.h"
#include "setup.h"
#include "sites.h"

#include <stdio.h>

int main(int argc, char **argv)
{
  if (argc != 2) {
    fprintf(stderr, "usage: pd_exact <input file>  (tools/pd_exact/README.md)\n");
    return 2;
  }
  exact_input in;
  exact_problem p;
  exact_sites s;
  if (exact_read_input(argv[1], &in, stderr) || exact_setup(&in, &p, stderr)) return 1;
  exact_report(&in, &p, stdout);
  if (!in.fields[0]) { /* the report alone */
    pd_family_free(&p.fam);
    return 0;
  }
  if (exact_read_sites(in.fields, &p, in.origin, &s, stderr)) return 1;
  const int bad = exact_evolve(&p, &s, stderr) || exact_write_sites(in.output, &s, p.time, stderr);
  if (!bad) printf("pd_exact: %d sites advanced to t = %.10g, written to %s\n", s.n, p.time, in.output);
  exact_free_sites(&s);
  pd_family_free(&p.fam);
  return bad;
}
