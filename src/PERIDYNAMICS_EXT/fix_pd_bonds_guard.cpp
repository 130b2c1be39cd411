/* ----------------------------------------------------------------------
   PERIDYNAMICS_EXT: the blow-up guard of fix pd/bonds.

   An unstable run (a time step above the stable estimate, particles pushed
   onto each other with a strain order m <= 0) grows without bound within a
   few steps and would end in NaN output or in an unrelated LAMMPS error
   (neighbor bins, lost atoms). Every step, after the forces of setup and
   after each step's velocities, each owned atom is checked: force and
   velocity finite, and no move longer than half the smallest horizon in
   one step (no stable peridynamic run comes near that: the stable step
   lets a wave cross a fraction of the spacing). A few compares per atom
   and one MPI_Allreduce of an int per step, well under 1% of a step. The
   error names the atom and the likely cause.
------------------------------------------------------------------------- */

#include "fix_pd_bonds.h"

#include "atom.h"
#include "error.h"
#include "modify.h"
#include "pd_compat.h"
#include "pd_error.h"
#include "update.h"

#include <cfloat>
#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;

void FixPDBonds::setup(int)
{
  guard_step = serving ? 0.5 * spec.smallest : INFINITY;
  guard(true);
}

void FixPDBonds::end_of_step()
{
  guard(false);
}

// Every rank checks its atoms; the first fault's message reaches the log
// through one collective call (pd_error.h) per step. A branch-free screen
// over the contiguous arrays comes first (the compiler vectorizes it: 1% of
// a pd/ordinary step at 64^3 with the atom by atom loop); only a rank that
// sees a fault walks its atoms to name the first.
void FixPDBonds::guard(bool forces_only)
{
  if (!serving) return;
  double **f = atom->f, **v = atom->v;
  const int nlocal = atom->nlocal;
  const double vmax = guard_step / update->dt, vmax2 = forces_only ? INFINITY : vmax * vmax;
  std::string fault;
  if (nlocal > 0 && !guard_screen(f[0], v[0], nlocal, vmax2))
    for (int i = 0; i < nlocal && fault.empty(); i++) {
      const double f2 = f[i][0] * f[i][0] + f[i][1] * f[i][1] + f[i][2] * f[i][2];
      if (!std::isfinite(f2)) fault = blow_up(i, "force", f2);
      if (forces_only || !fault.empty()) continue;
      const double v2 = v[i][0] * v[i][0] + v[i][1] * v[i][1] + v[i][2] * v[i][2];
      if (!(v2 <= vmax2)) fault = blow_up(i, "speed", sqrt(v2));
    }
  pd_error_collective(lmp, fault);
}

// True when every |f|^2 is finite and every |v|^2 at most vmax2 (n atoms,
// 3 values each); NaN fails both tests.
bool FixPDBonds::guard_screen(const double *f, const double *v, int n, double vmax2)
{
  int bad = 0;
  for (int k = 0; k < 3 * n; k += 3) {
    const double f2 = f[k] * f[k] + f[k + 1] * f[k + 1] + f[k + 2] * f[k + 2];
    const double v2 = v[k] * v[k] + v[k + 1] * v[k + 1] + v[k + 2] * v[k + 2];
    bad |= !(f2 <= DBL_MAX) | !(v2 <= vmax2);
  }
  return !bad;
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
  const double est = stable_dt;
  std::string likely = fmt::format("the time step {:.6g} is {:.3g} times the stable estimate {:.6g} "
                                   "(reduce it; fix pd/timestep follows the state as it stiffens), or "
                                   "an impact faster than the model resolves",
                                   update->dt, est > 0.0 ? update->dt / est : NAN, est);
  // a relaxation in pseudo time has no time step to blame
  for (Fix *fix : PDCompat::fixes(modify))
    if (strcmp(fix->style, "pd/adr") == 0)
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
