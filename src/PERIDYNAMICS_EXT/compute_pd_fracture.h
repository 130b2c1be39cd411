/* -*- c++ -*- ----------------------------------------------------------
   PERIDYNAMICS_EXT: compute pd/fracture, the fracture bookkeeping.
------------------------------------------------------------------------- */

#ifdef COMPUTE_CLASS
// clang-format off
ComputeStyle(pd/fracture,ComputePDFracture);
// clang-format on
#else

#ifndef LMP_COMPUTE_PD_FRACTURE_H
#define LMP_COMPUTE_PD_FRACTURE_H

#include "compute.h"

namespace LAMMPS_NS {

class ComputePDFracture : public Compute {
 public:
  ComputePDFracture(class LAMMPS *, int, char **);
  ~ComputePDFracture() override;
  void init() override;
  void compute_vector() override;
  void compute_peratom() override;
  double memory_usage() override;

 private:
  int nmax;
  double *dissipated;
  class FixPDBonds *bonds;
};

}    // namespace LAMMPS_NS

#endif
#endif
