/* ----------------------------------------------------------------------
   PERIDYNAMICS_EXT: each family calibrated on itself (core/pd_calibration.h).
   At each run's set-up the bond store's reference sums (family volume,
   weighted volume: of every bond, broken or not, so a family that loses
   bonds keeps its calibration) give each atom its share of its own sums
   and its calibrated weighted volume. Both live in the bond store as
   per-atom fields that migrate with the atoms during the run.
------------------------------------------------------------------------- */

#include "pair_pd.h"

#include "atom.h"
#include "comm.h"
#include "fix_pd_bonds.h"

#include <algorithm>
#include <cmath>
#include <mpi.h>
#include <utility>
#include <vector>

extern "C" {
#include "pd_bonds.h"
#include "pd_calibration.h"
}

using namespace LAMMPS_NS;

// the share of a type's atoms that must have its largest family moment for
// a lattice: a lattice's interior atoms (an 8^3 block at 3 spacings: 1.6%;
// larger bodies more) or, in a body too thin for any, its middle layers;
// an irregular arrangement has one or a few atoms there, a motif of more
// than 100 atoms repeated its copies
static constexpr double PD_LATTICE_SHARE = 0.01;

// The per-type median of q over the owned atoms that 'take' selects, on
// all ranks: bisection on the count of values at or below a guess (one
// reduction per step), then the smallest value above the lower bound,
// which is the median itself. NaN for a type with no selected atom.
std::vector<double> PairPD::type_medians(const double *q, const std::function<bool(int)> &take) const
{
  const int n = atom->ntypes + 1;
  // the values taken and their types, asked once (the bisection's passes
  // asked 'take' for every atom again: a tenth of a 32^3 block's set-up)
  std::vector<std::pair<int, double>> taken;
  for (int i = 0; i < atom->nlocal; i++)
    if (take(i)) taken.emplace_back(atom->type[i], q[i]);
  std::vector<double> lo(n, INFINITY), hi(n, -INFINITY), count(n, 0.0), rank(n, 0.0);
  for (const auto &tv : taken) {
    lo[tv.first] = MIN(lo[tv.first], tv.second);
    hi[tv.first] = MAX(hi[tv.first], tv.second);
    count[tv.first] += 1.0;
  }
  MPI_Allreduce(MPI_IN_PLACE, lo.data(), n, MPI_DOUBLE, MPI_MIN, world);
  MPI_Allreduce(MPI_IN_PLACE, hi.data(), n, MPI_DOUBLE, MPI_MAX, world);
  MPI_Allreduce(MPI_IN_PLACE, count.data(), n, MPI_DOUBLE, MPI_SUM, world);
  // the lower median is the k-th smallest: count(q <= lo) < k <= count(q <= hi)
  for (int t = 0; t < n; t++) {
    rank[t] = floor(0.5 * (count[t] + 1.0));
    lo[t] = std::nextafter(lo[t], -INFINITY);
  }
  // 'taken' keeps the values inside (lo, hi]; 'base' counts those <= lo
  // (each pass then looks only at the values still in question)
  std::vector<double> mid(n), below(n), base(n, 0.0);
  for (int step = 0; step < 100; step++) {
    bool open = false;
    for (int t = 0; t < n; t++) {
      mid[t] = 0.5 * (lo[t] + hi[t]);
      open = open || (count[t] > 0.0 && mid[t] > lo[t] && mid[t] < hi[t] && hi[t] - lo[t] > 1e-15 * fabs(hi[t]));
      below[t] = 0.0;
    }
    if (!open) break;
    for (const auto &tv : taken)
      if (tv.second <= mid[tv.first]) below[tv.first] += 1.0;
    MPI_Allreduce(MPI_IN_PLACE, below.data(), n, MPI_DOUBLE, MPI_SUM, world);
    for (int t = 0; t < n; t++)
      if (count[t] > 0.0 && mid[t] > lo[t] && mid[t] < hi[t]) {
        below[t] += base[t];
        if (below[t] >= rank[t]) hi[t] = mid[t];
        else lo[t] = mid[t], base[t] = below[t];
      }
    taken.erase(std::remove_if(taken.begin(), taken.end(),
                               [&](const std::pair<int, double> &tv) {
                                 return !(tv.second > lo[tv.first] && tv.second <= hi[tv.first]);
                               }),
                taken.end());
  }
  std::vector<double> median(n, INFINITY);
  for (const auto &tv : taken)
    if (tv.second > lo[tv.first]) median[tv.first] = MIN(median[tv.first], tv.second);
  MPI_Allreduce(MPI_IN_PLACE, median.data(), n, MPI_DOUBLE, MPI_MIN, world);
  for (int t = 0; t < n; t++)
    if (count[t] == 0.0) median[t] = NAN;
  return median;
}

// Types on a lattice: the largest geometric moment sum V |xi| is shared
// to round-off by at least two atoms and PD_LATTICE_SHARE of the type's
// (a lattice's interior atoms, or the middle layers of a body too thin to
// have any). Jittered particles of equal volumes may share a family
// volume (a count of partners), but not that moment, which is unweighted
// since a weight can make it a count (the inverse influence: w V |xi| =
// delta V); and an irregular motif repeated ('replicate') shares it only
// between its copies, a share of 1 / (atoms of the motif).
std::vector<bool> PairPD::lattice_types() const
{
  const int n = atom->ntypes + 1;
  const std::vector<double> moment = family_moments(1, false);
  std::vector<double> largest(n, 0.0), at_largest(2 * n, 0.0);    // then the type's count
  for (int i = 0; i < atom->nlocal; i++) largest[atom->type[i]] = MAX(largest[atom->type[i]], moment[i]);
  MPI_Allreduce(MPI_IN_PLACE, largest.data(), n, MPI_DOUBLE, MPI_MAX, world);
  for (int i = 0; i < atom->nlocal; i++) {
    if (moment[i] >= (1.0 - 1e-12) * largest[atom->type[i]]) at_largest[atom->type[i]] += 1.0;
    at_largest[n + atom->type[i]] += 1.0;
  }
  MPI_Allreduce(MPI_IN_PLACE, at_largest.data(), 2 * n, MPI_DOUBLE, MPI_SUM, world);
  std::vector<bool> lattice(n);
  for (int t = 0; t < n; t++) lattice[t] = at_largest[t] >= MAX(2.0, PD_LATTICE_SHARE * at_largest[n + t]);
  return lattice;
}

// The interior family volume of each type and the tolerance of its
// scatter. On a lattice it is the largest family volume (the interior
// atoms'), and nothing scatters. Otherwise (an irregular arrangement, where
// the largest is an outlier) the median over the atoms within the window
// of the largest, then again within the window of that median, and the
// robust scatter about it. Then each atom's share of its own sums and its
// calibrated weighted volume.
void PairPD::calibrate_families()
{
  const double *v = bonds->family_volume();
  const int n = atom->ntypes + 1;
  on_lattice = lattice_types();
  const std::vector<bool> &lattice = on_lattice;
  std::vector<double> largest(n, 0.0);
  for (int i = 0; i < atom->nlocal; i++) largest[atom->type[i]] = MAX(largest[atom->type[i]], v[i]);
  MPI_Allreduce(MPI_IN_PLACE, largest.data(), n, MPI_DOUBLE, MPI_MAX, world);
  std::vector<double> interior = largest, ref;
  // (a lattice's types need no median)
  const auto candidate = [&](int i) {
    const int t = atom->type[i];
    return !lattice[t] && v[i] >= (1.0 - PD_CALIBRATION_WINDOW) * ref[t];
  };
  for (int pass = 0; pass < 2; pass++) {
    ref = interior;
    interior = type_medians(v, candidate);
  }
  ref = interior;
  std::vector<double> deviation(atom->nlocal);
  for (int i = 0; i < atom->nlocal; i++) deviation[i] = fabs(v[i] - interior[atom->type[i]]);
  const std::vector<double> mad = type_medians(deviation.data(), candidate);
  family_tolerance.assign(n, 0.0);
  for (int t = 1; t < n; t++) {
    if (lattice[t]) interior[t] = largest[t];
    const double scatter = lattice[t] || !(interior[t] > 0.0) ? 0.0 : 1.4826 * mad[t] / interior[t];
    family_tolerance[t] = pd_calibration_tolerance(scatter);
  }
  double *share = bonds->field(field_index("family_share"));
  std::vector<double> complete_share(atom->nlocal);
  for (int i = 0; i < atom->nlocal; i++) {
    const int t = atom->type[i];
    const double c = interior[t] > 0.0 ? v[i] / interior[t] : 0.0;
    complete_share[i] = pd_calibration_share(c, family_tolerance[t]);
    share[i] = surface_corrected() ? 1.0 : complete_share[i];
  }
  mark_complete_families(complete_share, lattice);
  // the bond weights' directional correction, once (it changes the
  // weighted volumes, not the family volumes the shares come from); near
  // a surface on the complete family's, also with the surface correction
  if (directional && bonds->weights_as_built()) correct_directions(complete_share);
  double *m = bonds->field(field_index("calibrated_volume"));
  for (int i = 0; i < atom->nlocal; i++) m[i] = bonds->weighted_volume()[i];
  calibrated_reference = calibrate(m);

  // the log: per type, how the atoms were calibrated
  std::vector<double> kinds(3 * n, 0.0);
  for (int i = 0; i < atom->nlocal; i++)
    kinds[3 * atom->type[i] + (share[i] >= 1.0 ? 0 : share[i] > 0.0 ? 1 : 2)] += 1.0;
  MPI_Allreduce(MPI_IN_PLACE, kinds.data(), 3 * n, MPI_DOUBLE, MPI_SUM, world);
  std::string types;
  for (int t = 1; t < n; t++) {
    if (kinds[3 * t] + kinds[3 * t + 1] + kinds[3 * t + 2] == 0.0 || !(interior[t] > 0.0)) continue;
    const std::string arrangement = lattice[t]
        ? "lattice"
        : fmt::format("irregular, tolerance {:.1f}% of the interior family volume", 100.0 * family_tolerance[t]);
    types += fmt::format(" type {} ({}): {:.0f} atoms on their own family, {:.0f} blended, {:.0f} on the "
                         "complete one;", t, arrangement, kinds[3 * t], kinds[3 * t + 1], kinds[3 * t + 2]);
  }
  if (comm->me == 0)
    utils::logmesg(lmp, "{}: families calibrated on themselves ({}):{}\n", style_name(),
                   surface_corrected() ? "surfaces too" : "free surfaces on a complete family", types);
}

// The atoms whose family is certainly complete, whose sums a type's
// complete-family values are the medians of. On a lattice, the interior
// atoms (their sums agree to round-off). On an irregular arrangement, an
// atom that lost less than the tolerance of its family to a surface is
// interior too (share 1), and its sums are smaller: in a body a few
// horizons thick the median over them came out low (pd/bond's critical
// stretch calibrated on it made jittered hexagonal bands release 5-7% too
// much); so only interior atoms none of whose partners lost more than the
// tolerance, which lie about a horizon deeper. A type with no such atom
// takes its interior ones.
void PairPD::mark_complete_families(const std::vector<double> &complete_share, const std::vector<bool> &lattice)
{
  const int nlocal = atom->nlocal, nall = nlocal + atom->nghost, n = atom->ntypes + 1;
  std::vector<double> short_family(nall, 0.0), near_short(nall, 0.0);
  for (int i = 0; i < nlocal; i++) short_family[i] = complete_share[i] < 1.0;
  bonds->copy_to_ghosts(short_family.data());
  bonds->each_reference_bond([&](int i, int j, const double *, double) {
    near_short[i] = MAX(near_short[i], short_family[j]);
    near_short[j] = MAX(near_short[j], short_family[i]);
  });
  bonds->max_to_owners(near_short.data());
  complete_family.assign(nlocal, 0);
  std::vector<double> count(n, 0.0);
  for (int i = 0; i < nlocal; i++) {
    const int t = atom->type[i];
    complete_family[i] = complete_share[i] >= 1.0 && (lattice[t] || near_short[i] == 0.0);
    count[t] += complete_family[i];
  }
  MPI_Allreduce(MPI_IN_PLACE, count.data(), n, MPI_DOUBLE, MPI_SUM, world);
  for (int i = 0; i < nlocal; i++)
    if (count[atom->type[i]] == 0.0) complete_family[i] = complete_share[i] >= 1.0;
}

// In place over the owned atoms: q (a sum over each atom's reference
// family) becomes s q + (1 - s) q_complete, q_complete the median over the
// type's complete families (mark_complete_families), or the type's
// largest where none is interior (a body thinner than two horizons).
// Returns q_complete by type.
std::vector<double> PairPD::calibrate(double *q) const
{
  const double *share = bonds->field(field_index("family_share"));
  std::vector<double> complete = type_medians(q, [&](int i) { return complete_family[i] != 0; });
  std::vector<double> largest(complete.size(), 0.0);
  for (int i = 0; i < atom->nlocal; i++) largest[atom->type[i]] = MAX(largest[atom->type[i]], q[i]);
  MPI_Allreduce(MPI_IN_PLACE, largest.data(), (int) largest.size(), MPI_DOUBLE, MPI_MAX, world);
  for (size_t t = 0; t < complete.size(); t++)
    if (std::isnan(complete[t])) complete[t] = largest[t];
  for (int i = 0; i < atom->nlocal; i++) q[i] = pd_calibrated(q[i], complete[atom->type[i]], share[i]);
  return complete;
}

// Every owned atom on every rank calibrated on its type's complete family
// (a lattice's interior and surface alike): the loops may take one
// normalization per type.
bool PairPD::calibration_uniform() const
{
  const double *m = bonds->field(field_index("calibrated_volume"));
  int mine = 1, all = 1;
  for (int i = 0; i < atom->nlocal && mine; i++) mine = m[i] == calibrated_reference[atom->type[i]];
  MPI_Allreduce(&mine, &all, 1, MPI_INT, MPI_MIN, world);
  return all != 0;
}

std::vector<double> PairPD::family_moments(int power, bool weighted) const
{
  std::vector<double> moment(atom->nlocal + atom->nghost, 0.0);
  pd_bond_view view = bonds->view();
  if (!weighted) view.weight = nullptr;    // (w = 1)
  pd_family_moment(&view, atom->vfrac, power, moment.data());
  bonds->sum_to_owners(moment.data());
  return moment;
}

double PairPD::calibrated_volume(int i) const
{
  return bonds->field(calibrated_field)[i];
}
