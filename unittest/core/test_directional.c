/* Directional correction (core/pd_directional.c): the fitted quartic form
 * makes a family's fourth moment isotropic with its trace kept; an
 * isotropic family (the hexagonal lattice) gets f = 1; a family too flat to
 * fit says so. */
#include "check.h"
#include "lattice.h"
#include "pd_directional.h"

#include <math.h>

#define MAXB 512

typedef struct family {
  int dim, n;
  double dir[MAXB][3], mu[MAXB];
} family;

/* Bonds of a lattice family within the horizon delta (in spacings): simple
 * cubic, square, or hexagonal (2D, basis (1, 0), (1/2, sqrt 3 / 2));
 * stiffness share mu = |xi|^power, jittered by up to 'jitter' spacings. */
static family lattice_family(const char *kind, double delta, int power, double jitter)
{
  family f = {kind[0] == 's' && kind[1] == 'c' ? 3 : 2, 0, {{0}}, {0}};
  const int r = (int) delta + 2, zr = f.dim == 3 ? r : 0;
  unsigned seed = 7;
  for (int a = -r; a <= r; a++)
    for (int b = -r; b <= r; b++)
      for (int c = -zr; c <= zr; c++) {
        if (!a && !b && !c) continue;
        double x[3] = {a, b, c};
        if (kind[0] == 'h') {
          x[0] = a + 0.5 * b;
          x[1] = b * sqrt(3.0) / 2.0;
        }
        for (int k = 0; k < f.dim; k++) x[k] += jitter * urand(&seed);
        const double len = sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
        if (len > delta || f.n == MAXB) continue;
        for (int k = 0; k < 3; k++) f.dir[f.n][k] = x[k] / len;
        f.mu[f.n++] = pow(len, power);
      }
  return f;
}

/* Largest deviation of the corrected fourth moment from t (I I + 2 sym),
 * over all components, relative to t; and the corrected trace / the trace. */
static double anisotropy(const family *f, const double *form, double *trace_ratio)
{
  double m4[3][3][3][3] = {{{{0}}}}, trace = 0.0, corrected = 0.0;
  for (int b = 0; b < f->n; b++) {
    const double *n = f->dir[b], w = f->mu[b] * (form ? pd_directional_factor(f->dim, form, n) : 1.0);
    trace += f->mu[b];
    corrected += w;
    for (int i = 0; i < 3; i++)
      for (int j = 0; j < 3; j++)
        for (int k = 0; k < 3; k++)
          for (int l = 0; l < 3; l++) m4[i][j][k][l] += w * n[i] * n[j] * n[k] * n[l];
  }
  const double t = corrected / (f->dim == 3 ? 15.0 : 8.0);
  double worst = 0.0;
  for (int i = 0; i < f->dim; i++)
    for (int j = 0; j < f->dim; j++)
      for (int k = 0; k < f->dim; k++)
        for (int l = 0; l < f->dim; l++) {
          const double iso = t * ((i == j) * (k == l) + (i == k) * (j == l) + (i == l) * (j == k));
          worst = fmax(worst, fabs(m4[i][j][k][l] - iso) / t);
        }
  *trace_ratio = corrected / trace;
  return worst;
}

static double fitted(const family *f, double *form)
{
  double moments[PD_DIRECTIONAL_MAX_MOMENTS] = {0};
  for (int b = 0; b < f->n; b++) pd_directional_add(f->dim, f->dir[b], f->mu[b], moments);
  return pd_directional_fit(f->dim, moments, form);
}

int main(void)
{
  check_true("3D: 15 terms, 46 sums", pd_directional_terms(3) == 15 && pd_directional_moments(3) == 46);
  check_true("2D: 5 terms, 10 sums", pd_directional_terms(2) == 5 && pd_directional_moments(2) == 10);

  /* f = 1 as a form: 1 in every direction */
  double unit[PD_DIRECTIONAL_MAX_TERMS];
  const double oblique[3] = {0.48, -0.6, 0.64};    /* unit */
  pd_directional_unit(3, unit);
  check_rel("unit form, 3D: f = 1", pd_directional_factor(3, unit, oblique), 1.0, 1e-15);
  pd_directional_unit(2, unit);
  check_rel("unit form, 2D: f = 1", pd_directional_factor(2, unit, (double[3]){0.6, 0.8, 0.0}), 1.0, 1e-15);

  /* lattices and a jittered family, both stiffness shares: anisotropic
   * before (their shear moduli differ by direction), isotropic after to
   * round-off, trace kept */
  const struct {
    const char *kind;
    double delta, jitter, before;
  } cases[] = {{"sc", 3.0, 0.0, 0.05}, {"sc", 4.0, 0.0, 0.01}, {"square", 3.0, 0.0, 0.02},
               {"sc", 3.0, 0.25, 0.05}, {"square", 3.0, 0.25, 0.02}};
  for (int c = 0; c < 5; c++)
    for (int power = 1; power <= 2; power++) {
      family f = lattice_family(cases[c].kind, cases[c].delta, power, cases[c].jitter);
      double form[PD_DIRECTIONAL_MAX_TERMS], ratio;
      char what[160];
      snprintf(what, sizeof what, "%s%s, %g spacings, |xi|^%d", cases[c].kind, cases[c].jitter > 0 ? " jittered" : "",
               cases[c].delta, power);
      const double raw = anisotropy(&f, NULL, &ratio);
      char line[200];
      snprintf(line, sizeof line, "%s: anisotropic before (%.3g)", what, raw);
      check_true(line, raw > cases[c].before);
      check_true("fit succeeds", fitted(&f, form) == 0);
      snprintf(line, sizeof line, "%s: isotropic after", what);
      check_rel(line, anisotropy(&f, form, &ratio), 0.0, 1e-11);
      snprintf(line, sizeof line, "%s: trace kept", what);
      check_rel(line, ratio, 1.0, 1e-12);
      double lo = INFINITY;
      for (int b = 0; b < f.n; b++) lo = fmin(lo, pd_directional_factor(f.dim, form, f.dir[b]));
      snprintf(line, sizeof line, "%s: every factor positive (smallest %.3f)", what, lo);
      check_true(line, lo > 0.3);
      /* two forms at once (a bond's ends): each as alone, to the bit */
      double unit_form[PD_DIRECTIONAL_MAX_TERMS];
      pd_directional_unit(f.dim, unit_form);
      int same = 1;
      for (int b = 0; b < f.n; b++) {
        double two[2];
        pd_directional_factors(f.dim, form, unit_form, f.dir[b], two);
        same &= two[0] == pd_directional_factor(f.dim, form, f.dir[b]) &&
                two[1] == pd_directional_factor(f.dim, unit_form, f.dir[b]);
      }
      snprintf(line, sizeof line, "%s: two forms at once as alone", what);
      check_true(line, same);
    }

  /* the hexagonal lattice is isotropic already: f = 1 */
  family hex = lattice_family("hex", 3.0, 2, 0.0);
  double form[PD_DIRECTIONAL_MAX_TERMS], ratio;
  check_rel("hex: isotropic before", anisotropy(&hex, NULL, &ratio), 0.0, 1e-12);
  check_true("hex: fit succeeds", fitted(&hex, form) == 0);
  for (int b = 0; b < hex.n; b += 5)
    check_rel("hex: f = 1", pd_directional_factor(2, form, hex.dir[b]), 1.0, 1e-11);

  /* a form that would make a bond negative is moved toward f = 1 until its
   * smallest factor on the family is the floor; one above it is kept */
  double bent[PD_DIRECTIONAL_MAX_TERMS];
  pd_directional_unit(2, bent);
  bent[0] -= 1.5;    /* f = 1 - 1.5 n_x^4: -0.5 along x, 1 along y */
  const double along_x[3] = {1.0, 0.0, 0.0}, along_y[3] = {0.0, 1.0, 0.0};
  check_true("limit: a form with a negative factor is limited",
             pd_directional_limit(2, bent, pd_directional_factor(2, bent, along_x)) == 1);
  check_rel("limit: its smallest factor is the floor", pd_directional_factor(2, bent, along_x),
            PD_DIRECTIONAL_FLOOR, 1e-14);
  check_rel("limit: where it was 1 it stays 1", pd_directional_factor(2, bent, along_y), 1.0, 1e-14);
  double kept[PD_DIRECTIONAL_MAX_TERMS];
  pd_directional_unit(2, kept);
  kept[0] -= 0.5;    /* smallest 0.5: above the floor */
  check_true("limit: a form above the floor is kept", pd_directional_limit(2, kept, 0.5) == 0 &&
             fabs(pd_directional_factor(2, kept, along_x) - 0.5) < 1e-15);

  /* bonds on two lines only: no quartic form can be fitted */
  family flat = {3, 4, {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}}, {1, 1, 1, 1}};
  check_true("two lines: singular", fitted(&flat, form) == -1);
  check_rel("two lines: f = 1", pd_directional_factor(3, form, oblique), 1.0, 1e-15);
  return check_summary();
}
