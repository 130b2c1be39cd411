/* Bond-based prototype microelastic brittle (PMB) material (MS07 eq. 14-18). */
#ifndef PD_BOND_BASED_H
#define PD_BOND_BASED_H

#include "pd_bonds.h"
#include "pd_failure.h"

/* Micromoduli c per type pair, row-major ntypes x ntypes over the types
 * as indexed by the type array. */
typedef struct pd_pmb {
  int ntypes;
  const double *c;
} pd_pmb;

/* Proportional microplastic bonds (MS07 eq. 19-21, fig. 2): the force is
 * c (s - sp), and the plastic stretch sp follows s wherever |s - sp| would
 * exceed the yield stretch sy (per type pair, as c). */
typedef struct pd_microplastic {
  const double *sy;   /* yield stretch per type pair (ntypes x ntypes) */
  double *plastic;    /* per-bond plastic stretch, laid out as the bonds */
  double dissipated;  /* plastic work added by each call (energy-density sum) */
  double dissipated_joule; /* the same in joules */
  double *work_atom;  /* per-atom plastic work density added by each call (owned + ghost), or NULL */
} pd_microplastic;

/* Force density on every bond end: f_i += V_j c s w e_ij, f_j -= V_i c s w e_ij,
 * with s the stretch and e_ij the unit vector from i to j. x, f: 3 per atom
 * over owned and ghost atoms. When tally is not NULL, adds the energy density
 * 1/4 c s^2 |xi| w V_other to each end and the virial. With fail (NULL: no
 * bond is or can be broken) broken bonds act only in compression (recontact)
 * and a bond whose stretch exceeds s0 breaks in this evaluation, acting with
 * half its force, and releases its energy into fail's sums. */
void pd_pmb_forces(const pd_bond_view *b, const pd_pmb *mat, pd_failure *fail, const int *type,
                   const double *x, const double *vol, double *f, pd_tally *tally);

/* The same with microplastic bonds: updates plastic stretches, adds the
 * plastic work to mp->dissipated (1/2 c sy |d sp| |xi| w per unit volume of
 * each end's partner, as the energy); the energy tallied is the elastic part
 * 1/4 c (s - sp)^2 |xi| w V_other. */
void pd_microplastic_forces(const pd_bond_view *b, const pd_pmb *mat, pd_microplastic *mp,
                            const int *type, const double *x, const double *vol, double *f,
                            pd_tally *tally);

#endif
