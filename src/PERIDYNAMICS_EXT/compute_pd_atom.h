/* -*- c++ -*- ----------------------------------------------------------
   PERIDYNAMICS_EXT: compute pd/atom, per-atom peridynamic fields.
------------------------------------------------------------------------- */

#ifdef COMPUTE_CLASS
// clang-format off
ComputeStyle(pd/atom,ComputePDAtom);
// clang-format on
#else

#ifndef LMP_COMPUTE_PD_ATOM_H
#define LMP_COMPUTE_PD_ATOM_H

#include "compute.h"

#include <vector>

namespace LAMMPS_NS {

class ComputePDAtom : public Compute {
 public:
  ComputePDAtom(class LAMMPS *, int, char **);
  ~ComputePDAtom() override;
  void init() override;
  void compute_peratom() override;
  double memory_usage() override;

 private:
  enum Field { DILATATION, ENERGY };
  std::vector<Field> fields;
  int nmax;
  double *scratch;      // one field over owned + ghost atoms
  double *vector;       // single field output
  double **array;       // several fields output
  class FixPDBonds *bonds;

  void dilatation(double *out);
  void energy_density(double *out);
};

}    // namespace LAMMPS_NS

#endif
#endif
