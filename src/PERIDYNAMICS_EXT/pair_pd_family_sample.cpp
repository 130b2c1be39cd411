/* ----------------------------------------------------------------------
   PERIDYNAMICS_EXT: sums over a sample of each type's complete reference
   families (a calibration that needs a family's bonds together, not only
   per-atom sums: core/pd_law_stretch.h pd_ordinary_family_release).

   The bond store keeps each pair once, at one end, on one rank: a
   family's bonds are spread over the ranks that own or see its atom. The
   sampled atoms are those with complete families whose tags hash lowest;
   every rank sends rank 0 their bonds (reference vector, weight times the
   partner's volume), rank 0 sorts them into families in a fixed order and
   sums, and broadcasts the sums: the same families summed in the same
   order for any rank count (the weights themselves may differ in
   round-off: the directional correction sums each family in the order its
   ranks hold it).
------------------------------------------------------------------------- */

#include "pair_pd.h"

#include "atom.h"
#include "comm.h"
#include "fix_pd_bonds.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <mpi.h>

using namespace LAMMPS_NS;

// families sampled per irregular type: their sums scatter by a few per
// cent from family to family (positions +-0.25 spacings), the mean of 32
// by well under 1%
static constexpr int PD_FAMILY_SAMPLE = 32;

namespace {

// a tag's place in the sample: spread over the body, not the first rows
// a lattice command created (splitmix64's finalizer)
uint64_t sample_key(uint64_t tag)
{
  uint64_t z = tag + 0x9e3779b97f4a7c15ULL;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

using Record = std::array<double, 5>;    // tag, xi, w V of the partner

}    // namespace

std::vector<double> PairPD::family_sample_sums(int width,
                                               const std::function<void(const pd_family &, double *)> &add) const
{
  const int n = atom->ntypes + 1, nlocal = atom->nlocal;
  // (the calibration's, unless no calibration of this style has run yet)
  const std::vector<bool> lattice = on_lattice.size() == (size_t) n ? on_lattice : lattice_types();

  // the sample: per type, the complete families with the lowest keys, from
  // each rank's lowest (key, tag) pairs, as unsigned long long
  const int most = PD_FAMILY_SAMPLE;
  std::vector<unsigned long long> mine(2 * n * most, UINT64_MAX);
  {
    std::vector<std::vector<std::pair<uint64_t, uint64_t>>> by_type(n);
    for (int i = 0; i < nlocal; i++)
      if (complete_family[i]) by_type[atom->type[i]].push_back({sample_key(atom->tag[i]), atom->tag[i]});
    for (int t = 1; t < n; t++) {
      auto &v = by_type[t];
      const size_t k = std::min(v.size(), (size_t) most);
      std::partial_sort(v.begin(), v.begin() + k, v.end());
      for (size_t q = 0; q < k; q++) mine[2 * (t * most + q)] = v[q].first, mine[2 * (t * most + q) + 1] = v[q].second;
    }
  }
  std::vector<unsigned long long> all(mine.size() * comm->nprocs);
  MPI_Allgather(mine.data(), (int) mine.size(), MPI_UNSIGNED_LONG_LONG, all.data(), (int) mine.size(),
                MPI_UNSIGNED_LONG_LONG, world);
  std::map<uint64_t, int> sampled;    // tag -> type
  for (int t = 1; t < n; t++) {
    std::vector<std::pair<uint64_t, uint64_t>> v;
    for (int r = 0; r < comm->nprocs; r++)
      for (int q = 0; q < most; q++) {
        const unsigned long long *p = &all[r * mine.size() + 2 * (t * most + q)];
        if (p[0] != UINT64_MAX || p[1] != UINT64_MAX) v.push_back({p[0], p[1]});
      }
    std::sort(v.begin(), v.end());
    const size_t k = std::min(v.size(), (size_t) (lattice[t] ? 1 : most));
    for (size_t q = 0; q < k; q++) sampled[v[q].second] = t;
  }

  // their bonds, from both ends
  std::vector<double> out;
  const double *vol = atom->vfrac;
  bonds->each_reference_bond([&](int i, int j, const double *xi, double w) {
    if (sampled.count(atom->tag[i])) out.insert(out.end(), {(double) atom->tag[i], xi[0], xi[1], xi[2], w * vol[j]});
    if (sampled.count(atom->tag[j]))
      out.insert(out.end(), {(double) atom->tag[j], -xi[0], -xi[1], -xi[2], w * vol[i]});
  });
  int count = (int) out.size();
  std::vector<int> counts(comm->nprocs), offsets(comm->nprocs, 0);
  MPI_Gather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, world);
  int total = 0;
  for (int r = 0; r < comm->nprocs; r++) offsets[r] = total, total += counts[r];
  std::vector<Record> records(comm->me == 0 ? total / 5 : 0);
  MPI_Gatherv(out.data(), count, MPI_DOUBLE, records.data(), counts.data(), offsets.data(), MPI_DOUBLE, 0, world);

  // rank 0: the families in the order of their tags, bonds sorted
  std::vector<double> sums(width * n, 0.0);
  if (comm->me == 0) {
    std::sort(records.begin(), records.end());
    std::vector<pd_family_bond> bond;
    for (size_t a = 0; a < records.size();) {
      size_t b = a;
      bond.clear();
      for (; b < records.size() && records[b][0] == records[a][0]; b++) {
        const Record &r = records[b];
        pd_family_bond e = {{r[1], r[2], r[3]}, sqrt(r[1] * r[1] + r[2] * r[2] + r[3] * r[3]), r[4], {0, 0, 0}};
        bond.push_back(e);
      }
      const pd_family f = {dim(), (int) bond.size(), 1.0, bond.data()};
      add(f, &sums[width * sampled.at((uint64_t) records[a][0])]);
      a = b;
    }
  }
  MPI_Bcast(sums.data(), width * n, MPI_DOUBLE, 0, world);
  return sums;
}
