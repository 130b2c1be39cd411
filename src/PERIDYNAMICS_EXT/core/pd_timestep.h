/* Stable time step of the explicit scheme, linearized (MS07 eq. 43):
 * dt_i = sqrt(2 rho_i / sum_bonds V_other |C_bond|). Each material sums its
 * bonds' |C| onto both ends (pd_pmb_stiffness, pd_ordinary_stiffness); the
 * caller adds the ghosts' share onto their owners. */
#ifndef PD_TIMESTEP_H
#define PD_TIMESTEP_H

/* sqrt(2 rho / sum), or +inf for an atom without bonds. */
double pd_stable_dt(double rho, double sum);

#endif
