/* The stable time step of the current state (fix pd/timestep), for every
 * material: each particle's bound on its current stiffness.
 *
 * A central bond force t(|Y|) along Y couples its two ends through the 3x3
 * block K_ij = t' e(x)e + (t/|Y|) (I - e(x)e), whose spectral norm is
 * |C| = max(|t'|, |t|/|Y|): the axial tangent and the string (geometric)
 * stiffness. Block Gershgorin on M^-1 K (each atom's diagonal block is the
 * sum of its bonds' blocks, so it adds as much again) bounds every
 * eigenvalue: |lambda| <= max_i (2/rho_i) sum_j V_j |C_ij|. The central
 * difference scheme is stable for dt <= 2/sqrt(lambda_max), hence
 *   dt_i = sqrt(2 rho_i / sum_j V_j |C_ij|),
 * MS07 eq. 43 with the bond's current tangent in place of its reference
 * micromodulus (both agree in the reference state of a bond-based solid).
 * A state-based bond also couples through its ends' dilatation; its bound
 * (k_i + k_j) w g^2 generalizes the reference one of pd_ordinary_stiffness
 * with the strain's current rate g = d eps/d|Y| (Cauchy-Schwarz bounds the
 * dilatation coupling by it, as in the reference state).
 * unittest/core/test_tangent.c checks the bounds against the largest
 * eigenvalue of the assembled stiffness matrix. */
#ifndef PD_TANGENT_H
#define PD_TANGENT_H

#include "pd_bonds.h"
#include "pd_loop.h"

/* sum[i] += |C| V_j and sum[j] += |C| V_i over the bonds that act now
 * (intact ones, and broken ones while they push: pd_bond_inactive). The
 * caller zeroes sum over owned and ghost atoms and adds the ghosts' share
 * onto their owners. L->f and L->tally are not used.
 * With velocities v (3 per atom, owned + ghost; or NULL), closing[] gets
 * at both ends the largest rate at which a bond closes, relative to its
 * length: max(0, -d|Y|/dt) / |Y| (1/time; the caller takes the ghosts'
 * largest onto their owners): the estimate linearizes about the current
 * lengths, so a step must not close a bond by much of its length. */
typedef struct pd_pmb_tangent pd_pmb_tangent;
typedef struct pd_state_tangent pd_state_tangent;
void pd_pmb_tangent_sums(const pd_loop *L, const double *v, const pd_pmb_tangent *mat, double *sum,
                         double *closing);
void pd_state_tangent_sums(const pd_loop *L, const double *v, const pd_state_tangent *mat,
                           double *sum, double *closing);

/* The relative closing rate of a pair d = x_j - x_i of length len at
 * velocities vi, vj: max(0, -d|Y|/dt) / |Y|. */
static inline double pd_closing_rate(const double d[3], double len, const double *vi, const double *vj)
{
  const double rate = -((vj[0] - vi[0]) * d[0] + (vj[1] - vi[1]) * d[1] + (vj[2] - vi[2]) * d[2]);
  return rate > 0.0 && len > 0.0 ? rate / (len * len) : 0.0;
}

/* Bond-based (pd_pmb, MS07 eq. 14): t = c w s. */
struct pd_pmb_tangent {
  const double *c;        /* micromodulus per type pair (pd_pmb.c) */
  const double *plastic;  /* per-bond plastic stretch (microplastic), or NULL */
};

/* State-based (pd_ordinary.h; pd/corr as its ordinary counterpart):
 * axial (k_i + k_j) w g^2 + |A_i + A_j + (B_i + B_j) eps| w |dg/d|Y||,
 * string |t| / |Y| with t = (A_i + A_j + (B_i + B_j) eps) w g. k per atom
 * (owned + ghost) is the reference coefficient of pd_ordinary_stiffness;
 * ab (A, B per atom as pd_ordinary_state.ab) may be NULL: no stress terms. */
struct pd_state_tangent {
  double order;       /* Seth-Hill order m of the bond strain */
  const double *k;
  const double *ab;
};

/* Contact spring (pd_contact.h) of stiffness cs at distance dist, its
 * particles len apart: max(cs/dist, cs (dist - len)/(dist len)), per unit
 * V_i V_j; 0 beyond dist + reach (reach: how much closer the pair may come
 * before the next estimate). */
double pd_contact_tangent(double cs, double dist, double len, double reach);

#endif
