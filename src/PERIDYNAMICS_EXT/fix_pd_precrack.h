/* -*- c++ -*- ----------------------------------------------------------
   PERIDYNAMICS_EXT: fix pd/precrack, bonds broken across a crack.
------------------------------------------------------------------------- */

#ifdef FIX_CLASS
// clang-format off
FixStyle(pd/precrack,FixPDPrecrack);
// clang-format on
#else

#ifndef LMP_FIX_PD_PRECRACK_H
#define LMP_FIX_PD_PRECRACK_H

#include "fix.h"

namespace LAMMPS_NS {

class FixPDPrecrack : public Fix {
 public:
  FixPDPrecrack(class LAMMPS *, int, char **);
  int setmask() override;
  void init() override;
  void setup_pre_force(int) override;
  double compute_scalar() override;

 private:
  int patch;               // 0: 2D segment a-b; 1: 3D parallelogram o + u e1 + v e2
  double a[3], b[3], c[3]; // segment ends a, b; or origin a and edges b, c
  bigint ncut;             // bonds this crack broke (all ranks)
  class FixPDBonds *bonds;
};

}    // namespace LAMMPS_NS

#endif
#endif
