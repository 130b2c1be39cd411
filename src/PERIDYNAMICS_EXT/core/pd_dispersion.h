/* Linear waves on a periodic lattice: the Fourier symbol A(k) of the
 * linearized equation of motion, rho u_tt = -A(k) u for u = u_k e^{i k.x},
 * of pd/bond (PMB) and pd/ordinary as this package discretizes them, of
 * local elasticity with the same constants, and the effective elastic
 * tensor of a family (A(k) -> C_ijkl k_j k_l as k -> 0).
 *
 * Linearization (doc/exact_waves.md has the derivation; EW06 section 3:
 * on a lattice the operator is a convolution, so each Fourier mode is an
 * eigenmode and its dispersion is a lattice sum). With e = xi/|xi|, r = |xi|,
 * V the partner volume, w the bond weight, phi = k.xi:
 *   PMB (f_i += V_j c s w e_ij, s ~ e.(u_j - u_i)/r):
 *     A = sum c w V (1 - cos phi)/r  e (x) e
 *   ordinary (t = (A_i + A_j + (B_i + B_j) eps) w / r, A = lambda theta N,
 *   B = 2 mu N, theta = N sum w eps V, N = d/m, m = sum w V; every order m
 *   of the Seth-Hill strain has eps ~ e.(u_j - u_i)/r and d eps/d|Y| ~ 1/r):
 *     A = 4 mu N sum w V (1 - cos phi)/r^2  e (x) e  +  lambda N^2 s (x) s,
 *     s = sum w V sin(phi)/r  e
 *   classical: A = (lambda + mu) k (x) k + mu |k|^2 I.
 * A is real and symmetric because each family holds xi and -xi. */
#ifndef PD_DISPERSION_H
#define PD_DISPERSION_H

#include "pd_lattice.h"
#include "pd_params.h"
#include "pd_tensor.h"

/* PD_LINEAR_PMB_FAMILY: PMB with its E calibrated on the family (c times
 * pd_pmb_moment_continuum over the family's sum w V |xi|), as pd/bond sets
 * it up; only pd_lattice_expected_error takes it (its model is a PMB). */
typedef enum pd_linear_kind {
  PD_LINEAR_PMB,
  PD_LINEAR_ORDINARY,
  PD_LINEAR_CLASSICAL,
  PD_LINEAR_PMB_FAMILY
} pd_linear_kind;

typedef struct pd_linear_model {
  pd_linear_kind kind;
  int dim;           /* 1, 2 or 3 */
  double c;          /* PMB micromodulus (per unit partner volume) */
  double lambda, mu; /* ordinary: lambda_bar, mu_bar (pd_ordinary_lame);
                        classical: the Lame constants of the (plane) material */
  double norm;       /* ordinary: N = d / m */
} pd_linear_model;

/* The models as the pair styles set them up from their inputs:
 * pd/bond with K (3D) or E (2D, 3D) or c; pd/ordinary with its elastic
 * constants, N from the family's weighted volume (its complete-family
 * normalization); classical with the constants either targets. */
pd_linear_model pd_linear_pmb_K(double K, double horizon);
pd_linear_model pd_linear_pmb_E(pd_dimension dim, double E, double horizon, double thickness);
pd_linear_model pd_linear_pmb_c(int dim, double c);
pd_linear_model pd_linear_ordinary(pd_dimension dim, const pd_elastic *m, const pd_family *f);
pd_linear_model pd_linear_classical(pd_dimension dim, const pd_elastic *m);
/* 1D: A = E k^2 (lambda = E, mu = 0). */
pd_linear_model pd_linear_classical_1d(double E);

/* A(k), 3 x 3 row-major (zero beyond dim). f is not used by classical. */
void pd_symbol(const pd_linear_model *m, const pd_family *f, const double k[3], double A[9]);

/* Effective elastic tensor of the family (both symmetries; pd_tensor.h's
 * Mandel form): PMB 1/2 sum c w V r e e e e; ordinary
 * lambda N^2 M (x) M + 2 mu N sum w V e e e e with M = sum w V e (x) e;
 * classical lambda I (x) I + 2 mu I_sym (over dim). Its acoustic tensor
 * C_ijkl k_j k_l is the k -> 0 limit of A(k). */
void pd_effective_tensor(const pd_linear_model *m, const pd_family *f, double C[PD_SYM4]);

/* C_ijkl k_j k_l. */
void pd_acoustic_tensor(const double C[PD_SYM4], const double k[3], double Q[9]);

/* Energy density 1/2 eps : C : eps of a symmetric strain (xx yy zz xy xz yz). */
double pd_strain_energy(const double C[PD_SYM4], const double eps[6]);

/* Relative errors of the energy of a lattice tensor against the classical
 * one in the strain modes that diagonalize both for a cubic or square
 * lattice (and hex, whose 4th-order tensors are isotropic in the plane):
 * uniform dilatation (eps = I), shear xx = -yy (principal axes along the
 * lattice axes; equals a simple shear at 45 degrees to them) and simple
 * shear xy (principal axes at 45 degrees). 'worst' is the largest
 * magnitude: for those lattices it bounds the energy error of any strain. */
typedef struct pd_moduli_error {
  double dilatation, shear_xx_yy, shear_xy, worst;
} pd_moduli_error;
pd_moduli_error pd_moduli_error_of(const double C[PD_SYM4], const double Cref[PD_SYM4], int dim);

/* The expected lattice error of the constants, for a style's setup report
 * and the accuracy report: the family of a site of 'lat' within 'cutoff'
 * (the horizon, or farther for partial cells) with the style's bond
 * weights, the model set up as the style sets it up (PMB: c from E with
 * bond-based elasticity's nu, against the classical solid of that E and
 * nu, and PMB_FAMILY that c calibrated on the family; ordinary: from e,
 * against e), its effective tensor against the
 * classical one. Returns 0, or -1 (no bond, no memory; out->worst NaN). */
int pd_lattice_expected_error(const pd_lattice *lat, pd_linear_kind model, pd_dimension dim,
                              const pd_elastic *e, double horizon, double cutoff, double thickness,
                              pd_weight_fn weight, void *ctx, pd_moduli_error *out);

#endif
