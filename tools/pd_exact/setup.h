/* From the input to what the solver needs: the lattice, the family of one
 * site and the linear model, set up as the pair styles set up theirs. */
#ifndef PD_EXACT_SETUP_H
#define PD_EXACT_SETUP_H

#include "input.h"

#include "pd_dispersion.h"

typedef struct exact_problem {
  pd_lattice lat;
  pd_dimension pdim;       /* 3D or plane stress/strain (3D for a chain) */
  pd_family fam;           /* empty for classical */
  pd_linear_model model;
  pd_linear_model classical; /* local elasticity with the same constants */
  int grid[3];             /* grid points per side: n * sub */
  double density, time;
} exact_problem;

/* 0, or -1 with the reason printed to err. */
int exact_setup(const exact_input *in, exact_problem *p, FILE *err);

/* The family and the expected lattice error of the constants, to out. */
void exact_report(const exact_input *in, const exact_problem *p, FILE *out);

#endif
