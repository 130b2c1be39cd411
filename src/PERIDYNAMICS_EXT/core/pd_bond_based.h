/* Bond-based prototype microelastic brittle (PMB) material (MS07 eq. 14-18). */
#ifndef PD_BOND_BASED_H
#define PD_BOND_BASED_H

#include "pd_coefs.h"
#include "pd_loop.h"

/* The pair_coeff keywords of pair_style pd/bond (pd_bond_coefs, in this
 * order): horizon, micromodulus c or the modulus it comes from (K, E; nu
 * only as a check: bond-based elasticity fixes it), and the yield stretch
 * of microplastic bonds. A line between two types defines the whole bond
 * (stiffness too); unlike types mix by the mean. */
enum {
  PD_BOND_HORIZON,
  PD_BOND_C,
  PD_BOND_K,
  PD_BOND_E,
  PD_BOND_NU,
  PD_BOND_YIELD,
  PD_BOND_NCOEFS
};
extern const pd_coef pd_bond_coefs[PD_BOND_NCOEFS];

/* Micromoduli c per type pair (pd_loop.ntypes per row, indexed by the type
 * array). */
typedef struct pd_pmb {
  const double *c;
} pd_pmb;

/* Proportional microplastic bonds (MS07 eq. 19-21, fig. 2): the force is
 * c (s - sp), and the plastic stretch sp follows s wherever |s - sp| would
 * exceed the yield stretch sy (per type pair, as c). */
typedef struct pd_microplastic {
  const double *sy;   /* yield stretch per type pair */
  double *plastic;    /* per-bond plastic stretch, laid out as the bonds */
  double dissipated;  /* plastic work added by each call (energy-density sum) */
  double dissipated_joule; /* the same in joules */
  double *work_atom;  /* per-atom plastic work density added by each call (owned + ghost), or NULL */
} pd_microplastic;

/* Force density on every bond end: f_i += V_j c s w e_ij, f_j -= V_i c s w e_ij,
 * with s the stretch and e_ij the unit vector from i to j. With a tally,
 * adds the energy density 1/4 c s^2 |xi| w V_other to each end and the
 * virial. With L->fail, broken bonds act only in compression (recontact)
 * and intact bonds break by its law, releasing their energy. */
void pd_pmb_forces(const pd_loop *L, const pd_pmb *mat);

/* The same with microplastic bonds (L->fail must be NULL): updates plastic
 * stretches, adds the plastic work to mp->dissipated (1/2 c sy |d sp| |xi| w
 * per unit volume of each end's partner, as the energy); the energy
 * tallied is the elastic part 1/4 c (s - sp)^2 |xi| w V_other. */
void pd_microplastic_forces(const pd_loop *L, const pd_pmb *mat, pd_microplastic *mp);

/* Stable time step sums (pd_timestep.h): |C| = c w / |xi| (MS07 eq. 41). */
void pd_pmb_stiffness(const pd_bond_view *b, const pd_pmb *mat, const int *type, int ntypes,
                      const double *vol, double *sum);

#endif
