/* Each family calibrated on itself: a particle's constants and its bonds'
 * breaking thresholds come from sums over the reference family it actually
 * has (weighted volume, failure moment), not from a complete continuum or
 * lattice family, so that a uniform dilatation loads every interior
 * particle as the classical solid on any arrangement (lattices, jittered
 * points, particles of unequal volumes).
 *
 * A particle within a horizon of a free surface has lost part of its family
 * to the surface. Without surface correction it is not renormalized (T14
 * 6.1.3): it takes the sums of a complete family of its type (the median
 * over the type's interior particles). Which particles are interior is
 * read off the family volume v against the type's interior family volume
 * v_int (the median over the particles within PD_CALIBRATION_WINDOW of
 * it), with a tolerance tol for the scatter of interior family volumes
 * that an irregular arrangement has: the share of its own sums is
 *   s = clamp((v / v_int - (1 - 2 tol)) / tol, 0, 1),
 * 1 for interior particles, 0 for those that lost more than 2 tol of their
 * family, a linear blend between (no jump in stiffness across the layer).
 * The calibrated sum is s q + (1 - s) q_complete. */
#ifndef PD_CALIBRATION_H
#define PD_CALIBRATION_H

/* Family volumes within this share of the type's interior one may be
 * interior: a particle on a flat surface has lost half its family, and
 * jittered interior families scatter by a few per cent (positions +-0.25
 * spacings, volumes +-30%: 3% in 3D, 6% in 2D at 3 spacings). */
#define PD_CALIBRATION_WINDOW 0.25

/* The tolerance for a relative scatter of interior family volumes (a
 * robust standard deviation: 1.4826 times the median absolute deviation):
 * four of them, at least 1e-9 (a lattice, whose interior families agree
 * to round-off: any atom that lost a bond takes the complete family), at
 * most the window. */
double pd_calibration_tolerance(double scatter);

/* Share of a particle's own sums, from its completeness v / v_int. */
double pd_calibration_share(double completeness, double tolerance);

/* s q + (1 - s) q_complete; a q within round-off (1e-12 relative) of
 * q_complete is q_complete itself, so that the particles of a lattice share
 * one value exactly (and the loops may take it as a constant). */
double pd_calibrated(double own, double complete, double share);

/* The family moments the calibrations take, at both ends of every bond
 * (broken or not): moment_i += w V_j |xi|^power. power -1: the energy law's
 * failure moment (pd_law_energy.h); 1: a bond-based solid's stiffness
 * (pd_bond_based.h); 2: the energy of its bonds broken at one critical
 * stretch (pd_law_stretch.h). */
struct pd_bond_view;
void pd_family_moment(const struct pd_bond_view *b, const double *vol, int power, double *moment);

#endif
