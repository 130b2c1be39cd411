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
#include "neighbor.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <vector>

extern "C" {
#include "pd_influence.h"
#include "pd_ordinary.h"
#include "pd_params.h"
#include "pd_tangent.h"
#include "pd_timestep.h"
}

using namespace LAMMPS_NS;

PairPDOrdinary::PairPDOrdinary(LAMMPS *lmp) :
    PairPD(lmp, pd_ordinary_coefs, PD_ORD_NCOEFS), influence(-1), per_atom_norm(0), uniform_b(0), order(0.5),
    lambda_bar(nullptr), mu_bar(nullptr), strain(nullptr), nstrain(0)
{
}

PairPDOrdinary::~PairPDOrdinary()
{
  memory->destroy(lambda_bar);
  memory->destroy(mu_bar);
  memory->destroy(strain);
}

void PairPDOrdinary::settings(int narg, char **arg)
{
  influence = -1;
  per_atom_norm = 0;
  PairPD::settings(narg, arg);
}

int PairPDOrdinary::parse_setting(int narg, char **arg, int iarg)
{
  if (strcmp(arg[iarg], "surface_correction") == 0) {
    if (iarg + 1 >= narg) error->all(FLERR, "Pair pd/ordinary: 'surface_correction' needs yes or no");
    if (strcmp(arg[iarg + 1], "yes") == 0) per_atom_norm = 1;
    else if (strcmp(arg[iarg + 1], "no") == 0) per_atom_norm = 0;
    else error->all(FLERR, "Pair pd/ordinary: surface_correction '{}': expected yes or no", arg[iarg + 1]);
    return 2;
  }
  if (strcmp(arg[iarg], "influence") != 0) return 0;
  if (iarg + 1 >= narg)
    error->all(FLERR, "Pair pd/ordinary: 'influence' needs a name ({})", pd_influence_names());
  influence = pd_influence_from_name(arg[iarg + 1]);
  if (influence < 0)
    error->all(FLERR, "Pair pd/ordinary: unknown influence function '{}' ({})", arg[iarg + 1],
               pd_influence_names());
  return 2;
}

std::string PairPDOrdinary::family_settings() const
{
  return pd_influence_name((pd_influence_kind) influence);
}

// The horizon, positive moduli, m's range and the failure law's values are
// checked by their declarations (PairPD); a line between two types gives
// only the horizon and failure of their bonds (each atom's force state
// uses its own type's material).
void PairPDOrdinary::check_coeff(int i, int j)
{
  if (i != j) return;
  complete_elastic(i, j);
}

// E and nu of a type's material; between two types, their means
void PairPDOrdinary::fracture_elastic(int i, int j, double &E, double &nu) const
{
  mean_elastic(i, j, E, nu);
}

void PairPDOrdinary::init_style()
{
  // default influence: the one whose lattice moduli are closest to the input
  // at delta = 3 spacings (THEORY.md; test_waves.py): 1/|xi| on the cubic
  // lattice, constant on the square one
  if (influence < 0) influence = dim() == 3 ? PD_INFLUENCE_INVERSE : PD_INFLUENCE_CONSTANT;
  if (legacy) {
    influence = PD_INFLUENCE_LPS;
    per_atom_norm = 1;
    if (dim() != 3) error->all(FLERR, "Pair pd/ordinary legacy reproduces peri/lps, which is 3D");
  }
  order = shared_value(PD_ORD_M, 0.5);
  if (legacy && order != 0.5)
    error->all(FLERR, "Pair pd/ordinary legacy reproduces peri/lps, which is m = 0.5 (got {})", order);
  PairPD::init_style();
}

// The influence function, times PERI's partial volume with 'legacy' or the
// cell's share inside the horizon with 'quadrature partial'.
PDFamilySpec::Weight PairPDOrdinary::weight_rule() const
{
  const auto kind = (pd_influence_kind) influence;
  const int d = dim();
  const PDFamilySpec::Weight partial = PairPD::weight_rule();
  return [kind, d, partial](const PDBondGeometry &g) { return influence_at(kind, d, g) * partial(g); };
}

// The default 3D weight, 1/|xi| influence with point quadrature, is the
// horizon times 1/|xi| (pd_influence, and the cell's whole volume): the
// loops compute it when all type pairs share one horizon.
double PairPDOrdinary::inverse_weight_horizon() const
{
  if (legacy || partial_volumes() || directional || influence != PD_INFLUENCE_INVERSE) return 0.0;
  const double h = horizon(1, 1);
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = 1; j <= atom->ntypes; j++)
      if (horizon(i, j) != h) return 0.0;
  return h > 0.0 ? h : 0.0;
}

// N = d / m, m the atom's calibrated weighted volume: its own family's,
// and near a free surface, without the surface correction, a complete
// family's of its type (T14 6.1.3: no renormalization at free surfaces;
// surface atoms are softer). core/pd_calibration.h
double PairPDOrdinary::norm(int i) const
{
  return norm_of(calibrated_volume(i));
}

// N = d / m of a complete family of type t
double PairPDOrdinary::type_norm(int t) const
{
  return norm_of(calibrated_reference[t]);
}

double PairPDOrdinary::norm_of(double m) const
{
  return m > 0.0 ? dim() / m : 0.0;
}

// Per run: the Lame constants per type.
void PairPDOrdinary::setup_run()
{
  const int ntypes = atom->ntypes;
  memory->destroy(lambda_bar);
  memory->destroy(mu_bar);
  memory->create(lambda_bar, ntypes + 1, "pair:lambda_bar");
  memory->create(mu_bar, ntypes + 1, "pair:mu_bar");
  for (int t = 1; t <= ntypes; t++) {
    // a type of another hybrid sub-style has no bonds here: no energy either
    // (its NaN coefficients would make every atom's energy NaN)
    if (!setflag[t][t]) {
      lambda_bar[t] = mu_bar[t] = 0.0;
      continue;
    }
    pd_elastic m;
    pd_elastic_from_K_G(coef[PD_ORD_K][t][t], coef[PD_ORD_G][t][t], &m);
    const pd_lame l = pd_ordinary_lame(model_dim, &m);
    lambda_bar[t] = l.lambda;
    mu_bar[t] = l.mu;
  }
  // B = 2 mu_bar N (pd_ordinary_atom) is one number for all atoms when N is
  // its type's (a lattice's atoms without surface correction) and every
  // type has the same: the force pass then gathers no far end's B
  uniform_b = !per_atom_norm && calibration_uniform();
  // (the types of this style: another sub-style's atoms hold none of its bonds)
  double b1 = NAN;
  for (int t = 1; t <= ntypes; t++) {
    if (!setflag[t][t]) continue;
    const double b = pd_ordinary_atom(lambda_bar[t], mu_bar[t], type_norm(t), 0.0).b;
    if (std::isnan(b1)) b1 = b;
    if (b != b1) uniform_b = 0;
  }
}

// Per-atom state in the bond store: the dilatation of owned atoms (compute
// pd/atom lists it), A = lambda theta N and B = 2 mu N (owned + ghost).
std::vector<PDField> PairPDOrdinary::per_atom_fields() const
{
  return {{"dilatation", 1, PDField::OUTPUT}, {"ordinary_ab", 2, PDField::FORWARD}};
}

double *PairPDOrdinary::state(int f) const
{
  return f < (int) field_id.size() ? bonds->field(field_id[f]) : nullptr;
}

void PairPDOrdinary::compute(int eflag, int vflag)
{
  ev_init(eflag, vflag);
  grow_work();
  double *theta = state(F_DILATATION), *abstate = state(F_AB);
  if (report_pending) report_setup();

  const int nlocal = atom->nlocal, nall = nlocal + atom->nghost;
  const int *type = atom->type;
  double *sum = work;
  for (int i = 0; i < nall; i++) sum[i] = 0.0;
  Evaluation e;
  begin_evaluation(e);
  const pd_bond_view &v = e.view;
  // the bonds' strains, for owned rows only (a tenth more, so that atoms
  // migrating in rarely make it grow again), for the orders that keep it
  // between the passes
  const bool keep_strain = pd_ordinary_keeps_strain(order);
  if (keep_strain && (bigint) v.nowner * v.stride > nstrain) {
    nstrain = (bigint) (v.nowner + v.nowner / 10 + 1) * v.stride;
    memory->destroy(strain);
    memory->create(strain, nstrain, "pair:strain");
  }
  pd_ordinary_state st = {order, sum, abstate, keep_strain ? strain : nullptr, uniform_b};
  pd_ordinary_dilatation(&e.L, &st);
  bonds->sum_to_owners(sum);

  for (int i = 0; i < nlocal; i++) {
    const int ti = type[i];
    const pd_ordinary_atom_out o = pd_ordinary_atom(lambda_bar[ti], mu_bar[ti], norm(i), sum[i]);
    theta[i] = o.theta;
    abstate[2 * i] = o.a;
    abstate[2 * i + 1] = o.b;
    if (evflag) {
      e.tally.energy += o.energy;
      if (e.tally.eatom) e.tally.eatom[i] += o.energy;
    }
  }
  bonds->forward(field_id[F_AB]);
  force_pass(e, [&](const pd_loop *L) { pd_ordinary_forces(L, &st); });
  end_evaluation(e);
}

// Per atom (owned + ghost): the coefficient k of pd_ordinary_stiffness,
// N (2 mu_bar + d |lambda_bar|), in the pair's scratch.
double *PairPDOrdinary::stiffness_coefficients()
{
  double *k = scratch();
  for (int i = 0; i < atom->nlocal; i++) {
    const int ti = atom->type[i];
    k[i] = norm(i) * (2.0 * mu_bar[ti] + dim() * fabs(lambda_bar[ti]));
  }
  bonds->copy_to_ghosts(k);
  return k;
}

void PairPDOrdinary::stable_dt_sum(double *sum)
{
  const double *k = stiffness_coefficients();
  const pd_bond_view v = bonds->view();
  pd_ordinary_stiffness(&v, k, atom->vfrac, sum);
}

// with the stress terms of the last evaluation's A and B
void PairPDOrdinary::tangent_sum(double *sum, double *closing)
{
  const pd_state_tangent ctx = {order, stiffness_coefficients(), state(F_AB)};
  Evaluation e;
  begin_pass(e);
  pd_state_tangent_sums(&e.L, atom->v[0], &ctx, sum, closing);
}

bool PairPDOrdinary::linear_model(int t, pd_linear_kind &kind, pd_elastic &e) const
{
  kind = PD_LINEAR_ORDINARY;
  return pd_elastic_from_E_nu(value(PD_ORD_E, t, t), value(PD_ORD_NU, t, t), &e) == 0;
}

void PairPDOrdinary::report_extra()
{
  std::string lame;
  for (int t = 1; t <= atom->ntypes; t++)
    if (setflag[t][t]) lame += fmt::format(" type {}: lambda_bar {:.4g} mu_bar {:.4g};", t, lambda_bar[t], mu_bar[t]);
  utils::logmesg(lmp, "pd/ordinary: strain order m = {}, influence {}, {};{}\n", order,
                 pd_influence_name((pd_influence_kind) influence),
                 per_atom_norm ? "normalized per atom (surface correction)"
                               : "normalized by the complete family (no surface correction)",
                 lame);
}

void PairPDOrdinary::restart_settings(PDSettingsIO &io)
{
  PairPD::restart_settings(io);
  io(influence);
  io(per_atom_norm);
}

void *PairPDOrdinary::extract(const char *name, int &dim)
{
  dim = 0;
  if (strcmp(name, "theta") == 0) return bonds ? (void *) state(F_DILATATION) : nullptr;
  return nullptr;
}

// The PMB micromodulus of the same Young's modulus (the contact scale).
double PairPDOrdinary::contact_micromodulus(int i, int j) const
{
  // peri/lps's short-range constant: 18 K / (pi delta^4) of the first type
  if (legacy) return pd_pmb_micromodulus_3d(coef[PD_ORD_K][i][i], horizon(i, j));
  const double E = 0.5 * (coef[PD_ORD_E][i][i] + coef[PD_ORD_E][j][j]);
  return pd_pmb_micromodulus(model_dim, E, horizon(i, j), thickness);
}
