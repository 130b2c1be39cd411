/* ----------------------------------------------------------------------
   PERIDYNAMICS_EXT as a LAMMPS plugin: 'plugin load pdext.so' registers
   the package's styles with a LAMMPS built with the PLUGIN package (and
   shared libraries) that did not compile them in.
------------------------------------------------------------------------- */

#include "lammpsplugin.h"
#include "version.h"

#include "compute_pd_atom.h"
#include "compute_pd_damage.h"
#include "compute_pd_fracture.h"
#include "compute_pd_fragments.h"
#include "fix_pd_adr.h"
#include "fix_pd_bonds.h"
#include "fix_pd_precrack.h"
#include "fix_pd_timestep.h"
#include "pair_pd_bond.h"
#include "pair_pd_contact.h"
#include "pair_pd_corr.h"
#include "pair_pd_ordinary.h"

using namespace LAMMPS_NS;

namespace {

template <class T> void *pair_creator(void *lmp)
{
  return new T(static_cast<LAMMPS *>(lmp));
}

template <class T> void *styled_creator(void *lmp, int narg, char **arg)
{
  return new T(static_cast<LAMMPS *>(lmp), narg, arg);
}

struct Style {
  const char *kind, *name, *info;
  lammpsplugin_factory1 *pair;
  lammpsplugin_factory2 *other;
};

const Style styles[] = {
    {"pair", "pd/bond", "bond-based peridynamics (PMB, microplastic)", &pair_creator<PairPDBond>, nullptr},
    {"pair", "pd/ordinary", "ordinary state-based peridynamics (Seth-Hill strain)",
     &pair_creator<PairPDOrdinary>, nullptr},
    {"pair", "pd/corr", "correspondence peridynamics (classical laws, extended Seth-Hill strain)",
     &pair_creator<PairPDCorr>, nullptr},
    {"pair", "pd/contact", "short-range peridynamic contact", &pair_creator<PairPDContact>, nullptr},
    {"fix", "pd/bonds", "peridynamic bond families", nullptr, &styled_creator<FixPDBonds>},
    {"fix", "pd/precrack", "peridynamic pre-cracks", nullptr, &styled_creator<FixPDPrecrack>},
    {"fix", "pd/adr", "quasi-static loading by adaptive dynamic relaxation", nullptr,
     &styled_creator<FixPDAdr>},
    {"fix", "pd/timestep", "adaptive stable time step", nullptr, &styled_creator<FixPDTimestep>},
    {"compute", "pd/atom", "peridynamic per-atom fields", nullptr, &styled_creator<ComputePDAtom>},
    {"compute", "pd/damage", "peridynamic damage", nullptr, &styled_creator<ComputePDDamage>},
    {"compute", "pd/fracture", "dissipated fracture energy", nullptr, &styled_creator<ComputePDFracture>},
    {"compute", "pd/fragments", "fragments: components of the intact bonds", nullptr,
     &styled_creator<ComputePDFragments>},
};

}    // namespace

extern "C" void lammpsplugin_init(void *lmp, void *handle, void *regfunc)
{
  auto register_plugin = (lammpsplugin_regfunc) regfunc;
  for (const Style &s : styles) {
    lammpsplugin_t plugin;
    plugin.version = LAMMPS_VERSION;
    plugin.style = s.kind;
    plugin.name = s.name;
    plugin.info = s.info;
    plugin.author = "PERIDYNAMICS_EXT";
    if (s.pair) plugin.creator.v1 = s.pair;
    else plugin.creator.v2 = s.other;
    plugin.handle = handle;
    (*register_plugin)(&plugin, lmp);
  }
}
