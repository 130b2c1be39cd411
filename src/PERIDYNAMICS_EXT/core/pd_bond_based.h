/* Bond-based prototype microelastic brittle (PMB) material (MS07 eq. 14-18). */
#ifndef PD_BOND_BASED_H
#define PD_BOND_BASED_H

#include "pd_bonds.h"

/* Micromoduli c per type pair, row-major ntypes x ntypes over 0-based types. */
typedef struct pd_pmb {
  int ntypes;
  const double *c;
} pd_pmb;

/* Force density on every bond end: f_i += V_j c s w e_ij, f_j -= V_i c s w e_ij,
 * with s the stretch and e_ij the unit vector from i to j. x, f: 3 per atom
 * over owned and ghost atoms; type: 0-based. When tally is not NULL, adds the
 * energy density 1/4 c s^2 |xi| w V_other to each end and the virial. */
void pd_pmb_forces(const pd_bond_view *b, const pd_pmb *mat, const int *type,
                   const double *x, const double *vol, double *f, pd_tally *tally);

#endif
