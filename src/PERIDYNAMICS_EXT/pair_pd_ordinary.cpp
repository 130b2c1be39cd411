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

#include <cmath>
#include <cstring>
#include <vector>

extern "C" {
#include "pd_influence.h"
#include "pd_law_energy.h"
#include "pd_ordinary.h"
#include "pd_params.h"
#include "pd_timestep.h"
}

using namespace LAMMPS_NS;

enum { HORIZON, BULK, SHEAR, YOUNG, POISSON, ORDER };

PairPDOrdinary::PairPDOrdinary(LAMMPS *lmp) :
    PairPD(lmp, {"horizon", "K", "G", "E", "nu", "m"}), influence(-1),
    per_atom_norm(0), order(0.5), bulk_volume(nullptr), lambda_bar(nullptr), mu_bar(nullptr),
    strain(nullptr), nstrain(0), beta(nullptr), gc_pair(nullptr)
{
}

PairPDOrdinary::~PairPDOrdinary()
{
  memory->destroy(bulk_volume);
  memory->destroy(lambda_bar);
  memory->destroy(mu_bar);
  memory->destroy(strain);
  memory->destroy(beta);
  memory->destroy(gc_pair);
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

// Each atom's force state uses its own type's material (pair_coeff I I); an
// I J line with I != J sets only the horizon of the bonds between the types.
bool PairPDOrdinary::between_types(int p) const
{
  return p == HORIZON || p == ifail || p == is0 || p == iGc || p == ialpha;
}

void PairPDOrdinary::check_coeff(int i, int j)
{
  if (!given(HORIZON, i, j) || value(HORIZON, i, j) <= 0.0)
    error->all(FLERR, "Pair pd/ordinary coeff {} {}: horizon missing or not positive", i, j);
  if (i != j) {
    // interface bonds: their own failure (s0, or G_c: the critical stretch
    // follows in init_one, when both materials are known), else mixed
    check_failure(i, j, NAN, NAN);
    return;
  }
  for (int p : {BULK, SHEAR, YOUNG})
    if (given(p, i, j) && !(value(p, i, j) > 0.0))
      error->all(FLERR, "Pair pd/ordinary coeff {} {}: {} must be positive, got {}", i, j, names[p],
                 value(p, i, j));
  const pd_elastic m = elastic(i, j, "pd/ordinary");
  coef[BULK][i][j] = m.K;
  coef[SHEAR][i][j] = m.G;
  coef[YOUNG][i][j] = m.E;
  coef[POISSON][i][j] = m.nu;
  for (int p : {BULK, SHEAR, YOUNG}) check_derived(p, i, j);
  check_failure(i, j, m.E, m.nu);
  if (!given(ORDER, i, j)) coef[ORDER][i][j] = 0.5;
  if (!(value(ORDER, i, j) <= 1.0 && value(ORDER, i, j) >= -4.0))
    error->all(FLERR, "Pair pd/ordinary coeff {} {}: strain order m = {} is outside [-4, 1]", i, j,
               value(ORDER, i, j));
}

// An interface with the stretch law and its own G_c: the critical stretch
// of bond-based elasticity (MS07 eq. 28-29) for the two materials' mean E
// and nu, as for a type's own bonds.
double PairPDOrdinary::init_one(int i, int j)
{
  if (i != j && setflag[i][j] && value(ifail, i, j) == PD_FAIL_STRETCH && std::isnan(value(is0, i, j)) &&
      given(iGc, i, j)) {
    coef[is0][i][j] = pd_critical_stretch(dim(), model_dim == PD_PLANE_STRAIN,
                                          0.5 * (value(YOUNG, i, i) + value(YOUNG, j, j)),
                                          0.5 * (value(POISSON, i, i) + value(POISSON, j, j)),
                                          horizon(i, j), value(iGc, i, j));
    check_derived(is0, i, j);
  }
  return PairPD::init_one(i, j);
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
  // the types this style handles (under hybrid, others may belong to
  // another sub-style and have no order here)
  int first = 0;
  for (int i = 1; i <= atom->ntypes; i++) {
    if (!setflag[i][i]) continue;
    if (!first) first = i;
    if (coef[ORDER][i][i] != coef[ORDER][first][first])
      error->all(FLERR, "Pair pd/ordinary: all types need the same strain order m ({} has {}, {} has {})",
                 i, coef[ORDER][i][i], first, coef[ORDER][first][first]);
  }
  order = first ? coef[ORDER][first][first] : 0.5;
  if (legacy && order != 0.5)
    error->all(FLERR, "Pair pd/ordinary legacy reproduces peri/lps, which is m = 0.5 (got {})", order);
  PairPD::init_style();
}

// The influence function, times PERI's partial volume with 'legacy'.
PDFamilySpec::Weight PairPDOrdinary::weight_rule() const
{
  const auto kind = (pd_influence_kind) influence;
  const int d = dim();
  const PDFamilySpec::Weight partial = PairPD::weight_rule();
  return [kind, d, partial](double r, double horizon) {
    return pd_influence(kind, d, r, horizon) * partial(r, horizon);
  };
}

// N = d / m: m is the atom's own weighted volume with the surface
// correction, else that of a complete family of its type (T14 6.1.3: no
// renormalization at free surfaces; surface atoms are softer).
double PairPDOrdinary::norm(int i) const
{
  const double m = per_atom_norm ? bonds->weighted_volume()[i] : bulk_volume[atom->type[i]];
  return m > 0.0 ? dim() / m : 0.0;
}

// Per run: the Lame constants per type and the complete-family weighted
// volume, the largest over the type's atoms (an interior atom's).
void PairPDOrdinary::setup_run()
{
  const int ntypes = atom->ntypes;
  memory->destroy(bulk_volume);
  memory->destroy(lambda_bar);
  memory->destroy(mu_bar);
  memory->create(bulk_volume, ntypes + 1, "pair:bulk_volume");
  memory->create(lambda_bar, ntypes + 1, "pair:lambda_bar");
  memory->create(mu_bar, ntypes + 1, "pair:mu_bar");
  std::vector<double> mine(ntypes + 1, 0.0);
  for (int i = 0; i < atom->nlocal; i++)
    mine[atom->type[i]] = MAX(mine[atom->type[i]], bonds->weighted_volume()[i]);
  MPI_Allreduce(mine.data(), bulk_volume, ntypes + 1, MPI_DOUBLE, MPI_MAX, world);
  memory->destroy(beta);
  memory->create(beta, ntypes + 1, "pair:beta");
  std::vector<double> moment(ntypes + 1, 0.0);
  if (law == PD_FAIL_ENERGY) {
    // the complete family's moment sum w V / |xi|, the largest of the type
    grow_work();
    const int nall = atom->nlocal + atom->nghost;
    for (int i = 0; i < nall; i++) work[i] = 0.0;
    const pd_bond_view v = bonds->view();
    pd_failure_moment(&v, atom->vfrac, work);
    bonds->sum_to_owners(work);
    std::vector<double> mine(ntypes + 1, 0.0);
    for (int i = 0; i < atom->nlocal; i++) mine[atom->type[i]] = MAX(mine[atom->type[i]], work[i]);
    MPI_Allreduce(mine.data(), moment.data(), ntypes + 1, MPI_DOUBLE, MPI_MAX, world);
  }
  // beta per unit G_c, calibrated on each type's lattice; every bond takes
  // the G_c of its type pair (an interface has its own)
  memory->destroy(gc_pair);
  memory->create(gc_pair, (ntypes + 1) * (ntypes + 1), "pair:gc_pair");
  for (int t = 0; t <= ntypes; t++) beta[t] = 0.0;
  for (int ti = 0; ti <= ntypes; ti++)
    for (int tj = 0; tj <= ntypes; tj++) {
      const bool fails = ti && tj && law == PD_FAIL_ENERGY && coef[ifail][ti][tj] == PD_FAIL_ENERGY &&
          std::isfinite(coef[iGc][ti][tj]);
      gc_pair[ti * (ntypes + 1) + tj] = fails ? coef[iGc][ti][tj] : INFINITY;
      if (!fails) continue;
      // the continuum integral must exist (T14 eq. 6.1-6.2) ...
      if (pd_energy_failure_beta((pd_influence_kind) influence, dim(), coef[HORIZON][ti][tj], 1.0) < 0.0)
        error->all(FLERR, "Pair pd/ordinary: 'fail energy' with influence {} in 2D: the G_c "
                   "integral diverges (T14 eq. 6.2); use influence constant or tupek",
                   pd_influence_name((pd_influence_kind) influence));
    }
  // ... and beta is calibrated on the lattice itself
  if (law == PD_FAIL_ENERGY)
    for (int t = 1; t <= ntypes; t++)
      beta[t] = pd_energy_failure_beta_lattice(dim(), 1.0, bulk_volume[t], moment[t]);
  for (int t = 1; t <= ntypes; t++) {
    pd_elastic m;
    pd_elastic_from_K_G(coef[BULK][t][t], coef[SHEAR][t][t], &m);
    const pd_lame l = pd_ordinary_lame(model_dim, &m);
    lambda_bar[t] = l.lambda;
    mu_bar[t] = l.mu;
  }
}

// Per-atom state in the bond store: the dilatation of owned atoms (compute
// pd/atom lists it), A = lambda theta N and B = 2 mu N (owned + ghost), and
// with the energy law beta N for G_c = 1 (owned + ghost).
std::vector<PDField> PairPDOrdinary::per_atom_fields() const
{
  std::vector<PDField> f = {{"dilatation", 1, PDField::OUTPUT}, {"ordinary_ab", 2, PDField::FORWARD}};
  if (law == PD_FAIL_ENERGY) f.push_back({"energy_failure_crit", 1, PDField::FORWARD});
  return f;
}

double *PairPDOrdinary::state(int f) const
{
  return f < (int) field_id.size() ? bonds->field(field_id[f]) : nullptr;
}

void PairPDOrdinary::compute(int eflag, int vflag)
{
  ev_init(eflag, vflag);
  grow_work();
  double *theta = state(F_DILATATION), *abstate = state(F_AB), *crit = state(F_CRIT);
  if (report_pending) report_setup();

  const int nlocal = atom->nlocal, nall = nlocal + atom->nghost;
  const int *type = atom->type;
  double *sum = work;
  for (int i = 0; i < nall; i++) sum[i] = 0.0;
  const pd_bond_view v = bonds->view();
  if (order != 0.5 && (bigint) v.nowner * v.stride > nstrain) {
    nstrain = (bigint) atom->nmax * v.stride;
    memory->destroy(strain);
    memory->create(strain, nstrain, "pair:strain");
  }
  pd_ordinary_state st = {order, sum, abstate, order != 0.5 ? strain : nullptr};
  const bool fails = failing();
  pd_failure fail = fails ? failure_state() : pd_failure{};
  pd_failure *fp = fails ? &fail : nullptr;
  pd_tally t = {};
  t.eatom = eflag_atom ? eatom : nullptr;
  const pd_loop L = evaluation(v, evflag ? &t : nullptr, fp);
  pd_ordinary_dilatation(&L, &st);
  bonds->sum_to_owners(sum);

  for (int i = 0; i < nlocal; i++) {
    const int ti = type[i];
    const pd_ordinary_atom_out o = pd_ordinary_atom(lambda_bar[ti], mu_bar[ti], norm(i), sum[i]);
    theta[i] = o.theta;
    abstate[2 * i] = o.a;
    abstate[2 * i + 1] = o.b;
    if (evflag) {
      t.energy += o.energy;
      if (t.eatom) t.eatom[i] += o.energy;
    }
  }
  bonds->forward(field_id[F_AB]);
  if (law == PD_FAIL_ENERGY) {
    // beta N is fixed per atom: ghosts need it again only after reneighboring
    for (int i = 0; i < nlocal; i++) crit[i] = beta[type[i]] * norm(i);
    energy_law = {crit, gc_pair};
    fail.params = &energy_law;
    if (neighbor->ago == 0) bonds->forward(field_id[F_CRIT]);
  }
  pd_ordinary_forces(&L, &st);
  if (fails) account_failure(fail);
  if (evflag) tally(t);
}

void PairPDOrdinary::stable_dt_sum(double *sum)
{
  const int nlocal = atom->nlocal;
  double *k = state(F_AB);    // scratch: stiffness coefficient per atom
  for (int i = 0; i < nlocal; i++) {
    const int ti = atom->type[i];
    k[i] = norm(i) * (2.0 * mu_bar[ti] + dim() * fabs(lambda_bar[ti]));
  }
  bonds->copy_to_ghosts(k);
  const pd_bond_view v = bonds->view();
  pd_ordinary_stiffness(&v, k, atom->vfrac, sum);
}

void PairPDOrdinary::report_extra()
{
  std::string lame;
  for (int t = 1; t <= atom->ntypes; t++)
    lame += fmt::format(" type {}: lambda_bar {:.4g} mu_bar {:.4g};", t, lambda_bar[t], mu_bar[t]);
  if (law == PD_FAIL_ENERGY)
    for (int t = 1; t <= atom->ntypes; t++) {
      const double gc = gc_pair[t * (atom->ntypes + 1) + t];
      if (std::isfinite(gc))
        lame += fmt::format(" type {} energy failure beta {:.4g} (continuum {:.4g});", t, beta[t] * gc,
                            pd_energy_failure_beta((pd_influence_kind) influence, dim(),
                                                   coef[HORIZON][t][t], gc));
    }
  utils::logmesg(lmp, "pd/ordinary: strain order m = {}, influence {}, {};{}\n", order,
                 pd_influence_name((pd_influence_kind) influence),
                 per_atom_norm ? "normalized per atom (surface correction)"
                               : "normalized by the complete family (no surface correction)",
                 lame);
}

void PairPDOrdinary::write_restart_settings(FILE *fp)
{
  PairPD::write_restart_settings(fp);
  fwrite(&influence, sizeof(int), 1, fp);
  fwrite(&per_atom_norm, sizeof(int), 1, fp);
}

void PairPDOrdinary::read_restart_settings(FILE *fp)
{
  PairPD::read_restart_settings(fp);
  if (comm->me == 0) {
    utils::sfread(FLERR, &influence, sizeof(int), 1, fp, nullptr, error);
    utils::sfread(FLERR, &per_atom_norm, sizeof(int), 1, fp, nullptr, error);
  }
  MPI_Bcast(&influence, 1, MPI_INT, 0, world);
  MPI_Bcast(&per_atom_norm, 1, MPI_INT, 0, world);
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
  if (legacy) return pd_pmb_micromodulus_3d(coef[BULK][i][i], horizon(i, j));
  const double E = 0.5 * (coef[YOUNG][i][i] + coef[YOUNG][j][j]);
  return pd_pmb_micromodulus(model_dim, E, horizon(i, j), thickness);
}
