#include "pd_timestep.h"

#include <math.h>

double pd_stable_dt(double rho, double sum)
{
  return sum > 0.0 ? sqrt(2.0 * rho / sum) : INFINITY;
}

/* (dim a constant in each copy, and no early exit: the loop vectorizes) */
static inline int travel_count(int n, const double *restrict v, const double *restrict f,
                               const double *restrict rmass, const double *restrict vol, double dt,
                               double ftm2v, double travel, int dim, double thickness)
{
  int count = 0;
  for (int i = 0; i < n; i++) {
    double speed, accel;
    pd_particle_motion(v + 3 * i, f + 3 * i, rmass[i], ftm2v, &speed, &accel);
    const double moved = (speed * dt + 0.5 * accel * dt * dt) / travel;
    const double cell = dim == 3 ? vol[i] : vol[i] / thickness;
    count += (dim == 3 ? moved * moved * moved : moved * moved) > cell;
  }
  return count;
}

int pd_travel_count(int n, const double *v, const double *f, const double *rmass,
                    const double *vol, double dt, double ftm2v, double travel, int dim,
                    double thickness)
{
  if (dim == 3) return travel_count(n, v, f, rmass, vol, dt, ftm2v, travel, 3, thickness);
  return travel_count(n, v, f, rmass, vol, dt, ftm2v, travel, 2, thickness);
}
