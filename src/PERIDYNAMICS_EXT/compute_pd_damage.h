/* -*- c++ -*- ----------------------------------------------------------
   PERIDYNAMICS_EXT: compute pd/damage, damage of each atom's family.
------------------------------------------------------------------------- */

#ifdef COMPUTE_CLASS
// clang-format off
ComputeStyle(pd/damage,ComputePDDamage);
// clang-format on
#else

#ifndef LMP_COMPUTE_PD_DAMAGE_H
#define LMP_COMPUTE_PD_DAMAGE_H

#include "compute.h"

namespace LAMMPS_NS {

class ComputePDDamage : public Compute {
 public:
  ComputePDDamage(class LAMMPS *, int, char **);
  ~ComputePDDamage() override;
  void init() override;
  void compute_peratom() override;
  double memory_usage() override;

 private:
  int nmax;
  double *damage;
  class FixPDBonds *bonds;
  int weighted;    // T14 eq. 6.12 instead of MS07 eq. 25
};

}    // namespace LAMMPS_NS

#endif
#endif
