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

extern "C" {
#include "pd_precrack.h"
}

namespace LAMMPS_NS {

class FixPDPrecrack : public Fix {
 public:
  FixPDPrecrack(class LAMMPS *, int, char **);
  int setmask() override;
  void init() override;
  void setup_pre_force(int) override;
  double compute_scalar() override;

 private:
  pd_crack crack;
  bigint ncut;             // bonds this crack broke (all ranks)
  class FixPDBonds *bonds;
};

}    // namespace LAMMPS_NS

#endif
#endif
