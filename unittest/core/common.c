#include "common.h"

#include "check.h"

#include <stdlib.h>
#include <string.h>

void random_displacement(const lattice *l, double amp, unsigned seed, double *x)
{
  for (int k = 0; k < 3 * l->natoms; k++) x[k] = l->x0[k] + amp * urand(&seed);
  if (l->natoms == l->n * l->n)
    for (int a = 0; a < l->natoms; a++) x[3 * a + 2] = 0.0;
}

void check_energy_gradient(const char *name, const lattice *l, const double *x0,
                           evaluator eval, void *ctx, double tol)
{
  const int n3 = 3 * l->natoms;
  double *x = malloc(sizeof(double) * n3), *f = malloc(sizeof(double) * n3);
  double *g = malloc(sizeof(double) * n3);
  memcpy(x, x0, sizeof(double) * n3);
  eval(l, x, f, ctx);
  double fmax = 0.0, errmax = 0.0;
  for (int k = 0; k < n3; k++)
    if (fabs(l->vol[k / 3] * f[k]) > fmax) fmax = fabs(l->vol[k / 3] * f[k]);
  const double h = 1e-6 * l->h;
  const int is2d = l->natoms == l->n * l->n;
  for (int k = 0; k < n3; k += 7) {
    if (is2d && k % 3 == 2) continue;
    const double keep = x[k];
    x[k] = keep + h;
    const double ep = eval(l, x, g, ctx);
    x[k] = keep - h;
    const double em = eval(l, x, g, ctx);
    x[k] = keep;
    const double err = fabs(l->vol[k / 3] * f[k] + (ep - em) / (2 * h));
    if (err > errmax) errmax = err;
  }
  char what[96];
  snprintf(what, sizeof what, "%s: V f = -dE/dx (max err / max force)", name);
  check_rel(what, 1.0 + errmax / fmax, 1.0, tol);
  free(x);
  free(f);
  free(g);
}

void check_objectivity(const char *name, const lattice *l, const double *x,
                       evaluator eval, void *ctx)
{
  const int n3 = 3 * l->natoms;
  double R[3][3];
  if (l->natoms == l->n * l->n) rotation_matrix(0.0, 0.0, 0.7, R);
  else rotation_matrix(0.3, -1.1, 0.7, R);
  double *xr = malloc(sizeof(double) * n3), *f = malloc(sizeof(double) * n3);
  double *fr = malloc(sizeof(double) * n3), *rf = malloc(sizeof(double) * n3);
  const double e = eval(l, x, f, ctx);
  rotate(R, l->natoms, x, xr);
  const double er = eval(l, xr, fr, ctx);
  rotate(R, l->natoms, f, rf);
  double errmax = 0.0, fmax = 0.0;
  for (int k = 0; k < n3; k++) {
    if (fabs(fr[k] - rf[k]) > errmax) errmax = fabs(fr[k] - rf[k]);
    if (fabs(f[k]) > fmax) fmax = fabs(f[k]);
  }
  char what[96];
  /* Round-off: ~1e-16 per bond, summed over ~100 bonds on differences of
   * nearly equal positions scaled by 1e3 (displacement / spacing). */
  snprintf(what, sizeof what, "%s: energy invariant under rotation", name);
  check_rel(what, er, e, 1e-9);
  snprintf(what, sizeof what, "%s: forces rotate with the body", name);
  check_rel(what, 1.0 + errmax / fmax, 1.0, 1e-9);
  free(xr);
  free(f);
  free(fr);
  free(rf);
}

void check_momentum(const char *name, const lattice *l, const double *x,
                    evaluator eval, void *ctx)
{
  double *f = malloc(sizeof(double) * 3 * l->natoms);
  eval(l, x, f, ctx);
  double p[3] = {0}, L[3] = {0}, scale = 0.0, lscale = 0.0;
  for (int a = 0; a < l->natoms; a++) {
    const double *xa = x + 3 * a;
    double F[3];
    for (int c = 0; c < 3; c++) {
      F[c] = l->vol[a] * f[3 * a + c];
      p[c] += F[c];
      scale += fabs(F[c]);
    }
    L[0] += xa[1] * F[2] - xa[2] * F[1];
    L[1] += xa[2] * F[0] - xa[0] * F[2];
    L[2] += xa[0] * F[1] - xa[1] * F[0];
    lscale += (fabs(xa[0]) + fabs(xa[1]) + fabs(xa[2])) * (fabs(F[0]) + fabs(F[1]) + fabs(F[2]));
  }
  char what[96];
  /* Each bond adds equal and opposite forces: only round-off remains. */
  snprintf(what, sizeof what, "%s: sum of V f vanishes", name);
  check_rel(what, 1.0 + (fabs(p[0]) + fabs(p[1]) + fabs(p[2])) / scale, 1.0, 1e-13);
  snprintf(what, sizeof what, "%s: sum of V x cross f vanishes", name);
  check_rel(what, 1.0 + (fabs(L[0]) + fabs(L[1]) + fabs(L[2])) / lscale, 1.0, 1e-13);
  free(f);
}

double classical_energy(double lambda, double mu, double e[3][3])
{
  const double tr = e[0][0] + e[1][1] + e[2][2];
  double ee = 0.0;
  for (int i = 0; i < 3; i++)
    for (int j = 0; j < 3; j++) ee += e[i][j] * e[i][j];
  return 0.5 * lambda * tr * tr + mu * ee;
}
