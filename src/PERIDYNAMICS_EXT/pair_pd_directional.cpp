/* ----------------------------------------------------------------------
   PERIDYNAMICS_EXT: 'directional_correction yes' (core/pd_directional.h).
   At the set-up of the run that built the families, each atom's family
   fits a quartic form of the bond direction that makes its fourth moment
   isotropic, and every bond weight is multiplied by the mean of its two
   ends' forms (a bond belongs to both families; summed over the body the
   mean gives each family its own form). Near a free surface, as for the
   weighted volume, an atom blends its own form with its type's complete
   family's (the median of each coefficient over the interior atoms): a
   surface family's own fit would make the missing half of its moment up
   from the half it has (also with surface_correction yes, which
   renormalizes the weighted volume only). A family too irregular for the
   fit, whose own form would give one of its bonds a factor below
   PD_DIRECTIONAL_FLOOR, is moved toward f = 1 until it gives the floor.
   The weights, scaled once, are the families' from then on (restart
   files keep them).

   A lattice's complete families are one family repeated: an atom whose
   family has the eighth moments of its type's sampled one (by its sums of
   mu and of mu times two signatures of the direction) takes its form,
   fitted once in the same order on any rank count; only the others (near
   a surface, off the lattice) keep sums of their own, 46 numbers an atom
   in 3D, in rows of their own (the bench block's 48^3 lattice: 72 MB less
   at its peak).
------------------------------------------------------------------------- */

#include "pair_pd.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "fix_pd_bonds.h"

#include <cmath>
#include <cstring>
#include <mpi.h>

extern "C" {
#include "pd_calibration.h"
#include "pd_directional.h"
}

using namespace LAMMPS_NS;

// |xi|, and n = xi / |xi| (a bond of zero length: 0, n unset)
static double unit_direction(const double *xi, double n[3])
{
  const double r = sqrt(xi[0] * xi[0] + xi[1] * xi[1] + xi[2] * xi[2]);
  if (r > 0.0)
    for (int k = 0; k < 3; k++) n[k] = xi[k] / r;
  return r;
}

// a bond's share of the stiffness before its partner's volume (the powers
// the materials take, 0 and 1, without a call to pow per bond)
static double stiffness_share(double w, double r, int power)
{
  return w * (power == 0 ? 1.0 : power == 1 ? r : pow(r, power));
}

// A family's sums that tell it from another: mu, then mu times each
// signature of the direction (core/pd_directional.h); and the numbers a
// lattice's sample adds to its form: these and its smallest factor.
constexpr int SIGNATURE_SUMS = 1 + PD_DIRECTIONAL_SIGNATURES, SAMPLE_EXTRA = SIGNATURE_SUMS + 1;

// a bond of direction n and stiffness share mu onto its family's sums
static void add_signatures(const double n[3], double mu, double *sums)
{
  double s[PD_DIRECTIONAL_SIGNATURES];
  pd_directional_signatures(n, s);
  sums[0] += mu;
  for (int k = 0; k < PD_DIRECTIONAL_SIGNATURES; k++) sums[1 + k] += mu * s[k];
}

// Rows of 'width' numbers for some of the atoms (slot[i] >= 0: the row's
// place), owned and ghost, through the bond store's reverse sum or forward
// copy: a few columns at a time through an atom-indexed scratch, or in
// place when every atom has a row (the slots are then the atoms' order).
void PairPD::exchange_rows(double *rows, int width, const std::vector<int> &slot, int nslots, bool to_owners)
{
  const int nall = atom->nlocal + atom->nghost;
  int mine[2] = {nslots > 0, nslots < nall}, all[2];    // some rows, some atoms without
  MPI_Allreduce(mine, all, 2, MPI_INT, MPI_MAX, world);
  if (!all[0]) return;
  if (!all[1]) {
    if (to_owners) bonds->sum_to_owners(rows, width);
    else bonds->copy_to_ghosts(rows, width);
    return;
  }
  const int chunk = MIN(width, 8);
  std::vector<double> scratch((size_t) nall * chunk);
  for (int c0 = 0; c0 < width; c0 += chunk) {
    const int c = MIN(chunk, width - c0);
    for (int i = 0; i < nall; i++)
      for (int k = 0; k < c; k++) scratch[(size_t) i * c + k] = slot[i] < 0 ? 0.0 : rows[(size_t) slot[i] * width + c0 + k];
    if (to_owners) bonds->sum_to_owners(scratch.data(), c);
    else bonds->copy_to_ghosts(scratch.data(), c);
    for (int i = 0; i < nall; i++)
      if (slot[i] >= 0)
        for (int k = 0; k < c; k++) rows[(size_t) slot[i] * width + c0 + k] = scratch[(size_t) i * c + k];
  }
}

// Per lattice type, in rows of nterms + SAMPLE_EXTRA: the form of its
// sampled complete family, that family's sums (mu, then mu times each
// signature) and the form's smallest factor on its bonds; NaN for a type
// that has none (or is not on a lattice).
std::vector<double> PairPD::lattice_forms(int power)
{
  const int d = dim(), nterms = pd_directional_terms(d), row = nterms + SAMPLE_EXTRA, n = atom->ntypes + 1;
  std::vector<double> sample = family_sample_sums(row, [&](const pd_family &f, double *out) {
    pd_family_directional_form(&f, power, out);
    double *sums = out + nterms, &smallest = out[row - 1];
    smallest = INFINITY;
    for (int b = 0; b < f.n; b++) {
      const pd_family_bond &bd = f.bond[b];
      const double u[3] = {bd.xi[0] / bd.r, bd.xi[1] / bd.r, bd.xi[2] / bd.r};
      const double mu = stiffness_share(bd.w * f.volume, bd.r, power);
      add_signatures(u, mu, sums);
      smallest = MIN(smallest, pd_directional_factor(d, out, u));
    }
  });
  std::vector<double> present(n, 0.0);
  for (int i = 0; i < atom->nlocal; i++) present[atom->type[i]] += complete_family[i];
  MPI_Allreduce(MPI_IN_PLACE, present.data(), n, MPI_DOUBLE, MPI_SUM, world);
  for (int t = 0; t < n; t++)
    if (!on_lattice[t] || present[t] == 0.0)
      for (int k = 0; k < row; k++) sample[(size_t) t * row + k] = NAN;
  return sample;
}

void PairPD::correct_directions(const std::vector<double> &share)
{
  const int d = dim(), nterms = pd_directional_terms(d), width = pd_directional_moments(d);
  int power = 0;
  directional_moment(power);
  const int nlocal = atom->nlocal, nall = nlocal + atom->nghost, ntypes = atom->ntypes + 1;
  const int *type = atom->type;
  const double *vol = atom->vfrac;

  // which atoms take their lattice's form: each family's sums of mu and of
  // mu times each signature against the sample's (to round-off of sums of
  // a few hundred bonds, in another order)
  const std::vector<double> sample = lattice_forms(power);
  const auto sampled = [&](int t) { return sample.data() + (size_t) t * (nterms + SAMPLE_EXTRA); };
  std::vector<double> own(nall, 1.0);
  bool any_lattice = false;
  for (int t = 1; t < ntypes; t++) any_lattice = any_lattice || !std::isnan(sampled(t)[0]);
  if (any_lattice) {
    constexpr int w = SIGNATURE_SUMS;
    std::vector<double> sums(w * (size_t) nall, 0.0);
    bonds->each_reference_bond([&](int i, int j, const double *xi, double weight) {
      double n[3];
      const double r = unit_direction(xi, n);
      if (!(r > 0.0)) return;
      const double stiff = stiffness_share(weight, r, power);
      add_signatures(n, stiff * vol[j], &sums[w * i]);
      add_signatures(n, stiff * vol[i], &sums[w * j]);
    });
    bonds->sum_to_owners(sums.data(), w);
    for (int i = 0; i < nlocal; i++) {
      const double *ref = sampled(type[i]) + nterms;
      bool same = share[i] >= 1.0;
      for (int k = 0; k < w; k++) same = same && fabs(sums[w * i + k] - ref[k]) <= 1e-10 * fabs(ref[0]);
      own[i] = !same;
    }
    bonds->copy_to_ghosts(own.data());
  }
  std::vector<int> slot(nall, -1);
  int nslots = 0, fitted_here = 0;
  for (int i = 0; i < nall; i++)
    if (own[i] != 0.0) {
      slot[i] = nslots++;
      fitted_here += i < nlocal;
    }
  int any_own = nslots > 0;    // (a periodic lattice: no rank has a row, and no pass is needed)
  MPI_Allreduce(MPI_IN_PLACE, &any_own, 1, MPI_INT, MPI_MAX, world);

  // the other atoms' own sums, at both ends of every bond (broken or not)
  std::vector<double> rows((size_t) nslots * width, 0.0);
  if (any_own) bonds->each_reference_bond([&](int i, int j, const double *xi, double w) {
    double n[3], m[PD_DIRECTIONAL_MAX_MOMENTS - 1];
    if (slot[i] < 0 && slot[j] < 0) return;
    const double r = unit_direction(xi, n);
    if (!(r > 0.0)) return;
    pd_directional_monomials(d, n, m);
    const double stiff = stiffness_share(w, r, power);
    if (slot[i] >= 0) pd_directional_accumulate(d, m, stiff * vol[j], &rows[(size_t) slot[i] * width]);
    if (slot[j] >= 0) pd_directional_accumulate(d, m, stiff * vol[i], &rows[(size_t) slot[j] * width]);
  });
  exchange_rows(rows.data(), width, slot, nslots, true);

  // their forms, in rows of nterms from here on; then, coefficient by
  // coefficient, the blend with the type's complete family's: the
  // lattice's sampled form, or the median of an irregular type's interior
  // (a type with neither: f = 1)
  for (int s = 0; s < nslots; s++) {
    double f[PD_DIRECTIONAL_MAX_TERMS];
    pd_directional_fit(d, &rows[(size_t) s * width], f);
    std::memcpy(&rows[(size_t) s * nterms], f, nterms * sizeof(double));
  }
  rows.resize((size_t) nslots * nterms);
  rows.shrink_to_fit();
  double unit[PD_DIRECTIONAL_MAX_TERMS];
  pd_directional_unit(d, unit);
  std::vector<double> coefficient(nlocal, 0.0);
  for (int a = 0; a < nterms; a++) {
    for (int i = 0; i < nlocal; i++)
      if (slot[i] >= 0) coefficient[i] = rows[(size_t) slot[i] * nterms + a];
    const std::vector<double> median =
        type_medians(coefficient.data(), [&](int i) { return slot[i] >= 0 && share[i] >= 1.0; });
    for (int i = 0; i < nlocal; i++) {
      if (slot[i] < 0) continue;
      const double lat = sampled(type[i])[a], med = median[type[i]];
      const double c = !std::isnan(lat) ? lat : !std::isnan(med) ? med : unit[a];
      rows[(size_t) slot[i] * nterms + a] = pd_calibrated(coefficient[i], c, share[i]);
    }
  }
  // the types' shared forms (those of the atoms without a row)
  std::vector<double> shared((size_t) ntypes * nterms);
  for (int t = 0; t < ntypes; t++)
    for (int a = 0; a < nterms; a++)
      shared[(size_t) t * nterms + a] = std::isnan(sampled(t)[a]) ? unit[a] : sampled(t)[a];
  exchange_rows(rows.data(), nterms, slot, nslots, false);
  const auto form = [&](int i) {
    return slot[i] >= 0 ? &rows[(size_t) slot[i] * nterms] : &shared[(size_t) type[i] * nterms];
  };

  // each form's smallest factor on its own family's bonds; a form that
  // would soften a bond below the floor (or make it negative) moves toward
  // f = 1 just enough (a shared form by its sampled family's smallest)
  std::vector<double> lowest(nall, -INFINITY);    // minus the smallest
  if (any_own) bonds->each_reference_bond([&](int i, int j, const double *xi, double) {
    double n[3];
    if (slot[i] < 0 && slot[j] < 0) return;
    if (!(unit_direction(xi, n) > 0.0)) return;
    double f[2];
    pd_directional_factors(d, form(i), form(j), n, f);
    lowest[i] = MAX(lowest[i], -f[0]);
    lowest[j] = MAX(lowest[j], -f[1]);
  });
  if (any_own) bonds->max_to_owners(lowest.data());
  std::vector<double> sharing(ntypes, 0.0);
  bigint limited = 0;
  for (int i = 0; i < nlocal; i++)
    if (slot[i] >= 0) limited += pd_directional_limit(d, form(i), -lowest[i]);
    else sharing[type[i]] += 1.0;
  MPI_Allreduce(MPI_IN_PLACE, sharing.data(), ntypes, MPI_DOUBLE, MPI_SUM, world);
  MPI_Allreduce(MPI_IN_PLACE, &limited, 1, MPI_LMP_BIGINT, MPI_SUM, world);
  if (limited) exchange_rows(rows.data(), nterms, slot, nslots, false);
  for (int t = 1; t < ntypes; t++)
    if (sharing[t] > 0.0 && pd_directional_limit(d, &shared[(size_t) t * nterms], sampled(t)[nterms + SAMPLE_EXTRA - 1]))
      limited += (bigint) sharing[t];

  double range[2] = {INFINITY, INFINITY};    // smallest factor, minus the largest
  bonds->scale_weights([&](int i, int j, const double *xi) {
    double n[3];
    if (!(unit_direction(xi, n) > 0.0)) return 1.0;
    double ends[2];
    pd_directional_factors(d, form(i), form(j), n, ends);
    const double f = 0.5 * (ends[0] + ends[1]);
    range[0] = MIN(range[0], f);
    range[1] = MIN(range[1], -f);
    return f;
  });
  MPI_Allreduce(MPI_IN_PLACE, range, 2, MPI_DOUBLE, MPI_MIN, world);
  if (!(range[0] > 0.0))
    error->all(FLERR, "Pair {}: directional_correction: a bond's weight factor is {:.3g} after the floor "
               "of {} (a bug)", style_name(), range[0], PD_DIRECTIONAL_FLOOR);
  bigint fitted = fitted_here;
  MPI_Allreduce(MPI_IN_PLACE, &fitted, 1, MPI_LMP_BIGINT, MPI_SUM, world);
  if (comm->me == 0 && std::isfinite(range[0]))
    utils::logmesg(lmp, "{}: directional correction: each family's fourth moment made isotropic ({} atoms "
                   "fitted on their own family, the others on their lattice's), bond weights scaled by "
                   "{:.3f} .. {:.3f}{}\n", style_name(), fitted, range[0], -range[1],
                   limited ? fmt::format("; {} atoms' families too irregular for it (a factor below {}): "
                                         "corrected only partly", limited, PD_DIRECTIONAL_FLOOR)
                           : std::string());
}
