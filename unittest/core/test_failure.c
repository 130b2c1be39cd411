/* Bond failure (T14 ch. 6, MS07 eq. 25-31): calibration integrals, the
 * instantaneous bond energy, breaking and energy release, pre-crack
 * geometry. */
#include "check.h"
#include "common.h"
#include "model.h"
#include "pd_bond_based.h"
#include "pd_failure.h"
#include "pd_law_energy.h"
#include "pd_law_legacy.h"
#include "pd_law_stretch.h"
#include "pd_macros.h"
#include "pd_params.h"
#include "pd_precrack.h"

#include <stdlib.h>
#include <string.h>

/* kappa of pd_ordinary_dilatation_release, by another method: random
 * bonds in the unit ball (the half pointing across the plane n = z), and
 * for each depth z and each crossing bond the dilatation of its end summed
 * bond by bond over the crossing bonds that break later (O(n^2), no
 * sorting), averaged over random depths. */
static double kappa_monte_carlo(pd_influence_kind kind, int dim, int n, unsigned seed)
{
  double *r = malloc(sizeof(double) * n), *c = malloc(sizeof(double) * n), *w = malloc(sizeof(double) * n);
  srand(seed);
  double m = 0.0;
  int k = 0, drawn = 0;
  while (k < n) {
    double p[3] = {0.0, 0.0, 0.0}, rr = 0.0;
    for (int a = 0; a < dim; a++) {
      p[a] = 2.0 * rand() / RAND_MAX - 1.0;
      rr += p[a] * p[a];
    }
    if (rr > 1.0 || rr == 0.0) continue;
    drawn++;
    const double len = sqrt(rr), wk = pd_influence(kind, dim, len, 1.0);
    m += wk;
    if (p[dim - 1] <= 0.0) continue;
    r[k] = len, c[k] = p[dim - 1] / len, w[k] = wk;
    k++;
  }
  /* per unit ball volume: m = (sum w) / drawn; N = d / m */
  m /= drawn;
  const double half = (double) n / drawn; /* the share of draws kept */
  double across = 0.0, sum = 0.0;
  for (int b = 0; b < n; b++) across += w[b] * r[b] * c[b];
  const int nz = 200;
  for (int q = 0; q < nz; q++) {
    const double z = (q + 0.5) / nz;
    for (int b = 0; b < n; b++) {
      if (r[b] * c[b] <= z) continue;
      const double u = r[b] / c[b];
      double later = 0.0;
      for (int e = 0; e < n; e++)
        if (r[e] * c[e] > z && r[e] / c[e] >= u) later += w[e] * c[e] / r[e];
      sum += w[b] * (dim / m) * u * later * half / n / nz;
    }
  }
  free(r), free(c), free(w);
  return sum / across;
}

int main(void)
{
  const double delta = 0.0055, Gc = 400.0; /* PMMA, T14 6.2.1 */
  /* beta in closed form for Tupek's polynomials (THEORY.md): the thesis'
   * 2D value pi delta Gc / 16, and 16 delta Gc / 63 in 3D (eq. 6.1 gives
   * 63 beta / (32 delta) for the one-sided integral: no factor pi). */
  check_rel("2D Tupek beta = pi delta Gc / 16 (T14)", pd_energy_failure_beta(PD_INFLUENCE_TUPEK, PD_PROFILE_OPENING, 2, delta, Gc),
            PD_PI * delta * Gc / 16.0, 1e-8);
  check_rel("3D Tupek beta = 16 delta Gc / 63", pd_energy_failure_beta(PD_INFLUENCE_TUPEK, PD_PROFILE_OPENING, 3, delta, Gc),
            16.0 * delta * Gc / 63.0, 1e-8);
  /* constant omega, closed forms: 3D omega = 9 / (4 pi delta^3),
   * I = pi beta omega delta^2 / 2 -> beta = 4 delta Gc / 9; 2D omega =
   * 2 / (pi delta^2), I = 2 beta omega delta -> beta = pi delta Gc / 8 */
  check_rel("3D constant beta = 4 delta Gc / 9", pd_energy_failure_beta(PD_INFLUENCE_CONSTANT, PD_PROFILE_OPENING, 3, delta, Gc),
            4.0 * delta * Gc / 9.0, 1e-8);
  check_rel("2D constant beta = pi delta Gc / 8", pd_energy_failure_beta(PD_INFLUENCE_CONSTANT, PD_PROFILE_OPENING, 2, delta, Gc),
            PD_PI * delta * Gc / 8.0, 1e-8);
  check_true("2D inverse influence, opening profile: G_c integral diverges (refused)",
             pd_energy_failure_beta(PD_INFLUENCE_INVERSE, PD_PROFILE_OPENING, 2, delta, Gc) < 0.0);
  /* the uniform profile (s_c = beta omega): I = pi beta int omega r^3 dr
   * (3D), 2 beta int omega r^2 dr (2D); constant omega: beta = 8 Gc / (9
   * delta) and 3 pi Gc / (8 delta); 2D inverse, omega = 1 / (pi delta r):
   * I = beta delta / pi, beta = pi Gc / (2 delta) */
  check_rel("3D constant, uniform profile: beta = 8 Gc / (9 delta)",
            pd_energy_failure_beta(PD_INFLUENCE_CONSTANT, PD_PROFILE_UNIFORM, 3, delta, Gc), 8.0 * Gc / (9.0 * delta),
            1e-8);
  check_rel("2D constant, uniform profile: beta = 3 pi Gc / (8 delta)",
            pd_energy_failure_beta(PD_INFLUENCE_CONSTANT, PD_PROFILE_UNIFORM, 2, delta, Gc),
            3.0 * PD_PI * Gc / (8.0 * delta), 1e-8);
  check_rel("2D inverse, uniform profile: beta = pi Gc / (2 delta) (converges)",
            pd_energy_failure_beta(PD_INFLUENCE_INVERSE, PD_PROFILE_UNIFORM, 2, delta, Gc), PD_PI * Gc / (2.0 * delta),
            1e-6);
  /* critical stretch from G_c, MS07 eq. 29 in 3D */
  check_rel("3D s0 = sqrt(5 G / (9 K delta))", pd_critical_stretch(3, 0, 3.0e9, 0.25, 1e-3, 100.0),
            sqrt(5.0 * 100.0 / (9.0 * 2.0e9 * 1e-3)), 1e-14);
  /* the dilatation's share of the energy an ordinary solid's bonds release
   * at the critical stretch: the grid against random bonds (1500: a
   * sampling error of about 2%) */
  {
    const pd_influence_kind kinds[] = {PD_INFLUENCE_CONSTANT, PD_INFLUENCE_INVERSE};
    for (int q = 0; q < 2; q++)
      for (int dim = 2; dim <= 3; dim++) {
        char what[160];
        snprintf(what, sizeof what, "ordinary stretch law, %dD %s: the dilatation part of the release (kappa) "
                 "on the grid agrees with random bonds (5%%)", dim, pd_influence_name(kinds[q]));
        check_rel(what, pd_ordinary_dilatation_release(kinds[q], dim), kappa_monte_carlo(kinds[q], dim, 1500, 7),
                  0.05);
      }
    /* with lambda = 0 the calibration is the B part alone: the released
     * energy averaged over orientations, 2 mu N s0^2 <cos+> moment1, is G_c */
    const double mu = 3e9, mvol = 2e-9, moment1 = 3e-12, s0 = pd_critical_stretch_ordinary(3, Gc, 0.0, mu, 0.26, mvol, moment1);
    check_rel("ordinary stretch law: bonds broken at s0 release G_c on average (lambda = 0)",
              2.0 * mu * (3.0 / mvol) * s0 * s0 * 0.25 * moment1, Gc, 1e-12);
    const double s1 = pd_critical_stretch_ordinary(3, Gc, 1.5e9, mu, 0.26, mvol, moment1);
    check_rel("ordinary stretch law: the dilatation part (1 + kappa lambda / mu) lowers s0^2 by itself",
              s0 * s0 / (s1 * s1), 1.0 + 0.26 * 0.5, 1e-12);
  }

  /* The instantaneous bond energy (T14 eq. 6.5): the derivative of the
   * total energy with respect to a bond's weight, at fixed normalization,
   * is V_i V_j (s_i + s_j) with s = w eps (A + B eps / 2). */
  {
    const double h = 5e-4;
    lattice l = lattice_make(3, 5, h, 2.0001 * h, PD_INFLUENCE_TUPEK);
    const int n = l.natoms;
    double *x = malloc(sizeof(double) * 3 * n), *f = malloc(sizeof(double) * 3 * n);
    double *m = calloc(n, sizeof(double)), *ab = malloc(sizeof(double) * 2 * n);
    random_displacement(&l, 0.01 * h, 21, x);
    pd_bond_view v = lattice_view(&l);
    pd_weighted_volume(&v, l.vol, m);
    const pd_lame bar = pd_ordinary_lame_3d(14.9e9, 7e9);
    const double orders[] = {0.5, 0.0};
    for (int q = 0; q < 2; q++) {
      const int i = lattice_center(&l), slot = i * l.stride; /* first bond of the centre */
      const int j = l.far[slot];
      const double w = l.weight[slot], r0 = l.len0[slot];
      ordinary_eval_full(&l, bar.lambda, bar.mu, orders[q], m, NULL, NULL, x, f, ab);
      double d[3];
      for (int c = 0; c < 3; c++) d[c] = x[3 * j + c] - x[3 * i + c];
      const double len = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
      const double eps = orders[q] == 0.5 ? len / r0 - 1.0 : log(len / r0);
      const double si = w * eps * (ab[2 * i] + 0.5 * ab[2 * i + 1] * eps);
      const double sj = w * eps * (ab[2 * j] + 0.5 * ab[2 * j + 1] * eps);
      const double step = 1e-4;
      l.weight[slot] = w * (1 + step);
      const double ep = ordinary_eval_full(&l, bar.lambda, bar.mu, orders[q], m, NULL, NULL, x, f, NULL);
      l.weight[slot] = w * (1 - step);
      const double em = ordinary_eval_full(&l, bar.lambda, bar.mu, orders[q], m, NULL, NULL, x, f, NULL);
      l.weight[slot] = w;
      /* d E / d phi with phi scaling the weight; central difference, step 1e-4:
       * the energy is quadratic in phi, so the difference is exact up to
       * round-off (~1e-12 E / 1e-4) */
      char what[80];
      snprintf(what, sizeof what, "s_inst = dE/d(weight) for m = %g (T14 eq. 6.5)", orders[q]);
      check_rel(what, (ep - em) / (2 * step), l.vol[i] * l.vol[j] * (si + sj), 1e-6);
    }
    /* Energy law, end to end: a uniform stretch well above the critical one
     * breaks every bond in tension at once, and the energy released equals
     * the drop of the elastic energy to first order (the dilatation term is
     * quadratic in the cut bonds: the drop exceeds the sum of s_inst by
     * lambda/2 (cut dilatation)^2, zero here with lambda_bar = 0). */
    const pd_lame b0 = {0.0, 5e9};
    const double s = 1e-2;
    double e[3][3] = {{s, 0, 0}, {0, s, 0}, {0, 0, s}};
    lattice_strain(&l, e, x);
    double *crit = calloc(n, sizeof(double));
    double *len0 = l.len0;
    pd_failure fail = {.law = PD_FAIL_ENERGY, .recontact = 1, .len0 = len0};
    for (int a = 0; a < n; a++) crit[a] = 1e-30; /* tiny beta N: everything in tension breaks */
    const double before = ordinary_eval_full(&l, b0.lambda, b0.mu, 0.5, m, NULL, NULL, x, f, NULL);
    /* bonds that fail break before their force acts: this evaluation
     * already tallies the broken state */
    const double broken_now = ordinary_eval_full(&l, b0.lambda, b0.mu, 0.5, m, &fail, crit, x, f, NULL);
    long nb = 0;
    for (int a = 0; a < n; a++) nb += l.count[a];
    check_true("energy law: every bond in tension breaks", fail.nbroken == nb);
    pd_failure after_fail = {.law = PD_FAIL_ENERGY, .recontact = 1, .len0 = len0};
    const double after = ordinary_eval_full(&l, b0.lambda, b0.mu, 0.5, m, &after_fail, crit, x, f, NULL);
    check_rel("energy law: released energy = elastic energy lost (lambda_bar = 0)", fail.released_joule,
              before - after, 1e-12);
    check_true("broken bonds carry no tension afterwards", after == 0.0 && broken_now == 0.0 &&
               after_fail.nbroken == 0);
    /* recontact: compress instead, and the broken bonds push again */
    double ec[3][3] = {{-s, 0, 0}, {0, -s, 0}, {0, 0, -s}};
    lattice_strain(&l, ec, x);
    pd_failure comp = {.law = PD_FAIL_ENERGY, .recontact = 1, .len0 = len0};
    const double e_re = ordinary_eval_full(&l, b0.lambda, b0.mu, 0.5, m, &comp, crit, x, f, NULL);
    comp.recontact = 0;
    const double e_no = ordinary_eval_full(&l, b0.lambda, b0.mu, 0.5, m, &comp, crit, x, f, NULL);
    check_true("recontact: broken bonds resist compression (energy > 0), without it none", e_re > 0.0 && e_no == 0.0);
    lattice_free(&l);
    free(x);
    free(f);
    free(m);
    free(ab);
    free(crit);
  }
  /* PMB critical stretch on one bond: breaks above s0 only, releasing the
   * bond's energy 1/2 c s^2 |xi| V_i V_j. */
  {
    const double h = 1e-3, c = 1e18, s0 = 0.01;
    lattice l = lattice_make(3, 2, h, 1.0001 * h, -1);
    l.natoms = 2;
    l.count[0] = 1;
    l.count[1] = 0;
    l.vol[0] = 2e-9;
    l.vol[1] = 3e-9;
    pd_bond_view v = lattice_view(&l);
    pd_pmb mat = {&c};
    double x[6] = {0, 0, 0, h * 1.009, 0, 0}, f[6] = {0};
    pd_law_stretch stretch = {&s0, 0};
    pd_failure fail = {.law = PD_FAIL_STRETCH, .params = &stretch, .recontact = 1, .len0 = l.len0};
    pd_pmb_forces(&(pd_loop){&v, l.type, 1, x, l.vol, f, NULL, &fail, l.reaction, l.natoms, 0, NULL, 0}, &mat);
    check_true("PMB: below s0 nothing breaks", fail.nbroken == 0 && l.len0[0] > 0.0);
    x[3] = h * 1.011;
    pd_pmb_forces(&(pd_loop){&v, l.type, 1, x, l.vol, f, NULL, &fail, l.reaction, l.natoms, 0, NULL, 0}, &mat);
    check_true("PMB: above s0 the bond breaks", fail.nbroken == 1 && l.len0[0] < 0.0);
    const double sb = 0.011;
    check_rel("PMB: released energy 1/2 c s^2 |xi| V_i V_j", fail.released_joule,
              0.5 * c * sb * sb * h * 2e-9 * 3e-9, 1e-9);
    /* 'after' (PERI's rule at alpha 0): the breaking bond acts with its
     * whole force first, twice the half it acts with by default */
    double fx[2];
    for (int after = 0; after < 2; after++) {
      l.len0[0] = h;
      f[0] = 0.0;
      stretch.after = after;
      pd_failure fa = {.law = PD_FAIL_STRETCH, .params = &stretch, .recontact = 1, .len0 = l.len0};
      pd_pmb_forces(&(pd_loop){&v, l.type, 1, x, l.vol, f, NULL, &fa, l.reaction, l.natoms, 0, NULL, 0}, &mat);
      check_true(after ? "PMB, after: above s0 the bond breaks" : "PMB, now: above s0 the bond breaks",
                 fa.nbroken == 1 && l.len0[0] < 0.0);
      fx[after] = f[0];
    }
    check_rel("PMB: a bond that breaks after acts with twice the force of one that breaks now",
              fx[1], 2.0 * fx[0], 1e-14);
    check_true("PMB: that force pulls i towards j", fx[0] > 0.0);
    l.natoms = 8;
    lattice_free(&l);
  }
  /* The screens' floor: the smallest value wherever it sits (the running
   * minima side by side, and the tail), NaNs skipped, +inf for none. */
  {
    enum { N = 21 };
    double v[N];
    int right = 1;
    for (int n = 0; n <= N; n++)
      for (int at = 0; at < n; at++) {
        for (int a = 0; a < n; a++) v[a] = a == at ? -2.0 - a : (a % 3 ? NAN : 1.0 + a);
        right &= pd_failure_floor(v, n) == -2.0 - at;
      }
    check_true("floor: the smallest of n = 1..21 values, at every position, NaNs skipped", right);
    check_true("floor of no values: +inf", isinf(pd_failure_floor(v, 0)) && pd_failure_floor(v, 0) > 0.0);
  }
  /* The laws' screens (pd_law_<name>_ahead, the vectorized pass's only
   * question): yes whenever the exact tests say yes, and no for some bonds
   * (else they screen nothing). Random atoms' s0 and crit, stretches and
   * energies around the thresholds. */
  {
    enum { NATOM = 16, NBOND = 20000 };
    double s0_atom[NATOM], crit[NATOM];
    srand(7);
    for (int a = 0; a < NATOM; a++) {
      s0_atom[a] = 0.004 + 0.002 * rand() / RAND_MAX;
      crit[a] = 1.0 + rand() / (double) RAND_MAX;
    }
    const double s00[4] = {0, 0, 0, 0.005}, alpha[4] = {0, 0, 0, 0.25}, gc[4] = {0, 0, 0, 2.0};
    const pd_law_legacy legacy = {s00, alpha, s0_atom, pd_failure_floor(s0_atom, NATOM)};
    /* the energy law with each profile (its length factor: bonds of
     * lengths 0.5-1.5) */
    pd_law_energy energy[2] = {{crit, pd_failure_floor(crit, NATOM), gc, 0.0, 0.0},
                               {crit, pd_failure_floor(crit, NATOM), gc, 0.0, 0.0}};
    pd_law_energy_profile(&energy[0], PD_PROFILE_UNIFORM);
    pd_law_energy_profile(&energy[1], PD_PROFILE_OPENING);
    const pd_failure fl = {.law = PD_FAIL_LEGACY, .params = &legacy};
    const pd_failure fe[2] = {{.law = PD_FAIL_ENERGY, .params = &energy[0]},
                              {.law = PD_FAIL_ENERGY, .params = &energy[1]}};
    int broke_energy[2] = {0, 0}, profiles_differ = 0, wrong_test = 0;
    /* the critical stretch, breaking now or after */
    const pd_law_stretch stretch[2] = {{s00, 0}, {s00, 1}};
    const pd_failure fs[2] = {{.law = PD_FAIL_STRETCH, .params = &stretch[0]},
                              {.law = PD_FAIL_STRETCH, .params = &stretch[1]}};
    int missed = 0, screened_legacy = 0, screened_energy = 0, screened_stretch = 0, broke_stretch[2] = {0, 0};
    for (int k = 0; k < NBOND; k++) {
      pd_bond bd = {0};
      bd.i = rand() % NATOM;
      bd.j = rand() % NATOM;
      bd.tij = 3;
      bd.w = 0.5 + rand() / (double) RAND_MAX;
      bd.r0 = 0.5 + rand() / (double) RAND_MAX;
      bd.len = bd.r0 * (1.0 + 0.008 * rand() / RAND_MAX - 0.001);
      const double eps = pd_bond_stretch(&bd), e = 4.0 * rand() / RAND_MAX;
      const pd_bond_force bf = {.release_i = e, .release_j = 0.5 * e, .release = e + 0.5 * e};
      missed += (pd_law_legacy_now(&fl, &bd, eps, &bf) | pd_law_legacy_after(&fl, &bd, eps)) &&
                !pd_law_legacy_ahead(&fl, &bd, eps, &bf);
      for (int a = 0; a < 2; a++) {
        const int now = pd_law_energy_now(&fe[a], &bd, eps, &bf);
        missed += (now | pd_law_energy_after(&fe[a], &bd, eps)) && !pd_law_energy_ahead(&fe[a], &bd, eps, &bf);
        screened_energy += !pd_law_energy_ahead(&fe[a], &bd, eps, &bf);
        broke_energy[a] += now;
        /* the test itself: uniform s_c = G_c w (crit_i + crit_j), opening the same / r0^2 */
        const double threshold = bd.w * (crit[bd.i] + crit[bd.j]) * gc[3] / (a ? bd.r0 * bd.r0 : 1.0);
        wrong_test += now != (eps > 0.0 && bf.release >= threshold) && fabs(bf.release / threshold - 1.0) > 1e-12;
      }
      profiles_differ += pd_law_energy_now(&fe[0], &bd, eps, &bf) != pd_law_energy_now(&fe[1], &bd, eps, &bf);
      for (int a = 0; a < 2; a++) {
        const int now = pd_law_stretch_now(&fs[a], &bd, eps, &bf), after = pd_law_stretch_after(&fs[a], &bd, eps);
        missed += (now | after) && !pd_law_stretch_ahead(&fs[a], &bd, eps, &bf);
        broke_stretch[a] += a ? after && !now : now && !after;
      }
      screened_stretch += !pd_law_stretch_ahead(&fs[0], &bd, eps, &bf);
      screened_legacy += !pd_law_legacy_ahead(&fl, &bd, eps, &bf);
    }
    check_true("screens: no bond that breaks is screened out (PERI's rule, energy law, stretch)", missed == 0);
    check_true("screens: the stretch's screens out a bond below s0",
               screened_stretch > 0 && screened_stretch < NBOND);
    check_true("stretch: some bonds break now (after: none), some after (now: none)",
               broke_stretch[0] > 0 && broke_stretch[1] == broke_stretch[0]);
    check_true("screens: PERI's rule's screens out a bond below every atom's s0",
               screened_legacy > 0 && screened_legacy < NBOND);
    check_true("screens: the energy law's screens out a bond below every pair's threshold (both profiles)",
               screened_energy > 0 && screened_energy < 2 * NBOND);
    check_true("energy law: each profile's test is release >= G_c w (crit_i + crit_j) |xi|^q", wrong_test == 0);
    check_true("energy law: each profile breaks some bonds, and they differ on some",
               broke_energy[0] > 0 && broke_energy[1] > 0 && profiles_differ > 0);
  }
  /* Pre-crack geometry. */
  {
    const double a[2] = {0, 0}, b[2] = {1, 0};
    const double p[2] = {0.5, -0.1}, q[2] = {0.5, 0.1}, r[2] = {1.5, 0.1}, s[2] = {1.5, -0.1};
    const double t[2] = {0.5, 0.0}, u[2] = {0.7, 0.3};
    check_true("2D: a bond across the crack crosses it", pd_crosses_segment(p, q, a, b));
    check_true("2D: a bond beside the crack's end does not", !pd_crosses_segment(r, s, a, b));
    check_true("2D: a bond ending on the crack line does not", !pd_crosses_segment(t, u, a, b));
    const double o[3] = {0, 0, 0}, e1[3] = {1, 0, 0}, e2[3] = {0, 1, 0};
    const double p3[3] = {0.5, 0.5, -0.1}, q3[3] = {0.5, 0.5, 0.1}, r3[3] = {1.5, 0.5, -0.1}, s3[3] = {1.5, 0.5, 0.1};
    check_true("3D: a bond through the patch crosses it", pd_crosses_patch(p3, q3, o, e1, e2));
    check_true("3D: a bond beside the patch does not", !pd_crosses_patch(r3, s3, o, e1, e2));
    check_true("3D: a bond parallel to the patch does not", !pd_crosses_patch(p3, r3, o, e1, e2));
  }
  return check_summary();
}
