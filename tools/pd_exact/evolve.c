#include "evolve.h"

#include "pd_macros.h"
#include "pd_tensor.h"

#include <complex.h>
#include <fftw3.h>
#include <math.h>
#include <stdlib.h>

static void centred(const exact_problem *p, const int m[3], int shift, double k[3])
{
  for (int d = 0; d < 3; d++) {
    k[d] = 0.0;
    if (d >= p->lat.dim) continue;
    const int g = p->grid[d];
    int q = (m[d] + (shift ? g / 2 : 0)) % g;
    if (q > g / 2) q -= g;
    k[d] = 2.0 * PD_PI * q / (g * p->lat.h[d]);
  }
}

void exact_wave_vector(const exact_problem *p, const int m[3], double k[3])
{
  centred(p, m, 0, k);
  if (!p->lat.parity) return;
  double ka[3];
  centred(p, m, 1, ka);
  if (ka[0] * ka[0] + ka[1] * ka[1] + ka[2] * ka[2] < k[0] * k[0] + k[1] * k[1] + k[2] * k[2])
    for (int d = 0; d < 3; d++) k[d] = ka[d];
}

/* One mode: u, v (3 complex each) advanced by t under rho u'' = -A u. */
static int advance(const double A[9], double rho, double t, double complex u[3], double complex v[3])
{
  const double s[6] = {A[0], A[4], A[8], A[1], A[2], A[5]};
  double l[3], q[9];
  pd_sym_eigen(s, l, q);
  const double big = fmax(fabs(l[0]), fmax(fabs(l[1]), fabs(l[2])));
  double complex a[3], b[3];
  for (int e = 0; e < 3; e++) {
    if (l[e] < -1e-10 * big) return -1;
    const double w = sqrt(fmax(l[e], 0.0) / rho), wt = w * t;
    const double c = cos(wt), sw = w > 0.0 ? sin(wt) / w : t; /* sin(Wt)/W -> t */
    /* components along eigenvector e (column e of q) */
    double complex ue = 0.0, ve = 0.0;
    for (int i = 0; i < 3; i++) {
      ue += q[3 * i + e] * u[i];
      ve += q[3 * i + e] * v[i];
    }
    a[e] = c * ue + sw * ve;
    b[e] = -w * w * sw * ue + c * ve;
  }
  for (int i = 0; i < 3; i++) {
    u[i] = v[i] = 0.0;
    for (int e = 0; e < 3; e++) {
      u[i] += q[3 * i + e] * a[e];
      v[i] += q[3 * i + e] * b[e];
    }
  }
  return 0;
}

int exact_evolve(const exact_problem *p, exact_sites *s, FILE *err)
{
  const long n = s->ngrid;
  fftw_complex *f = fftw_malloc(sizeof(fftw_complex) * 6 * n);
  if (!f) return -1;
  int dims[3] = {p->grid[0], p->grid[1], p->grid[2]};
  /* six transforms of stride 6: ux uy uz vx vy vz of each grid point together */
  fftw_plan fwd = fftw_plan_many_dft(p->lat.dim, dims, 6, f, NULL, 6, 1, f, NULL, 6, 1, FFTW_FORWARD, FFTW_ESTIMATE);
  fftw_plan bwd = fftw_plan_many_dft(p->lat.dim, dims, 6, f, NULL, 6, 1, f, NULL, 6, 1, FFTW_BACKWARD, FFTW_ESTIMATE);
  double complex *z = (double complex *) f;
  for (long g = 0; g < n; g++)
    for (int c = 0; c < 3; c++) {
      z[6 * g + c] = s->u[3 * g + c];
      z[6 * g + 3 + c] = s->v[3 * g + c];
    }
  fftw_execute(fwd);
  int bad = 0;
  for (long g = 0; g < n && !bad; g++) {
    const int m[3] = {(int) (g / ((long) dims[1] * dims[2])), (int) ((g / dims[2]) % dims[1]), (int) (g % dims[2])};
    double k[3], A[9];
    /* the lattice symbol is periodic over the reciprocal lattice: any
     * representative of the mode serves; the classical one is not */
    exact_wave_vector(p, m, k);
    pd_symbol(&p->model, &p->fam, k, A);
    if (advance(A, p->density, p->time, z + 6 * g, z + 6 * g + 3)) {
      fprintf(err, "pd_exact: mode k = (%g, %g, %g) is unstable: A(k) is not positive\n", k[0], k[1], k[2]);
      bad = 1;
    }
  }
  if (!bad) {
    fftw_execute(bwd);
    for (long g = 0; g < n; g++)
      for (int c = 0; c < 3; c++) {
        s->u[3 * g + c] = creal(z[6 * g + c]) / n;
        s->v[3 * g + c] = creal(z[6 * g + 3 + c]) / n;
      }
  }
  fftw_destroy_plan(fwd);
  fftw_destroy_plan(bwd);
  fftw_free(f);
  return bad ? -1 : 0;
}
