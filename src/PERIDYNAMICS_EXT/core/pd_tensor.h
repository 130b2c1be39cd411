/* Small tensor algebra for the correspondence material: 3x3 tensors
 * row-major (a[3 * r + c]); symmetric tensors as six components in LAMMPS's
 * order xx, yy, zz, xy, xz, yz. */
#ifndef PD_TENSOR_H
#define PD_TENSOR_H

/* Symmetric <-> full. */
void pd_sym_to_full(const double s[6], double a[9]);
void pd_full_to_sym(const double a[9], double s[6]);  /* symmetric part */

/* c = a b, c = a^T b, c = a b^T (c must not alias a or b). */
void pd_mat_mul(const double a[9], const double b[9], double c[9]);
void pd_mat_tmul(const double a[9], const double b[9], double c[9]);
void pd_mat_mult(const double a[9], const double b[9], double c[9]);

double pd_det3(const double a[9]);

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

/* s = Q diag(l) Q^T; t' = Q^T t Q (both symmetric). */
void pd_sym_from_eigen(const double l[3], const double q[9], double s[6]);
void pd_sym_rotate_to(const double q[9], const double t[6], double out[6]);
void pd_sym_rotate_from(const double q[9], const double t[6], double out[6]);

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
