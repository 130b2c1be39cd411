/* Stable time step of the explicit scheme, linearized (MS07 eq. 43):
 * dt_i = sqrt(2 rho_i / sum_bonds V_other |C_bond|). Each material sums its
 * bonds' |C| onto both ends (pd_pmb_stiffness, pd_ordinary_stiffness); the
 * caller adds the ghosts' share onto their owners. */
#ifndef PD_TIMESTEP_H
#define PD_TIMESTEP_H

/* sqrt(2 rho / sum), or +inf for an atom without bonds. */
double pd_stable_dt(double rho, double sum);

/* How many of n particles (v, f: 3 per particle; mass; volume) move more
 * than 'travel' of their spacing in a step dt, v dt + |a| dt^2 / 2 with
 * a = ftm2v f / mass. Compared in the spacing's d-th power (the volume, or
 * volume / thickness in 2D) so that no root of the volume is taken: cheap
 * enough for every step. */
int pd_travel_count(int n, const double *v, const double *f, const double *rmass,
                    const double *vol, double dt, double ftm2v, double travel, int dim,
                    double thickness);

#endif
