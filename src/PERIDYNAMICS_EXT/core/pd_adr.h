/* Adaptive dynamic relaxation (KM10: A. Kilic and E. Madenci, "An adaptive
 * dynamic relaxation method for quasi-static simulations using the
 * peridynamic theory", Theor. Appl. Fract. Mech. 53 (2010) 194-204).
 *
 * The static equations F(U) = 0 (F the force density on each particle) are
 * solved as the steady state of damped fictitious dynamics
 *   lambda U'' + c lambda U' = F(U)
 * integrated by central differences in a pseudo time with step dt = 1:
 *   V^{n+1/2} = ((2 - c_n) V^{n-1/2} + 2 F^n / lambda) / (2 + c_n)   (KM10 eq. 17)
 *   U^{n+1}   = U^n + V^{n+1/2}                                       (KM10 eq. 18)
 *   V^{1/2}   = F^0 / (2 lambda)                                      (KM10 eq. 19, from rest)
 * lambda is a diagonal fictitious density, large enough for central
 * differences to be stable at dt = 1 (KM10 eq. 20, Gershgorin):
 *   lambda_i >= (1/4) dt^2 sum_j |K_ij|.
 * With S_i = sum_j V_j |C_ij| (the stiffness sum of pd_tangent.h: the
 * off-diagonal blocks of row i; its diagonal block adds as much again)
 * sum_j |K_ij| <= 2 S_i, so lambda_i = safety S_i / 2.
 * The damping is the critical one of the lowest mode present, from the
 * Rayleigh quotient of a local diagonal stiffness (KM10 eq. 21-22):
 *   K1_kk = -(F_k^n - F_k^{n-1}) / (lambda_k V_k^{n-1/2})   (0 where V_k = 0)
 *   c_n   = 2 sqrt(U^T K1 U / U^T U)
 * with the sums over every degree of freedom (the caller reduces them over
 * all ranks; a component whose |K1_kk| exceeds PD_ADR_K1MAX counts as one
 * whose velocity is 0); a negative quotient (softening, unloading) gives c_n = 0 and
 * c_n is kept below PD_ADR_CMAX so that 2 - c_n stays positive.
 * Units: F a force density, lambda a force density per length (the pseudo
 * step is 1), V and U lengths; c_n is per pseudo step. */
#ifndef PD_ADR_H
#define PD_ADR_H

#include <math.h>

/* The largest damping: 2 - c stays positive, so a pseudo velocity keeps
 * its sign from one iteration to the next unless the force turns it. */
#define PD_ADR_CMAX 1.99

/* lambda_i from the stiffness sum S_i (force density per length) and a
 * safety factor >= 1; 0 for a particle without stiffness (it is held). */
double pd_adr_density(double stiffness_sum, double safety);

/* c_n from the global sums U^T K1 U and U^T U. */
double pd_adr_damping(double uku, double uu);

/* The largest |K1_kk| that means a stiffness: with lambda at the
 * stability bound no mode of lambda^-1 K exceeds (2 / dt)^2 = 4. A larger
 * quotient divides by a velocity passing through 0 (its round-off), and
 * such a component counts as one whose velocity is 0: one particle at its
 * turning point would otherwise set c_n to its limit. */
#define PD_ADR_K1MAX 4.0

/* Adds one particle's share of U^T K1 U and U^T U over its ndof (2 or 3)
 * components: f = F^n, fprev = F^{n-1}, v = V^{n-1/2}, u = U^n. */
static inline void pd_adr_rayleigh_terms(int ndof, const double *f, const double *fprev,
                                         double lambda, const double *v, const double *u,
                                         double *uku, double *uu)
{
  for (int k = 0; k < ndof; k++) {
    *uu += u[k] * u[k];
    if (!(lambda > 0.0) || v[k] == 0.0) continue;
    const double dv = -(f[k] - fprev[k]) / lambda;    /* K1_kk V_k */
    if (fabs(dv) <= PD_ADR_K1MAX * fabs(v[k])) *uku += dv / v[k] * u[k] * u[k];
  }
}

/* V^{n-1/2} -> V^{n+1/2} in place (KM10 eq. 17); a held particle
 * (lambda = 0) does not move. */
static inline void pd_adr_velocity(int ndof, double c, const double *f, double lambda, double *v)
{
  for (int k = 0; k < ndof; k++)
    v[k] = lambda > 0.0 ? ((2.0 - c) * v[k] + 2.0 * f[k] / lambda) / (2.0 + c) : 0.0;
}

/* V^{1/2} from rest (KM10 eq. 19). */
static inline void pd_adr_start(int ndof, const double *f, double lambda, double *v)
{
  for (int k = 0; k < ndof; k++) v[k] = lambda > 0.0 ? f[k] / (2.0 * lambda) : 0.0;
}

#endif
