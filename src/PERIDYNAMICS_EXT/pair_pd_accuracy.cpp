/* ----------------------------------------------------------------------
   PERIDYNAMICS_EXT: what the chosen discretization buys, in the setup
   report: the lattice error of the elastic constants and the fracture
   energy a crack releases across planes of every orientation, from the
   lattice sums of one site's family (core/pd_dispersion.h,
   core/pd_orientation.h). The family is built with the bond store's own
   rule (which candidates are bonds, their weights: PDFamilySpec) on the
   lattice the atoms were created on (the 'lattice' command), or on a
   simple cubic (square) lattice of the particles' spacing.
------------------------------------------------------------------------- */

#include "pair_pd.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "lattice.h"
#include "math_const.h"
#include "pd_failure_law.h"

#include <cmath>
#include <mpi.h>

extern "C" {
#include "pd_directional.h"
#include "pd_orientation.h"
}

using namespace LAMMPS_NS;

namespace {

// A bond's weight as the store gives it, for pd_lattice_family: with the
// directional correction, times the complete family's factor.
struct StoreRule {
  const PDFamilySpec *spec;
  int weighted;
  double volume, horizon;
  int dim;
  const double *form;    // the quartic form of the directional correction, or null
};

double store_weight(const double xi[3], double r, void *ctx)
{
  const StoreRule &s = *(const StoreRule *) ctx;
  PDBondGeometry g = {{xi[0], xi[1], xi[2]}, r, s.volume, s.volume, s.horizon, 1.0};
  if (!s.spec->is_bond(g)) return 0.0;
  const double w = s.weighted ? s.spec->weight(g) : 1.0;
  if (!s.form || !(r > 0.0)) return w;
  const double n[3] = {xi[0] / r, xi[1] / r, xi[2] / r};
  return w * pd_directional_factor(s.dim, s.form, n);
}

std::string percent(double x)
{
  return fabs(x) < 5e-4 ? "0%" : fmt::format("{:+.1f}%", 100.0 * x);
}

// The lattice's axes along the box's (its default orientation).
bool lattice_upright(Lattice *l)
{
  double o[3] = {0.0, 0.0, 0.0};
  l->lattice2box(o[0], o[1], o[2]);
  for (int a = 0; a < 3; a++) {
    double v[3] = {a == 0 ? 1.0 : 0.0, a == 1 ? 1.0 : 0.0, a == 2 ? 1.0 : 0.0};
    l->lattice2box(v[0], v[1], v[2]);
    for (int b = 0; b < 3; b++)
      if (b != a && fabs(v[b] - o[b]) > 1e-9 * fabs(v[a] - o[a])) return false;
  }
  return true;
}

}    // namespace

// The lattice of the atoms: the 'lattice' command's when its volume per
// site is the atoms' (sc, fcc, sq, hex in their default orientation), else
// sc or sq of the atoms' spacing. Returns its description for the log.
std::string PairPD::site_lattice(double volume, pd_lattice &lat) const
{
  Lattice *l = domain->lattice;
  int kind = -1;
  if (l && dim() == 3 && l->style == Lattice::SC) kind = PD_LATTICE_SC;
  if (l && dim() == 3 && l->style == Lattice::FCC) kind = PD_LATTICE_FCC;
  if (l && dim() == 2 && l->style == Lattice::SQ) kind = PD_LATTICE_SQ;
  if (l && dim() == 2 && l->style == Lattice::HEX) kind = PD_LATTICE_HEX;
  // (only a lattice of one of these styles has its orientation set: the
  // default 'none' leaves it uninitialized)
  if (kind >= 0 && !lattice_upright(l)) kind = -1;
  const double site = dim() == 3 ? volume : volume / thickness;
  if (kind >= 0 && pd_lattice_make((pd_lattice_kind) kind, l->xlattice, &lat) == 0 &&
      fabs(lat.volume / site - 1.0) < 1e-3)
    return pd_lattice_name((pd_lattice_kind) kind);
  pd_lattice_make(dim() == 3 ? PD_LATTICE_SC : PD_LATTICE_SQ, dim() == 3 ? cbrt(site) : sqrt(site), &lat);
  return fmt::format("{} of the particles' spacing (no matching 'lattice' command)", dim() == 3 ? "sc" : "sq");
}

void PairPD::report_accuracy(const PDFamilySpec &spec)
{
  // lines per type that has atoms (the volume: the largest of each rank's
  // first atom of the type)
  const int nt = atom->ntypes + 1;
  std::vector<double> mine(nt, 0.0), volume(nt, 0.0);
  for (int i = 0; i < atom->nlocal; i++)
    if (mine[atom->type[i]] == 0.0) mine[atom->type[i]] = atom->vfrac[i];
  MPI_Allreduce(mine.data(), volume.data(), nt, MPI_DOUBLE, MPI_MAX, world);
  if (comm->me != 0) return;

  for (int t = 1; t < nt; t++) {
    const double h = spec.horizon(t, t);
    if (!(volume[t] > 0.0) || !(h > 0.0) || !std::isfinite(h)) continue;
    pd_lattice lat;
    const std::string where = site_lattice(volume[t], lat);
    StoreRule rule = {&spec, uses_weights(), volume[t], h, dim(), nullptr};
    double form[PD_DIRECTIONAL_MAX_TERMS];
    int power;
    pd_family site;
    if (directional && directional_moment(power) &&
        pd_lattice_family(&lat, spec.reach(t, t), thickness, store_weight, &rule, &site) > 0) {
      if (pd_family_directional_form(&site, power, form) == 0) rule.form = form;
      pd_family_free(&site);
    }
    const double ratio = h / (dim() == 3 ? cbrt(lat.volume) : sqrt(lat.volume));
    const char *quad = partial_volumes() ? "partial" : "point";
    pd_linear_kind kind = PD_LINEAR_CLASSICAL;
    pd_elastic e;
    pd_moduli_error err;
    const bool linear = linear_model(t, kind, e);
    if (!linear) {
      utils::logmesg(lmp, "{}: type {}: constants exact under uniform strain on any lattice (the family's "
                     "shape normalizes them), horizon {:.3g} spacings\n", style_name(), t, ratio);
    } else if (pd_lattice_expected_error(&lat, kind, model_dim, &e, h, spec.reach(t, t), thickness,
                                         store_weight, &rule, &err) == 0) {
      utils::logmesg(lmp, "{}: type {}: lattice error of the constants on {}, horizon {:.3g} spacings, {} "
                     "quadrature{}: dilatation {}, shear along the lattice axes {}, simple shear xy {}\n",
                     style_name(), t, where, ratio, quad, rule.form ? ", directional correction" : "",
                     percent(err.dilatation), percent(err.shear_xx_yy), percent(err.shear_xy));
    }
    const int release = law->release_kind(t);
    pd_family f;
    if (release < 0 || pd_lattice_family(&lat, spec.reach(t, t), thickness, store_weight, &rule, &f) < 1)
      continue;
    // an ordinary solid's stretch law: its bond and dilatation parts
    const bool ordinary = release == PD_RELEASE_ORDINARY_STRETCH;
    const double dilatation = law->release_dilatation(t);
    const auto across = [&](double deg) {
      const double a = deg * MathConst::MY_PI / 180.0, n[3] = {cos(a), sin(a), 0.0};
      return ordinary ? pd_release_ordinary(&f, dilatation, n) : pd_release(&f, (pd_release_kind) release, n);
    };
    double lo, hi;
    if (ordinary) pd_release_ordinary_range(&f, dilatation, &lo, &hi);
    else pd_release_range(&f, (pd_release_kind) release, &lo, &hi);
    utils::logmesg(lmp, "{}: type {}: a crack releases {:.3f} .. {:.3f} G_c by its orientation (lattice "
                   "sums): normal along x {:.3f}, at 22.5 degrees {:.3f}, at 45 degrees {:.3f}\n",
                   style_name(), t, lo, hi, across(0.0), across(22.5), across(45.0));
    pd_family_free(&f);
  }
}
