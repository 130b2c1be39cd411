/* Every failure law's hooks, for the kernels that instantiate the bond loop
 * once per law (pd_bond_loop.h); the list itself is in pd_laws.h. */
#ifndef PD_LAW_HOOKS_H
#define PD_LAW_HOOKS_H

#include "pd_law_none.h"
#include "pd_law_stretch.h"
#include "pd_law_energy.h"
#include "pd_law_legacy.h"

#endif
