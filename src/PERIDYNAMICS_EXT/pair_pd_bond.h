/* -*- c++ -*- ----------------------------------------------------------
   PERIDYNAMICS_EXT: pair_style pd/bond, bond-based peridynamics (PMB).
------------------------------------------------------------------------- */

#ifdef PAIR_CLASS
// clang-format off
PairStyle(pd/bond,PairPDBond);
// clang-format on
#else

#ifndef LMP_PAIR_PD_BOND_H
#define LMP_PAIR_PD_BOND_H

#include "pair_pd.h"

namespace LAMMPS_NS {

class PairPDBond : public PairPD {
 public:
  PairPDBond(class LAMMPS *);
  void compute(int, int) override;

 protected:
  int parse_model(const char *) override;
  void check_coeff(int, int) override;
  void stable_dt_sum(double *) override;
};

}    // namespace LAMMPS_NS

#endif
#endif
