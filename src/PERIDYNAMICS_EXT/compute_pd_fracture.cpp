/* ----------------------------------------------------------------------
   PERIDYNAMICS_EXT: compute pd/fracture.
   Global vector: 1 dissipated energy (sum of energy densities, the PERI
   convention of the thermo energies), 2 the same in energy units, 3 bonds broken
   by fracture, 4 partners lost. Per atom: dissipated energy density.
   The dissipated energy includes microplastic work (pd/bond).
------------------------------------------------------------------------- */

#include "compute_pd_fracture.h"

#include "atom.h"
#include "error.h"
#include "fix_pd_bonds.h"
#include "memory.h"
#include "pd_modify_lookup.h"
#include "update.h"

using namespace LAMMPS_NS;

ComputePDFracture::ComputePDFracture(LAMMPS *lmp, int narg, char **arg) :
    Compute(lmp, narg, arg), nmax(0), dissipated(nullptr), bonds(nullptr)
{
  if (narg != 3) error->all(FLERR, "Illegal compute pd/fracture command: it takes no arguments");
  vector_flag = 1;
  size_vector = 4;
  extvector = 1;
  peratom_flag = 1;
  size_peratom_cols = 0;
  vector = new double[size_vector];
}

ComputePDFracture::~ComputePDFracture()
{
  delete[] vector;
  memory->destroy(dissipated);
}

void ComputePDFracture::init()
{
  bonds = find_bond_store(lmp, "compute pd/fracture");
}

void ComputePDFracture::compute_vector()
{
  invoked_vector = update->ntimestep;
  const PDFractureRecord &record = bonds->fracture();
  double mine[4] = {record.local_dissipated(), record.local_dissipated_joule(),
                    (double) record.local_broken(), (double) bonds->local_lost()};
  MPI_Allreduce(mine, vector, 4, MPI_DOUBLE, MPI_SUM, world);
}

void ComputePDFracture::compute_peratom()
{
  invoked_peratom = update->ntimestep;
  if (atom->nmax > nmax) {
    nmax = atom->nmax;
    memory->destroy(dissipated);
    memory->create(dissipated, nmax, "pd/fracture:dissipated");
    vector_atom = dissipated;
  }
  const double *booked = bonds->dissipated_atom();
  for (int i = 0; i < atom->nlocal; i++) dissipated[i] = (atom->mask[i] & groupbit) ? booked[i] : 0.0;
}

double ComputePDFracture::memory_usage()
{
  return (double) nmax * sizeof(double);
}
