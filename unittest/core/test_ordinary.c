/* Ordinary state-based solid (T14 eq. 5.1): LPS at m = 1/2, nonlinear
 * orders, on a simple-cubic lattice. */
#include "check.h"
#include "common.h"
#include "model.h"
#include "pd_params.h"

#include <stdlib.h>

typedef struct {
  double lambda, mu, order;
} material;

static double eval_ordinary(const lattice *l, const double *x, double *f, void *ctx)
{
  const material *m = ctx;
  return ordinary_eval(l, m->lambda, m->mu, m->order, x, f, NULL, NULL);
}

static double classical(double lambda, double mu, const double e[3][3])
{
  const double tr = e[0][0] + e[1][1] + e[2][2];
  double ee = 0.0;
  for (int i = 0; i < 3; i++)
    for (int j = 0; j < 3; j++) ee += e[i][j] * e[i][j];
  return 0.5 * lambda * tr * tr + mu * ee;
}

int main(void)
{
  const double K = 14.9e9, G = 7.0e9, h = 5e-4;
  const double lambda = K - 2.0 * G / 3.0;
  const pd_lame bar = pd_ordinary_lame_3d(K, G);
  check_rel("3D mu_bar = 5 mu / 2", bar.mu, 2.5 * G, 1e-15);
  check_rel("3D lambda_bar = lambda - mu", bar.lambda, lambda - G, 1e-15);
  /* LPS (m = 1/2, peri/lps influence, discrete normalization) at the centre
   * of a 9^3 block with delta = 3h: the centre's family is complete. */
  {
    lattice l = lattice_make(3, 9, h, 3.0001 * h, PD_INFLUENCE_LPS);
    const int n = l.natoms, ctr = lattice_center(&l);
    double *x = malloc(sizeof(double) * 3 * n), *f = malloc(sizeof(double) * 3 * n);
    double *psi = malloc(sizeof(double) * n), *theta = malloc(sizeof(double) * n);
    const double s = 1e-4;
    const double dil[3][3] = {{s, 0, 0}, {0, s, 0}, {0, 0, s}};
    lattice_strain(&l, dil, x);
    ordinary_eval(&l, bar.lambda, bar.mu, 0.5, x, f, psi, theta);
    /* Every bond has stretch s, and the weighted volume normalizes the sum
     * exactly: theta = 3 s to round-off, at every atom, even at surfaces. */
    check_rel("LPS dilatation theta = 3 s at the centre", theta[ctr], 3 * s, 1e-12);
    check_rel("LPS dilatation theta = 3 s at a corner", theta[0], 3 * s, 1e-12);
    check_rel("LPS dilatation energy = K theta^2 / 2", psi[ctr], 0.5 * K * 9 * s * s, 1e-10);
    lattice_free(&l);
    free(x);
    free(f);
    free(psi);
    free(theta);
  }
  /* Deviatoric strains: on the lattice at delta = 3h the discrete 4th moment
   * of omega = 1/|xi| (discretely normalized) makes shear along the axes 1.5%
   * too stiff and shear off the axes 1.0% too soft (THEORY.md, discretization
   * facts; recomputed for this lattice), so the energy of any small strain is
   * within 1.5% of the classical one: tolerance 2%. (peri/lps's influence,
   * omega ~ |xi| here, is off by -13% and +8.6%: not a good default.) */
  {
    lattice l = lattice_make(3, 9, h, 3.0001 * h, PD_INFLUENCE_INVERSE);
    const int n = l.natoms, ctr = lattice_center(&l);
    double *x = malloc(sizeof(double) * 3 * n), *f = malloc(sizeof(double) * 3 * n);
    double *psi = malloc(sizeof(double) * n), *theta = malloc(sizeof(double) * n);
    unsigned seed = 11;
    for (int trial = 0; trial < 3; trial++) {
      double e[3][3];
      for (int i = 0; i < 3; i++)
        for (int j = 0; j <= i; j++) e[i][j] = e[j][i] = 1e-4 * urand(&seed);
      lattice_strain(&l, e, x);
      ordinary_eval(&l, bar.lambda, bar.mu, 0.5, x, f, psi, theta);
      check_rel("m = 1/2 random strain: classical energy", psi[ctr], classical(lambda, G, e), 0.02);
      /* Small strain: every order m agrees with LPS to O(strain). */
      ordinary_eval(&l, bar.lambda, bar.mu, 0.0, x, f, psi, theta);
      check_rel("m = 0, random small strain: classical energy", psi[ctr], classical(lambda, G, e), 0.02);
    }
    lattice_free(&l);
    free(x);
    free(f);
    free(psi);
    free(theta);
  }
  /* Energy-force consistency for m = 1/2, 0, -1 on a small block with a
   * random displacement of 1% of the spacing and Tupek's weights. */
  {
    lattice l = lattice_make(3, 5, h, 2.0001 * h, PD_INFLUENCE_TUPEK);
    double *x = malloc(sizeof(double) * 3 * l.natoms);
    random_displacement(&l, 0.01 * h, 5, x);
    const double orders[] = {0.5, 0.0, -1.0};
    for (int k = 0; k < 3; k++) {
      material m = {bar.lambda, bar.mu, orders[k]};
      char name[32];
      snprintf(name, sizeof name, "ordinary m = %g", orders[k]);
      check_energy_gradient(name, &l, x, eval_ordinary, &m, 1e-6);
      check_objectivity(name, &l, x, eval_ordinary, &m);
      check_momentum(name, &l, x, eval_ordinary, &m);
    }
    lattice_free(&l);
    free(x);
  }
  return check_summary();
}
