/* Energy-based failure (T14 eq. 6.1-6.5): an intact bond in tension breaks
 * when the instantaneous energies it stores at its two ends, per partner
 * volume (the material's release_i, release_j), reach
 * s_c(i) + s_c(j) = G_c w (crit_i + crit_j) / |xi|^2, crit = beta N per unit
 * G_c, G_c of the bond's type pair (an interface has its own). */
#ifndef PD_LAW_ENERGY_H
#define PD_LAW_ENERGY_H

#include "pd_failure.h"
#include "pd_influence.h"

typedef struct pd_law_energy {
  const double *crit;  /* per atom beta N for G_c = 1 (owned + ghost) */
  double crit_floor;   /* the smallest of them */
  const double *gc;    /* per type pair G_c (+inf: the pair does not fail) */
} pd_law_energy;

/* The test with the far end's crit given: in tension, the released
 * energies (their sum as the material computes it, release) reach the
 * threshold. '&', not '&&': no branch, so the bond loop's first pass
 * vectorizes; (crit_i + crit_far) G_c first: in the screen, a row's
 * constant (with pd_bond_force.release, pd/ordinary's energy law 1.26x ->
 * 1.18x the cycles of its elastic passes, llvm-mca's model of Zen 3). */
PD_INLINE int pd_law_energy_reached(const pd_law_energy *p, const pd_bond *bd, double eps,
                                        const pd_bond_force *bf, double crit_far)
{
  return (eps > 0.0) & (bf->release * bd->r0 * bd->r0 >=
                        bd->w * ((p->crit[bd->i] + crit_far) * p->gc[bd->tij]));
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

/* Calibration. s_c(xi) = beta omega |xi|^-2 with omega the influence
 * function normalized to integrate to d over the horizon. Cutting every
 * bond across a unit area releases, bond by bond, s_c at both ends:
 * G_c = 2 I with I = pi int_0^delta r omega dr (3D) or 2 int_0^delta omega dr
 * (2D), integrated numerically here. Returns beta for a given G_c, or a
 * negative value when the integral diverges (the 2D inverse influence). */
double pd_energy_failure_beta(pd_influence_kind kind, int dim, double delta, double Gc);

/* The same calibration on the lattice actually used: the sum over a
 * complete family replaces the integral, and the crack orientation is
 * averaged (the mean of max(cos, 0) is 1/pi in 2D, 1/4 in 3D), so that
 * cutting bonds across a plane of any orientation releases G_c on average:
 * G = 2 beta N <cos+> sum w V / |xi|, N = d / (sum w V). The sums are those
 * of one complete family: its weighted volume and its failure moment sum
 * w V / |xi| (pd_family_moment of power -1). On a
 * simple cubic or square lattice a crack along the lattice axes then
 * releases 0.94-0.97 G_c (delta = 3-6 spacings); the continuum calibration
 * above gives 0.76 G_c in 2D at delta = 3 spacings with a constant omega. */
double pd_energy_failure_beta_lattice(int dim, double Gc, double weighted_volume, double moment);


#endif
