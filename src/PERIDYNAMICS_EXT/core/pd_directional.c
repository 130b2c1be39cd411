#include "pd_directional.h"

#include "pd_lattice.h"

#include <math.h>

/* The monomials n^e of one degree, in a fixed order: in 3D e = (a, b, c)
 * for a from the degree down, then b down; in 2D e = (a, degree - a, 0). */
static int monomial_count(int dim, int degree)
{
  return dim == 3 ? (degree + 1) * (degree + 2) / 2 : degree + 1;
}

static void monomial(int dim, int degree, int index, int e[3])
{
  if (dim != 3) {
    e[0] = degree - index;
    e[1] = index;
    e[2] = 0;
    return;
  }
  for (int a = degree; a >= 0; a--) {
    const int row = degree - a + 1;    /* the monomials with this a */
    if (index < row) {
      e[0] = a;
      e[1] = degree - a - index;
      e[2] = index;
      return;
    }
    index -= row;
  }
}

static int monomial_index(int dim, const int e[3])
{
  if (dim != 3) return e[1];
  const int degree = e[0] + e[1] + e[2];
  int index = 0;
  for (int a = degree; a > e[0]; a--) index += degree - a + 1;
  return index + e[2];
}

/* The powers 0 .. degree of each component of n (a monomial is then
 * two products: the fits of a 3D body's families took a tenth of a
 * 600-step run with each monomial multiplied out). */
static void component_powers(const double n[3], int degree, double p[3][9])
{
  for (int k = 0; k < 3; k++) {
    p[k][0] = 1.0;
    for (int q = 1; q <= degree; q++) p[k][q] = p[k][q - 1] * n[k];
  }
}

int pd_directional_terms(int dim)
{
  return monomial_count(dim, 4);
}

int pd_directional_moments(int dim)
{
  return 1 + monomial_count(dim, 8);
}

void pd_directional_monomials(int dim, const double n[3], double *m)
{
  double p[3][9];
  component_powers(n, 8, p);
  /* monomial()'s order walked in place (found one by one with monomial(),
   * a loop each, the sums were most of the correction's set-up: 4.7x) */
  if (dim != 3) {
    for (int i = 0; i <= 8; i++) m[i] = p[0][8 - i] * p[1][i] * p[2][0];
    return;
  }
  for (int a = 8; a >= 0; a--)
    for (int c = 0; c <= 8 - a; c++) *m++ = p[0][a] * p[1][8 - a - c] * p[2][c];
}

void pd_directional_accumulate(int dim, const double *m, double mu, double *moments)
{
  moments[0] += mu;
  const int count = monomial_count(dim, 8);
  for (int k = 0; k < count; k++) moments[1 + k] += mu * m[k];
}

void pd_directional_add(int dim, const double n[3], double mu, double *moments)
{
  double m[PD_DIRECTIONAL_MAX_MOMENTS - 1];
  pd_directional_monomials(dim, n, m);
  pd_directional_accumulate(dim, m, mu, moments);
}

void pd_directional_signatures(const double n[3], double s[PD_DIRECTIONAL_SIGNATURES])
{
  /* two directions with unrelated irrational components (a family's sums
   * of mu (a.n)^8 are linear in its eighth moments, and weigh every one) */
  static const double a[PD_DIRECTIONAL_SIGNATURES][3] = {{0.5772156649015329, 0.3183098861837907, 0.7548776662466927},
                                                         {0.4142135623730950, 0.7320508075688772, -0.2360679774997897}};
  for (int k = 0; k < PD_DIRECTIONAL_SIGNATURES; k++) {
    const double t = a[k][0] * n[0] + a[k][1] * n[1] + a[k][2] * n[2];
    const double t2 = t * t, t4 = t2 * t2;
    s[k] = t4 * t4;
  }
}

/* The isotropic fourth moment t (I I + 2 sym) at monomial e: 3t for
 * n_x^4, t for n_x^2 n_y^2, 0 for every odd exponent. */
static double isotropic_moment(const int e[3], double t)
{
  if (e[0] % 2 || e[1] % 2 || e[2] % 2) return 0.0;
  return (e[0] == 4 || e[1] == 4 || e[2] == 4) ? 3.0 * t : t;
}

void pd_directional_unit(int dim, double *form)
{
  const int count = pd_directional_terms(dim);
  for (int a = 0; a < count; a++) {
    int e[3];
    monomial(dim, 4, a, e);
    /* (n.n)^2: each n_x^4 once, each n_x^2 n_y^2 twice */
    const double moment = isotropic_moment(e, 1.0);
    form[a] = moment == 3.0 ? 1.0 : 2.0 * moment;
  }
}

int pd_directional_limit(int dim, double *form, double smallest)
{
  if (!(smallest < PD_DIRECTIONAL_FLOOR)) return 0;
  double unit[PD_DIRECTIONAL_MAX_TERMS];
  pd_directional_unit(dim, unit);
  /* the factor 1 + a (f - 1) is the floor where f is smallest */
  const double a = (1.0 - PD_DIRECTIONAL_FLOOR) / (1.0 - smallest);
  for (int k = 0; k < pd_directional_terms(dim); k++) form[k] = a * form[k] + (1.0 - a) * unit[k];
  return 1;
}

int pd_directional_fit(int dim, const double *moments, double *form)
{
  const int count = pd_directional_terms(dim);
  double g[PD_DIRECTIONAL_MAX_TERMS][PD_DIRECTIONAL_MAX_TERMS + 1];
  const double t = moments[0] / (dim == 3 ? 15.0 : 8.0);
  double scale = 0.0;
  for (int a = 0; a < count; a++) {
    int ea[3];
    monomial(dim, 4, a, ea);
    for (int b = 0; b < count; b++) {
      int eb[3], e[3];
      monomial(dim, 4, b, eb);
      for (int k = 0; k < 3; k++) e[k] = ea[k] + eb[k];
      g[a][b] = moments[1 + monomial_index(dim, e)];
    }
    g[a][count] = isotropic_moment(ea, t);
    scale = fmax(scale, fabs(g[a][a]));
  }
  /* Gaussian elimination with partial pivoting */
  for (int c = 0; c < count; c++) {
    int pivot = c;
    for (int r = c + 1; r < count; r++)
      if (fabs(g[r][c]) > fabs(g[pivot][c])) pivot = r;
    if (!(fabs(g[pivot][c]) > 1e-10 * scale)) {
      pd_directional_unit(dim, form);
      return -1;
    }
    for (int k = 0; k <= count; k++) {
      const double swap = g[c][k];
      g[c][k] = g[pivot][k];
      g[pivot][k] = swap;
    }
    for (int r = c + 1; r < count; r++) {
      const double f = g[r][c] / g[c][c];
      for (int k = c; k <= count; k++) g[r][k] -= f * g[c][k];
    }
  }
  for (int a = count - 1; a >= 0; a--) {
    double s = g[a][count];
    for (int k = a + 1; k < count; k++) s -= g[a][k] * form[k];
    form[a] = s / g[a][a];
  }
  return 0;
}

double pd_directional_factor(int dim, const double *form, const double n[3])
{
  double f[2];
  pd_directional_factors(dim, form, form, n, f);
  return f[0];
}

void pd_directional_factors(int dim, const double *form_a, const double *form_b, const double n[3],
                            double f[2])
{
  double p[3][9];
  component_powers(n, 4, p);
  double fa = 0.0, fb = 0.0;
  /* monomial()'s order walked in place, the same products in the same
   * order (found one by one with monomial(), the factors were most of the
   * correction's passes) */
  int a = 0;
  if (dim != 3)
    for (int i = 0; i <= 4; i++, a++) {
      const double v = p[0][4 - i] * p[1][i] * p[2][0];
      fa += form_a[a] * v;
      fb += form_b[a] * v;
    }
  else
    for (int x = 4; x >= 0; x--)
      for (int z = 0; z <= 4 - x; z++, a++) {
        const double v = p[0][x] * p[1][4 - x - z] * p[2][z];
        fa += form_a[a] * v;
        fb += form_b[a] * v;
      }
  f[0] = fa;
  f[1] = fb;
}

int pd_family_directional_form(const pd_family *f, int power, double *form)
{
  double moments[PD_DIRECTIONAL_MAX_MOMENTS] = {0.0};
  for (int b = 0; b < f->n; b++) {
    const pd_family_bond *bd = &f->bond[b];
    const double n[3] = {bd->xi[0] / bd->r, bd->xi[1] / bd->r, bd->xi[2] / bd->r};
    pd_directional_add(f->dim, n, bd->w * f->volume * pow(bd->r, power), moments);
  }
  return pd_directional_fit(f->dim, moments, form);
}
