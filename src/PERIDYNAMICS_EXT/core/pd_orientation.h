/* How much fracture energy one family releases across a plane, by the
 * plane's orientation: the lattice sum of the bonds that cross it.
 *
 * Pairs i, j = i + xi with xi . n > 0 straddle a plane of normal n; per unit
 * area there are (xi . n) / V of them (V the volume per particle), so a
 * plane releases G(n) = sum over xi . n > 0 of (xi . n) phi(xi) / V, with
 * phi the energy of one broken pair. Both failure laws are calibrated on
 * the family itself, so that G averaged over orientations is G_c; a
 * discrete family makes G depend on n about that mean. The setup report
 * prints G(n) / G_c; the accuracy report sweeps it. */
#ifndef PD_ORIENTATION_H
#define PD_ORIENTATION_H

#include "pd_lattice.h"

typedef enum pd_release_kind {
  /* fail energy, calibrated on this family averaged over orientations
   * (pd_energy_failure_beta_lattice), with its uniform profile: phi ~ w */
  PD_RELEASE_ENERGY_UNIFORM,
  /* ... with the opening profile: phi ~ w / |xi|^2 */
  PD_RELEASE_ENERGY_OPENING,
  /* a bond-based pair broken at the critical stretch calibrated on this
   * family averaged over orientations (pd_critical_stretch_factor):
   * phi ~ w |xi| */
  PD_RELEASE_BOND_BASED,
  /* an ordinary state-based pair broken at the critical stretch
   * calibrated on this family (pd_critical_stretch_ordinary): phi ~ w,
   * its bond part (with the dilatation's: pd_release_ordinary) */
  PD_RELEASE_ORDINARY_STRETCH
} pd_release_kind;

/* G(n) / G_c across a plane of unit normal n, for a complete family f
 * (pd_lattice.h). */
double pd_release(const pd_family *f, pd_release_kind kind, const double n[3]);

/* The smallest and largest G(n) / G_c over orientations: 360 normals in the
 * xy plane (2D) or 4000 spread evenly over the sphere (3D). */
void pd_release_range(const pd_family *f, pd_release_kind kind, double *lo, double *hi);

/* The same for an ordinary state-based solid broken at the critical
 * stretch calibrated on this family (pd_critical_stretch_ordinary) with
 * the dilatation's share of the release taken on it
 * (pd_ordinary_family_release), lambda / mu of the bond moduli = ratio:
 * the bond part and the dilatation part (pd_ordinary_release_at) across
 * n against their calibrated orientation average. The range takes 1000
 * normals in 3D (each costs a sum over pairs of crossing bonds). */
double pd_release_ordinary(const pd_family *f, double ratio, const double n[3]);
void pd_release_ordinary_range(const pd_family *f, double ratio, double *lo, double *hi);

/* The k-th of count unit normals spread evenly over the directions: on the
 * xy plane's circle (dim 2) or over the sphere (3). */
void pd_spread_normal(int dim, int k, int count, double n[3]);

#endif
