/* Fourier symbols and effective elastic tensors of the linearized
 * materials (the derivation: doc/exact_waves.md). */
#include "pd_dispersion.h"

#include <math.h>
#include <string.h>

pd_linear_model pd_linear_pmb_K(double K, double horizon)
{
  pd_linear_model m = {PD_LINEAR_PMB, 3, pd_pmb_micromodulus_3d(K, horizon), 0.0, 0.0, 0.0};
  return m;
}

pd_linear_model pd_linear_pmb_E(pd_dimension dim, double E, double horizon, double thickness)
{
  pd_linear_model m = {PD_LINEAR_PMB, pd_dimension_count(dim),
                       pd_pmb_micromodulus(dim, E, horizon, thickness), 0.0, 0.0, 0.0};
  return m;
}

pd_linear_model pd_linear_pmb_c(int dim, double c)
{
  pd_linear_model m = {PD_LINEAR_PMB, dim, c, 0.0, 0.0, 0.0};
  return m;
}

/* as pair_pd_ordinary.cpp: lambda_bar, mu_bar per type, N = d / m with m
 * the complete family's weighted volume */
pd_linear_model pd_linear_ordinary(pd_dimension dim, const pd_elastic *e, const pd_family *f)
{
  const pd_lame l = pd_ordinary_lame(dim, e);
  const double wv = pd_family_weighted_volume(f);
  const int d = pd_dimension_count(dim);
  pd_linear_model m = {PD_LINEAR_ORDINARY, d, 0.0, l.lambda, l.mu, wv > 0.0 ? d / wv : 0.0};
  return m;
}

pd_linear_model pd_linear_classical(pd_dimension dim, const pd_elastic *e)
{
  const double lambda = dim == PD_PLANE_STRESS ? e->E * e->nu / (1.0 - e->nu * e->nu)
                                               : e->K - 2.0 * e->G / 3.0;
  pd_linear_model m = {PD_LINEAR_CLASSICAL, pd_dimension_count(dim), 0.0, lambda, e->G, 0.0};
  return m;
}

pd_linear_model pd_linear_classical_1d(double E)
{
  pd_linear_model m = {PD_LINEAR_CLASSICAL, 1, 0.0, E, 0.0, 0.0};
  return m;
}

static void add_dyad(double A[9], const double a[3], const double b[3], double w)
{
  for (int i = 0; i < 3; i++)
    for (int j = 0; j < 3; j++) A[3 * i + j] += w * a[i] * b[j];
}

void pd_symbol(const pd_linear_model *m, const pd_family *f, const double k[3], double A[9])
{
  memset(A, 0, 9 * sizeof(double));
  if (m->kind == PD_LINEAR_CLASSICAL) {
    const double k2 = k[0] * k[0] + k[1] * k[1] + k[2] * k[2];
    add_dyad(A, k, k, m->lambda + m->mu);
    for (int i = 0; i < m->dim; i++) A[4 * i] += m->mu * k2;
  } else {
    /* bond part: c w V (1 - cos)/r for PMB, 4 mu N w V (1 - cos)/r^2 for
     * ordinary; s for the ordinary's dilatation */
    const int pmb = m->kind == PD_LINEAR_PMB;
    const double scale = pmb ? m->c : 4.0 * m->mu * m->norm;
    double s[3] = {0.0, 0.0, 0.0};
    for (int b = 0; b < f->n; b++) {
      const pd_family_bond *bd = f->bond + b;
      const double phi = k[0] * bd->xi[0] + k[1] * bd->xi[1] + k[2] * bd->xi[2];
      const double e[3] = {bd->xi[0] / bd->r, bd->xi[1] / bd->r, bd->xi[2] / bd->r};
      const double wv = bd->w * f->volume;
      /* 2 sin^2(phi/2): 1 - cos without cancellation at small k */
      const double sh = sin(0.5 * phi), one_minus_cos = 2.0 * sh * sh;
      add_dyad(A, e, e, scale * wv * one_minus_cos / (pmb ? bd->r : bd->r * bd->r));
      if (!pmb)
        for (int c = 0; c < 3; c++) s[c] += wv * sin(phi) / bd->r * e[c];
    }
    if (!pmb) add_dyad(A, s, s, m->lambda * m->norm * m->norm);
  }
  /* exactly symmetric */
  for (int i = 0; i < 3; i++)
    for (int j = i + 1; j < 3; j++) A[3 * i + j] = A[3 * j + i] = 0.5 * (A[3 * i + j] + A[3 * j + i]);
}

/* C += w v v^T for Mandel vectors v (pd_tensor.h's packed upper triangle) */
static void add_outer(double C[PD_SYM4], const double v[6], double w)
{
  int p = 0;
  for (int r = 0; r < 6; r++)
    for (int c = r; c < 6; c++) C[p++] += w * v[r] * v[c];
}

void pd_effective_tensor(const pd_linear_model *m, const pd_family *f, double C[PD_SYM4])
{
  memset(C, 0, PD_SYM4 * sizeof(double));
  static const int plane[3] = {0, 1, 3}, all[6] = {0, 1, 2, 3, 4, 5};
  if (m->kind == PD_LINEAR_CLASSICAL) {
    const double eye[6] = {1.0, m->dim > 1, m->dim > 2, 0.0, 0.0, 0.0};
    double v[6];
    pd_mandel_from_sym(eye, v);
    add_outer(C, v, m->lambda);
    /* 2 mu times the identity on the strain components of dim */
    const int n = m->dim == 3 ? 6 : m->dim == 2 ? 3 : 1;
    const int *ix = m->dim == 3 ? all : plane;
    for (int a = 0; a < n; a++) {
      double u[6] = {0, 0, 0, 0, 0, 0};
      u[ix[a]] = 1.0;
      add_outer(C, u, 2.0 * m->mu);
    }
    return;
  }
  const int pmb = m->kind == PD_LINEAR_PMB;
  double M[6] = {0, 0, 0, 0, 0, 0};
  for (int b = 0; b < f->n; b++) {
    const pd_family_bond *bd = f->bond + b;
    const double e[3] = {bd->xi[0] / bd->r, bd->xi[1] / bd->r, bd->xi[2] / bd->r};
    const double wv = bd->w * f->volume;
    pd_sym4_add_dyad(C, e, pmb ? 0.5 * m->c * wv * bd->r : 2.0 * m->mu * m->norm * wv);
    const double ee[6] = {e[0] * e[0], e[1] * e[1], e[2] * e[2], e[0] * e[1], e[0] * e[2], e[1] * e[2]};
    for (int c = 0; c < 6; c++) M[c] += wv * ee[c];
  }
  if (!pmb) {
    double v[6];
    pd_mandel_from_sym(M, v);
    add_outer(C, v, m->lambda * m->norm * m->norm);
  }
}

void pd_acoustic_tensor(const double C[PD_SYM4], const double k[3], double Q[9])
{
  /* column c: C : sym(e_c (x) k) = C_ijcl k_l, contracted with k_j */
  for (int c = 0; c < 3; c++) {
    double E[9] = {0, 0, 0, 0, 0, 0, 0, 0, 0}, s[6], out[6], o[9];
    for (int l = 0; l < 3; l++) {
      E[3 * c + l] += 0.5 * k[l];
      E[3 * l + c] += 0.5 * k[l];
    }
    pd_full_to_sym(E, s);
    pd_sym4_apply(C, s, out);
    pd_sym_to_full(out, o);
    for (int i = 0; i < 3; i++) Q[3 * i + c] = o[3 * i] * k[0] + o[3 * i + 1] * k[1] + o[3 * i + 2] * k[2];
  }
}

double pd_strain_energy(const double C[PD_SYM4], const double eps[6])
{
  double s[6];
  pd_sym4_apply(C, eps, s);
  return 0.5 * (s[0] * eps[0] + s[1] * eps[1] + s[2] * eps[2] +
                2.0 * (s[3] * eps[3] + s[4] * eps[4] + s[5] * eps[5]));
}

static double mode_error(const double C[PD_SYM4], const double Cref[PD_SYM4], const double eps[6])
{
  const double ref = pd_strain_energy(Cref, eps);
  return ref != 0.0 ? pd_strain_energy(C, eps) / ref - 1.0 : 0.0;
}

pd_moduli_error pd_moduli_error_of(const double C[PD_SYM4], const double Cref[PD_SYM4], int dim)
{
  const double dil[6] = {1.0, dim > 1, dim > 2, 0.0, 0.0, 0.0};
  const double xxyy[6] = {1.0, -1.0, 0.0, 0.0, 0.0, 0.0};
  const double xy[6] = {0.0, 0.0, 0.0, 1.0, 0.0, 0.0};
  pd_moduli_error e = {mode_error(C, Cref, dil), 0.0, 0.0, 0.0};
  if (dim > 1) {
    e.shear_xx_yy = mode_error(C, Cref, xxyy);
    e.shear_xy = mode_error(C, Cref, xy);
  }
  e.worst = fmax(fabs(e.dilatation), fmax(fabs(e.shear_xx_yy), fabs(e.shear_xy)));
  return e;
}

int pd_lattice_expected_error(const pd_lattice *lat, pd_linear_kind model, pd_dimension dim,
                              const pd_elastic *e, double horizon, double cutoff, double thickness,
                              pd_weight_fn weight, void *ctx, pd_moduli_error *out)
{
  const pd_moduli_error none = {NAN, NAN, NAN, NAN};
  *out = none;
  pd_family f;
  if (model == PD_LINEAR_CLASSICAL || pd_lattice_family(lat, cutoff, thickness, weight, ctx, &f) < 1)
    return -1;
  pd_elastic ref = *e;
  pd_linear_model m;
  if (model == PD_LINEAR_PMB || model == PD_LINEAR_PMB_FAMILY) {
    pd_elastic_from_E_nu(e->E, pd_pmb_poisson(dim), &ref);
    m = pd_linear_pmb_E(dim, e->E, horizon, thickness);
    if (model == PD_LINEAR_PMB_FAMILY)
      m.c *= pd_pmb_moment_continuum(lat->dim, horizon, thickness) / pd_family_moment_sum(&f, 1);
  } else {
    m = pd_linear_ordinary(dim, e, &f);
  }
  const pd_linear_model cl = pd_linear_classical(dim, &ref);
  double C[PD_SYM4], Cref[PD_SYM4];
  pd_effective_tensor(&m, &f, C);
  pd_effective_tensor(&cl, NULL, Cref);
  *out = pd_moduli_error_of(C, Cref, lat->dim);
  pd_family_free(&f);
  return 0;
}
