/* Energy-based failure (T14 eq. 6.1-6.5): an intact bond in tension breaks
 * when the instantaneous energies it stores at its two ends, per partner
 * volume (the material's release_i, release_j), reach
 * s_c(i) + s_c(j) = G_c w (crit_i + crit_j) |xi|^q, crit = beta N per unit
 * G_c, G_c of the bond's type pair (an interface has its own). The
 * bond-failure-energy profile |xi|^q is a constitutive choice (T14 6.1.1). */
#ifndef PD_LAW_ENERGY_H
#define PD_LAW_ENERGY_H

#include "pd_failure.h"
#include "pd_influence.h"

/* s_c(xi) = beta omega |xi|^q */
typedef enum pd_energy_profile {
  /* q = 0: every bond holds beta omega, whatever its length: under a
   * uniform strain, bonds along one direction with a constant influence
   * break together */
  PD_PROFILE_UNIFORM,
  /* q = -2 (T14 eq. 6.3): for a linear bond-based solid a critical opening
   * |Y| - |xi| of every bond; long bonds break first */
  PD_PROFILE_OPENING
} pd_energy_profile;

PD_INLINE int pd_energy_profile_power(pd_energy_profile profile)
{
  return profile == PD_PROFILE_OPENING ? -2 : 0;
}

typedef struct pd_law_energy {
  const double *crit;  /* per atom beta N for G_c = 1 (owned + ghost) */
  double crit_floor;   /* the smallest of them */
  const double *gc;    /* per type pair G_c (+inf: the pair does not fail) */
  /* the bond's length factor f = unit + opening |xi|, exactly 1 (uniform)
   * or |xi| (opening), f^2 = |xi|^-q: the test is release f^2 >=
   * w (crit_i + crit_j) G_c */
  double unit, opening;
} pd_law_energy;

/* unit and opening of a profile, from its power (f^2 = |xi|^-q) */
PD_INLINE void pd_law_energy_profile(pd_law_energy *p, pd_energy_profile profile)
{
  p->opening = pd_energy_profile_power(profile) == -2 ? 1.0 : 0.0;
  p->unit = 1.0 - p->opening;
}

/* The test with the far end's crit given: in tension, the released
 * energies (their sum as the material computes it, release) reach the
 * threshold. '&', not '&&': no branch, so the bond loop's first pass
 * vectorizes; (crit_i + crit_far) G_c first: in the screen, a row's
 * constant (with pd_bond_force.release, pd/ordinary's energy law 1.26x ->
 * 1.18x the cycles of its elastic passes, llvm-mca's model of Zen 3). */
PD_INLINE int pd_law_energy_reached(const pd_law_energy *p, const pd_bond *bd, double eps,
                                        const pd_bond_force *bf, double crit_far)
{
  const double f = p->unit + p->opening * bd->r0;
  return (eps > 0.0) & (bf->release * f * f >= bd->w * ((p->crit[bd->i] + crit_far) * p->gc[bd->tij]));
}

PD_INLINE int pd_law_energy_now(const pd_failure *f, const pd_bond *bd, double eps,
                                    const pd_bond_force *bf)
{
  const pd_law_energy *p = (const pd_law_energy *) f->params;
  return pd_law_energy_reached(p, bd, eps, bf, p->crit[bd->j]);
}

/* with the far end's crit at its floor: no per-atom load but the owner's
 * (the same in a whole row) */
PD_INLINE int pd_law_energy_ahead(const pd_failure *f, const pd_bond *bd, double eps,
                                      const pd_bond_force *bf)
{
  const pd_law_energy *p = (const pd_law_energy *) f->params;
  return pd_law_energy_reached(p, bd, eps, bf, p->crit_floor);
}

PD_INLINE int pd_law_energy_after(const pd_failure *f, const pd_bond *bd, double eps)
{
  (void) f, (void) bd, (void) eps;
  return 0;
}

PD_INLINE int pd_law_energy_takes_notes(void) { return PD_NOTES_NONE; }

PD_INLINE double pd_law_energy_notes(const pd_failure *f, const pd_bond *bd)
{
  (void) f, (void) bd;
  return 0.0;
}

/* Calibration. s_c(xi) = beta omega |xi|^q with omega the influence
 * function normalized to integrate to d over the horizon. Cutting every
 * bond across a unit area releases, bond by bond, s_c at both ends:
 * G_c = 2 I with I = pi int_0^delta r^(3+q) omega dr (3D) or
 * 2 int_0^delta r^(2+q) omega dr (2D), integrated numerically here.
 * Returns beta for a given G_c, or a negative value when the integral
 * diverges (the 2D inverse influence with the opening profile). */
double pd_energy_failure_beta(pd_influence_kind kind, pd_energy_profile profile, int dim, double delta,
                              double Gc);

/* The same calibration on the lattice actually used: the sum over a
 * complete family replaces the integral, and the crack orientation is
 * averaged (the mean of max(cos, 0) is 1/pi in 2D, 1/4 in 3D), so that
 * cutting bonds across a plane of any orientation releases G_c on average:
 * G = 2 beta N <cos+> sum w V |xi|^(q+1), N = d / (sum w V). The sums are
 * those of one complete family: its weighted volume and its failure moment
 * sum w V |xi|^(q+1) (pd_family_moment of power q + 1). On a simple cubic
 * or square lattice a crack along the lattice axes then releases 0.97
 * (uniform) or 0.92-0.95 G_c (opening) at delta = 3 spacings; the continuum
 * calibration above gives 0.76 G_c in 2D at delta = 3 spacings with a
 * constant omega and the opening profile. */
double pd_energy_failure_beta_lattice(int dim, double Gc, double weighted_volume, double moment);


#endif
