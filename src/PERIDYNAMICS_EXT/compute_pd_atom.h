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
#include "pd_field.h"

#include <string>
#include <vector>

namespace LAMMPS_NS {

class ComputePDAtom : public Compute {
 public:
  ComputePDAtom(class LAMMPS *, int, char **);
  ~ComputePDAtom() override;
  void init() override;
  void compute_peratom() override;
  double memory_usage() override;
  bool lists(const std::string &name) const;    // whether it outputs that field

 private:
  // ENERGY: the pair's per-atom energy; BOND_DILATATION: the linear
  // dilatation from the bonds (no style declares one); FIELD: a declared
  // per-atom field of the bond store
  enum Source { ENERGY, BOND_DILATATION, FIELD };
  struct Output {
    std::string name;
    Source source;
    int width;
    int id;    // the store's field id (FIELD)
    bool on_demand;    // computed only when due (PDField::ON_DEMAND)
  };
  std::vector<Output> outputs;
  int ncols;
  int nmax;
  double *scratch;      // one computed value over owned + ghost atoms
  double *vector;       // single value output
  double **array;       // several columns
  class FixPDBonds *bonds;

  std::vector<PDField> known_fields() const;
  std::string available(const std::vector<PDField> &) const;
  void current_or_error(const std::string &name) const;
  void dilatation(double *out);
  void energy_density(double *out);
};

}    // namespace LAMMPS_NS

#endif
#endif
