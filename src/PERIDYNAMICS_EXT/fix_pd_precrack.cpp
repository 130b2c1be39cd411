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

#include <cstring>

extern "C" {
#include "pd_precrack.h"
}

using namespace LAMMPS_NS;
using namespace FixConst;

FixPDPrecrack::FixPDPrecrack(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), patch(0), ncut(0), bonds(nullptr)
{
  const bool is_segment = narg == 8 && strcmp(arg[3], "segment") == 0;
  const bool is_patch = narg == 13 && strcmp(arg[3], "patch") == 0;
  if (!is_segment && !is_patch)
    error->all(FLERR, "Illegal fix pd/precrack command: expected 'segment x1 y1 x2 y2' (2D) or "
               "'patch ox oy oz ax ay az bx by bz' (3D)");
  patch = is_patch;
  if (patch != (domain->dimension == 3))
    error->all(FLERR, "Fix pd/precrack: '{}' is for {}D", arg[3], patch ? 3 : 2);
  double v[9] = {0};
  for (int k = 0; k < narg - 4; k++) v[k] = utils::numeric(FLERR, arg[4 + k], false, lmp);
  if (patch) {
    for (int d = 0; d < 3; d++) {
      a[d] = v[d];
      b[d] = v[3 + d];
      c[d] = v[6 + d];
    }
  } else {
    a[0] = v[0], a[1] = v[1], b[0] = v[2], b[1] = v[3];
    a[2] = b[2] = c[0] = c[1] = c[2] = 0.0;
  }
  // the crack must touch the box: a crack outside it is a typo
  double lo[3], hi[3];
  for (int d = 0; d < 3; d++) {
    lo[d] = patch ? MIN(MIN(a[d], a[d] + b[d]), MIN(a[d] + c[d], a[d] + b[d] + c[d])) : MIN(a[d], b[d]);
    hi[d] = patch ? MAX(MAX(a[d], a[d] + b[d]), MAX(a[d] + c[d], a[d] + b[d] + c[d])) : MAX(a[d], b[d]);
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

void FixPDPrecrack::init()
{
  bonds = find_bond_store(lmp, "fix pd/precrack");
}

void FixPDPrecrack::setup_pre_force(int)
{
  double **x0 = atom->x0;
  const int *mask = atom->mask;
  const pd_bond_view v = bonds->view();
  double *len0 = bonds->len0_data();
  bigint mine = 0;
  for (int i = 0; i < v.nowner; i++)
    for (int k = 0; k < v.count[i]; k++) {
      const int idx = i * v.stride + k;
      if (len0[idx] < 0.0) continue;
      const int j = v.far[idx];
      if (!(mask[i] & groupbit) || !(mask[j] & groupbit)) continue;   // both ends in the group
      double d[3] = {x0[j][0] - x0[i][0], x0[j][1] - x0[i][1], x0[j][2] - x0[i][2]};
      domain->minimum_image(d[0], d[1], d[2]);
      const double p[3] = {x0[i][0], x0[i][1], x0[i][2]};
      const double q[3] = {p[0] + d[0], p[1] + d[1], p[2] + d[2]};
      if (patch ? pd_crosses_patch(p, q, a, b, c) : pd_crosses_segment(p, q, a, b)) {
        len0[idx] = -len0[idx];
        mine++;
      }
    }
  bigint total = 0;
  MPI_Allreduce(&mine, &total, 1, MPI_LMP_BIGINT, MPI_SUM, world);
  ncut += total;
  if (ncut > 0) bonds->set_has_broken();
}

double FixPDPrecrack::compute_scalar()
{
  return (double) ncut;
}
