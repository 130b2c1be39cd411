/* ----------------------------------------------------------------------
   PERIDYNAMICS_EXT: compute pd/damage [weighted]
   default (MS07 eq. 25): phi = 1 - (volume of intact partners) / (volume of
   the reference family);
   weighted (T14 eq. 6.12): D = 1 - (1/d) sum omega phi V with the atom's own
   normalization: 1 - (weighted volume of intact partners) / (reference
   weighted volume).
------------------------------------------------------------------------- */

#include "compute_pd_damage.h"

#include "atom.h"
#include "error.h"
#include "fix_pd_bonds.h"
#include "memory.h"
#include "pd_modify_lookup.h"
#include "update.h"

#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;

ComputePDDamage::ComputePDDamage(LAMMPS *lmp, int narg, char **arg) :
    Compute(lmp, narg, arg), nmax(0), damage(nullptr), bonds(nullptr), weighted(0)
{
  if (narg == 4 && strcmp(arg[3], "weighted") == 0) weighted = 1;
  else if (narg != 3)
    error->all(FLERR, "Illegal compute pd/damage command: expected no argument or 'weighted'");
  peratom_flag = 1;
  size_peratom_cols = 0;
}

ComputePDDamage::~ComputePDDamage()
{
  memory->destroy(damage);
}

void ComputePDDamage::init()
{
  bonds = find_bond_store(lmp, "compute pd/damage");
}

// The intact sum and the reference add the same volumes in another order
// once atoms are sorted or spread over processors, so an intact family reads
// 1 - (1 +- 1e-15), which 'damage > 0' would take for a crack. One gone bond
// weighs about 1 / (bonds per atom) with whole cells, many orders above
// ROUND_OFF (only a sliver of a partial cell, or a weight that vanishes at
// the horizon, weighs less). A family with no intact bond reads exactly 1.
static double zero_if_round_off(double damage)
{
  static constexpr double ROUND_OFF = 1e-12;
  return fabs(damage) < ROUND_OFF ? 0.0 : damage;
}

void ComputePDDamage::compute_peratom()
{
  invoked_peratom = update->ntimestep;
  if (atom->nmax > nmax) {
    nmax = atom->nmax;
    memory->destroy(damage);
    memory->create(damage, nmax, "pd/damage:damage");
    vector_atom = damage;
  }
  if (!bonds->is_built()) error->all(FLERR, "Compute pd/damage: bond families are built by the first run");
  const int nall = atom->nlocal + atom->nghost;
  for (int i = 0; i < nall; i++) damage[i] = 0.0;
  pd_bond_view v = bonds->view();
  if (!weighted) v.weight = nullptr;
  pd_intact_volume(&v, atom->vfrac, damage);    // intact family (weighted) volume
  bonds->sum_to_owners(damage);
  const double *reference = weighted ? bonds->weighted_volume() : bonds->family_volume();
  for (int i = 0; i < atom->nlocal; i++) {
    const double all = reference[i];
    damage[i] = (all > 0.0 && (atom->mask[i] & groupbit)) ? zero_if_round_off(1.0 - damage[i] / all) : 0.0;
  }
}

double ComputePDDamage::memory_usage()
{
  return (double) nmax * sizeof(double);
}
