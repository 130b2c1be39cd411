/* ----------------------------------------------------------------------
   PERIDYNAMICS_EXT: the fracture record of the bond store (totals of
   broken bonds and dissipated energy) and the fresh-bond replay.
------------------------------------------------------------------------- */

#include "pd_fracture_record.h"

#include "atom.h"
#include "comm.h"

#include <mpi.h>

using namespace LAMMPS_NS;

PDFractureRecord::PDFractureRecord(LAMMPS *lmp) :
    Pointers(lmp), nbroken(0), breaks_since_map(0), dissipated(0.0), dissipated_joule(0.0),
    any_broken(0), fresh_step(-1)
{
}

PDFractureRecord::Totals PDFractureRecord::sum_over_ranks() const
{
  Totals t;
  double mine[2] = {dissipated, dissipated_joule}, sums[2];
  MPI_Allreduce(mine, sums, 2, MPI_DOUBLE, MPI_SUM, world);
  bigint counts[2] = {nbroken, breaks_since_map}, totals[2];
  MPI_Allreduce(counts, totals, 2, MPI_LMP_BIGINT, MPI_SUM, world);
  t.broken = totals[0];
  t.breaks_since_map = totals[1];
  t.dissipated = sums[0];
  t.dissipated_joule = sums[1];
  t.any_broken = any_broken;
  t.fresh_step = fresh_step;
  return t;
}

void PDFractureRecord::restore(const Totals &t)
{
  const bool root = comm->me == 0;
  nbroken = root ? t.broken : 0;
  breaks_since_map = root ? t.breaks_since_map : 0;
  dissipated = root ? t.dissipated : 0.0;
  dissipated_joule = root ? t.dissipated_joule : 0.0;
  any_broken = t.any_broken;
  fresh_step = t.fresh_step;
}

void PDFractureRecord::restore_fresh(std::vector<tagint> fresh_pairs, std::vector<double> fresh_lengths)
{
  pairs = std::move(fresh_pairs);
  lengths = std::move(fresh_lengths);
}

// A second evaluation of the step in which the listed bonds broke replays
// it only if they are where they were then (after a restart, or the setup of
// the next run); commands between runs that move atoms (displace_atoms in a
// 'run 0' loop, set, velocity ...) make it a new evaluation, booked as such.
bool PDFractureRecord::unbreak_fresh(const PDBondTable &bonds, bigint step)
{
  if (step != fresh_step || pairs.empty()) return false;
  int moved = 0, anymoved;
  for (size_t p = 0; p < lengths.size() && !moved; p++) {
    const int i = atom->map(pairs[2 * p]);
    if (i < 0 || i >= bonds.nowned) continue;
    for (int k = 0; k < bonds.count[i]; k++)
      if (bonds.partner[i * bonds.stride + k] == pairs[2 * p + 1] &&
          fabs(bonds.length(atom->x, i, k) - lengths[p]) > 1e-10 * lengths[p])
        moved = 1;
  }
  MPI_Allreduce(&moved, &anymoved, 1, MPI_INT, MPI_MAX, world);
  if (anymoved) {
    pairs.clear();
    lengths.clear();
    return false;
  }
  sign_fresh(bonds, 1.0);
  return true;
}

void PDFractureRecord::rebreak_fresh(const PDBondTable &bonds)
{
  sign_fresh(bonds, -1.0);
}

// Set the sign of the listed bonds' reference lengths (on their owners).
void PDFractureRecord::sign_fresh(const PDBondTable &bonds, double sign)
{
  for (size_t p = 0; p < pairs.size(); p += 2) {
    const int i = atom->map(pairs[p]);
    if (i < 0 || i >= atom->nlocal) continue;
    for (int k = 0; k < bonds.count[i]; k++) {
      const size_t slot = (size_t) i * bonds.stride + k;
      if (bonds.partner[slot] == pairs[p + 1]) bonds.len0[slot] = sign * fabs(bonds.len0[slot]);
    }
  }
}

void PDFractureRecord::note_fresh(const PDBondTable &bonds, const int *idx, int n, bigint step, bool any)
{
  fresh_step = step;
  pairs.clear();
  lengths.clear();
  if (!any) return;
  std::vector<tagint> mine(2 * (size_t) n);
  std::vector<double> mylength(n);
  for (int q = 0; q < n; q++) {
    const int i = idx[q] / bonds.stride, k = idx[q] % bonds.stride;
    mine[2 * q] = atom->tag[i];
    mine[2 * q + 1] = bonds.partner[idx[q]];
    mylength[q] = bonds.length(atom->x, i, k);
  }
  std::vector<int> counts(comm->nprocs), displs(comm->nprocs, 0);
  MPI_Allgather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, world);
  for (int r = 1; r < comm->nprocs; r++) displs[r] = displs[r - 1] + counts[r - 1];
  lengths.resize(displs.back() + counts.back());
  MPI_Allgatherv(mylength.data(), n, MPI_DOUBLE, lengths.data(), counts.data(), displs.data(),
                 MPI_DOUBLE, world);
  for (int r = 0; r < comm->nprocs; r++) {
    counts[r] *= 2;
    displs[r] *= 2;
  }
  pairs.resize(2 * lengths.size());
  MPI_Allgatherv(mine.data(), 2 * n, MPI_LMP_TAGINT, pairs.data(), counts.data(), displs.data(),
                 MPI_LMP_TAGINT, world);
}
