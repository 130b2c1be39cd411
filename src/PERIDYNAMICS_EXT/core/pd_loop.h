/* What one evaluation of a material works on, besides the material. */
#ifndef PD_LOOP_H
#define PD_LOOP_H

#include "pd_bonds.h"
#include "pd_failure.h"

typedef struct pd_loop {
  const pd_bond_view *b;
  const int *type;         /* per atom (owned + ghost), or NULL when every atom is of
                              type 1: the loops then load no type */
  int ntypes;              /* row length of the type-pair tables (pd_bond.tij) */
  const double *x, *vol;   /* 3 per atom; 1 per atom (owned + ghost) */
  double *f;               /* force density, 3 per atom */
  pd_tally *tally;         /* energy and virial, or NULL */
  pd_failure *fail;        /* NULL: no bond is or can be broken */
  /* the force loop's scratch for its sums onto far ends: 4 doubles per
   * atom (the 4th for the failure law's notes), owned + ghost, all zero
   * on entry and left all zero (pd_bond_loop.h); NULL where no force is
   * computed */
  double *reaction;
  int nall;                /* owned + ghost atoms */
  int bond_by_bond;        /* every row bond by bond, none in the vectorized pass,
                              in the force loop and the sums (tests compare the two
                              ways' arithmetic; pd/corr's stabilization, which the
                              force loop's pass leaves out) */
  /* each end's factor of a bond's stored energy (pd_bond_force.stored):
   * atom a's at energy_scale[energy_scale_stride * a] (owned + ghost), or
   * 1 for every atom when NULL. A material whose bonds store s_i e and
   * s_j e at their ends (pd/ordinary: s = B) sets it; a tallied step then
   * sums e alone per bond and takes each atom's factor once. */
  const double *energy_scale;
  int energy_scale_stride;
} pd_loop;

#endif
