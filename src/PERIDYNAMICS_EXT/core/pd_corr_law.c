/* Classical constitutive laws for the correspondence material. */
#include "pd_corr_law.h"

#include "pd_seth_hill.h"
#include "pd_tensor.h"

#include <math.h>

static double trace(const double s[6])
{
  return s[0] + s[1] + s[2];
}

/* s:s for symmetric tensors */
static double contract(const double a[6], const double b[6])
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + 2.0 * (a[3] * b[3] + a[4] * b[4] + a[5] * b[5]);
}

/* Isotropic elasticity on a strain: T and the energy. */
static double elastic(const pd_corr_material *mat, const double e[6], double T[6])
{
  const double tr = trace(e);
  for (int k = 0; k < 6; k++) T[k] = 2.0 * mat->mu * e[k] + (k < 3 ? mat->lambda * tr : 0.0);
  return 0.5 * mat->lambda * tr * tr + mat->mu * contract(e, e);
}

/* a - log(1 + a) without cancellation at small a (its series) */
static double excess_minus_log1p(double a)
{
  if (fabs(a) > 1e-3) return a - log1p(a);
  double term = a * a, sum = 0.0;
  for (int k = 2; k < 9; k++, term *= -a) sum += term / k;
  return sum;
}

static int neohookean(const pd_corr_material *mat, double m, const double E[6], pd_corr_stress *o)
{
  double e[3], q[9], a[3], c[3], t[3];
  pd_sym_eigen(E, e, q);
  for (int k = 0; k < 3; k++) {
    a[k] = pd_seth_hill_inverse_excess(m, e[k]);  /* c - 1: small strains keep their digits */
    c[k] = 1.0 + a[k];
  }
  if (!(c[0] > 0.0 && c[1] > 0.0 && c[2] > 0.0)) return 0;
  const double logj = 0.5 * (log1p(a[0]) + log1p(a[1]) + log1p(a[2]));
  for (int k = 0; k < 3; k++) {
    /* S_k = 2 d psi/d c_k; T_k = d psi/d e_k = S_k / (2 de_k/dc_k) */
    const double s = (mat->lambda * logj + mat->mu * a[k]) / c[k];  /* (lambda log J - mu)/c + mu */
    t[k] = s / (2.0 * pd_seth_hill_slope(m, c[k]));
  }
  pd_sym_from_eigen(t, q, o->T);
  /* -mu log J + mu/2 (tr C - 3) as mu/2 sum (a - log(1 + a)), each term
   * second order in the strain */
  double shear = 0.0;
  for (int k = 0; k < 3; k++) shear += excess_minus_log1p(a[k]);
  o->energy = 0.5 * mat->lambda * logj * logj + 0.5 * mat->mu * shear;
  return 1;
}

double pd_corr_flow_stress(const pd_corr_material *mat, double eps_p, double rate, double temp)
{
  if (mat->model == PD_CORR_J2) return mat->yield + mat->hardening * eps_p;
  /* (each factor is exactly 1 at eps_p = 0 and rate = 0: the yield check
   * of an atom that never yielded takes no power and no asinh) */
  double y = mat->yield;
  if (eps_p > 0.0) y *= pow(1.0 + eps_p / pow(mat->yield / mat->jc_b, 1.0 / mat->jc_n), mat->jc_n);
  if (rate > 0.0) y *= 1.0 + mat->jc_c * asinh(rate / (2.0 * mat->jc_rate0));
  if (mat->thermal) {
    const double homologous = fmin(fmax((temp - mat->t_room) / (mat->t_melt - mat->t_room), 0.0), 1.0);
    y *= 1.0 - pow(homologous, mat->t_exp);
  }
  return y;
}

/* Radial return: the increment dg of the equivalent plastic strain with
 * q_trial - 3 mu dg = Y(eps_p + dg, dg/dt). Linear hardening in one step;
 * Johnson-Cook by bisection (the residual falls monotonically in dg, and
 * bisection cannot diverge where asinh and the power law are steep). */
static double return_increment(const pd_corr_material *mat, double q_trial, const pd_corr_history *h,
                               double dt)
{
  if (mat->model == PD_CORR_J2) return (q_trial - pd_corr_flow_stress(mat, h->eqps, 0.0, 0.0)) /
      (3.0 * mat->mu + mat->hardening);
  double lo = 0.0, hi = q_trial / (3.0 * mat->mu), dg = 0.5 * hi;
  for (int it = 0; it < 60; it++) {
    const double rate = dt > 0.0 ? dg / dt : 0.0;
    const double r = q_trial - 3.0 * mat->mu * dg - pd_corr_flow_stress(mat, h->eqps + dg, rate, h->temperature);
    if (r > 0.0) lo = dg;
    else hi = dg;
    if (hi - lo <= 1e-14 * hi) break;
    dg = 0.5 * (lo + hi);
  }
  return 0.5 * (lo + hi);
}

static void plastic(const pd_corr_material *mat, const double E[6], pd_corr_history *h, double dt,
                    double rho, pd_corr_stress *o)
{
  double ee[6], dev[6];
  for (int k = 0; k < 6; k++) ee[k] = E[k] - h->plastic[k];
  o->energy = elastic(mat, ee, o->T);
  const double p = trace(o->T) / 3.0;
  for (int k = 0; k < 6; k++) dev[k] = o->T[k] - (k < 3 ? p : 0.0);
  const double q = sqrt(1.5 * contract(dev, dev));
  /* elastic unless beyond the flow stress at rest */
  if (!(q > pd_corr_flow_stress(mat, h->eqps, 0.0, h->temperature))) return;
  const double dg = return_increment(mat, q, h, dt);
  const double scale = 1.0 - 3.0 * mat->mu * dg / q;
  for (int k = 0; k < 6; k++) {
    const double n = 1.5 * dev[k] / q;  /* flow direction */
    h->plastic[k] += dg * n;
    ee[k] -= dg * n;
    o->T[k] = (k < 3 ? p : 0.0) + scale * dev[k];
  }
  const double q_new = scale * q;
  const double work = q_new * dg;  /* T : dE_p */
  h->eqps += dg;
  h->plastic_work += work;
  o->energy = 0.5 * mat->lambda * trace(ee) * trace(ee) + mat->mu * contract(ee, ee);
  const double rate = dt > 0.0 ? dg / dt : 0.0;
  double homologous = 0.0;
  if (mat->thermal) {
    homologous = fmin(fmax((h->temperature - mat->t_room) / (mat->t_melt - mat->t_room), 0.0), 1.0);
    if (rho > 0.0) h->temperature += mat->taylor_quinney * work / (rho * mat->heat_capacity);
  }
  if (mat->damage && h->damage < 1.0) {
    const double triax = q_new > 0.0 ? p / q_new : 0.0;
    double ef = (mat->d[0] + mat->d[1] * exp(-mat->d[2] * triax)) *
        (1.0 + mat->d[3] * log(fmax(rate / mat->jc_rate0, 1.0))) * (1.0 + mat->d[4] * homologous);
    ef = fmax(ef, 1e-12);
    h->damage = fmin(1.0, h->damage + dg / ef);
  }
}

void pd_corr_increment_enter(pd_corr_increment *inc, const double E[6], pd_corr_history *h)
{
  int same = 1;
  for (int k = 0; k < 6; k++) same &= fabs(E[k] - inc->strain[k]) <= 1e-12;
  if (same) {
    *h = inc->start;
    return;
  }
  inc->start = *h;
  for (int k = 0; k < 6; k++) inc->strain[k] = E[k];
}

int pd_corr_law_stress(const pd_corr_material *mat, double m, double E[6], pd_corr_history *h,
                       double dt, double rho, pd_corr_stress *out)
{
  if (mat->plane_stress)
    E[2] = -mat->lambda / (mat->lambda + 2.0 * mat->mu) * (E[0] + E[1]);
  switch (mat->model) {
  case PD_CORR_ELASTIC: out->energy = elastic(mat, E, out->T); break;
  case PD_CORR_NEOHOOKEAN:
    if (!neohookean(mat, m, E, out)) return 0;
    break;
  default: plastic(mat, E, h, dt, rho, out); break;
  }
  for (int k = 0; k < 6; k++)
    if (!isfinite(out->T[k])) return 0;
  return isfinite(out->energy);
}

void pd_corr_second_pk(double m, const double c[3], const double q[9], const double T[6], double S[6])
{
  double t[6], s[6];
  pd_sym_rotate_to(q, T, t);
  static const int row[6] = {0, 1, 2, 0, 0, 1}, col[6] = {0, 1, 2, 1, 2, 2};
  for (int k = 0; k < 6; k++) {
    const double a = c[row[k]], b = c[col[k]];
    /* dE/dC: f'(c) on the diagonal, divided differences off it */
    /* the midpoint slope errs by (a-b)^2 f'''/24, the quotient by round-off
     * over (a-b): 1e-5 balances them near 1e-11 */
    const double slope = fabs(a - b) > 1e-5 * fmax(a, b)
        ? (pd_seth_hill(m, a) - pd_seth_hill(m, b)) / (a - b)
        : pd_seth_hill_slope(m, 0.5 * (a + b));
    s[k] = 2.0 * slope * t[k];
  }
  pd_sym_rotate_from(q, s, S);
}
