/* ----------------------------------------------------------------------
   PERIDYNAMICS_EXT: the blow-up guard of fix pd/bonds.

   An unstable run (a time step above the stable estimate, particles pushed
   onto each other with a strain order m <= 0) grows without bound and
   would end in NaN output or in an unrelated LAMMPS error (neighbor bins,
   lost atoms). Every step, after the forces of setup and after each
   step's velocities, each owned atom is checked: force and velocity
   finite, and no move longer than half the smallest horizon in one step
   relative to the body's mean motion (no stable peridynamic run comes
   near that: the stable step lets a wave cross a fraction of the spacing;
   a rigid translation, however fast, is not a fault). A slower growth is
   caught by the kinetic energy: when it grows geometrically (guard_energy)
   the stable step of the current state (its bonds' tangents, as fix
   pd/timestep takes it) is computed once; a time step above it, in a state
   stiffer than the setup's, is the fault. A few operations per atom and
   two small MPI_Allreduce per step, well under 1% of a step. The error
   names the atom or the energy, and the likely cause.
------------------------------------------------------------------------- */

#include "fix_pd_bonds.h"

#include "atom.h"
#include "error.h"
#include "force.h"
#include "modify.h"
#include "pd_compat.h"
#include "pd_error.h"
#include "update.h"

#include <cfloat>
#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;

namespace {
// growth of the kinetic energy that asks for the current stable step: an
// impact's energy stays below its start, a loading's grows by this factor
// only a few dozen times in a run
constexpr double ENERGY_GROWTH = 3.0;
// windows of that growth, none longer than the one before, that make it
// geometric
constexpr int GEOMETRIC_WINDOWS = 3;
}    // namespace

void FixPDBonds::setup(int)
{
  guard_step = serving ? 0.5 * spec.smallest : INFINITY;
  guard_relaxing = relaxation() != nullptr;
  guard_ke = -1.0;    // set by the first check
  guard_window = 0;
  guard_streak = 0;
  guard(true);
}

void FixPDBonds::end_of_step()
{
  guard(false);
}

// Every rank checks its atoms; the first fault's message reaches the log
// through one collective call (pd_error.h) per step. A branch-free screen
// over the contiguous arrays comes first (the compiler vectorizes it: 1% of
// a pd/ordinary step at 64^3 with the atom by atom loop), which also sums
// the kinetic energy; only when some rank sees a fault do the ranks take
// the body's mean velocity and walk their atoms to name the first.
void FixPDBonds::guard(bool forces_only)
{
  if (!serving) return;
  double **f = atom->f, **v = atom->v;
  const int nlocal = atom->nlocal;
  const double vmax = guard_step / update->dt, vmax2 = forces_only ? INFINITY : vmax * vmax;
  double mv2 = 0.0;
  const bool clean = nlocal == 0 || guard_screen(f[0], v[0], atom->rmass, atom->vfrac, nlocal, vmax2, mv2);
  double mine[2] = {clean ? 0.0 : 1.0, mv2}, all[2];
  MPI_Allreduce(mine, all, 2, MPI_DOUBLE, MPI_SUM, world);
  std::string fault;
  if (all[0] > 0.0) {
    double vc[3] = {0.0, 0.0, 0.0};
    if (!forces_only) guard_drift(vc);
    for (int i = 0; i < nlocal && fault.empty() && !clean; i++) {
      const double f2 = f[i][0] * f[i][0] + f[i][1] * f[i][1] + f[i][2] * f[i][2];
      if (!std::isfinite(f2)) fault = blow_up(i, "force", f2);
      if (forces_only || !fault.empty()) continue;
      const double u[3] = {v[i][0] - vc[0], v[i][1] - vc[1], v[i][2] - vc[2]};
      const double u2 = u[0] * u[0] + u[1] * u[1] + u[2] * u[2];
      if (!(u2 <= vmax2)) fault = blow_up(i, "speed", sqrt(u2));
    }
  }
  const double ke = 0.5 * force->mvv2e * all[1];
  if (fault.empty() && !forces_only && !guard_relaxing) fault = guard_energy(ke);
  if (guard_ke < 0.0 || forces_only) {
    guard_ke = ke;
    guard_ke_step = update->ntimestep;
  }
  pd_error_collective(lmp, fault);
}

// True when every |f|^2 is finite and every |v|^2 at most vmax2 (n atoms,
// 3 values each); NaN fails both tests. mv2: the sum of m |v|^2 (mass:
// density times volume).
bool FixPDBonds::guard_screen(const double *f, const double *v, const double *mass, const double *volume,
                              int n, double vmax2, double &mv2)
{
  int bad = 0;
  double sum = 0.0;
  for (int i = 0; i < n; i++) {
    const int k = 3 * i;
    const double f2 = f[k] * f[k] + f[k + 1] * f[k + 1] + f[k + 2] * f[k + 2];
    const double v2 = v[k] * v[k] + v[k + 1] * v[k + 1] + v[k + 2] * v[k + 2];
    bad |= !(f2 <= DBL_MAX) | !(v2 <= vmax2);
    sum += mass[i] * volume[i] * v2;
  }
  mv2 = sum;
  return !bad;
}

// The mass-weighted mean velocity of the pd/ atoms (collective): the speed
// limit is on motion relative to it, so that a fast rigid translation
// passes.
void FixPDBonds::guard_drift(double *vc)
{
  double **v = atom->v;
  const double *rho = atom->rmass, *vol = atom->vfrac;
  double mine[4] = {0.0, 0.0, 0.0, 0.0}, all[4];
  for (int i = 0; i < atom->nlocal; i++) {
    const double m = rho[i] * vol[i];
    for (int c = 0; c < 3; c++) mine[c] += std::isfinite(v[i][c]) ? m * v[i][c] : 0.0;
    mine[3] += m;
  }
  MPI_Allreduce(mine, all, 4, MPI_DOUBLE, MPI_SUM, world);
  for (int c = 0; c < 3; c++) vc[c] = all[3] > 0.0 ? all[c] / all[3] : 0.0;
}

// Collective: the same ke on every rank, so every rank asks for the current
// stable step together; the message comes from rank 0. An instability
// grows geometrically: the kinetic energy takes ENERGY_GROWTH times in
// windows of steps that do not lengthen. Growth driven by a load or by
// round-off forces from rest (ke ~ t^2) takes ever longer windows; a
// physical instability (buckling) grows geometrically too, and so does a
// load's onset (an indenter's first contact), so the fault is named only
// when the time step is also above the current stable one and the state
// stiffened since the setup: a step above the setup's estimate was the
// deck's choice, which the setup's log line states (PERI's examples run at
// 1.2 times this conservative estimate).
std::string FixPDBonds::guard_energy(double ke)
{
  if (!(guard_ke >= 0.0) || !(ke > ENERGY_GROWTH * guard_ke)) return "";
  const bigint window = update->ntimestep - guard_ke_step;
  guard_streak = guard_window > 0 && window <= guard_window + guard_window / 8 ? guard_streak + 1 : 0;
  guard_window = window;
  guard_ke = ke;
  guard_ke_step = update->ntimestep;
  if (guard_streak < GEOMETRIC_WINDOWS - 1) return "";
  PDFamilySource *source = pd_family_source(force);
  const double stable = source ? source->current_stable_dt() : INFINITY;
  if (!(update->dt > stable) || !(stable < stable_dt) || comm->me != 0) return "";
  return fmt::format("Fix pd/bonds: the run is unstable at step {}: the kinetic energy grew {:.3g} times "
                     "every {} steps or faster, {} times in a row (to {:.6g}), and the time step {:.6g} is "
                     "{:.3g} times the stable estimate of the current state {:.6g} (the setup's estimate: "
                     "{:.6g}). Likely cause: the material stiffened (compression with strain order m <= 0, "
                     "contact) beyond what the time step resolves; fix pd/timestep follows the state, or "
                     "reduce the time step", update->ntimestep, ENERGY_GROWTH, window, guard_streak + 1, ke,
                     update->dt, update->dt / stable, stable, stable_dt);
}

// The run's pseudo-time relaxation (fix pd/adr), or null.
Fix *FixPDBonds::relaxation() const
{
  for (Fix *fix : PDCompat::fixes(modify))
    if (strcmp(fix->style, "pd/adr") == 0) return fix;
  return nullptr;
}

// What went wrong where; a bond of zero length at this rank is the usual
// cause of a non-finite force (strain order m <= 0: log 0).
std::string FixPDBonds::blow_up(int i, const char *what, double value)
{
  double **x = atom->x;
  const PDBondTable bonds = table();
  std::string cause;
  for (int a = 0; a < nowned && cause.empty(); a++)
    for (int k = 0; k < npartner[a]; k++)
      if (bonds.length(x, a, k) <= 1e-9 * fabs(r0[a][k])) {
        cause = fmt::format("bond {}-{} has length 0 (the two particles were pushed onto each "
                            "other; with strain order m <= 0 its force is infinite). ",
                            atom->tag[a], partner[a][k]);
        break;
      }
  // below the setup's estimate, the state outgrew it (stiffening, contact)
  const double est = stable_dt;
  const bool above = !(update->dt <= est);
  std::string likely = fmt::format("the time step {:.6g} is {:.3g} times the setup's stable estimate {:.6g}{}: "
                                   "fix pd/timestep follows the state as it stiffens; or an impact "
                                   "faster than the model resolves",
                                   update->dt, est > 0.0 ? update->dt / est : NAN, est,
                                   above ? ": reduce it, or" : ", but the state stiffened since (compression "
                                   "with strain order m <= 0, contact springs, pushing broken bonds)");
  // a relaxation in pseudo time has no time step to blame
  if (const Fix *fix = relaxation())
    likely = fmt::format("the relaxation of fix {} (pd/adr) is unstable: its fictitious density is "
                         "too small for the stiffness now (raise its safety, or lower its every)",
                         fix->id);
  return fmt::format("Fix pd/bonds: the run is unstable at step {}: atom {} at ({:.6g}, {:.6g}, "
                     "{:.6g}) has {} {:.6g}{}. {}Likely cause: {}",
                     update->ntimestep, atom->tag[i], x[i][0], x[i][1], x[i][2], what, value,
                     std::isfinite(value) ? fmt::format(" (above {:.3g}: it would move more than half "
                                                        "the horizon in one step)", guard_step / update->dt)
                                          : " (not finite)",
                     cause, likely);
}
