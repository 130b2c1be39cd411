/* Adaptive dynamic relaxation (pd_adr.h) on a chain of unit springs held
 * at both ends, one end moved by 1: its equilibrium is u_i = i / N.
 * lambda from the chain's stiffness sums (2 per particle) is exactly the
 * stability bound here (Gershgorin is sharp for nearest neighbours: the
 * highest mode of lambda^-1 K is 4 sin^2(pi (N-1) / 2N), just below 4), so
 * the tests take safety 1.1: at the bound itself the highest mode has a
 * root of the damped recurrence near -1 and decays slowly (for peridynamic
 * families the bound is loose: partners at 2 and 3 spacings are not out of
 * phase with the checkerboard mode). Critical damping of the lowest mode,
 * omega_1 = 2 sin(pi / 2N) / sqrt(1.1), reduces the error by
 * exp(-omega_1 n): the relaxation must reach 1e-10 within twice
 * ln(1e10) / omega_1 iterations. */
#include "check.h"
#include "pd_adr.h"

#include <math.h>
#include <string.h>

#define N 40
#define PI 3.14159265358979323846

static void forces(const double *u, double *f)
{
  for (int i = 1; i < N; i++) f[i] = u[i + 1] - 2.0 * u[i] + u[i - 1];
}

static int relax(double safety, double *err)
{
  double u[N + 1], v[N + 1], f[N + 1], fprev[N + 1], lambda[N + 1];
  memset(u, 0, sizeof(u));
  memset(v, 0, sizeof(v));
  memset(f, 0, sizeof(f));
  u[N] = 1.0;
  for (int i = 0; i <= N; i++) lambda[i] = pd_adr_density(2.0, safety);
  forces(u, f);
  for (int i = 1; i < N; i++) {
    pd_adr_start(1, &f[i], lambda[i], &v[i]);
    fprev[i] = f[i];
  }
  for (int n = 1; n <= 100000; n++) {
    for (int i = 1; i < N; i++) u[i] += v[i];
    forces(u, f);
    double uku = 0.0, uu = 0.0, r = 0.0;
    for (int i = 1; i < N; i++) {
      pd_adr_rayleigh_terms(1, &f[i], &fprev[i], lambda[i], &v[i], &u[i], &uku, &uu);
      r = fmax(r, fabs(f[i]));
    }
    const double c = pd_adr_damping(uku, uu);
    for (int i = 1; i < N; i++) {
      pd_adr_velocity(1, c, &f[i], lambda[i], &v[i]);
      fprev[i] = f[i];
    }
    if (r < 1e-10) {
      *err = 0.0;
      for (int i = 0; i <= N; i++) *err = fmax(*err, fabs(u[i] - (double) i / N));
      return n;
    }
  }
  *err = INFINITY;
  return -1;
}

int main(void)
{
  check_rel("lambda is half the stiffness sum times the safety factor", pd_adr_density(2.0, 1.5), 1.5, 1e-15);
  check_rel("no stiffness, no density (the particle is held)", pd_adr_density(0.0, 1.0), 0.0, 0.0);
  check_rel("c = 2 sqrt(quotient)", pd_adr_damping(0.01, 1.0), 0.2, 1e-15);
  check_rel("a negative quotient gives no damping", pd_adr_damping(-0.01, 1.0), 0.0, 0.0);
  check_rel("no displacement yet gives no damping", pd_adr_damping(0.0, 0.0), 0.0, 0.0);
  check_rel("c stays below 2", pd_adr_damping(4.0, 1.0), PD_ADR_CMAX, 0.0);
  double uku = 0.0, uu = 0.0;
  const double f = 1.0, fprev = 0.0, v = 1e-30, u = 1.0;
  pd_adr_rayleigh_terms(1, &f, &fprev, 1.0, &v, &u, &uku, &uu);
  check_rel("a velocity passing through 0 adds no stiffness", uku, 0.0, 0.0);

  const double omega1 = 2.0 * sin(PI / (2.0 * N)) / sqrt(1.1);
  const double limit = 2.0 * log(1e10) / omega1;
  double err;
  const int n = relax(1.1, &err);
  printf("chain of %d springs: %d iterations to 1e-10 (limit %.0f), largest error %.3g\n", N, n, limit, err);
  check_true("the chain relaxes to 1e-10 within twice the critically damped count", n > 0 && n <= limit);
  /* e = K^-1 R: the chain's |K^-1| (max row sum) is N^2 / 8 */
  check_rel("to its equilibrium u_i = i / N (error below N^2/8 x 1e-10)", 1.0 + err, 1.0, N * N / 8.0 * 1e-10);
  double err4;
  const int n4 = relax(4.4, &err4);
  printf("safety 4.4: %d iterations\n", n4);
  check_true("four times the density takes about twice the iterations (1.6 .. 2.5)",
             n4 >= 1.6 * n && n4 <= 2.5 * n);
  return check_summary();
}
