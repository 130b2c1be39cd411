/* -*- c++ -*- ----------------------------------------------------------
   PERIDYNAMICS_EXT: fix pd/adr, quasi-static loading with failure by
   adaptive dynamic relaxation (Kilic and Madenci 2010; core/pd_adr.h).
   The fix integrates its group itself, in pseudo time, with its own
   fictitious density from the particles' stiffness sums.
------------------------------------------------------------------------- */

#ifdef FIX_CLASS
// clang-format off
FixStyle(pd/adr,FixPDAdr);
// clang-format on
#else

#ifndef LMP_FIX_PD_ADR_H
#define LMP_FIX_PD_ADR_H

#include "fix.h"

namespace LAMMPS_NS {

class FixPDAdr : public Fix {
 public:
  FixPDAdr(class LAMMPS *, int, char **);
  ~FixPDAdr() override;
  int setmask() override;
  void init() override;
  void setup(int) override;
  void initial_integrate(int) override;
  void final_integrate() override;
  void post_run() override;
  double compute_scalar() override;
  double compute_vector(int) override;
  void write_restart(FILE *) override;
  void restart(char *) override;

  void grow_arrays(int) override;
  void copy_arrays(int, int, int) override;
  void set_arrays(int) override;
  int pack_exchange(int, double *) override;
  int unpack_exchange(int, double *) override;
  int pack_restart(int, double *) override;
  void unpack_restart(int, int) override;
  int size_restart(int) override;
  int maxsize_restart() override;
  double memory_usage() override;

 private:
  // per atom: the pseudo velocity V^{n+1/2} (3), the force of the last
  // iteration F^n (3), the fictitious density lambda (1)
  enum { V = 0, FPREV = 3, LAMBDA = 6, NSTATE = 7 };
  double **state;
  double safety;      // lambda is this factor above the stability bound
  int every;          // lambda follows the stiffness every N steps (0: once)
  double tol;         // log a line when the residual falls below it (0: no line)
  class PairPD *material;
  class PairPDContact *contact;
  int started;        // V^{1/2} taken (restart)
  double damping;     // c_n of the last iteration
  double residual;    // |R| / reference
  double rnorm;       // |R|: the force on the group's particles (force units)
  double reaction;    // the force on the particles outside the group
  double reference;   // the force scale of the residual
  double carried;     // the largest reaction at the end of a run: the load the body carried (restart)
  double runmax;      // the largest |R| of this run (the scale when nothing outside the group carries load)
  bigint iterations;  // iterations since the fix started (restart)
  bigint run_start;   // the step this run started at
  int converged;      // the tol line was written in this run
  double *sums, *scratch, *springs;    // stiffness sums (atom->nmax)
  int nmax_sums;

  int ndof() const;
  void update_lambda();
};

}    // namespace LAMMPS_NS

#endif
#endif
