/* Stable time step of the explicit scheme, linearized (MS07 eq. 43):
 * dt_i = sqrt(2 rho_i / sum_bonds V_other |C_bond|). The sums run over both
 * ends of each bond; the caller adds the ghosts' share onto their owners. */
#ifndef PD_TIMESTEP_H
#define PD_TIMESTEP_H

#include "pd_bond_based.h"
#include "pd_bonds.h"

/* PMB: |C| = c w / |xi| (MS07 eq. 41). */
void pd_pmb_stiffness(const pd_bond_view *b, const pd_pmb *mat, const int *type,
                      const double *vol, double *sum);

/* Ordinary solid: |C| <= (k_i + k_j) w / |xi|^2 with k = N (2 mu + d |lambda|)
 * per atom; the d |lambda| part bounds the coupling through the dilatation
 * (Cauchy-Schwarz over the family). */
void pd_ordinary_stiffness(const pd_bond_view *b, const double *k,
                           const double *vol, double *sum);

/* sqrt(2 rho / sum), or +inf for an atom without bonds. */
double pd_stable_dt(double rho, double sum);

#endif
