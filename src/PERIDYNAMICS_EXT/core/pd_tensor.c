/* Small tensor algebra for the correspondence material (pd_tensor.h). */
#include "pd_tensor.h"

#include "pd_macros.h"

#include <math.h>
#include <string.h>

double pd_inverse3(const double a[9], double inv[9], double tiny)
{
  const double det = pd_det3(a);
  if (!(fabs(det) > tiny)) {
    memset(inv, 0, 9 * sizeof(double));
    return det;
  }
  const double r = 1.0 / det;
  inv[0] = (a[4] * a[8] - a[5] * a[7]) * r;
  inv[1] = (a[2] * a[7] - a[1] * a[8]) * r;
  inv[2] = (a[1] * a[5] - a[2] * a[4]) * r;
  inv[3] = (a[5] * a[6] - a[3] * a[8]) * r;
  inv[4] = (a[0] * a[8] - a[2] * a[6]) * r;
  inv[5] = (a[2] * a[3] - a[0] * a[5]) * r;
  inv[6] = (a[3] * a[7] - a[4] * a[6]) * r;
  inv[7] = (a[1] * a[6] - a[0] * a[7]) * r;
  inv[8] = (a[0] * a[4] - a[1] * a[3]) * r;
  return det;
}

/* Cyclic Jacobi on 'lanes' tensors side by side (a[c][k]: component c of
 * tensor k, full 3x3; v the same for Q). Each tensor's rotations are its
 * own: a tensor that converged, or has nothing to rotate at (p, r), turns
 * by the identity (c = 1, s = 0: its numbers stay as they are), so that a
 * tensor's numbers are the same in any lane and alone. */
enum { EIGEN_LANES = 16 };  /* (AVX-512: 2.4x faster per tensor at 8, 3.7x at 16) */
typedef double eigen_lanes[9][EIGEN_LANES];

PD_INLINE void jacobi_rotate(eigen_lanes a, eigen_lanes v, const int *restrict done, int p, int r,
                             int lanes)
{
  for (int k = 0; k < lanes; k++) {
    /* the rotation that zeroes a_pr: with h = a_rr - a_pp, g = 2 a_pr and
     * rho = |(h, g)|, the smaller angle's tan = g / (|h| + rho) (signed as
     * h) and cos^2 = (|h| + rho) / (2 rho): a chain of a root, a divide and
     * a root, where the form through cot 2phi = h/g chained three divides
     * and two roots. rho underflows only for entries below 1e-154. */
    const double apr = a[3 * p + r][k];
    const double h = a[3 * r + r][k] - a[3 * p + p][k], g = 2.0 * apr;
    const double rho = sqrt(h * h + g * g), sum = fabs(h) + rho;
    const int turn = !done[k] & (apr != 0.0) & (sum > 0.0);  /* (no &&: no branch in the lanes) */
    const double t = (h >= 0.0 ? g : -g) / sum, cr = sqrt(sum / (2.0 * rho));
    const double c = turn ? cr : 1.0, sn = turn ? t * cr : 0.0;
    for (int m = 0; m < 3; m++) {  /* a <- a G (columns p, r) */
      const double amp = a[3 * m + p][k], amr = a[3 * m + r][k];
      a[3 * m + p][k] = c * amp - sn * amr;
      a[3 * m + r][k] = sn * amp + c * amr;
    }
    for (int m = 0; m < 3; m++) {  /* a <- G^T a (rows p, r) */
      const double apm = a[3 * p + m][k], arm = a[3 * r + m][k];
      a[3 * p + m][k] = c * apm - sn * arm;
      a[3 * r + m][k] = sn * apm + c * arm;
    }
    for (int m = 0; m < 3; m++) {  /* q <- q G */
      const double vmp = v[3 * m + p][k], vmr = v[3 * m + r][k];
      v[3 * m + p][k] = c * vmp - sn * vmr;
      v[3 * m + r][k] = sn * vmp + c * vmr;
    }
  }
}

/* One sweep, of all lanes or of the first alone; (p, r) as constants and
 * a sweep of its own: so the lanes vectorize. */
typedef void (*jacobi_sweep_fn)(eigen_lanes a, eigen_lanes v, const int *restrict done);
static void sweep_lanes(eigen_lanes a, eigen_lanes v, const int *restrict done)
{
  jacobi_rotate(a, v, done, 0, 1, EIGEN_LANES);
  jacobi_rotate(a, v, done, 0, 2, EIGEN_LANES);
  jacobi_rotate(a, v, done, 1, 2, EIGEN_LANES);
}
static void sweep_one(eigen_lanes a, eigen_lanes v, const int *restrict done)
{
  jacobi_rotate(a, v, done, 0, 1, 1);
  jacobi_rotate(a, v, done, 0, 2, 1);
  jacobi_rotate(a, v, done, 1, 2, 1);
}

/* n <= lanes tensors (the lanes past n: zero, converged at once). */
PD_INLINE void jacobi(int n, int lanes, jacobi_sweep_fn sweep, const double *s, double *l, double *q)
{
  eigen_lanes a, v;
  int done[EIGEN_LANES];
  for (int k = 0; k < lanes; k++) {
    double full[9] = {0};
    if (k < n) pd_sym_to_full(s + 6 * k, full);
    for (int c = 0; c < 9; c++) a[c][k] = full[c], v[c][k] = (c % 4 == 0);
    done[k] = 0;
  }
  for (int sweep_count = 0; sweep_count < 50; sweep_count++) {
    int all = 1;
    for (int k = 0; k < lanes; k++) {
      const double off = a[1][k] * a[1][k] + a[2][k] * a[2][k] + a[5][k] * a[5][k];
      const double diag = a[0][k] * a[0][k] + a[4][k] * a[4][k] + a[8][k] * a[8][k];
      done[k] |= off <= 1e-32 * diag || off == 0.0;
      all &= done[k];
    }
    if (all) break;
    sweep(a, v, done);
  }
  for (int k = 0; k < n; k++) {
    for (int c = 0; c < 3; c++) l[3 * k + c] = a[4 * c][k];
    for (int c = 0; c < 9; c++) q[9 * k + c] = v[c][k];
  }
}

void pd_sym_eigen_many(int n, const double *s, double *l, double *q)
{
  for (int k0 = 0; k0 < n; k0 += EIGEN_LANES) {
    const int m = n - k0 < EIGEN_LANES ? n - k0 : EIGEN_LANES;
    jacobi(m, EIGEN_LANES, sweep_lanes, s + 6 * k0, l + 3 * k0, q + 9 * k0);
  }
}

void pd_sym_eigen(const double s[6], double l[3], double q[9])
{
  jacobi(1, 1, sweep_one, s, l, q);
}

#define SQRT2 1.41421356237309504880

void pd_mandel_from_sym(const double s[6], double v[6])
{
  for (int k = 0; k < 6; k++) v[k] = k < 3 ? s[k] : SQRT2 * s[k];
}

void pd_mandel_to_sym(const double v[6], double s[6])
{
  for (int k = 0; k < 6; k++) s[k] = k < 3 ? v[k] : v[k] / SQRT2;
}

/* position of (r, c), r <= c, in the packed upper triangle */
static int packed(int r, int c)
{
  return r * 6 - r * (r - 1) / 2 + (c - r);
}

void pd_sym4_add_dyad(double m[PD_SYM4], const double n[3], double w)
{
  const double nn[6] = {n[0] * n[0], n[1] * n[1], n[2] * n[2], n[0] * n[1], n[0] * n[2], n[1] * n[2]};
  double v[6];
  pd_mandel_from_sym(nn, v);
  int p = 0;
  for (int r = 0; r < 6; r++)
    for (int c = r; c < 6; c++) m[p++] += w * v[r] * v[c];
}

int pd_sym4_invert(double m[PD_SYM4], int dim)
{
  static const int all[6] = {0, 1, 2, 3, 4, 5}, plane[3] = {0, 1, 3};
  const int *ix = dim == 2 ? plane : all;
  const int n = dim == 2 ? 3 : 6;
  /* Gauss-Jordan on the used block; a positive pivot at each step is what
   * a positive definite matrix gives */
  double a[6][12];
  for (int r = 0; r < n; r++)
    for (int c = 0; c < n; c++) {
      const int i = ix[r], j = ix[c];
      a[r][c] = m[i <= j ? packed(i, j) : packed(j, i)];
      a[r][n + c] = r == c;
    }
  double scale = 0.0;
  for (int r = 0; r < n; r++) scale = fmax(scale, fabs(a[r][r]));
  int ok = scale > 0.0;
  for (int p = 0; ok && p < n; p++) {
    if (!(a[p][p] > 1e-12 * scale)) {
      ok = 0;
      break;
    }
    const double inv = 1.0 / a[p][p];
    for (int c = 0; c < 2 * n; c++) a[p][c] *= inv;
    for (int r = 0; r < n; r++) {
      if (r == p || a[r][p] == 0.0) continue;
      const double f = a[r][p];
      for (int c = 0; c < 2 * n; c++) a[r][c] -= f * a[p][c];
    }
  }
  memset(m, 0, PD_SYM4 * sizeof(double));
  if (!ok) return 0;
  for (int r = 0; r < n; r++)
    for (int c = r; c < n; c++) {
      const int i = ix[r], j = ix[c];
      m[i <= j ? packed(i, j) : packed(j, i)] = 0.5 * (a[r][n + c] + a[c][n + r]);
    }
  return 1;
}

void pd_sym4_apply(const double m[PD_SYM4], const double s[6], double out[6])
{
  double v[6], r[6] = {0, 0, 0, 0, 0, 0};
  pd_mandel_from_sym(s, v);
  for (int i = 0; i < 6; i++)
    for (int j = 0; j < 6; j++) r[i] += m[i <= j ? packed(i, j) : packed(j, i)] * v[j];
  pd_mandel_to_sym(r, out);
}
