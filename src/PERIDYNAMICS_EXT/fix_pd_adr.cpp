/* ----------------------------------------------------------------------
   PERIDYNAMICS_EXT: fix pd/adr. Quasi-static loading with failure by
   adaptive dynamic relaxation (KM10, core/pd_adr.h): each LAMMPS step is
   one iteration in pseudo time (step 1) with the fix's own fictitious
   density lambda in place of the mass, taken from the particles' stiffness
   sums (the bound of fix pd/timestep) at the first step and then every N
   steps, and the damping of the lowest mode present from a Rayleigh
   quotient reduced over all ranks. The fix integrates its group itself
   (as fix nve does). atom->v holds the pseudo velocity per LAMMPS time
   unit, V / dt, so that x moves by v dt as LAMMPS expects and the bond
   store's blow-up guard (a move of half a horizon in one step) applies
   unchanged. The residual |R| / reference is a global vector for fix
   halt, which ends a load step.
------------------------------------------------------------------------- */

#include "fix_pd_adr.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "force.h"
#include "memory.h"
#include "modify.h"
#include "pair_pd.h"
#include "pair_pd_contact.h"
#include "pd_compat.h"
#include "update.h"

#include <cmath>
#include <cstring>

extern "C" {
#include "pd_adr.h"
}

using namespace LAMMPS_NS;
using namespace FixConst;

FixPDAdr::FixPDAdr(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), state(nullptr), safety(1.0), every(100), tol(0.0), material(nullptr),
    contact(nullptr), started(0), damping(0.0), residual(NAN), rnorm(0.0), reaction(0.0),
    reference(0.0), carried(0.0), runmax(0.0), iterations(0), run_start(0), converged(0), sums(nullptr),
    scratch(nullptr), springs(nullptr), nmax_sums(0)
{
  for (int iarg = 3; iarg < narg; iarg += 2) {
    const char *key = arg[iarg];
    if (iarg + 1 >= narg) error->all(FLERR, "Fix pd/adr: '{}' needs a value", key);
    const char *text = arg[iarg + 1];
    if (strcmp(key, "every") == 0) {
      every = utils::inumeric(FLERR, text, false, lmp);
      if (every < 0)
        error->all(FLERR, "Fix pd/adr: every must be a step count >= 0 (0: lambda once), got '{}'", text);
      continue;
    }
    const double v = utils::numeric(FLERR, text, false, lmp);
    if (strcmp(key, "safety") == 0) {
      if (!(v >= 1.0) || !std::isfinite(v))
        error->all(FLERR, "Fix pd/adr: safety must be a factor >= 1 on the stability bound, got '{}'", text);
      safety = v;
    } else if (strcmp(key, "tol") == 0) {
      if (!(v > 0.0) || !std::isfinite(v))
        error->all(FLERR, "Fix pd/adr: tol must be a relative residual > 0, got '{}'", text);
      tol = v;
    } else
      error->all(FLERR, "Fix pd/adr: unknown keyword '{}' (safety, every, tol)", key);
  }
  time_integrate = 1;
  scalar_flag = 1;
  vector_flag = 1;
  size_vector = 5;
  global_freq = 1;
  extscalar = 0;
  extvector = 0;
  restart_global = 1;
  restart_peratom = 1;
  dynamic_group_allow = 0;
  create_attribute = 1;    // atoms created later start at rest, held until lambda is taken

  grow_arrays(atom->nmax);
  atom->add_callback(Atom::GROW);
  atom->add_callback(Atom::RESTART);
  for (int i = 0; i < atom->nmax; i++)
    for (int k = 0; k < NSTATE; k++) state[i][k] = 0.0;
}

FixPDAdr::~FixPDAdr()
{
  atom->delete_callback(id, Atom::GROW);
  atom->delete_callback(id, Atom::RESTART);
  memory->destroy(state);
  memory->destroy(sums);
  memory->destroy(scratch);
  memory->destroy(springs);
}

int FixPDAdr::setmask()
{
  return INITIAL_INTEGRATE | FINAL_INTEGRATE;
}

int FixPDAdr::ndof() const
{
  return domain->dimension == 2 ? 2 : 3;
}

void FixPDAdr::init()
{
  material = PairPD::active(force);
  if (!material)
    error->all(FLERR, "Fix pd/adr needs a pd/ material pair style (pd/bond, pd/ordinary, pd/corr)");
  contact = dynamic_cast<PairPDContact *>(force->pair_match("pd/contact", 0, 0));
  if (utils::strmatch(update->integrate_style, "^respa"))
    error->all(FLERR, "Fix pd/adr does not work with run_style respa");
  // two integrators on one atom would move it twice, one of them by a mass
  // the relaxation knows nothing of
  for (Fix *fix : PDCompat::fixes(modify)) {
    if (fix == this) continue;
    if (strcmp(fix->style, "pd/timestep") == 0)
      error->all(FLERR, "Fix pd/adr runs in pseudo time, where fix {} (pd/timestep) has nothing to "
                 "do: unfix it for the relaxation", fix->id);
    if (!fix->time_integrate) continue;
    int mine = 0, all;
    for (int i = 0; i < atom->nlocal && !mine; i++)
      if ((atom->mask[i] & groupbit) && (atom->mask[i] & fix->groupbit)) mine = 1;
    MPI_Allreduce(&mine, &all, 1, MPI_INT, MPI_MAX, world);
    if (all)
      error->all(FLERR, "Fix pd/adr integrates its group itself: fix {} ({}) integrates some of "
                 "its atoms too; give the two fixes groups without common atoms", fix->id, fix->style);
  }
}

// A run is a load step for the residual's fallback scale and the tol line;
// the relaxation itself continues (a converged state has V close to 0).
void FixPDAdr::setup(int)
{
  run_start = update->ntimestep;
  runmax = 0.0;
  converged = 0;
  double **f = atom->f;
  const int *mask = atom->mask;
  const int nd = ndof();
  double mine[2] = {0.0, 0.0}, all[2];
  for (int i = 0; i < atom->nlocal; i++)
    for (int k = 0; k < nd; k++) {
      const double fv = f[i][k] * atom->vfrac[i];
      mine[(mask[i] & groupbit) ? 0 : 1] += fv * fv;
    }
  MPI_Allreduce(mine, all, 2, MPI_DOUBLE, MPI_SUM, world);
  rnorm = sqrt(all[0]);
  reaction = sqrt(all[1]);
  runmax = rnorm;
  reference = fmax(reaction, carried);
  if (reference == 0.0) reference = runmax;
  residual = reference > 0.0 ? rnorm / reference : 0.0;
  // the guard reads the pseudo velocity as a speed: per LAMMPS time unit
  double **v = atom->v;
  for (int i = 0; i < atom->nlocal; i++)
    if (mask[i] & groupbit)
      for (int k = 0; k < 3; k++) v[i][k] = state[i][V + k] / update->dt;
}

// U^{n+1} = U^n + V^{n+1/2}; at the very first iteration V^{1/2} from rest,
// from the forces of setup after every fix's setup changed them
// (setforce, enforce2d), which is why it is not taken in setup().
void FixPDAdr::initial_integrate(int)
{
  double **x = atom->x, **f = atom->f;
  const int *mask = atom->mask;
  const int nlocal = atom->nlocal, nd = ndof();
  if (!started) {
    update_lambda();
    for (int i = 0; i < nlocal; i++)
      if (mask[i] & groupbit) {
        pd_adr_start(nd, f[i], state[i][LAMBDA], &state[i][V]);
        for (int k = 0; k < 3; k++) state[i][FPREV + k] = f[i][k];
      }
    started = 1;
  }
  for (int i = 0; i < nlocal; i++)
    if (mask[i] & groupbit)
      for (int k = 0; k < nd; k++) x[i][k] += state[i][V + k];
}

// One iteration: the damping from F^n, F^{n-1}, V^{n-1/2} and U^n, then
// V^{n+1/2}; the residual of F^n.
void FixPDAdr::final_integrate()
{
  iterations++;
  if (every > 0 && update->ntimestep % every == 0) update_lambda();
  double **x = atom->x, **x0 = atom->x0, **f = atom->f, **v = atom->v;
  const double *vfrac = atom->vfrac;
  const int *mask = atom->mask;
  const int nlocal = atom->nlocal, nd = ndof();
  // U^T K1 U, U^T U, |R|^2, |reaction|^2
  double mine[4] = {0.0, 0.0, 0.0, 0.0}, all[4];
  for (int i = 0; i < nlocal; i++) {
    if (mask[i] & groupbit) {
      double u[3] = {x[i][0] - x0[i][0], x[i][1] - x0[i][1], x[i][2] - x0[i][2]};
      PDCompat::minimum_image(domain, u);
      pd_adr_rayleigh_terms(nd, f[i], &state[i][FPREV], state[i][LAMBDA], &state[i][V], u, &mine[0],
                            &mine[1]);
    }
    const int slot = (mask[i] & groupbit) ? 2 : 3;
    for (int k = 0; k < nd; k++) {
      const double fv = f[i][k] * vfrac[i];
      mine[slot] += fv * fv;
    }
  }
  MPI_Allreduce(mine, all, 4, MPI_DOUBLE, MPI_SUM, world);
  damping = pd_adr_damping(all[0], all[1]);
  for (int i = 0; i < nlocal; i++)
    if (mask[i] & groupbit) {
      pd_adr_velocity(nd, damping, f[i], state[i][LAMBDA], &state[i][V]);
      for (int k = 0; k < 3; k++) {
        state[i][FPREV + k] = f[i][k];
        v[i][k] = state[i][V + k] / update->dt;
      }
    }

  rnorm = sqrt(all[2]);
  reaction = sqrt(all[3]);
  runmax = fmax(runmax, rnorm);
  reference = fmax(reaction, carried);
  if (reference == 0.0) reference = runmax;
  residual = reference > 0.0 ? rnorm / reference : 0.0;
  if (tol > 0.0 && !converged && residual < tol) {
    converged = 1;
    if (comm->me == 0)
      utils::logmesg(lmp, "pd/adr: step {}: relative residual {:.4g} < tol {:.4g} after {} iterations "
                     "of this run (|R| {:.6g}, reference {:.6g} from the {})\n", update->ntimestep,
                     residual, tol, update->ntimestep - run_start, rnorm, reference,
                     reference == runmax ? "largest |R| of this run" : "reaction");
  }
}

// lambda_i from each particle's stiffness now (its bonds' current
// tangents, broken bonds that push, contact springs), never below that of
// the reference state: the bound must hold until the next update.
void FixPDAdr::update_lambda()
{
  if (atom->nmax > nmax_sums) {
    nmax_sums = atom->nmax;
    memory->destroy(sums);
    memory->destroy(scratch);
    memory->destroy(springs);
    memory->create(sums, nmax_sums, "pd/adr:sums");
    memory->create(scratch, nmax_sums, "pd/adr:scratch");
    memory->create(springs, nmax_sums, "pd/adr:springs");
  }
  const int nlocal = atom->nlocal, nall = nlocal + atom->nghost;
  const int *mask = atom->mask;
  for (int i = 0; i < nall; i++) springs[i] = 0.0;
  if (contact) {
    // contacts that may close before the next update count already
    double vmax = 0.0, all;
    for (int i = 0; i < nlocal; i++)
      if (mask[i] & groupbit)
        vmax = fmax(vmax, sqrt(state[i][V] * state[i][V] + state[i][V + 1] * state[i][V + 1] +
                               state[i][V + 2] * state[i][V + 2]));
    MPI_Allreduce(&vmax, &all, 1, MPI_DOUBLE, MPI_MAX, world);
    for (int i = 0; i < nall; i++) scratch[i] = 0.0;
    contact->tangent_sum(springs, scratch, 2.0 * all * (every > 0 ? every : 1));
    material->sum_to_owners(springs);
  }
  material->current_stiffness_sums(sums, scratch);
  for (int i = 0; i < nlocal; i++) sums[i] += springs[i];
  material->reference_stiffness_sums(springs);
  for (int i = 0; i < nlocal; i++)
    if (mask[i] & groupbit) state[i][LAMBDA] = pd_adr_density(fmax(sums[i], springs[i]), safety);
}

// the load the body carried at the end of a load step: the residual's
// scale once the reaction falls (a crack cut the body in two)
void FixPDAdr::post_run()
{
  carried = fmax(carried, reaction);
}

double FixPDAdr::compute_scalar()
{
  return residual;
}

// 1: |R| / reference, 2: c_n, 3: |R|, 4: the reference, 5: iterations so far
double FixPDAdr::compute_vector(int n)
{
  switch (n) {
    case 0:
      return residual;
    case 1:
      return damping;
    case 2:
      return rnorm;
    case 3:
      return reference;
    default:
      return (double) iterations;
  }
}

void FixPDAdr::write_restart(FILE *fp)
{
  if (comm->me != 0) return;
  const double list[4] = {(double) started, damping, (double) iterations, carried};
  const int size = sizeof(list);
  fwrite(&size, sizeof(int), 1, fp);
  fwrite(list, sizeof(list), 1, fp);
}

void FixPDAdr::restart(char *buf)
{
  double list[4];
  memcpy(list, buf, sizeof(list));
  started = (int) list[0];
  damping = list[1];
  iterations = (bigint) list[2];
  carried = list[3];
}

void FixPDAdr::grow_arrays(int nmax)
{
  memory->grow(state, nmax, NSTATE, "pd/adr:state");
}

void FixPDAdr::set_arrays(int i)
{
  for (int k = 0; k < NSTATE; k++) state[i][k] = 0.0;
}

void FixPDAdr::copy_arrays(int i, int j, int)
{
  for (int k = 0; k < NSTATE; k++) state[j][k] = state[i][k];
}

int FixPDAdr::pack_exchange(int i, double *buf)
{
  for (int k = 0; k < NSTATE; k++) buf[k] = state[i][k];
  return NSTATE;
}

int FixPDAdr::unpack_exchange(int nlocal, double *buf)
{
  for (int k = 0; k < NSTATE; k++) state[nlocal][k] = buf[k];
  return NSTATE;
}

int FixPDAdr::pack_restart(int i, double *buf)
{
  buf[0] = NSTATE + 1;
  for (int k = 0; k < NSTATE; k++) buf[k + 1] = state[i][k];
  return NSTATE + 1;
}

void FixPDAdr::unpack_restart(int nlocal, int nth)
{
  double **extra = atom->extra;
  int m = 0;
  for (int i = 0; i < nth; i++) m += static_cast<int>(extra[nlocal][m]);
  for (int k = 0; k < NSTATE; k++) state[nlocal][k] = extra[nlocal][m + 1 + k];
}

int FixPDAdr::size_restart(int)
{
  return NSTATE + 1;
}

int FixPDAdr::maxsize_restart()
{
  return NSTATE + 1;
}

double FixPDAdr::memory_usage()
{
  return (double) atom->nmax * NSTATE * sizeof(double) + 3.0 * nmax_sums * sizeof(double);
}
