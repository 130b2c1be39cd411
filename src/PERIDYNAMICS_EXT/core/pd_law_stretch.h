/* Critical stretch (MS07 eq. 25-29): an intact bond breaks once its stretch
 * exceeds s0 of its type pair, in the evaluation where it does; with
 * 'after', once its force acted (PERI's rule whose s0 is s00 for every
 * atom: pd_law_legacy.cpp runs it so, without per-bond notes). */
#ifndef PD_LAW_STRETCH_H
#define PD_LAW_STRETCH_H

#include "pd_failure.h"

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

#endif
