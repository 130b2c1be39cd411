/* Short-range contact (MS07 eq. 32-34): a repulsive force between particles
 * closer than their contact distance d = r_i + r_j,
 *   F_ij = V_i V_j c_s (1 - |Y| / d)   (pushing apart, |Y| < d),
 * equal and opposite whatever the volumes (legacy PERI uses V_j only), with
 * the energy V_i V_j c_s (d - |Y|)^2 / (2 d). Node radius r = s / 2 with s
 * the particle spacing, cbrt(V) in 3D, sqrt(V / thickness) in 2D. */
#ifndef PD_CONTACT_H
#define PD_CONTACT_H

#include "pd_bonds.h"

#include <math.h>

/* Node radius from the particle volume (dim 3, or 2 with thickness). */
static inline double pd_contact_radius(int dim, double vol, double thickness)
{
  return 0.5 * (dim == 3 ? cbrt(vol) : sqrt(vol / thickness));
}

/* One candidate pair: adds the force densities to f_i and f_j (3 each) and,
 * when tally is not NULL, the energy (half to each end) and virial.
 * d[] = x_j - x_i. With mu > 0 and dv[] = v_j - v_i, Coulomb friction of
 * magnitude mu times the normal force opposes the tangential slip
 * (Peridigm's contact friction); it dissipates and has no energy.
 * Returns 1 if the pair was in contact. */
static inline int pd_contact_pair(double cs, double dist, double mu, double vi, double vj,
                                  const double d[3], const double *dv, double *fi, double *fj,
                                  pd_tally *tally, int i, int j)
{
  const double r2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
  if (r2 >= dist * dist) return 0;
  const double len = sqrt(r2);
  const double push = cs * (1.0 - len / dist);    /* per unit V_i V_j */
  const double tl = len > 0.0 ? -push / len : 0.0;  /* along d: negative = apart */
  for (int c = 0; c < 3; c++) {
    fi[c] += vj * tl * d[c];
    fj[c] -= vi * tl * d[c];
  }
  if (mu > 0.0 && len > 0.0) {
    const double n[3] = {d[0] / len, d[1] / len, d[2] / len};
    const double vn = dv[0] * n[0] + dv[1] * n[1] + dv[2] * n[2];
    const double vt[3] = {dv[0] - vn * n[0], dv[1] - vn * n[1], dv[2] - vn * n[2]};
    const double slip = sqrt(vt[0] * vt[0] + vt[1] * vt[1] + vt[2] * vt[2]);
    if (slip > 0.0) {
      const double ft = mu * push / slip;    /* i is dragged along j's slip */
      for (int c = 0; c < 3; c++) {
        fi[c] += vj * ft * vt[c];
        fj[c] -= vi * ft * vt[c];
      }
    }
  }
  if (tally) {
    const double e = 0.25 * cs * (dist - len) * (dist - len) / dist;    /* half of the pair's */
    tally->energy += e * (vi + vj);
    if (tally->eatom) {
      tally->eatom[i] += e * vj;
      tally->eatom[j] += e * vi;
    }
    const double dij[3] = {-d[0], -d[1], -d[2]};
    pd_tally_virial(tally, i, j, dij, -tl * vi * vj);
  }
  return 1;
}

/* LAMMPS PERI's contact (peri/pmb, peri/lps), reproduced for comparison:
 * acting below d = min(0.9 |xi|, 1.35 lc), a force density of magnitude
 * 15 c V_j (d - |Y|) / delta on both ends (V_j only: it conserves momentum
 * only for equal volumes), energy 15 c V_j (d - |Y|)^2 / (2 delta).
 * d[] = x_j - x_i. */
static inline void pd_contact_legacy_pair(double c, double delta, double dist, double vi, double vj,
                                          const double d[3], double *fi, double *fj,
                                          pd_tally *tally, int i, int j)
{
  const double r2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
  if (r2 >= dist * dist) return;
  const double len = sqrt(r2), dr = len - dist;
  const double rk = 15.0 * c * vj * dr / delta;
  const double tl = len > 0.0 ? rk / len : 0.0;    /* along d, as PERI's fpair */
  for (int k = 0; k < 3; k++) {
    fi[k] += tl * d[k];
    fj[k] -= tl * d[k];
  }
  if (tally) {
    const double e = 0.5 * rk * dr;
    tally->energy += e;
    if (tally->eatom) {
      tally->eatom[i] += 0.5 * e;
      tally->eatom[j] += 0.5 * e;
    }
    const double dij[3] = {-d[0], -d[1], -d[2]};
    pd_tally_virial(tally, i, j, dij, -tl * vi);    /* PERI: fpair V_i, a true force */
  }
}

#endif
