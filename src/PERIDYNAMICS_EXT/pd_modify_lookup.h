/* Finding the bond store that the pd/ material pair style created, for
 * computes and fixes: by its fixed ID, checked by type (fix pd/bonds). */
#ifndef LMP_PD_MODIFY_LOOKUP_H
#define LMP_PD_MODIFY_LOOKUP_H

#include "error.h"
#include "fix_pd_bonds.h"
#include "lammps.h"
#include "modify.h"
#include "pd_compat.h"

namespace LAMMPS_NS {

inline FixPDBonds *find_bond_store(LAMMPS *lmp, const char *who)
{
  auto *fix = dynamic_cast<FixPDBonds *>(PDCompat::fix_by_id(lmp->modify, "PD_BONDS"));
  if (!fix)
    lmp->error->all(FLERR, "{} needs a pd/ material pair style (one that stores bonds) and one "
                    "run or 'run 0' before it is used, so the bond families exist", who);
  return fix;
}

}    // namespace LAMMPS_NS

#endif
