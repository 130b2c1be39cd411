/* ----------------------------------------------------------------------
   PERIDYNAMICS_EXT: compute pd/atom: per-atom dilatation and strain energy
   density, in the order the keywords are given.
------------------------------------------------------------------------- */

#include "compute_pd_atom.h"

#include "atom.h"
#include "domain.h"
#include "error.h"
#include "fix_pd_bonds.h"
#include "force.h"
#include "memory.h"
#include "pair.h"
#include "pd_modify_lookup.h"
#include "update.h"

#include <cstring>

extern "C" {
#include "pd_ordinary.h"
}

using namespace LAMMPS_NS;

ComputePDAtom::ComputePDAtom(LAMMPS *lmp, int narg, char **arg) :
    Compute(lmp, narg, arg), nmax(0), scratch(nullptr), vector(nullptr), array(nullptr), bonds(nullptr)
{
  if (narg < 4) error->all(FLERR, "Illegal compute pd/atom command: name at least one field (dilatation, energy)");
  for (int iarg = 3; iarg < narg; iarg++) {
    if (strcmp(arg[iarg], "dilatation") == 0) fields.push_back(DILATATION);
    else if (strcmp(arg[iarg], "energy") == 0) fields.push_back(ENERGY);
    else error->all(FLERR, "Compute pd/atom: unknown field '{}' (dilatation, energy)", arg[iarg]);
  }
  peratom_flag = 1;
  size_peratom_cols = fields.size() == 1 ? 0 : (int) fields.size();
  for (auto f : fields)
    if (f == ENERGY) {
      peatomflag = 1;    // the integrator then tallies per-atom energy when we are invoked
      timeflag = 1;
    }
}

ComputePDAtom::~ComputePDAtom()
{
  memory->destroy(scratch);
  memory->destroy(vector);
  memory->destroy(array);
}

void ComputePDAtom::init()
{
  bonds = find_bond_store(lmp, "compute pd/atom");
}

void ComputePDAtom::compute_peratom()
{
  invoked_peratom = update->ntimestep;
  if (atom->nmax > nmax) {
    nmax = atom->nmax;
    memory->destroy(scratch);
    memory->create(scratch, nmax, "pd/atom:scratch");
    if (size_peratom_cols == 0) {
      memory->destroy(vector);
      memory->create(vector, nmax, "pd/atom:vector");
      vector_atom = vector;
    } else {
      memory->destroy(array);
      memory->create(array, nmax, size_peratom_cols, "pd/atom:array");
      array_atom = array;
    }
  }
  for (size_t c = 0; c < fields.size(); c++) {
    if (fields[c] == DILATATION) dilatation(scratch);
    else energy_density(scratch);
    for (int i = 0; i < atom->nlocal; i++) {
      const double v = (atom->mask[i] & groupbit) ? scratch[i] : 0.0;
      if (size_peratom_cols == 0) vector[i] = v;
      else array[i][c] = v;
    }
  }
}

// The pair style's own dilatation when it has one (pd/ordinary: theta of
// order m, as in its force state); otherwise theta = d / m sum w s V, the
// linear dilatation with the bond weights and weighted volume (for pd/bond,
// whose bonds carry no weight, m = sum V).
void ComputePDAtom::dilatation(double *out)
{
  int dim = 0;
  const double *theta = force->pair ? (const double *) force->pair->extract("theta", dim) : nullptr;
  if (theta) {
    for (int i = 0; i < atom->nlocal; i++) out[i] = theta[i];
    return;
  }
  const int nall = atom->nlocal + atom->nghost;
  for (int i = 0; i < nall; i++) out[i] = 0.0;
  const pd_bond_view v = bonds->view();
  pd_ordinary_state st = {0.5, out, nullptr, nullptr};
  pd_failure intact_only = {};    // broken bonds stretch freely: they do not count
  intact_only.recontact = 0;
  const pd_loop L = {&v, atom->type, atom->ntypes + 1, atom->x[0], atom->vfrac, nullptr, nullptr, &intact_only};
  pd_ordinary_dilatation(&L, &st);
  bonds->sum_to_owners(out);
  for (int i = 0; i < atom->nlocal; i++) {
    const double m = bonds->weighted_volume[i];
    out[i] = m > 0.0 ? domain->dimension * out[i] / m : 0.0;
  }
}

// The pair style's per-atom energy density (owned + ghost shares summed).
void ComputePDAtom::energy_density(double *out)
{
  if (update->eflag_atom != invoked_peratom)
    error->all(FLERR, "Compute pd/atom energy: per-atom energy was not tallied on this timestep "
               "(use it on thermo or dump steps)");
  const int nall = atom->nlocal + atom->nghost;
  double *eatom = force->pair ? force->pair->eatom : nullptr;
  for (int i = 0; i < nall; i++) out[i] = eatom ? eatom[i] : 0.0;
  bonds->sum_to_owners(out);
}

double ComputePDAtom::memory_usage()
{
  return (double) nmax * (1 + fields.size()) * sizeof(double);
}
