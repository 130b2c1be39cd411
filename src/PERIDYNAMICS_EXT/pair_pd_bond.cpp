/* ----------------------------------------------------------------------
   PERIDYNAMICS_EXT: pair_style pd/bond (PMB, MS07 eq. 14-18; proportional
   microplastic bonds, MS07 eq. 19-21).
------------------------------------------------------------------------- */

#include "pair_pd_bond.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "fix_pd_bonds.h"

#include <cmath>
#include <cstring>

extern "C" {
#include "pd_bond_based.h"
#include "pd_params.h"
#include "pd_timestep.h"
}

using namespace LAMMPS_NS;

enum { HORIZON, MICROMODULUS, BULK, YOUNG, POISSON, YIELD };
enum { PMB, MICROPLASTIC };

PairPDBond::~PairPDBond()
{
  delete[] pvector;
}

PairPDBond::PairPDBond(LAMMPS *lmp) :
    PairPD(lmp, {"horizon", "c", "K", "E", "nu", "yield_stretch"}), model(PMB), plastic(0)
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

void PairPDBond::check_coeff(int i, int j)
{
  const double delta = value(HORIZON, i, j);
  if (!given(HORIZON, i, j) || delta <= 0.0)
    error->all(FLERR, "Pair pd/bond coeff {} {}: horizon missing or not positive", i, j);
  const int nstiff = given(MICROMODULUS, i, j) + given(BULK, i, j) + given(YOUNG, i, j);
  if (nstiff != 1)
    error->all(FLERR, "Pair pd/bond coeff {} {}: give exactly one of 'c' (micromodulus), 'E' "
               "(Young's modulus) or 'K' (bulk modulus, 3D)", i, j);
  const int p = given(MICROMODULUS, i, j) ? MICROMODULUS : (given(BULK, i, j) ? BULK : YOUNG);
  if (!(value(p, i, j) > 0.0))
    error->all(FLERR, "Pair pd/bond coeff {} {}: {} must be positive, got {}", i, j, names[p], value(p, i, j));
  if (p == BULK && dim() == 2)
    error->all(FLERR, "Pair pd/bond coeff {} {}: K is a 3D option; in 2D give E", i, j);
  const double nu_pmb = pd_pmb_poisson(model_dim);
  if (given(POISSON, i, j) && fabs(value(POISSON, i, j) - nu_pmb) > 1e-6)
    error->all(FLERR, "Pair pd/bond coeff {} {}: bond-based elasticity has Poisson's ratio {:.4g} "
               "here, not nu = {}; leave nu out or use pd/ordinary", i, j, nu_pmb, value(POISSON, i, j));

  const double E = p == YOUNG ? value(YOUNG, i, j) : NAN;
  if (p == BULK) coef[MICROMODULUS][i][j] = pd_pmb_micromodulus_3d(value(BULK, i, j), delta);
  if (p == YOUNG) coef[MICROMODULUS][i][j] = pd_pmb_micromodulus(model_dim, E, delta, thickness);

  check_derived(MICROMODULUS, i, j);
  // E of the bond-based solid, for the critical stretch from G_c
  const double Eb = value(MICROMODULUS, i, j) / pd_pmb_micromodulus(model_dim, 1.0, delta, thickness);
  if (given(ifail, i, j) && value(ifail, i, j) == PD_FAIL_ENERGY)
    error->all(FLERR, "Pair pd/bond coeff {} {}: 'fail energy' needs a state-based material "
               "(pd/ordinary); bond-based bonds fail by 'fail stretch'", i, j);
  if (given(ifail, i, j) && model == MICROPLASTIC)
    error->all(FLERR, "Pair pd/bond coeff {} {}: failure of microplastic bonds is not supported "
               "(its G_c calibration needs the plastic work, MS07 after eq. 29)", i, j);
  check_failure(i, j, Eb, nu_pmb);

  if (model == MICROPLASTIC) {
    if (!given(YIELD, i, j) || !(value(YIELD, i, j) > 0.0))
      error->all(FLERR, "Pair pd/bond coeff {} {}: microplastic needs a positive yield_stretch "
                 "(about sigma_ut / 2E, MS07 eq. 50)", i, j);
    plastic = 1;
  } else if (given(YIELD, i, j)) {
    error->all(FLERR, "Pair pd/bond coeff {} {}: yield_stretch belongs to the microplastic model "
               "('pair_coeff I J microplastic ...')", i, j);
  } else {
    coef[YIELD][i][j] = INFINITY;    // elastic pairs never yield
  }
}

void PairPDBond::compute(int eflag, int vflag)
{
  ev_init(eflag, vflag);
  if (report_pending) report_setup();

  const pd_bond_view v = bonds->view();
  const pd_pmb mat = {coef[MICROMODULUS][0]};
  pd_tally t = {};
  t.eatom = eflag_atom ? eatom : nullptr;
  pd_tally *tp = evflag ? &t : nullptr;
  if (plastic) {
    if (bonds->fracture().has_broken() || law != PD_FAIL_NONE)
      error->all(FLERR, "Pair pd/bond: microplastic bonds cannot be broken (no failure law or "
                 "pre-crack in a style with microplastic pairs)");
    pd_microplastic mp = {coef[YIELD][0], bonds->history_data(), 0.0, 0.0, zero_released()};
    const pd_loop L = evaluation(v, tp, nullptr);
    pd_microplastic_forces(&L, &mat, &mp);
    bonds->fracture().add_dissipated(mp.dissipated, mp.dissipated_joule);
    book_released();
  } else if (failing()) {
    pd_failure fail = failure_state();
    const pd_loop L = evaluation(v, tp, &fail);
    pd_pmb_forces(&L, &mat);
    account_failure(fail);
  } else {
    const pd_loop L = evaluation(v, tp, nullptr);
    pd_pmb_forces(&L, &mat);
  }
  if (evflag) tally(t);
  pvector[0] = bonds->fracture().local_dissipated();    // compute pair sums it over ranks
}

void PairPDBond::stable_dt_sum(double *sum)
{
  const pd_bond_view v = bonds->view();
  const pd_pmb mat = {coef[MICROMODULUS][0]};
  pd_pmb_stiffness(&v, &mat, atom->type, atom->ntypes + 1, atom->vfrac, sum);
}

void PairPDBond::write_restart_settings(FILE *fp)
{
  PairPD::write_restart_settings(fp);
  fwrite(&plastic, sizeof(int), 1, fp);
}

void PairPDBond::read_restart_settings(FILE *fp)
{
  PairPD::read_restart_settings(fp);
  if (comm->me == 0) utils::sfread(FLERR, &plastic, sizeof(int), 1, fp, nullptr, error);
  MPI_Bcast(&plastic, 1, MPI_INT, 0, world);
}
