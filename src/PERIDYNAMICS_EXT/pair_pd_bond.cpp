/* ----------------------------------------------------------------------
   PERIDYNAMICS_EXT: pair_style pd/bond (PMB, MS07 eq. 14-18; proportional
   microplastic bonds, MS07 eq. 19-21).
------------------------------------------------------------------------- */

#include "pair_pd_bond.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "fix_pd_bonds.h"
#include "pd_failure_law.h"

#include <cmath>
#include <cstring>

extern "C" {
#include "pd_bond_based.h"
#include "pd_params.h"
#include "pd_tangent.h"
#include "pd_timestep.h"
}

using namespace LAMMPS_NS;

enum { PMB, MICROPLASTIC };

PairPDBond::~PairPDBond()
{
  delete[] pvector;
}

PairPDBond::PairPDBond(LAMMPS *lmp) :
    PairPD(lmp, pd_bond_coefs, PD_BOND_NCOEFS), model(PMB), plastic(0)
{
  // compute pair pd/bond reports the dissipated (plastic) work as its first extra value
  nextra = 1;
  pvector = new double[nextra];
}

// the model word applies to its own pair_coeff line only
void PairPDBond::coeff(int narg, char **arg)
{
  model = PMB;
  PairPD::coeff(narg, arg);
}

int PairPDBond::parse_model(const char *word)
{
  if (strcmp(word, "pmb") == 0) model = PMB;
  else if (strcmp(word, "microplastic") == 0) model = MICROPLASTIC;
  else return 0;
  return 1;
}

// The horizon, positive moduli and the failure law's values are checked
// by their declarations (PairPD); this is the model's part.
void PairPDBond::check_coeff(int i, int j)
{
  const double delta = horizon(i, j);
  const int nstiff = given(PD_BOND_C, i, j) + given(PD_BOND_K, i, j) + given(PD_BOND_E, i, j);
  if (nstiff != 1)
    error->all(FLERR, "Pair pd/bond coeff {} {}: give exactly one of 'c' (micromodulus), 'E' "
               "(Young's modulus) or 'K' (bulk modulus, 3D)", i, j);
  if (given(PD_BOND_K, i, j) && dim() == 2)
    error->all(FLERR, "Pair pd/bond coeff {} {}: K is a 3D option; in 2D give E", i, j);
  const double nu_pmb = pd_pmb_poisson(model_dim);
  if (given(PD_BOND_NU, i, j) && fabs(value(PD_BOND_NU, i, j) - nu_pmb) > 1e-6)
    error->all(FLERR, "Pair pd/bond coeff {} {}: bond-based elasticity has Poisson's ratio {:.4g} "
               "here, not nu = {}; leave nu out or use pd/ordinary", i, j, nu_pmb, value(PD_BOND_NU, i, j));

  if (given(PD_BOND_K, i, j)) coef[PD_BOND_C][i][j] = pd_pmb_micromodulus_3d(value(PD_BOND_K, i, j), delta);
  if (given(PD_BOND_E, i, j))
    coef[PD_BOND_C][i][j] = pd_pmb_micromodulus(model_dim, value(PD_BOND_E, i, j), delta, thickness);
  check_derived(PD_BOND_C, i, j);
  if (failure_given(i, j) && model == MICROPLASTIC)
    error->all(FLERR, "Pair pd/bond coeff {} {}: failure of microplastic bonds is not supported "
               "(its G_c calibration needs the plastic work, MS07 after eq. 29)", i, j);

  if (model == MICROPLASTIC) {
    if (!given(PD_BOND_YIELD, i, j) || !(value(PD_BOND_YIELD, i, j) > 0.0))
      error->all(FLERR, "Pair pd/bond coeff {} {}: microplastic needs a positive yield_stretch "
                 "(about sigma_ut / 2E, MS07 eq. 50)", i, j);
    plastic = 1;
  } else if (given(PD_BOND_YIELD, i, j)) {
    error->all(FLERR, "Pair pd/bond coeff {} {}: yield_stretch belongs to the microplastic model "
               "('pair_coeff I J microplastic ...')", i, j);
  } else {
    coef[PD_BOND_YIELD][i][j] = INFINITY;    // elastic pairs never yield
  }
}

double PairPDBond::contact_micromodulus(int i, int j) const
{
  return coef[PD_BOND_C][i][j];
}

// E of the bond-based solid of the pair's micromodulus, and its fixed nu
void PairPDBond::fracture_elastic(int i, int j, double &E, double &nu) const
{
  E = value(PD_BOND_C, i, j) / pd_pmb_micromodulus(model_dim, 1.0, horizon(i, j), thickness);
  nu = pd_pmb_poisson(model_dim);
}

// Per run: each type's stiffness calibrated on its complete family (the
// median interior family's moment sum w V |xi|, core/pd_calibration.h),
// and the micromodulus of each type pair: the mean of the two types'
// scales, where the pair's stiffness was given as E or K (a micromodulus c
// given as such, and legacy PERI, are taken as they are).
void PairPDBond::setup_run()
{
  const int n = atom->ntypes + 1;
  std::vector<double> moment = family_moments(1);
  const std::vector<double> complete = calibrate(moment.data());
  kappa.assign(n, 1.0);
  for (int t = 1; t < n; t++) {
    const double continuum = pd_pmb_moment_continuum(dim(), horizon(t, t), thickness);
    if (!legacy && complete[t] > 0.0 && std::isfinite(continuum)) kappa[t] = continuum / complete[t];
  }
  micromodulus.assign((size_t) n * n, 0.0);
  for (int i = 1; i < n; i++)
    for (int j = 1; j < n; j++) {
      const bool from_moduli = given(PD_BOND_E, i, j) || given(PD_BOND_K, i, j);
      micromodulus[i * n + j] = coef[PD_BOND_C][i][j] * (from_moduli ? 0.5 * (kappa[i] + kappa[j]) : 1.0);
    }
}

void PairPDBond::report_extra()
{
  std::string scales;
  for (int t = 1; t <= atom->ntypes; t++) scales += fmt::format(" type {} {:.4f};", t, kappa[t]);
  utils::logmesg(lmp, "pd/bond: micromodulus from E or K calibrated on the complete family (its moment sum "
                 "w V |xi| against the continuum's), scale:{}\n", scales);
}

void PairPDBond::compute(int eflag, int vflag)
{
  ev_init(eflag, vflag);
  if (report_pending) report_setup();

  const pd_pmb mat = {micromodulus.data()};
  Evaluation e;
  if (plastic) {
    if (failing())
      error->all(FLERR, "Pair pd/bond: microplastic bonds cannot be broken (no failure law or "
                 "pre-crack in a style with microplastic pairs)");
    begin_evaluation(e);
    pd_microplastic mp = {coef[PD_BOND_YIELD][0], bonds->history_data(), 0.0, 0.0, zero_released()};
    pd_microplastic_forces(&e.L, &mat, &mp);
    bonds->fracture().add_dissipated(mp.dissipated, mp.dissipated_joule);
    book_released();
  } else {
    begin_evaluation(e);
    force_pass(e, [&](const pd_loop *L) { pd_pmb_forces(L, &mat); });
  }
  end_evaluation(e);
  pvector[0] = bonds->fracture().local_dissipated();    // compute pair sums it over ranks
}

void PairPDBond::stable_dt_sum(double *sum)
{
  const pd_bond_view v = bonds->view();
  const pd_pmb mat = {micromodulus.data()};
  pd_pmb_stiffness(&v, &mat, atom->type, atom->ntypes + 1, atom->vfrac, sum);
}

void PairPDBond::tangent_sum(double *sum, double *closing)
{
  Evaluation e;
  begin_pass(e);
  const pd_pmb_tangent ctx = {micromodulus.data(), plastic ? bonds->history_data() : nullptr};
  pd_pmb_tangent_sums(&e.L, atom->v[0], &ctx, sum, closing);
}

void PairPDBond::restart_settings(PDSettingsIO &io)
{
  PairPD::restart_settings(io);
  io(plastic);
}
