/* Small tensor algebra for the correspondence material: 3x3 tensors
 * row-major (a[3 * r + c]); symmetric tensors as six components in LAMMPS's
 * order xx, yy, zz, xy, xz, yz. */
#ifndef PD_TENSOR_H
#define PD_TENSOR_H

/* (Small enough to inline: pd/corr calls them per atom and step.) */

/* full index of the symmetric components xx, yy, zz, xy, xz, yz */
static const int PD_SYM_ROW[6] = {0, 1, 2, 0, 0, 1};
static const int PD_SYM_COL[6] = {0, 1, 2, 1, 2, 2};

/* Symmetric <-> full (the symmetric part). */
static inline void pd_sym_to_full(const double s[6], double a[9])
{
  for (int k = 0; k < 6; k++)
    a[3 * PD_SYM_ROW[k] + PD_SYM_COL[k]] = a[3 * PD_SYM_COL[k] + PD_SYM_ROW[k]] = s[k];
}

static inline void pd_full_to_sym(const double a[9], double s[6])
{
  for (int k = 0; k < 6; k++)
    s[k] = 0.5 * (a[3 * PD_SYM_ROW[k] + PD_SYM_COL[k]] + a[3 * PD_SYM_COL[k] + PD_SYM_ROW[k]]);
}

/* c = a b, c = a^T b, c = a b^T (c must not alias a or b). */
static inline void pd_mat_mul(const double a[9], const double b[9], double c[9])
{
  for (int r = 0; r < 3; r++)
    for (int k = 0; k < 3; k++)
      c[3 * r + k] = a[3 * r] * b[k] + a[3 * r + 1] * b[3 + k] + a[3 * r + 2] * b[6 + k];
}

static inline void pd_mat_tmul(const double a[9], const double b[9], double c[9])
{
  for (int r = 0; r < 3; r++)
    for (int k = 0; k < 3; k++) c[3 * r + k] = a[r] * b[k] + a[3 + r] * b[3 + k] + a[6 + r] * b[6 + k];
}

static inline void pd_mat_mult(const double a[9], const double b[9], double c[9])
{
  for (int r = 0; r < 3; r++)
    for (int k = 0; k < 3; k++)
      c[3 * r + k] = a[3 * r] * b[3 * k] + a[3 * r + 1] * b[3 * k + 1] + a[3 * r + 2] * b[3 * k + 2];
}

static inline double pd_det3(const double a[9])
{
  return a[0] * (a[4] * a[8] - a[5] * a[7]) - a[1] * (a[3] * a[8] - a[5] * a[6]) +
      a[2] * (a[3] * a[7] - a[4] * a[6]);
}

/* Inverse of a 3x3 tensor; returns its determinant, and leaves inv zero
 * when |det| <= tiny (a family that spans no volume). */
double pd_inverse3(const double a[9], double inv[9], double tiny);

/* Eigen-decomposition of a symmetric tensor: s = Q diag(l) Q^T, the
 * eigenvectors in Q's columns (cyclic Jacobi, converged to round-off). */
void pd_sym_eigen(const double s[6], double l[3], double q[9]);
/* The same for n tensors (6 numbers each in s; 3 in l and 9 in q each),
 * solved side by side in vector lanes: each one's numbers are those of
 * pd_sym_eigen, to the bit, at a fraction of the time per tensor (the
 * solve is a chain of roots and divides that one tensor alone waits on). */
void pd_sym_eigen_many(int n, const double *s, double *l, double *q);

/* s = Q diag(l) Q^T; t' = Q^T t Q and back (all symmetric). */
static inline void pd_sym_from_eigen(const double l[3], const double q[9], double s[6])
{
  for (int k = 0; k < 6; k++) {
    const int r = PD_SYM_ROW[k], c = PD_SYM_COL[k];
    s[k] = q[3 * r] * l[0] * q[3 * c] + q[3 * r + 1] * l[1] * q[3 * c + 1] +
        q[3 * r + 2] * l[2] * q[3 * c + 2];
  }
}

static inline void pd_sym_rotate_to(const double q[9], const double t[6], double out[6])
{
  double a[9], qt_a[9], b[9];
  pd_sym_to_full(t, a);
  pd_mat_tmul(q, a, qt_a);
  pd_mat_mul(qt_a, q, b);
  pd_full_to_sym(b, out);
}

static inline void pd_sym_rotate_from(const double q[9], const double t[6], double out[6])
{
  double a[9], qa[9], b[9];
  pd_sym_to_full(t, a);
  pd_mat_mul(q, a, qa);
  pd_mat_mult(qa, q, b);
  pd_full_to_sym(b, out);
}

/* A symmetric linear map on symmetric tensors (a fourth-order tensor with
 * both symmetries), held as the 6x6 matrix of its Mandel components
 * (off-diagonal components scaled by sqrt 2), upper triangle by rows
 * (21 numbers). */
enum { PD_SYM4 = 21 };
void pd_mandel_from_sym(const double s[6], double v[6]);
void pd_mandel_to_sym(const double v[6], double s[6]);
/* m += w (n (x) n) (x) (n (x) n) for a vector n (of any length). */
void pd_sym4_add_dyad(double m[PD_SYM4], const double n[3], double w);
/* Invert in place: over all six components in 3D, over xx, yy, xy in 2D
 * (dim 2: a plane family spans no z). Returns 0, inverse left zero, if the
 * map is not positive definite there (a family too small to give a strain). */
int pd_sym4_invert(double m[PD_SYM4], int dim);
/* out = M : s */
void pd_sym4_apply(const double m[PD_SYM4], const double s[6], double out[6]);

#endif
