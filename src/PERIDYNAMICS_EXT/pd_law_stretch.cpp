/* ----------------------------------------------------------------------
   PERIDYNAMICS_EXT: 'fail stretch <s0>' or 'fail stretch Gc <Gc>', the
   critical stretch (MS07 eq. 25-31; the bond test: core/pd_law_stretch.h).
------------------------------------------------------------------------- */

#include "pd_failure_law.h"

#include "atom.h"
#include "error.h"
#include "pair_pd.h"

#include <cmath>

extern "C" {
#include "pd_law_stretch.h"
#include "pd_orientation.h"
}

using namespace LAMMPS_NS;

namespace {

enum { S0, GC };
const pd_coef COEFS[] = {
    // bonds between two types without their own: the smaller (MS07 eq. 31)
    {"s0", "critical stretch", PD_MIX_MIN, PD_COEF_PAIR, PD_CHECK_POSITIVE, 0.0, 0.0, 0.0, nullptr},
    {"Gc", "fracture energy", PD_MIX_MEAN, PD_COEF_PAIR | PD_COEF_FILE, PD_CHECK_POSITIVE, 0.0, 0.0, 0.0,
     nullptr},
};

class LawStretch : public PDFailureLaw {
 public:
  LawStretch(PairPD *pair, pd_fail_law id) : PDFailureLaw(pair, id, "stretch", COEFS, 2) {}

  std::string usage() const override { return "fail stretch <s0> | fail stretch Gc <Gc>"; }

  int parse(PDCoefLine &line, int narg, char **arg, int iarg) override
  {
    const int next = take_keyword(line, GC, narg, arg, iarg);
    if (next != iarg) return next;
    if (iarg >= narg || line_keyword(arg[iarg])) return iarg;
    // the word after 'fail stretch' that is no keyword is meant as s0
    if (!utils::is_double(arg[iarg]))
      error->all(FLERR, "Pair {} coeff: 'fail stretch' takes a critical stretch s0, got '{}' ({})", style(),
                 arg[iarg], usage());
    take(line, S0, arg[iarg]);
    return iarg + 1;
  }

  // an s0 on the line decides the critical stretch: a material file's G_c
  // is then not used
  void settle(PDCoefLine &line) const override
  {
    PDFailureLaw::settle(line);
    if (line.seen[cols[S0]] && !line.seen[cols[GC]]) line.values[cols[GC]] = NAN;
  }

  void check(int i, int j) override
  {
    if (given(S0, i, j)) {
      if (given(GC, i, j))
        error->all(FLERR, "Pair {} coeff {} {}: 'fail stretch' takes s0 or 'Gc <Gc>', not both", style(),
                   i, j);
    } else if (given(GC, i, j)) {
      // a type's own bonds now; bonds between two types in init_one, when
      // both materials are known
      if (i == j) from_fracture_energy(i, j);
    } else if (i == j) {
      error->all(FLERR, "Pair {} coeff {} {}: 'fail stretch' needs s0 or 'Gc <Gc>' (here or in the "
                 "material file)", style(), i, j);
    }
  }

  // bonds between two types: from their own G_c and the two materials, or
  // the smaller of the two types' s0
  void mix(int i, int j, bool explicit_pair) override
  {
    if (!std::isnan(value(S0, i, j))) return;
    if (explicit_pair && given(GC, i, j)) from_fracture_energy(i, j);
    else value(S0, i, j) = pd_coef_mixed(COEFS[S0].mix, value(S0, i, i), value(S0, j, j));
  }

  // the bonds of a material whose critical stretch from G_c is calibrated
  // on the family (setup_run)
  int release_kind(int t) const override
  {
    if (!given(GC, t, t) || legacy_mode()) return -1;
    if (pair->bond_based()) return PD_RELEASE_BOND_BASED;
    return ordinary(t) ? PD_RELEASE_ORDINARY_STRETCH : -1;
  }

  double release_dilatation(int t) const override
  {
    double lambda, mu;
    return ordinary(t) && pair->bond_energies()->bond_moduli(t, lambda, mu) ? lambda / mu : 0.0;
  }

  // Per run: the critical stretch from G_c calibrated on the types'
  // complete families (their median interior sums), as a factor on the
  // continuum's s0, the mean of the two types' factors for a pair. A
  // bond-based solid: its moment sum w V |xi|^2 and the material's
  // stiffness scale (core/pd_law_stretch.h pd_critical_stretch_factor). An
  // ordinary state-based solid: its weighted volume and moment sum
  // w V |xi|, with the bond energy's moduli (pd_critical_stretch_ordinary;
  // the continuum's s0 is the bond-based one, which releases 0.53-0.58 G_c
  // in 3D and 0.86-0.97 in 2D there), and the dilatation's share of the
  // release of the family itself (pd_ordinary_family_release: on a coarse
  // family larger than the continuum's, 0.244 against 0.196 on the square
  // lattice at 3 spacings). An s0 given as such, legacy PERI, and
  // correspondence (whose bond energy has neither form) take s0 as it is.
  void setup_run() override
  {
    const int n = atom->ntypes + 1;
    factor.assign(n, 1.0);
    kappa.clear();
    if (pair->bond_based() && !legacy_mode()) {
      std::vector<double> moment = pair->family_moments(2);
      const std::vector<double> complete = pair->calibrate(moment.data());
      for (int t = 1; t < n; t++)
        factor[t] = pd_critical_stretch_factor(dim(), pair->horizon(t, t), pair->plate_thickness(),
                                               pair->stiffness_scale(t), complete[t]);
    } else if (ordinary_any() && !legacy_mode()) {
      std::vector<double> moment = pair->family_moments(1);
      const std::vector<double> complete = pair->calibrate(moment.data());
      const PDBondEnergies *m = pair->bond_energies();
      const std::vector<double> release = pair->family_sample_sums(
          2, [](const pd_family &f, double *sums) { pd_ordinary_family_release(&f, sums); });
      kappa.assign(n, pd_ordinary_dilatation_release(m->influence_kind(), dim()));
      for (int t = 1; t < n; t++) {
        double lambda, mu;
        if (!ordinary(t) || !m->bond_moduli(t, lambda, mu)) continue;
        if (release[2 * t + 1] > 0.0) kappa[t] = release[2 * t] / release[2 * t + 1];
        const double s0 = pd_critical_stretch_ordinary(dim(), table(GC)[t * n + t], lambda, mu, kappa[t],
                                                       pair->complete_volume(t), complete[t]);
        if (std::isfinite(s0)) factor[t] = s0 / table(S0)[t * n + t];
      }
    }
    s0.assign((size_t) n * n, INFINITY);
    const double *given_s0 = table(S0);
    for (int i = 1; i < n; i++)
      for (int j = 1; j < n; j++)
        s0[i * n + j] = given_s0[i * n + j] * (given(GC, i, j) ? 0.5 * (factor[i] + factor[j]) : 1.0);
  }

  const void *evaluation() override
  {
    params = {s0.data(), 0};
    return &params;
  }

  void report() const override
  {
    const int n = atom->ntypes + 1;
    std::string types;
    for (int t = 1; t < n; t++)
      if (given(GC, t, t))
        types += fmt::format(" type {} s0 {:.4g} (continuum {:.4g}{});", t, s0[t * n + t], table(S0)[t * n + t],
                             kappa.empty() ? ""
                                           : fmt::format(", dilatation share of the release {:.3f}", kappa[t]));
    if (!types.empty() && (pair->bond_based() || ordinary_any()) && !legacy_mode())
      utils::logmesg(lmp, "{}: fail stretch from G_c, calibrated on the family:{}\n", style(), types);
  }

 private:
  // type t's bonds store the ordinary solid's energy (pd/ordinary) and
  // break by a G_c of their own
  bool ordinary(int t) const
  {
    const PDBondEnergies *m = pair->bond_energies();
    double lambda, mu;
    return m && given(GC, t, t) && m->bond_moduli(t, lambda, mu) && mu > 0.0;
  }
  bool ordinary_any() const
  {
    for (int t = 1; t <= atom->ntypes; t++)
      if (ordinary(t)) return true;
    return false;
  }

  pd_law_stretch params;
  std::vector<double> factor;    // per type: s0 from G_c calibrated on its complete family over the continuum's
  std::vector<double> s0;        // per type pair: the critical stretch of the run
  std::vector<double> kappa;     // per type: an ordinary solid's dilatation share (none: bond-based)

  // the critical stretch of bond-based elasticity (MS07 eq. 28-29) for the
  // pair's E and nu (the material's; between two types, their means)
  void from_fracture_energy(int i, int j)
  {
    double E, nu;
    pair->fracture_elastic(i, j, E, nu);
    value(S0, i, j) = pd_critical_stretch(dim(), plane_strain(), E, nu, pair->horizon(i, j), value(GC, i, j));
    check_derived(S0, i, j);
  }
};

}    // namespace

PDFailureLaw *LAMMPS_NS::pd_make_law_stretch(PairPD *pair, pd_fail_law id)
{
  return new LawStretch(pair, id);
}
