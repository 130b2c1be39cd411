/* -*- c++ -*- ----------------------------------------------------------
   PERIDYNAMICS_EXT: fix pd/timestep, the stable time step of the current
   state, taken every N steps: each particle's bound on its current
   stiffness (its bonds' tangents, intact and pushing broken ones, with
   nonlinear stiffening; its contact springs), core/pd_tangent.h.
------------------------------------------------------------------------- */

#ifdef FIX_CLASS
// clang-format off
FixStyle(pd/timestep,FixPDTimestep);
// clang-format on
#else

#ifndef LMP_FIX_PD_TIMESTEP_H
#define LMP_FIX_PD_TIMESTEP_H

#include "fix.h"

#include <cmath>

namespace LAMMPS_NS {

class FixPDTimestep : public Fix {
 public:
  FixPDTimestep(class LAMMPS *, int, char **);
  ~FixPDTimestep() override;
  int setmask() override;
  void init() override;
  void setup(int) override;
  void end_of_step() override;
  void post_run() override;
  double compute_scalar() override;
  double compute_vector(int) override;
  void write_restart(FILE *) override;
  void restart(char *) override;

 private:
  int every;              // steps between estimates
  double safety;          // the step is this fraction of the stable one
  double travel;          // and lets no particle move more than this fraction of its spacing
  double dtmin, dtmax;    // bounds on the step (0, inf: none)
  double grow;            // the step grows only when the stable one allows this factor more
  class PairPD *material;
  class PairPDContact *contact;
  double estimate;        // the last stable step (before the safety factor)
  bigint nchanges;        // changes of the step so far
  double dt_set;          // the step this fix set last (0: none yet), restart
  int interval;           // steps from this check to the next (1 .. every)
  bigint next_check;      // the step of the next check
  double *current, *reference, *springs;    // per-atom stiffness sums
  double *closing;        // per atom: the largest relative closing rate of its bonds and contacts
  double *contact_closing;    // the same of its contacts alone
  int nmax;
  bigint reference_build;    // the neighbor build the reference sums are of (-1: none)

  // what limits the step (their names: CAUSES in the .cpp)
  enum { CAUSE_MATERIAL, CAUSE_COMPRESSION, CAUSE_CONTACT, CAUSE_TRAVEL, CAUSE_CLOSING, NCAUSES };
  // what this run's checks did (the summary line at its end)
  struct RunSummary {
    bigint checks = 0;
    bigint changes[NCAUSES] = {};    // by cause
    double dtmin = INFINITY, dtmax = 0.0;
    double base = 0.0;           // the material's stable step (setup estimate)
    double warned = INFINITY;    // the step of the last shrink warning
    bigint total() const
    {
      bigint n = 0;
      for (bigint c : changes) n += c;
      return n;
    }
  } run;

  struct Limit;
  void check(const char *when);
  Limit limiting_atom();
  void set_dt(double dt);
  double contact_reach() const;
  double travel_dt(int i) const;
};

}    // namespace LAMMPS_NS

#endif
#endif
