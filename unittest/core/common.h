/* Checks shared by the material tests: energy-force consistency, rigid-
 * rotation objectivity and momentum balance, for any whole-body evaluator. */
#ifndef PD_TEST_COMMON_H
#define PD_TEST_COMMON_H

#include "lattice.h"

/* Returns total energy (J), fills the force density f (3 per atom). */
typedef double (*evaluator)(const lattice *l, const double *x, double *f, void *ctx);

/* V_i f_i = -dE/dx_i by central differences on every 7th coordinate. */
void check_energy_gradient(const char *name, const lattice *l, const double *x,
                           evaluator eval, void *ctx, double tol);
/* E(Rx) = E(x) and f(Rx) = R f(x). */
void check_objectivity(const char *name, const lattice *l, const double *x,
                       evaluator eval, void *ctx);
/* sum V f = 0 and sum V x cross f = 0 (forces along bonds, equal and opposite). */
void check_momentum(const char *name, const lattice *l, const double *x,
                    evaluator eval, void *ctx);
/* Classical isotropic energy density lambda/2 tr(e)^2 + mu e:e. */
double classical_energy(double lambda, double mu, double e[3][3]);
/* x0 plus a random displacement of amplitude amp (deterministic). */
void random_displacement(const lattice *l, double amp, unsigned seed, double *x);

#endif
