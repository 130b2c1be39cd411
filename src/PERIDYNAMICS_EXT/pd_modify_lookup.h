/* Finding the bond store that the pd/ pair style created, for computes. */
#ifndef LMP_PD_MODIFY_LOOKUP_H
#define LMP_PD_MODIFY_LOOKUP_H

#include "error.h"
#include "fix_pd_bonds.h"
#include "lammps.h"
#include "modify.h"

namespace LAMMPS_NS {

inline FixPDBonds *find_bond_store(LAMMPS *lmp, const char *who)
{
  const int ifix = lmp->modify->find_fix("PD_BONDS");
  FixPDBonds *fix = ifix < 0 ? nullptr : dynamic_cast<FixPDBonds *>(lmp->modify->fix[ifix]);
  if (!fix)
    lmp->error->all(FLERR, "{} needs a pd/ pair style (pd/bond, pd/ordinary) and one run or "
                    "'run 0' before it is used, so the bond families exist", who);
  return fix;
}

}    // namespace LAMMPS_NS

#endif
