/* ----------------------------------------------------------------------
   PERIDYNAMICS_EXT: fix pd/precrack.
     fix ID all pd/precrack segment x1 y1 x2 y2                 (2D)
     fix ID all pd/precrack patch ox oy oz ax ay az bx by bz    (3D)
   Breaks every bond of the group (both ends in it) whose reference segment
   (x0 to x0') crosses the crack, at the start of every run (idempotent: a
   broken bond stays broken, and restart files keep the broken state).
   Bonds cut this way release no energy: the body is assumed undeformed
   there, as when a notch is cut.
------------------------------------------------------------------------- */

#include "fix_pd_precrack.h"

#include "atom.h"
#include "domain.h"
#include "error.h"
#include "fix_pd_bonds.h"
#include "pd_modify_lookup.h"

#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;
using namespace FixConst;

FixPDPrecrack::FixPDPrecrack(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), crack(), ncut(0), bonds(nullptr)
{
  const bool is_segment = narg == 8 && strcmp(arg[3], "segment") == 0;
  const bool is_patch = narg == 13 && strcmp(arg[3], "patch") == 0;
  if (!is_segment && !is_patch)
    error->all(FLERR, "Illegal fix pd/precrack command: expected 'segment x1 y1 x2 y2' (2D) or "
               "'patch ox oy oz ax ay az bx by bz' (3D)");
  crack.patch = is_patch;
  if (crack.patch != (domain->dimension == 3))
    error->all(FLERR, "Fix pd/precrack: '{}' is for {}D", arg[3], crack.patch ? 3 : 2);
  double v[9] = {0};
  for (int k = 0; k < narg - 4; k++) {
    v[k] = utils::numeric(FLERR, arg[4 + k], false, lmp);
    if (!std::isfinite(v[k]))
      error->all(FLERR, "Fix pd/precrack: coordinate '{}' must be a finite number", arg[4 + k]);
  }
  double *a = crack.a, *b = crack.b, *c = crack.c;
  if (crack.patch) {
    for (int d = 0; d < 3; d++) {
      a[d] = v[d];
      b[d] = v[3 + d];
      c[d] = v[6 + d];
    }
  } else {
    a[0] = v[0], a[1] = v[1], b[0] = v[2], b[1] = v[3];
  }
  // a crack of zero length or area would cut nothing without a word
  const double area = crack.patch
      ? sqrt(pow(b[1] * c[2] - b[2] * c[1], 2) + pow(b[2] * c[0] - b[0] * c[2], 2) + pow(b[0] * c[1] - b[1] * c[0], 2))
      : sqrt((b[0] - a[0]) * (b[0] - a[0]) + (b[1] - a[1]) * (b[1] - a[1]));
  if (!(area > 0.0))
    error->all(FLERR, "Fix pd/precrack: the crack has zero {} ({})", crack.patch ? "area" : "length",
               crack.patch ? "its two edges are parallel or zero" : "its two ends coincide");
  // the crack must touch the box: a crack outside it is a typo
  double lo[3], hi[3];
  for (int d = 0; d < 3; d++) {
    lo[d] = crack.patch ? MIN(MIN(a[d], a[d] + b[d]), MIN(a[d] + c[d], a[d] + b[d] + c[d])) : MIN(a[d], b[d]);
    hi[d] = crack.patch ? MAX(MAX(a[d], a[d] + b[d]), MAX(a[d] + c[d], a[d] + b[d] + c[d])) : MAX(a[d], b[d]);
  }
  for (int d = 0; d < domain->dimension; d++)
    if (hi[d] < domain->boxlo[d] || lo[d] > domain->boxhi[d])
      error->all(FLERR, "Fix pd/precrack: the crack lies outside the simulation box");
  scalar_flag = 1;
  global_freq = 1;
  extscalar = 1;
}

// PRE_FORCE only to be called at setup (pre_force itself does nothing)
int FixPDPrecrack::setmask()
{
  return PRE_FORCE | MIN_PRE_FORCE;
}

// Before the families exist the store remembers the crack, so that a
// restart file written now carries it (the families are built later).
void FixPDPrecrack::init()
{
  bonds = find_bond_store(lmp, "fix pd/precrack");
  if (!bonds->is_built()) bonds->remember_cut(id, crack, groupbit);
}

void FixPDPrecrack::setup_pre_force(int)
{
  ncut += bonds->cut_crossing(crack, groupbit);
}

double FixPDPrecrack::compute_scalar()
{
  return (double) ncut;
}
