/* ----------------------------------------------------------------------
   PERIDYNAMICS_EXT: finding the pair style that describes the bond
   families (pd_family_spec.h).
------------------------------------------------------------------------- */

#include "pd_family_spec.h"

#include "pair.h"
#include "pd_compat.h"

using namespace LAMMPS_NS;

PDFamilySource *LAMMPS_NS::pd_family_source(Force *force)
{
  for (Pair *p : PDCompat::pair_styles(force))
    if (auto *source = dynamic_cast<PDFamilySource *>(p)) return source;
  return nullptr;
}
