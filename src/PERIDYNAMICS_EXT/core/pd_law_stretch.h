/* Critical stretch (MS07 eq. 25-29): an intact bond breaks once its stretch
 * exceeds s0 of its type pair, in the evaluation where it does; with
 * 'after', once its force acted (PERI's rule whose s0 is s00 for every
 * atom: pd_law_legacy.cpp runs it so, without per-bond notes). */
#ifndef PD_LAW_STRETCH_H
#define PD_LAW_STRETCH_H

#include "pd_failure.h"
#include "pd_influence.h"

typedef struct pd_law_stretch {
  const double *s0;    /* per type pair (+inf: the pair does not fail) */
  int after;           /* the bond breaks after its force acted, not before */
} pd_law_stretch;

PD_INLINE int pd_law_stretch_now(const pd_failure *f, const pd_bond *bd, double eps,
                                     const pd_bond_force *bf)
{
  (void) eps, (void) bf;
  const pd_law_stretch *p = (const pd_law_stretch *) f->params;
  return !p->after && pd_bond_stretch(bd) > p->s0[bd->tij];
}

/* (a test per bond here costs nothing: only bonds that the screen below
 * lets through, and rows with broken bonds, come bond by bond) */
PD_INLINE int pd_law_stretch_after(const pd_failure *f, const pd_bond *bd, double eps)
{
  (void) eps;
  const pd_law_stretch *p = (const pd_law_stretch *) f->params;
  return p->after && pd_bond_stretch(bd) > p->s0[bd->tij];
}

/* |Y| - |xi| > s0 |xi|, with s0 (> 0) a little smaller: every bond that
 * _now or _after breaks passes (its stretch is within a few ulps of this quotient), and
 * an elastic step computes no stretch for it (pd/bond's cost of the law
 * on AVX2 1.24x -> 1.06-1.14x) */
PD_INLINE int pd_law_stretch_ahead(const pd_failure *f, const pd_bond *bd, double eps,
                                       const pd_bond_force *bf)
{
  (void) eps, (void) bf;
  const pd_law_stretch *p = (const pd_law_stretch *) f->params;
  return bd->len - bd->r0 > p->s0[bd->tij] * (1.0 - 1e-12) * bd->r0;
}

PD_INLINE int pd_law_stretch_takes_notes(void) { return PD_NOTES_NONE; }

PD_INLINE double pd_law_stretch_notes(const pd_failure *f, const pd_bond *bd)
{
  (void) f, (void) bd;
  return 0.0;
}

/* Critical stretch from the fracture energy for bond-based elasticity
 * (MS07 eq. 28-29 and the 2D analogues in THEORY.md): 3D sqrt(5 G / (9 K
 * delta)) with K = E / (3 (1 - 2 nu)), plane stress sqrt(4 pi G / (9 E delta)),
 * plane strain sqrt(5 pi G / (12 E delta)). dim: 3, or 2 with plane = 0
 * (stress) or 1 (strain). */
double pd_critical_stretch(int dim, int plane_strain, double E, double nu, double delta, double Gc);

/* That critical stretch calibrated on a family: bonds broken at s0 release
 * c s0^2 |xi| w / 2 each, and across planes of every orientation, on
 * average, c s0^2 <cos+> sum w V |xi|^2 / 2 per unit area (<cos+> the mean of
 * the positive part of the cosine: 1/4 in 3D, 1/pi in 2D); the continuum
 * calibration above takes the integral of |xi|^2 over the horizon (times
 * t in 2D) in place of the sum. With the stiffness scaled by 'stiffness'
 * (a bond-based solid calibrated on the family: pd_pmb_moment_continuum),
 * s0 is multiplied by sqrt(integral / (stiffness sum)), the factor this
 * returns for moment2 = sum w V |xi|^2 (pd_family_moment of power 2); 1 for
 * a family without bonds. */
double pd_critical_stretch_factor(int dim, double delta, double thickness, double stiffness, double moment2);

/* The critical stretch of an ordinary state-based solid (pd_ordinary.h),
 * calibrated on a family as the energy law is: a bond broken at strain s0
 * releases at its two ends w s0 (A + B s0 / 2) each, B = 2 mu N, N = d / m,
 * A = lambda N theta. The B part is 2 mu N w s0^2 per unit partner volume,
 * across planes of every orientation, on average, 2 mu N s0^2 <cos+>
 * sum w V |xi| per unit area; the A part adds kappa lambda / mu of that
 * (pd_ordinary_dilatation_release). So
 * s0 = sqrt(G_c m / (2 mu d <cos+> moment1 (1 + kappa lambda / mu))), m the
 * weighted volume sum w V and moment1 = sum w V |xi| (pd_family_moment of
 * power 1); NaN for a family without bonds, mu <= 0 or a released energy
 * that would not be positive. */
double pd_critical_stretch_ordinary(int dim, double Gc, double lambda, double mu, double kappa,
                                    double weighted_volume, double moment1);

/* kappa: what the dilatation's part of the released energy adds, per unit
 * lambda / mu, when two half-spaces of the continuum are pulled apart
 * rigidly (the separation that defines G_c): a bond crossing the plane
 * breaks at the opening u where its strain u (xi.n) / |xi|^2 reaches s0;
 * then the dilatation of each end, at depth z, is N sum w eps V over its
 * crossing bonds still intact. Integrated over z, the bonds and their
 * order of breaking on a grid (0.28 in 3D and 0.20 in 2D with omega = 1;
 * independent of s0 and delta). */
double pd_ordinary_dilatation_release(pd_influence_kind kind, int dim);

/* kappa on a family as the particles have it (the continuum's integral is
 * its limit at fine resolution: a family of 3 spacings on the square
 * lattice has 0.244 for 0.196). Per normal n of a spread
 * (PD_RELEASE_NORMALS: pd_spread_normal; kappa(n) has kinks at the lattice
 * planes, and 64 normals in 2D made it 1.7% large), a crossing bond b (xi.n > 0) breaks at the
 * opening |xi| / cos in units of s0 and strains by cos / |xi| per unit
 * opening; an end at depth z feels the bonds that cross from there (z <
 * xi.n). So the dilatation part is
 *   pairs(n) = (d / m) sum over crossing b, b' with b' breaking no earlier
 *              than b of w_b w_b' (|xi_b| / cos_b) (cos_b' / |xi_b'|) min(xi_b.n, xi_b'.n)
 * (pairs that break together count both ways: each sees the other intact),
 * against across(n) = sum over crossing b of w_b |xi_b| cos_b, with w a
 * bond's weight times its partner's volume and m = sum w. Adds the sums
 * of pairs(n) and across(n) over the spread to sums[0] and sums[1], so
 * that kappa = sums[0] / sums[1] over one family or a sample of them. A
 * family without bonds adds nothing. */
#define PD_RELEASE_NORMALS(dim) ((dim) == 3 ? 128 : 360)
struct pd_family;
void pd_ordinary_family_release(const struct pd_family *f, double sums[2]);
/* pairs(n) and across(n) of one normal */
void pd_ordinary_release_at(const struct pd_family *f, const double n[3], double *pairs, double *across);

#endif
