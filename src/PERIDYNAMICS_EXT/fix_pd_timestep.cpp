/* ----------------------------------------------------------------------
   PERIDYNAMICS_EXT: fix pd/timestep. At the start of a run and then at
   least every N steps, each particle's stiffness bound in the current
   state gives its stable step (core/pd_tangent.h). The smallest over all
   ranks times the safety factor, and the kinematic limits (no particle
   travels, no bond or contact closes, more than a fraction of its spacing
   or length in a step: the estimate holds while the arrangement changes
   little), bound the time step, which is set as fix dt/reset sets it.
   Checks come at every step while the state stiffens fast, and a cheap
   per-step test takes one at once when a particle starts to travel too
   far. The step changes only when it leaves a band of width 'grow' below
   what is allowed, so the log (one line per change) stays short.
------------------------------------------------------------------------- */

#include "fix_pd_timestep.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "force.h"
#include "memory.h"
#include "modify.h"
#include "neighbor.h"
#include "pair_pd.h"
#include "pair_pd_contact.h"
#include "pd_compat.h"
#include "update.h"

#include <algorithm>
#include <cmath>
#include <cstring>

extern "C" {
#include "pd_contact.h"
#include "pd_timestep.h"
}

using namespace LAMMPS_NS;
using namespace FixConst;

// A WARNING when the step falls this many times below the material's
// stable step (and at each further 10x)
static constexpr double SHRINK_WARNING = 100.0;

// What limits the step: the atom whose stable step is the smallest, and why.
struct FixPDTimestep::Limit {
  double dt;         // the step it allows (safety factor applied)
  double stable;     // the smallest stable step of all atoms (no safety factor)
  tagint tag;
  int cause;         // CAUSE_*
  double stiffening; // its material stiffness now over the reference state's
};
static const char *const CAUSES[] = {"material", "compression", "contact", "travel", "closing"};

FixPDTimestep::FixPDTimestep(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), every(10), safety(0.8), travel(0.05), dtmin(0.0), dtmax(INFINITY),
    grow(1.1), material(nullptr), contact(nullptr), estimate(0.0), nchanges(0), dt_set(0.0),
    interval(1), next_check(-1), current(nullptr), reference(nullptr), springs(nullptr),
    closing(nullptr), contact_closing(nullptr), nmax(0), reference_build(-1)
{
  nevery = 1;    // LAMMPS calls end_of_step every step: the cheap check
  for (int iarg = 3; iarg < narg; iarg += 2) {
    const char *key = arg[iarg];
    if (iarg + 1 >= narg) error->all(FLERR, "Fix pd/timestep: '{}' needs a value", key);
    const char *text = arg[iarg + 1];
    if (strcmp(key, "every") == 0) {
      every = utils::inumeric(FLERR, text, false, lmp);
      if (every < 1) error->all(FLERR, "Fix pd/timestep: every must be a step count >= 1, got '{}'", text);
      continue;
    }
    const double v = utils::numeric(FLERR, text, false, lmp);
    if (strcmp(key, "safety") == 0) {
      if (!(v > 0.0 && v <= 1.0))
        error->all(FLERR, "Fix pd/timestep: safety must be a fraction in (0, 1], got '{}'", text);
      safety = v;
    } else if (strcmp(key, "min") == 0 || strcmp(key, "max") == 0) {
      if (!(v > 0.0) || !std::isfinite(v))
        error->all(FLERR, "Fix pd/timestep: {} must be a time step > 0, got '{}'", key, text);
      (key[1] == 'i' ? dtmin : dtmax) = v;
    } else if (strcmp(key, "travel") == 0) {
      if (!(v >= 0.0) || !std::isfinite(v))
        error->all(FLERR, "Fix pd/timestep: travel must be a fraction of the spacing >= 0 (0: no "
                   "limit), got '{}'", text);
      travel = v;
    } else if (strcmp(key, "grow") == 0) {
      if (!(v > 1.0) || !std::isfinite(v))
        error->all(FLERR, "Fix pd/timestep: grow must be a factor > 1, got '{}'", text);
      grow = v;
    } else
      error->all(FLERR, "Fix pd/timestep: unknown keyword '{}' (every, safety, travel, min, max, grow)", key);
  }
  if (dtmin > dtmax) error->all(FLERR, "Fix pd/timestep: min {} exceeds max {}", dtmin, dtmax);
  if (igroup != 0)
    error->all(FLERR, "Fix pd/timestep: the stable step concerns every atom: use group all, not '{}'",
               arg[1]);
  scalar_flag = 1;
  vector_flag = 1;
  size_vector = 3;
  global_freq = 1;
  extscalar = 0;
  extvector = 0;
  restart_global = 1;
}

FixPDTimestep::~FixPDTimestep()
{
  memory->destroy(current);
  memory->destroy(reference);
  memory->destroy(springs);
  memory->destroy(closing);
  memory->destroy(contact_closing);
}

int FixPDTimestep::setmask()
{
  return END_OF_STEP;
}

void FixPDTimestep::init()
{
  material = PairPD::active(force);
  if (!material)
    error->all(FLERR, "Fix pd/timestep needs a pd/ material pair style (pd/bond, pd/ordinary, pd/corr)");
  contact = dynamic_cast<PairPDContact *>(force->pair_match("pd/contact", 0, 0));
  if (utils::strmatch(update->integrate_style, "^respa"))
    error->all(FLERR, "Fix pd/timestep does not work with run_style respa");
  // two fixes that set the step would undo each other's every change
  for (int i = 0; i < modify->nfix; i++)
    if (utils::strmatch(modify->fix[i]->style, "^dt/reset"))
      error->all(FLERR, "Fix pd/timestep and fix {} ({}) both set the time step: unfix one of them",
                 modify->fix[i]->id, modify->fix[i]->style);
  run = RunSummary();
}

// One line at the end of each run: what the many lines of changes add up to.
void FixPDTimestep::post_run()
{
  if (comm->me != 0) return;
  std::string causes;
  for (int c = 0; c < NCAUSES; c++)
    if (run.changes[c]) causes += fmt::format("{}{} {}", causes.empty() ? "" : ", ", CAUSES[c], run.changes[c]);
  utils::logmesg(lmp, "pd/timestep: this run: {} checks, {} changes of the step{}; step {:.6g} .. {:.6g}\n",
                 run.checks, run.total(), causes.empty() ? "" : " (limited by " + causes + ")",
                 std::isfinite(run.dtmin) ? run.dtmin : update->dt,
                 std::isfinite(run.dtmin) ? run.dtmax : update->dt);
}

// A run starts: its first step comes from the state it starts in, unless
// this fix set the step itself off its schedule (a restart or a next run
// between two checks keeps the step the uninterrupted run would have).
void FixPDTimestep::setup(int)
{
  // the scale a shrinking step is measured against: the material's stable
  // step in its reference state (the setup estimate)
  run.base = material->stable_dt() > 0.0 ? material->stable_dt() : update->dt;
  if (!(dt_set > 0.0 && update->dt == dt_set && update->ntimestep < next_check)) check("run start");
}

// Between the checks, a cheap one: an impact or a wall can make a particle
// travel too far in a step long before the next check sees the stiffening.
void FixPDTimestep::end_of_step()
{
  if (update->ntimestep >= next_check) {
    check("");
    return;
  }
  if (travel == 0.0) return;
  const int nlocal = atom->nlocal;
  int mine = nlocal ? pd_travel_count(nlocal, atom->v[0], atom->f[0], atom->rmass, atom->vfrac,
                                      update->dt, force->ftm2v, travel, material->dimension(),
                                      material->plate_thickness())
                    : 0,
      all;
  MPI_Allreduce(&mine, &all, 1, MPI_INT, MPI_MAX, world);
  if (all) check("travel");
}

// The estimate holds while the arrangement changes little: the step in
// which atom i moves 'travel' of its spacing, v dt + |a| dt^2 / 2 = travel
// spacing (as fix dt/reset's xmax; a = ftm2v f / rho).
double FixPDTimestep::travel_dt(int i) const
{
  if (travel == 0.0) return INFINITY;
  double speed, accel;
  pd_particle_motion(atom->v[i], atom->f[i], atom->rmass[i], force->ftm2v, &speed, &accel);
  const double reach =
      travel * 2.0 * pd_contact_radius(material->dimension(), atom->vfrac[i], material->plate_thickness());
  // the positive root of accel/2 dt^2 + speed dt - reach = 0, without cancellation
  const double root = speed + sqrt(speed * speed + 2.0 * accel * reach);
  return root > 0.0 ? 2.0 * reach / root : INFINITY;
}

// How much closer two particles may come in 'every' steps at twice the
// step: contacts about to form count already (the same reach at every
// check, so that a check soon after another does not undo it).
double FixPDTimestep::contact_reach() const
{
  double **v = atom->v;
  double vmax = 0.0;
  for (int i = 0; i < atom->nlocal; i++)
    vmax = fmax(vmax, v[i][0] * v[i][0] + v[i][1] * v[i][1] + v[i][2] * v[i][2]);
  double all;
  MPI_Allreduce(&vmax, &all, 1, MPI_DOUBLE, MPI_MAX, world);
  return 2.0 * sqrt(all) * every * 2.0 * update->dt;
}

FixPDTimestep::Limit FixPDTimestep::limiting_atom()
{
  if (atom->nmax > nmax) {
    nmax = atom->nmax;
    memory->destroy(current);
    memory->destroy(reference);
    memory->destroy(springs);
    memory->destroy(closing);
    memory->destroy(contact_closing);
    memory->create(current, nmax, "pd/timestep:current");
    memory->create(reference, nmax, "pd/timestep:reference");
    memory->create(springs, nmax, "pd/timestep:springs");
    memory->create(closing, nmax, "pd/timestep:closing");
    memory->create(contact_closing, nmax, "pd/timestep:contact_closing");
    reference_build = -1;
  }
  material->current_stiffness_sums(current, closing);
  // the reference sums change only with the atoms' order (reneighboring)
  if (reference_build != neighbor->ncalls) {
    material->reference_stiffness_sums(reference);
    reference_build = neighbor->ncalls;
  }
  if (contact) {
    const int nall = atom->nlocal + atom->nghost;
    for (int i = 0; i < nall; i++) springs[i] = contact_closing[i] = 0.0;
    contact->tangent_sum(springs, contact_closing, contact_reach());
    material->sum_to_owners(springs);
    material->max_to_owners(contact_closing);
    for (int i = 0; i < atom->nlocal; i++) closing[i] = std::max(closing[i], contact_closing[i]);
  } else
    for (int i = 0; i < atom->nlocal; i++) springs[i] = 0.0;
  struct {
    double dt;
    int rank;
  } mine = {INFINITY, comm->me}, all;
  double stable = INFINITY;
  int imin = -1, travels = 0, kinematic = CAUSE_TRAVEL;
  for (int i = 0; i < atom->nlocal; i++) {
    // a = ftm2v f / m in every unit system (rmass is the density, f a force density)
    const double dt = pd_stable_dt(atom->rmass[i], force->ftm2v * (current[i] + springs[i]));
    stable = fmin(stable, dt);
    // no particle travels, no bond or contact closes, more than 'travel' in a step
    const double dt_travel = travel_dt(i);
    const double dt_closing = travel > 0.0 && closing[i] > 0.0 ? travel / closing[i] : INFINITY;
    const double allowed = fmin(safety * dt, fmin(dt_travel, dt_closing));
    if (allowed < mine.dt) {
      mine.dt = allowed;
      imin = i;
      kinematic = dt_closing <= dt_travel ? CAUSE_CLOSING : CAUSE_TRAVEL;
      travels = fmin(dt_travel, dt_closing) < safety * dt;
    }
  }
  MPI_Allreduce(&mine, &all, 1, MPI_DOUBLE_INT, MPI_MINLOC, world);
  Limit lim = {all.dt, 0.0, 0, CAUSE_MATERIAL, 1.0};
  MPI_Allreduce(&stable, &lim.stable, 1, MPI_DOUBLE, MPI_MIN, world);
  if (comm->me == all.rank && imin >= 0) {
    lim.tag = atom->tag[imin];
    lim.stiffening = reference[imin] > 0.0 ? current[imin] / reference[imin] : 1.0;
    lim.cause = travels                       ? kinematic
        : springs[imin] > current[imin] ? CAUSE_CONTACT
        : lim.stiffening > 1.05              ? CAUSE_COMPRESSION
                                             : CAUSE_MATERIAL;
  }
  MPI_Bcast(&lim.tag, 1, MPI_LMP_TAGINT, all.rank, world);
  MPI_Bcast(&lim.cause, 1, MPI_INT, all.rank, world);
  MPI_Bcast(&lim.stiffening, 1, MPI_DOUBLE, all.rank, world);
  return lim;
}

void FixPDTimestep::check(const char *when)
{
  const Limit lim = limiting_atom();
  run.checks++;
  // the next check: at once while the state stiffens fast (the stable step
  // fell by more than 'grow' since the last one), else after twice the
  // interval, up to 'every' steps
  interval = estimate > 0.0 && lim.stable * grow < estimate ? 1 : std::min(2 * interval, every);
  next_check = update->ntimestep + interval;
  estimate = lim.stable;
  if (!std::isfinite(lim.dt)) return;    // no bond, contact or motion: nothing limits the step
  material->note_stable_dt(estimate);    // the blow-up guard quotes it
  const double allowed = fmin(lim.dt, dtmax);
  if (allowed < dtmin)
    error->all(FLERR, "Fix pd/timestep: at step {} the step the state allows, {:.6g}, is below min "
               "{:.6g} ({} at atom {}): the run would be unstable; lower min or change the scene",
               update->ntimestep, allowed, dtmin, CAUSES[lim.cause], lim.tag);
  // a band: the step stays while it is within [allowed / grow, allowed]
  // (with a slack of a tenth of grow - 1 at its lower end), else becomes
  // allowed / grow: a shrinking step changes once per factor grow, and a
  // step the state allows to grow follows only by more than the slack
  // (without it, a step set to allowed / grow was set again at every check
  // in which the allowed step grew by a hair: a plate pulled apart logged
  // 300 changes of the step to itself)
  const double old = update->dt;
  const double slack = 1.0 + 0.1 * (grow - 1.0);
  if (dt_set > 0.0 && old <= allowed && old * grow * slack >= allowed) return;
  const double dt = fmax(fmin(lim.dt / grow, dtmax), dtmin);
  set_dt(dt);
  run.changes[lim.cause]++;
  run.dtmin = fmin(run.dtmin, dt);
  run.dtmax = fmax(run.dtmax, dt);
  // a step that shrinks by orders of magnitude slows the run as much: say
  // so at 100x and at each further 10x (without 'min' nothing else would)
  if (run.base > 0.0 && dt * SHRINK_WARNING < run.base && dt < run.warned / 10.0) {
    run.warned = dt;
    if (comm->me == 0)
      error->warning(FLERR, "Fix pd/timestep: at step {} the step is {:.3g}, {:.3g} times below the "
                     "material's stable step {:.3g} (limited by {} at atom {}): the run slows as much; "
                     "'min' stops a run instead", update->ntimestep, dt, run.base / dt, run.base,
                     CAUSES[lim.cause], lim.tag);
  }
  if (comm->me == 0) {
    const std::string why = lim.cause == CAUSE_COMPRESSION
        ? fmt::format("compression: {:.3g}x its reference stiffness", lim.stiffening)
        : CAUSES[lim.cause];
    utils::logmesg(lmp, "pd/timestep: step {}{}: dt {:.6g} -> {:.6g} (stable {:.6g}, limited by {} at "
                   "atom {}{})\n", update->ntimestep, *when ? fmt::format(" ({})", when) : "", old, dt,
                   estimate, why, lim.tag, dt == dtmax ? "; capped by max" : "");
  }
}

void FixPDTimestep::set_dt(double dt)
{
  update->update_time();
  update->dt = dt;
  update->dt_default = 0;
  PDCompat::time_step_changed(lmp);
  dt_set = dt;
  nchanges++;
}

double FixPDTimestep::compute_scalar()
{
  return update->dt;
}

// 1: the step, 2: the last stable estimate (before the safety factor),
// 3: how many times the step changed
double FixPDTimestep::compute_vector(int n)
{
  return n == 0 ? update->dt : n == 1 ? estimate : (double) nchanges;
}

void FixPDTimestep::write_restart(FILE *fp)
{
  if (comm->me != 0) return;
  const double list[5] = {dt_set, estimate, (double) nchanges, (double) interval, (double) next_check};
  const int size = sizeof(list);
  fwrite(&size, sizeof(int), 1, fp);
  fwrite(list, sizeof(list), 1, fp);
}

void FixPDTimestep::restart(char *buf)
{
  double list[5];
  memcpy(list, buf, sizeof(list));
  dt_set = list[0];
  estimate = list[1];
  nchanges = (bigint) list[2];
  interval = (int) list[3];
  next_check = (bigint) list[4];
}
