/* Stable time step of the explicit scheme, linearized (MS07 eq. 43):
 * dt_i = sqrt(2 rho_i / sum_bonds V_other |C_bond|). Each material sums its
 * bonds' |C| onto both ends (pd_pmb_stiffness, pd_ordinary_stiffness); the
 * caller adds the ghosts' share onto their owners. */
#ifndef PD_TIMESTEP_H
#define PD_TIMESTEP_H

#include <math.h>

/* sqrt(2 rho / sum), or +inf for an atom without bonds. */
double pd_stable_dt(double rho, double sum);

/* A particle's speed |v| and acceleration |a| = ftm2v |f| / mass: what the
 * travel limits take (inline: the per-step count vectorizes with it). */
static inline void pd_particle_motion(const double v[3], const double f[3], double mass,
                                      double ftm2v, double *speed, double *accel)
{
  *speed = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  *accel = ftm2v * sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]) / mass;
}

/* How many of n particles (v, f: 3 per particle; mass; volume) move more
 * than 'travel' of their spacing in a step dt, v dt + |a| dt^2 / 2 with
 * a = ftm2v f / mass. Compared in the spacing's d-th power (the volume, or
 * volume / thickness in 2D) so that no root of the volume is taken: cheap
 * enough for every step. */
int pd_travel_count(int n, const double *v, const double *f, const double *rmass,
                    const double *vol, double dt, double ftm2v, double travel, int dim,
                    double thickness);

#endif
