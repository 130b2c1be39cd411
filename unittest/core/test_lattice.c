/* Lattice families and the Fourier symbol of the linearized materials
 * (pd_lattice.h, pd_dispersion.h): hand-derived dispersion of a chain, the
 * symbol against the package's own force kernels for a small plane wave,
 * symmetry and positivity, the k -> 0 limit against the effective tensor
 * and the classical wave speeds, and the lattice error of the constants. */
#include "check.h"
#include "lattice.h"
#include "model.h"
#include "pd_dispersion.h"

#include <stdlib.h>

static const double H = 5e-4, RHO = 2200.0, K = 14.9e9, G = 7.0e9;

/* 1D chain, PMB, bonds p = 1..P at p h, weight 1, V = h: by hand
 * (u_j = e^{i k x_j}, s = (u_{j+p} - u_j)/(p h) summed over +-p):
 * rho u_tt = sum_p c V [(e^{ikph} - 1) + (e^{-ikph} - 1)]/(p h) u
 *          = -sum_p 2 c V (1 - cos kph)/(p h) u. */
static void chain(void)
{
  pd_lattice lat;
  pd_lattice_make(PD_LATTICE_CHAIN, H, &lat);
  const int P = 3;
  pd_family f;
  const int n = pd_lattice_family(&lat, P * H, 0.0, NULL, NULL, &f);
  check_true("chain: 2P bonds within P spacings", n == 2 * P);
  const double c = 2.0e20;
  const pd_linear_model m = pd_linear_pmb_c(1, c);
  for (int q = 1; q <= 4; q++) {
    const double k[3] = {q * 0.7 / H, 0.0, 0.0};
    double hand = 0.0;
    for (int p = 1; p <= P; p++) hand += 2.0 * c * H * (1.0 - cos(k[0] * p * H)) / (p * H);
    double A[9];
    pd_symbol(&m, &f, k, A);
    char what[80];
    snprintf(what, sizeof what, "chain PMB: A(k) by hand, k h = %.1f", k[0] * H);
    check_rel(what, A[0], hand, 1e-13);
  }
  /* k -> 0: A/k^2 -> c V h^2 sum p = c h^3 P(P+1)/2, against the
   * continuum E = c delta^2 / 2 (c = 2E/delta^2 per unit area): the lattice
   * sum is (P+1)/P of the integral, +33% at P = 3 */
  const double k[3] = {1e-4 / H, 0.0, 0.0};
  double A[9], C[PD_SYM4];
  pd_symbol(&m, &f, k, A);
  const double E_lattice = c * H * H * H * P * (P + 1) / 2.0 / H; /* per unit area: V = h x 1 */
  check_rel("chain PMB: A/k^2 -> c h^2 P(P+1)/2", A[0] / (k[0] * k[0]), E_lattice, 1e-7);
  check_rel("chain PMB: lattice modulus is (P+1)/P of c delta^2/2", E_lattice / (0.5 * c * (P * H) * (P * H)),
            (P + 1.0) / P, 1e-12);
  pd_effective_tensor(&m, &f, C);
  const double eps[6] = {1, 0, 0, 0, 0, 0};
  check_rel("chain PMB: effective tensor = k -> 0 limit", 2.0 * pd_strain_energy(C, eps), E_lattice, 1e-12);
  pd_family_free(&f);
}

/* Families: bond counts of known shells, +-pairs, site volumes. */
static void families(void)
{
  pd_lattice lat;
  pd_family f;
  pd_lattice_make(PD_LATTICE_SC, H, &lat);
  check_true("sc: 122 bonds within 3 spacings (x^2+y^2+z^2 <= 9)", pd_lattice_family(&lat, 3 * H, 0, NULL, NULL, &f) == 122);
  pd_family_free(&f);
  pd_lattice_make(PD_LATTICE_FCC, H, &lat);
  check_rel("fcc: volume a^3/4 per site", lat.volume, H * H * H / 4, 1e-15);
  check_true("fcc: 12 nearest neighbours at a/sqrt2", pd_lattice_family(&lat, lat.nearest, 0, NULL, NULL, &f) == 12);
  pd_family_free(&f);
  pd_lattice_make(PD_LATTICE_HEX, H, &lat);
  check_rel("hex: area sqrt3/2 a^2 per site", lat.volume, sqrt(3.0) / 2 * H * H, 1e-15);
  check_true("hex: 6 nearest neighbours at a", pd_lattice_family(&lat, H, 0, NULL, NULL, &f) == 6);
  pd_family_free(&f);
  check_true("hex: 18 neighbours within 2a", pd_lattice_family(&lat, 2 * H, 0, NULL, NULL, &f) == 18);
  pd_family_free(&f);
  pd_lattice_make(PD_LATTICE_SQ, H, &lat);
  check_true("sq: 28 bonds within 3 spacings", pd_lattice_family(&lat, 3 * H, 0, NULL, NULL, &f) == 28);
  pd_family_free(&f);
}

/* The symbol is the package's own linearized force: a plane wave of tiny
 * amplitude u = a cos(k.(x - x_c)) n on a block whose centre sees complete
 * families two horizons deep; the force density at the centre is
 * -a A(k) n to O(a k) (geometric nonlinearity). */
static void against_kernels(const char *name, int dim, int ordinary, pd_influence_kind kind,
                            pd_dimension pdim, double order)
{
  /* off the shell at 3h: which bonds at exactly 3h exist is round-off */
  const double delta = 3.015 * H;
  const int n = 13; /* 4 * 3 + 1: centre's partners' families complete */
  lattice l = lattice_make(dim, n, H, delta, ordinary ? (int) kind : -1);
  const int ctr = lattice_center(&l);
  pd_lattice lat;
  pd_lattice_make(dim == 2 ? PD_LATTICE_SQ : PD_LATTICE_SC, H, &lat);
  pd_influence_weight iw = {kind, dim, delta};
  pd_family fam;
  pd_lattice_family(&lat, delta, 1.0, ordinary ? pd_influence_weight_fn : NULL, &iw, &fam);
  pd_elastic e;
  pd_elastic_from_K_G(K, G, &e);
  if (dim == 2) pd_elastic_from_E_nu(3.5e9, 0.35, &e);
  pd_linear_model m = ordinary ? pd_linear_ordinary(pdim, &e, &fam)
                               : (dim == 3 ? pd_linear_pmb_K(K, delta) : pd_linear_pmb_E(pdim, e.E, delta, 1.0));
  const double kv[3] = {0.9 / H, -0.4 / H, dim == 3 ? 0.6 / H : 0.0};
  const double dir[3] = {0.48, 0.6, dim == 3 ? 0.64 : 0.0};
  const double amp = 1e-7 * H; /* strain 1e-7: nonlinearity 1e-7, round-off of x0 + u 1e-8 */
  double *x = malloc(sizeof(double) * 3 * l.natoms), *f = malloc(sizeof(double) * 3 * l.natoms);
  double *mfix = malloc(sizeof(double) * l.natoms);
  const double wv = pd_family_weighted_volume(&fam);
  for (int a = 0; a < l.natoms; a++) {
    double ph = 0.0;
    for (int c = 0; c < 3; c++) ph += kv[c] * (l.x0[3 * a + c] - l.x0[3 * ctr + c]);
    for (int c = 0; c < 3; c++) x[3 * a + c] = l.x0[3 * a + c] + amp * cos(ph) * dir[c];
    mfix[a] = wv; /* the complete family's, as pd/ordinary normalizes */
  }
  if (ordinary) ordinary_eval_full(&l, m.lambda, m.mu, order, mfix, NULL, NULL, x, f, NULL);
  else pmb_eval(&l, m.c, x, f, NULL);
  double A[9];
  pd_symbol(&m, &fam, kv, A);
  double scale = 0.0;
  for (int c = 0; c < 3; c++) {
    const double want = -amp * (A[3 * c] * dir[0] + A[3 * c + 1] * dir[1] + A[3 * c + 2] * dir[2]);
    scale = fmax(scale, fabs(want));
  }
  for (int c = 0; c < dim; c++) {
    const double want = -amp * (A[3 * c] * dir[0] + A[3 * c + 1] * dir[1] + A[3 * c + 2] * dir[2]);
    char what[120];
    snprintf(what, sizeof what, "%s: kernel force %c = -a A(k) n", name, "xyz"[c]);
    /* relative to the largest component */
    check_rel(what, f[3 * ctr + c] / scale, want / scale, 1e-5);
  }
  free(x);
  free(f);
  free(mfix);
  pd_family_free(&fam);
  lattice_free(&l);
}

/* A symmetric, positive semi-definite over the Brillouin zone. */
static void symmetry_positivity(const char *name, const pd_linear_model *m, const pd_family *f, double h)
{
  double asym = 0.0, lmin = INFINITY, lmax = 0.0;
  unsigned seed = 7;
  for (int t = 0; t < 200; t++) {
    double k[3];
    for (int c = 0; c < 3; c++) k[c] = c < m->dim ? PD_PI / h * urand(&seed) : 0.0;
    double A[9], l[3], q[9];
    pd_symbol(m, f, k, A);
    for (int i = 0; i < 3; i++)
      for (int j = 0; j < 3; j++) asym = fmax(asym, fabs(A[3 * i + j] - A[3 * j + i]));
    const double s[6] = {A[0], A[4], A[8], A[1], A[2], A[5]};
    pd_sym_eigen(s, l, q);
    for (int i = 0; i < m->dim; i++) {
      lmin = fmin(lmin, l[i]);
      lmax = fmax(lmax, l[i]);
    }
  }
  char what[120];
  snprintf(what, sizeof what, "%s: A(k) symmetric", name);
  check_true(what, asym == 0.0);
  snprintf(what, sizeof what, "%s: A(k) positive (smallest eigenvalue %.3g of largest %.3g)", name, lmin, lmax);
  check_true(what, lmin > 0.0);
}

/* k -> 0: A(k)/|k|^2 -> the acoustic tensor of the effective C (to
 * O((k delta)^2)); its speeds against the classical ones of the constants
 * the package calibrates to, whose gap is the lattice error of the
 * constants (stated). Returns the moduli errors. */
static pd_moduli_error long_waves(const char *name, const pd_linear_model *m, const pd_family *f,
                                  pd_dimension pdim, const pd_elastic *e, double delta,
                                  double want_long, double want_shear, double tol)
{
  double C[PD_SYM4], Cref[PD_SYM4], A[9], Q[9];
  pd_effective_tensor(m, f, C);
  const pd_linear_model cl = pd_linear_classical(pdim, e);
  pd_effective_tensor(&cl, NULL, Cref);
  const double dirs[2][3] = {{1, 0, 0}, {0.6, 0.8, 0}};
  char what[160];
  for (int d = 0; d < 2; d++) {
    const double kk = 1e-4 / delta;
    const double k[3] = {kk * dirs[d][0], kk * dirs[d][1], 0.0};
    pd_symbol(m, f, k, A);
    pd_acoustic_tensor(C, k, Q);
    double err = 0.0, sc = 0.0;
    for (int i = 0; i < 9; i++) {
      err = fmax(err, fabs(A[i] - Q[i]));
      sc = fmax(sc, fabs(Q[i]));
    }
    snprintf(what, sizeof what, "%s: A(k) -> C k k as k -> 0 (direction %d)", name, d);
    check_rel(what, err / sc, 0.0, 1e-7);
  }
  /* along x: longitudinal sqrt(C_xxxx/rho), transverse sqrt(C_xyxy/rho) */
  const double kx[3] = {1.0, 0.0, 0.0};
  pd_acoustic_tensor(C, kx, Q);
  const double cl_pd = sqrt(Q[0] / RHO), ct_pd = sqrt(Q[4] / RHO);
  const double cl_classic = pd_longitudinal_speed(pdim, e, RHO), ct_classic = sqrt(e->G / RHO);
  snprintf(what, sizeof what, "%s: longitudinal speed / classical - 1 (lattice error)", name);
  check_rel(what, cl_pd / cl_classic - 1.0, want_long, tol / fabs(want_long ? want_long : 1.0));
  snprintf(what, sizeof what, "%s: shear speed along x / classical - 1 (lattice error)", name);
  check_rel(what, ct_pd / ct_classic - 1.0, want_shear, tol / fabs(want_shear ? want_shear : 1.0));
  const pd_moduli_error me = pd_moduli_error_of(C, Cref, m->dim);
  printf("     %s: energy errors: dilatation %+.4f, shear xx=-yy %+.4f, shear xy %+.4f\n", name,
         me.dilatation, me.shear_xx_yy, me.shear_xy);
  return me;
}

static void limits(void)
{
  pd_lattice sc, sq, fcc;
  pd_lattice_make(PD_LATTICE_SC, H, &sc);
  pd_lattice_make(PD_LATTICE_SQ, H, &sq);
  pd_lattice_make(PD_LATTICE_FCC, H * cbrt(4.0), &fcc); /* same volume per site */
  pd_elastic e3, epmb3, e2, epmb2;
  pd_elastic_from_K_G(K, G, &e3);
  pd_elastic_from_K_G(K, 0.6 * K, &epmb3);                  /* nu = 1/4 */
  pd_elastic_from_E_nu(3.5e9, 0.35, &e2);
  pd_elastic_from_E_nu(3.5e9, 1.0 / 3.0, &epmb2);           /* plane stress PMB */
  pd_family f;
  pd_moduli_error me;

  /* The lattice errors at delta = 3h (lattice sums, stated here as
   * regression values to 1e-3 absolute in the speed ratio).
   * PMB, sc: the sum of c V r e e e e over the 122 bonds against its
   * integral (MS07 eq. 18): dilatation +12.1%, shear xy +21.8%, xx=-yy
   * -2.4%; longitudinal speed along x +2.8%, shear speed +10.3%. */
  const double d3 = 3.0 * H;
  pd_lattice_family(&sc, d3, 1.0, NULL, NULL, &f);
  pd_linear_model m = pd_linear_pmb_K(K, d3);
  symmetry_positivity("PMB sc 3h", &m, &f, H);
  const pd_moduli_error pmb3 = long_waves("PMB sc 3h", &m, &f, PD_3D, &epmb3, d3, 0.0278, 0.1034, 1e-3);
  pd_family_free(&f);

  /* ordinary, sc, 1/|xi| (the 3D default), delta = 3h: dilatation exact
   * (discrete normalization), shear xx=-yy +1.5% (THEORY.md), xy -1.0%;
   * speeds along x +0.30% (longitudinal), -0.51% (shear) */
  pd_influence_weight iw = {PD_INFLUENCE_INVERSE, 3, d3};
  pd_lattice_family(&sc, d3, 1.0, pd_influence_weight_fn, &iw, &f);
  m = pd_linear_ordinary(PD_3D, &e3, &f);
  symmetry_positivity("ordinary sc 3h inverse", &m, &f, H);
  me = long_waves("ordinary sc 3h inverse", &m, &f, PD_3D, &e3, d3, 0.00296, -0.00515, 1e-3);
  check_rel("ordinary sc 3h inverse: dilatation exact", me.dilatation, 0.0, 1e-12);
  pd_family_free(&f);
  /* the one-call form a setup report uses gives the same */
  pd_moduli_error one;
  pd_lattice_expected_error(&sc, PD_LINEAR_ORDINARY, PD_3D, &e3, d3, d3, 1.0, pd_influence_weight_fn, &iw, &one);
  check_rel("pd_lattice_expected_error: ordinary sc 3h inverse, shear xx=-yy", one.shear_xx_yy, me.shear_xx_yy, 1e-14);
  pd_lattice_expected_error(&sc, PD_LINEAR_PMB, PD_3D, &e3, d3, d3, 1.0, NULL, NULL, &one);
  check_rel("pd_lattice_expected_error: PMB sc 3h, dilatation (+12.1%)", one.dilatation, pmb3.dilatation, 1e-12);

  /* 2D plane stress, square, constant influence (the 2D default): shears
   * +-6.3% (as measured on strained blocks), speeds along x +1.0%, -3.2% */
  iw.kind = PD_INFLUENCE_CONSTANT, iw.dim = 2;
  pd_lattice_family(&sq, d3, 1.0, pd_influence_weight_fn, &iw, &f);
  m = pd_linear_ordinary(PD_PLANE_STRESS, &e2, &f);
  symmetry_positivity("ordinary sq 3h plane stress", &m, &f, H);
  me = long_waves("ordinary sq 3h plane stress", &m, &f, PD_PLANE_STRESS, &e2, d3, 0.0102, -0.0319, 1e-3);
  check_rel("ordinary sq 3h plane stress: shear xy -6.3%", me.shear_xy, -0.0629, 0.01);
  check_rel("ordinary sq 3h plane stress: dilatation exact", me.dilatation, 0.0, 1e-12);
  pd_family_free(&f);

  /* continuum limit: the calibration is right when the lattice error
   * goes away; it falls as the cut cells at the horizon weigh less
   * (O(h/delta)): 2.4% at 12h, a fifth of 3h's */
  const double d12 = 12.0 * H;
  pd_lattice_family(&sc, d12, 1.0, NULL, NULL, &f);
  m = pd_linear_pmb_K(K, d12);
  me = long_waves("PMB sc 12h", &m, &f, PD_3D, &epmb3, d12, -0.0098, -0.0050, 1e-3);
  check_true("PMB sc: worst energy error at 12h below 3% and a fifth of 3h's",
             me.worst < 0.03 && me.worst < 0.2 * pmb3.worst);
  pd_family_free(&f);

  /* fcc and hex: symmetric, positive; hex's 4th-order tensors are
   * isotropic in the plane, so both shears err alike */
  pd_lattice_family(&fcc, d3, 1.0, NULL, NULL, &f);
  m = pd_linear_pmb_K(K, d3);
  symmetry_positivity("PMB fcc", &m, &f, fcc.nearest);
  pd_family_free(&f);
  pd_lattice hex;
  pd_lattice_make(PD_LATTICE_HEX, H, &hex);
  pd_lattice_family(&hex, d3, 1.0, NULL, NULL, &f);
  m = pd_linear_pmb_E(PD_PLANE_STRESS, epmb2.E, d3, 1.0);
  symmetry_positivity("PMB hex plane stress", &m, &f, hex.nearest);
  double Ch[PD_SYM4], Cr[PD_SYM4];
  pd_effective_tensor(&m, &f, Ch);
  const pd_linear_model cl = pd_linear_classical(PD_PLANE_STRESS, &epmb2);
  pd_effective_tensor(&cl, NULL, Cr);
  me = pd_moduli_error_of(Ch, Cr, 2);
  printf("     PMB hex 3a: energy errors: dilatation %+.4f, shear xx=-yy %+.4f, shear xy %+.4f\n",
         me.dilatation, me.shear_xx_yy, me.shear_xy);
  check_rel("PMB hex: shear errors equal (isotropic in the plane)", 1.0 + me.shear_xx_yy, 1.0 + me.shear_xy, 1e-12);
  pd_family_free(&f);
}

int main(void)
{
  chain();
  families();
  against_kernels("PMB sc", 3, 0, PD_INFLUENCE_CONSTANT, PD_3D, 0.5);
  against_kernels("ordinary sc inverse m=1/2", 3, 1, PD_INFLUENCE_INVERSE, PD_3D, 0.5);
  against_kernels("ordinary sc tupek m=0", 3, 1, PD_INFLUENCE_TUPEK, PD_3D, 0.0);
  against_kernels("ordinary sq plane stress", 2, 1, PD_INFLUENCE_CONSTANT, PD_PLANE_STRESS, 0.5);
  against_kernels("ordinary sq plane strain", 2, 1, PD_INFLUENCE_CONSTANT, PD_PLANE_STRAIN, 0.5);
  limits();
  return check_summary();
}
