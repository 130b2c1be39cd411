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
------------------------------------------------------------------------- */

#include "pair_pd.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "fix_pd_bonds.h"

#include <cmath>
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

void PairPD::correct_directions(const std::vector<double> &share)
{
  const int d = dim(), nterms = pd_directional_terms(d), width = pd_directional_moments(d);
  int power = 0;
  directional_moment(power);
  const int nlocal = atom->nlocal, nall = nlocal + atom->nghost;
  const double *vol = atom->vfrac;
  // the fit's sums, then its quartic forms: scratch of this set-up only
  std::vector<double> scratch((size_t) nall * width, 0.0);
  double *sums = scratch.data();

  // each family's sums, at both ends of every bond (broken or not)
  bonds->each_reference_bond([&](int i, int j, const double *xi, double w) {
    double n[3];
    const double r = unit_direction(xi, n);
    if (!(r > 0.0)) return;
    // (the powers the materials take, 0 and 1, without a call to pow per bond)
    const double stiff = w * (power == 0 ? 1.0 : power == 1 ? r : pow(r, power));
    pd_directional_add(d, n, stiff * vol[j], sums + (size_t) i * width);
    pd_directional_add(d, n, stiff * vol[i], sums + (size_t) j * width);
  });
  bonds->sum_to_owners(sums, width);

  // own forms; then, coefficient by coefficient, the blend with the
  // complete family's (a type with no interior atom: f = 1)
  std::vector<std::vector<double>> form(nterms, std::vector<double>(nlocal));
  for (int i = 0; i < nlocal; i++) {
    double f[PD_DIRECTIONAL_MAX_TERMS];
    pd_directional_fit(d, sums + (size_t) i * width, f);
    for (int a = 0; a < nterms; a++) form[a][i] = f[a];
  }
  double unit[PD_DIRECTIONAL_MAX_TERMS];
  pd_directional_unit(d, unit);
  for (int a = 0; a < nterms; a++) {
    const std::vector<double> complete = type_medians(form[a].data(), [&](int i) { return share[i] >= 1.0; });
    for (int i = 0; i < nlocal; i++) {
      const double c = complete[atom->type[i]];
      sums[(size_t) i * width + a] = pd_calibrated(form[a][i], std::isnan(c) ? unit[a] : c, share[i]);
    }
  }
  bonds->copy_to_ghosts(sums, width);

  // each form's smallest factor on its own family's bonds; a form that
  // would soften a bond below the floor (or make it negative) moves toward
  // f = 1 just enough
  std::vector<double> lowest(nall, -INFINITY);    // minus the smallest
  bonds->each_reference_bond([&](int i, int j, const double *xi, double) {
    double n[3];
    if (!(unit_direction(xi, n) > 0.0)) return;
    double f[2];
    pd_directional_factors(d, sums + (size_t) i * width, sums + (size_t) j * width, n, f);
    lowest[i] = MAX(lowest[i], -f[0]);
    lowest[j] = MAX(lowest[j], -f[1]);
  });
  bonds->max_to_owners(lowest.data());
  bigint limited = 0;
  for (int i = 0; i < nlocal; i++) limited += pd_directional_limit(d, sums + (size_t) i * width, -lowest[i]);
  MPI_Allreduce(MPI_IN_PLACE, &limited, 1, MPI_LMP_BIGINT, MPI_SUM, world);
  if (limited) bonds->copy_to_ghosts(sums, width);

  double range[2] = {INFINITY, INFINITY};    // smallest factor, minus the largest
  bonds->scale_weights([&](int i, int j, const double *xi) {
    double n[3];
    if (!(unit_direction(xi, n) > 0.0)) return 1.0;
    double ends[2];
    pd_directional_factors(d, sums + (size_t) i * width, sums + (size_t) j * width, n, ends);
    const double f = 0.5 * (ends[0] + ends[1]);
    range[0] = MIN(range[0], f);
    range[1] = MIN(range[1], -f);
    return f;
  });
  MPI_Allreduce(MPI_IN_PLACE, range, 2, MPI_DOUBLE, MPI_MIN, world);
  if (!(range[0] > 0.0))
    error->all(FLERR, "Pair {}: directional_correction: a bond's weight factor is {:.3g} after the floor "
               "of {} (a bug)", style_name(), range[0], PD_DIRECTIONAL_FLOOR);
  if (comm->me == 0 && std::isfinite(range[0]))
    utils::logmesg(lmp, "{}: directional correction: each family's fourth moment made isotropic, bond "
                   "weights scaled by {:.3f} .. {:.3f}{}\n", style_name(), range[0], -range[1],
                   limited ? fmt::format("; {} atoms' families too irregular for it (a factor below {}): "
                                         "corrected only partly", limited, PD_DIRECTIONAL_FLOOR)
                           : std::string());
}
