/* ----------------------------------------------------------------------
   PERIDYNAMICS_EXT as a LAMMPS plugin: 'plugin load pdext.so' registers
   the package's styles with a LAMMPS built with the PLUGIN package (and
   shared libraries) that did not compile them in.
------------------------------------------------------------------------- */

#include "lammpsplugin.h"
#include "version.h"

// every style of the package: generated from their registration lines
#include "pdext_plugin_includes.h"

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
#include "pdext_plugin_table.h"
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
