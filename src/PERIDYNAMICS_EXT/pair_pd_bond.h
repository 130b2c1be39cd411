/* -*- c++ -*- ----------------------------------------------------------
   PERIDYNAMICS_EXT: pair_style pd/bond, bond-based peridynamics: PMB and
   proportional microplastic bonds.
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
  ~PairPDBond() override;
  void compute(int, int) override;
  void coeff(int, char **) override;
  const char *style_name() const override { return "pd/bond"; }
  double contact_micromodulus(int i, int j) const override;
  void fracture_elastic(int i, int j, double &E, double &nu) const override;
  bool bond_based() const override { return true; }
  double stiffness_scale(int t) const override { return t < (int) kappa.size() ? kappa[t] : 1.0; }

 protected:
  int model;            // word given with the last pair_coeff (pmb or microplastic)
  int plastic;          // some type pair is microplastic: per-bond plastic stretch
  // the micromoduli calibrated on the types' complete families (c when given as
  // E or K: core/pd_params.h pd_pmb_moment_continuum), per type pair, and the
  // scale of each type
  std::vector<double> micromodulus;
  std::vector<double> kappa;

  void setup_run() override;
  void report_extra() override;

  int parse_model(const char *) override;
  void check_coeff(int, int) override;
  int history_per_bond() const override { return plastic; }
  void stable_dt_sum(double *) override;
  void tangent_sum(double *, double *) override;
  void restart_settings(PDSettingsIO &io) override;
  // partial cells: at equal bonds per atom, 3 spacings with partial cells
  // beat 4 without (constants 2.8% against 7.7%, 3D; doc/accuracy.md)
  int default_quadrature() const override { return QUADRATURE_PARTIAL; }
  // a bond's share of the stiffness: c w V |xi| (PMB's energy c s^2 |xi| / 4 at each end)
  bool directional_moment(int &power) const override
  {
    power = 1;
    return true;
  }
  // PMB: its relative lattice error does not depend on the stiffness
  bool linear_model(int, pd_linear_kind &kind, pd_elastic &e) const override
  {
    kind = legacy ? PD_LINEAR_PMB : PD_LINEAR_PMB_FAMILY;
    return pd_elastic_from_E_nu(1.0, pd_pmb_poisson(model_dim), &e) == 0;
  }
};

}    // namespace LAMMPS_NS

#endif
#endif
