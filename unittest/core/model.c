#include "model.h"

#include "pd_bond_based.h"
#include "pd_law_energy.h"
#include "pd_ordinary.h"

#include <stdlib.h>
#include <string.h>

static double total(const lattice *l, const double *psi)
{
  double e = 0.0;
  for (int a = 0; a < l->natoms; a++) e += l->vol[a] * psi[a];
  return e;
}

double pmb_eval(const lattice *l, double c, const double *x, double *f, double *psi_out)
{
  double *psi = calloc(l->natoms, sizeof(double));
  memset(f, 0, sizeof(double) * 3 * l->natoms);
  pd_bond_view v = lattice_view(l);
  pd_pmb mat = {&c};
  pd_tally t = {0};
  t.eatom = psi;
  pd_pmb_forces(&(pd_loop){&v, l->type, 1, x, l->vol, f, &t, NULL, l->reaction, l->natoms, 0, NULL, 0}, &mat);
  const double e = total(l, psi);
  if (psi_out) memcpy(psi_out, psi, sizeof(double) * l->natoms);
  free(psi);
  return e;
}

static double ordinary_run(const lattice *l, double lambda, double mu, double order,
                           const double *mfixed, pd_failure *fail, const double *crit,
                           const double *x, double *f, double *psi_out, double *theta_out,
                           double *ab_out);

double ordinary_eval(const lattice *l, double lambda, double mu, double order,
                     const double *x, double *f, double *psi_out, double *theta_out)
{
  return ordinary_run(l, lambda, mu, order, NULL, NULL, NULL, x, f, psi_out, theta_out, NULL);
}

double ordinary_eval_full(const lattice *l, double lambda, double mu, double order,
                          const double *mfixed, pd_failure *fail, const double *crit,
                          const double *x, double *f, double *ab_out)
{
  return ordinary_run(l, lambda, mu, order, mfixed, fail, crit, x, f, NULL, NULL, ab_out);
}

static double ordinary_run(const lattice *l, double lambda, double mu, double order,
                           const double *mfixed, pd_failure *fail, const double *crit,
                           const double *x, double *f, double *psi_out, double *theta_out,
                           double *ab_out)
{
  const int n = l->natoms;
  const int dim = l->natoms == l->n * l->n ? 2 : 3;
  double *m = calloc(n, sizeof(double)), *sum = calloc(n, sizeof(double));
  double *ab = calloc(2 * n, sizeof(double));
  double *psi = calloc(n, sizeof(double));
  pd_bond_view v = lattice_view(l);
  if (mfixed) memcpy(m, mfixed, sizeof(double) * n);
  else pd_weighted_volume(&v, l->vol, m);
  double *strain = malloc(sizeof(double) * (size_t) l->stride * n);
  /* use the per-bond strain cache on odd calls, so both paths are tested */
  static int calls;
  static const double unit_gc = 1.0; /* crit is beta N for the whole G_c */
  pd_ordinary_state st = {order, sum, ab, (calls++ & 1) ? strain : NULL, 0};
  pd_law_energy energy = {crit, crit ? pd_failure_floor(crit, n) : 0.0, &unit_gc, 0.0, 0.0};
  pd_law_energy_profile(&energy, PD_PROFILE_UNIFORM);
  if (fail && crit) fail->params = &energy;
  pd_tally t = {0};
  t.eatom = psi;
  const pd_loop L = {&v, l->type, 1, x, l->vol, f, &t, fail, l->reaction, l->natoms, 0, NULL, 0};
  pd_ordinary_dilatation(&L, &st);
  for (int i = 0; i < n; i++) {
    const pd_ordinary_atom_out o = pd_ordinary_atom(lambda, mu, dim / m[i], sum[i]);
    ab[2 * i] = o.a;
    ab[2 * i + 1] = o.b;
    psi[i] = o.energy;
    if (theta_out) theta_out[i] = o.theta;
  }
  memset(f, 0, sizeof(double) * 3 * n);
  pd_ordinary_forces(&L, &st);
  if (ab_out) memcpy(ab_out, ab, sizeof(double) * 2 * n);
  const double e = total(l, psi);
  if (psi_out) memcpy(psi_out, psi, sizeof(double) * n);
  free(m);
  free(sum);
  free(ab);
  free(strain);
  free(psi);
  return e;
}
