/* ----------------------------------------------------------------------
   PERIDYNAMICS_EXT: pair_style pd/bond (PMB, MS07 eq. 14-18).
------------------------------------------------------------------------- */

#include "pair_pd_bond.h"

#include "atom.h"
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

enum { HORIZON, MICROMODULUS, BULK };

PairPDBond::PairPDBond(LAMMPS *lmp) : PairPD(lmp, {"horizon", "c", "K"}) {}

int PairPDBond::parse_model(const char *word)
{
  return strcmp(word, "pmb") == 0;
}

void PairPDBond::check_coeff(int i, int j)
{
  if (!given(HORIZON, i, j) || value(HORIZON, i, j) <= 0.0)
    error->all(FLERR, "Pair pd/bond coeff {} {}: horizon missing or not positive", i, j);
  const bool has_c = given(MICROMODULUS, i, j), has_k = given(BULK, i, j);
  if (has_c == has_k)
    error->all(FLERR, "Pair pd/bond coeff {} {}: give exactly one of 'c' (micromodulus) or 'K' "
               "(bulk modulus)", i, j);
  const int p = has_c ? MICROMODULUS : BULK;
  if (!(value(p, i, j) > 0.0))
    error->all(FLERR, "Pair pd/bond coeff {} {}: {} must be positive, got {}", i, j,
               names[p], value(p, i, j));
  if (has_k) coef[MICROMODULUS][i][j] = pd_pmb_micromodulus_3d(value(BULK, i, j), value(HORIZON, i, j));
  else coef[BULK][i][j] = value(MICROMODULUS, i, j) * M_PI * pow(value(HORIZON, i, j), 4) / 18.0;
}

void PairPDBond::compute(int eflag, int vflag)
{
  ev_init(eflag, vflag);
  if (report_pending) report_setup();

  const pd_bond_view v = bonds->view();
  const pd_pmb mat = {atom->ntypes + 1, coef[MICROMODULUS][0]};
  pd_tally t = {};
  t.eatom = eflag_atom ? eatom : nullptr;
  pd_pmb_forces(&v, &mat, atom->type, atom->x[0], atom->vfrac, atom->f[0], evflag ? &t : nullptr);
  if (evflag) tally(t);
}

void PairPDBond::stable_dt_sum(double *sum)
{
  const pd_bond_view v = bonds->view();
  const pd_pmb mat = {atom->ntypes + 1, coef[MICROMODULUS][0]};
  pd_pmb_stiffness(&v, &mat, atom->type, atom->vfrac, sum);
}
