/* Whole-body evaluation of the core materials on a test lattice: forces and
 * per-atom energy density, in the order a host (LAMMPS) calls the kernels. */
#ifndef PD_TEST_MODEL_H
#define PD_TEST_MODEL_H

#include "lattice.h"
#include "pd_failure.h"

/* Each returns the total energy in joules, sum_i V_i psi_i; f is the force
 * density, psi (may be NULL) the per-atom energy density. */
double pmb_eval(const lattice *l, double c, const double *x, double *f, double *psi);
double ordinary_eval(const lattice *l, double lambda, double mu, double order,
                     const double *x, double *f, double *psi, double *theta);

/* The same with the weighted volumes m given (not recomputed from the
 * weights) and optional failure; ab receives A, B per atom (2 per atom). */
double ordinary_eval_full(const lattice *l, double lambda, double mu, double order,
                          const double *mfixed, pd_failure *fail, const double *crit,
                          const double *x, double *f, double *ab_out);

#endif
