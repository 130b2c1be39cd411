/* ----------------------------------------------------------------------
   PERIDYNAMICS_EXT: pd/contact's candidates and short list
   (pd_contact_cache.h).
------------------------------------------------------------------------- */

#include "pd_contact_cache.h"

#include "atom.h"
#include "memory.h"

using namespace LAMMPS_NS;

PDContactCache::PDContactCache(LAMMPS *lmp) :
    Pointers(lmp), cand(nullptr), nearby(nullptr), ncand(0), maxcand(0), nnear(0), maxnear(0), skin(0.0),
    atoms(nullptr), natoms(0), maxatoms(0), ref(nullptr), seen(nullptr), maxseen(0)
{
}

PDContactCache::~PDContactCache()
{
  memory->sfree(cand);
  memory->sfree(nearby);
  memory->destroy(atoms);
  memory->destroy(ref);
  memory->destroy(seen);
}

void PDContactCache::grow()
{
  maxcand = 2 * maxcand + 1024;
  cand = (pd_contact_cand *) memory->srealloc(cand, sizeof(pd_contact_cand) * maxcand, "pd/contact:cand");
}

void PDContactCache::settle(double skin_short)
{
  skin = skin_short;
  natoms = nnear = 0;
  if (skin <= 0.0 || ncand == 0) return;
  if (maxnear < ncand) {
    maxnear = maxcand;
    memory->sfree(nearby);
    nearby = (pd_contact_cand *) memory->smalloc(sizeof(pd_contact_cand) * maxnear, "pd/contact:nearby");
  }
  // the atoms whose motion can bring a candidate into contact, each once
  const int nall = atom->nlocal + atom->nghost;
  if (maxseen < nall) {
    maxseen = atom->nmax;
    memory->destroy(seen);
    memory->create(seen, maxseen, "pd/contact:seen");
  }
  for (int k = 0; k < nall; k++) seen[k] = 0;
  natoms = 0;
  for (int p = 0; p < ncand; p++)
    for (int a : {cand[p].i, cand[p].j})
      if (!seen[a]) {
        seen[a] = 1;
        if (natoms == maxatoms) {
          maxatoms = 2 * maxatoms + 1024;
          memory->grow(atoms, maxatoms, "pd/contact:atoms");
          memory->grow(ref, 3 * maxatoms, "pd/contact:ref");
        }
        atoms[natoms++] = a;
      }
  take();
}

void PDContactCache::take()
{
  const double *x = atom->x[0];
  for (int k = 0; k < natoms; k++)
    for (int c = 0; c < 3; c++) ref[3 * k + c] = x[3 * atoms[k] + c];
  nnear = pd_contact_select(cand, ncand, x, skin, nearby);
}

void PDContactCache::refresh()
{
  // slightly less than half the skin: two atoms that moved by just that
  // much each stay farther apart than their contact distance after round-off
  if (skin > 0.0 && natoms > 0 && pd_contact_moved(atoms, natoms, atom->x[0], ref, 0.5 * skin * (1.0 - 1e-9)))
    take();
}

double PDContactCache::memory_usage() const
{
  return (double) sizeof(pd_contact_cand) * (maxcand + maxnear) + (sizeof(int) + 3 * sizeof(double)) * maxatoms +
      sizeof(int) * (double) maxseen;
}
