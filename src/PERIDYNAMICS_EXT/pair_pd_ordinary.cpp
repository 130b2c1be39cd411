/* ----------------------------------------------------------------------
   PERIDYNAMICS_EXT: pair_style pd/ordinary (T14 eq. 5.1; LPS at m = 1/2).

   Per step: dilatation sums over each bond once, summed onto owners;
   per-atom A and B (pd_ordinary.h) sent to ghosts; forces over each bond
   once. Legacy PERI visits every bond four times for the same result.
------------------------------------------------------------------------- */

#include "pair_pd_ordinary.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "fix_pd_bonds.h"
#include "force.h"
#include "memory.h"

#include <cmath>
#include <cstring>

extern "C" {
#include "pd_influence.h"
#include "pd_ordinary.h"
#include "pd_params.h"
#include "pd_timestep.h"
}

using namespace LAMMPS_NS;

enum { HORIZON, BULK, SHEAR, ORDER };

PairPDOrdinary::PairPDOrdinary(LAMMPS *lmp) :
    PairPD(lmp, {"horizon", "K", "G", "m"}), influence(PD_INFLUENCE_INVERSE), order(0.5),
    theta(nullptr), abstate(nullptr), nmax(0)
{
}

PairPDOrdinary::~PairPDOrdinary()
{
  memory->destroy(theta);
  memory->destroy(abstate);
}

int PairPDOrdinary::parse_setting(int narg, char **arg, int iarg)
{
  if (strcmp(arg[iarg], "influence") != 0) return 0;
  if (iarg + 1 >= narg) error->all(FLERR, "Pair pd/ordinary: 'influence' needs a name");
  influence = pd_influence_from_name(arg[iarg + 1]);
  if (influence < 0)
    error->all(FLERR, "Pair pd/ordinary: unknown influence function '{}' (constant, inverse, lps, "
               "tupek, gauss)", arg[iarg + 1]);
  return 2;
}

void PairPDOrdinary::check_coeff(int i, int j)
{
  if (!given(HORIZON, i, j) || value(HORIZON, i, j) <= 0.0)
    error->all(FLERR, "Pair pd/ordinary coeff {} {}: horizon missing or not positive", i, j);
  for (int p : {BULK, SHEAR})
    if (!given(p, i, j) || !(value(p, i, j) > 0.0))
      error->all(FLERR, "Pair pd/ordinary coeff {} {}: {} missing or not positive", i, j, names[p]);
  if (!given(ORDER, i, j)) coef[ORDER][i][j] = 0.5;
  if (!(value(ORDER, i, j) <= 1.0 && value(ORDER, i, j) >= -4.0))
    error->all(FLERR, "Pair pd/ordinary coeff {} {}: strain order m = {} is outside [-4, 1]", i, j,
               value(ORDER, i, j));
}

void PairPDOrdinary::init_style()
{
  if (legacy) influence = PD_INFLUENCE_LPS;
  if (domain->dimension != 3) error->all(FLERR, "Pair pd/ordinary supports 3D only for now");
  order = coef[ORDER][1][1];
  for (int i = 1; i <= atom->ntypes; i++)
    if (coef[ORDER][i][i] != order)
      error->all(FLERR, "Pair pd/ordinary: all types need the same strain order m ({} has {}, 1 has {})",
                 i, coef[ORDER][i][i], order);
  if (legacy && order != 0.5)
    error->all(FLERR, "Pair pd/ordinary legacy reproduces peri/lps, which is m = 0.5 (got {})", order);
  PairPD::init_style();
}

double PairPDOrdinary::bond_weight(int itype, int jtype, double r) const
{
  return pd_influence((pd_influence_kind) influence, 3, r, horizon(itype, jtype)) *
      PairPD::bond_weight(itype, jtype, r);
}

double PairPDOrdinary::norm(int i) const
{
  const double m = bonds->weighted_volume[i];
  return m > 0.0 ? 3.0 / m : 0.0;
}

void PairPDOrdinary::grow_state()
{
  if (atom->nmax > nmax) {
    nmax = atom->nmax;
    memory->destroy(theta);
    memory->destroy(abstate);
    memory->create(theta, nmax, "pair:theta");
    memory->create(abstate, 2 * nmax, "pair:abstate");
  }
}

void PairPDOrdinary::compute(int eflag, int vflag)
{
  ev_init(eflag, vflag);
  grow_state();
  grow_work();
  if (report_pending) report_setup();

  const int nlocal = atom->nlocal, nall = nlocal + atom->nghost;
  const int *type = atom->type;
  double *sum = work;
  for (int i = 0; i < nall; i++) sum[i] = 0.0;
  const pd_bond_view v = bonds->view();
  pd_ordinary_state st = {order, sum, abstate};
  pd_ordinary_dilatation(&v, &st, atom->x[0], atom->vfrac);
  bonds->sum_to_owners(sum);

  pd_tally t = {};
  t.eatom = eflag_atom ? eatom : nullptr;
  for (int i = 0; i < nlocal; i++) {
    const int ti = type[i];
    const pd_lame l = pd_ordinary_lame_3d(coef[BULK][ti][ti], coef[SHEAR][ti][ti]);
    const pd_ordinary_atom_out o = pd_ordinary_atom(l.lambda, l.mu, norm(i), sum[i]);
    theta[i] = o.theta;
    abstate[2 * i] = o.a;
    abstate[2 * i + 1] = o.b;
    if (evflag) {
      t.energy += o.energy;
      if (t.eatom) t.eatom[i] += o.energy;
    }
  }
  bonds->copy_to_ghosts(abstate, 2);
  pd_ordinary_forces(&v, &st, atom->x[0], atom->vfrac, atom->f[0], evflag ? &t : nullptr);
  if (evflag) tally(t);
}

void PairPDOrdinary::stable_dt_sum(double *sum)
{
  grow_state();
  const int nlocal = atom->nlocal;
  double *k = abstate;    // scratch: stiffness coefficient per atom
  for (int i = 0; i < nlocal; i++) {
    const int ti = atom->type[i];
    const pd_lame l = pd_ordinary_lame_3d(coef[BULK][ti][ti], coef[SHEAR][ti][ti]);
    k[i] = norm(i) * (2.0 * l.mu + 3.0 * fabs(l.lambda));
  }
  bonds->copy_to_ghosts(k);
  const pd_bond_view v = bonds->view();
  pd_ordinary_stiffness(&v, k, atom->vfrac, sum);
}

void PairPDOrdinary::report_extra()
{
  utils::logmesg(lmp, "pd/ordinary: strain order m = {}, influence {}, normalized per atom by "
                 "its weighted volume\n", order, pd_influence_name((pd_influence_kind) influence));
}

void PairPDOrdinary::write_restart_settings(FILE *fp)
{
  PairPD::write_restart_settings(fp);
  fwrite(&influence, sizeof(int), 1, fp);
}

void PairPDOrdinary::read_restart_settings(FILE *fp)
{
  PairPD::read_restart_settings(fp);
  if (comm->me == 0) utils::sfread(FLERR, &influence, sizeof(int), 1, fp, nullptr, error);
  MPI_Bcast(&influence, 1, MPI_INT, 0, world);
}

void *PairPDOrdinary::extract(const char *name, int &dim)
{
  dim = 0;
  if (strcmp(name, "theta") == 0) return (void *) theta;
  return nullptr;
}
