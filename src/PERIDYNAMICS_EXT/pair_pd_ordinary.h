/* -*- c++ -*- ----------------------------------------------------------
   PERIDYNAMICS_EXT: pair_style pd/ordinary, ordinary state-based solid
   with Seth-Hill bond strain of order m (m = 1/2: LPS).
------------------------------------------------------------------------- */

#ifdef PAIR_CLASS
// clang-format off
PairStyle(pd/ordinary,PairPDOrdinary);
// clang-format on
#else

#ifndef LMP_PAIR_PD_ORDINARY_H
#define LMP_PAIR_PD_ORDINARY_H

#include "pair_pd.h"
#include "pd_failure_law.h"

namespace LAMMPS_NS {

class PairPDOrdinary : public PairPD, public PDBondEnergies {
 public:
  PairPDOrdinary(class LAMMPS *);
  ~PairPDOrdinary() override;
  void compute(int, int) override;
  void settings(int, char **) override;
  const char *style_name() const override { return "pd/ordinary"; }
  void init_style() override;
  void *extract(const char *, int &) override;
  double contact_micromodulus(int, int) const override;
  std::vector<PDField> per_atom_fields() const override;
  void fracture_elastic(int i, int j, double &E, double &nu) const override;
  const PDBondEnergies *bond_energies() const override { return this; }
  double family_norm(int i) const override { return norm(i); }
  pd_influence_kind influence_kind() const override { return (pd_influence_kind) influence; }
  bool bond_moduli(int t, double &lambda, double &mu) const override
  {
    lambda = lambda_bar[t], mu = mu_bar[t];
    return true;
  }

 protected:
  int influence;       // pd_influence_kind
  int per_atom_norm;   // surface correction: normalize by each atom's weighted volume
  int uniform_b;       // B = 2 mu_bar N is one number for all atoms (setup_run)
  double order;        // Seth-Hill order m, the same for all types
  double *lambda_bar, *mu_bar;    // per type: peridynamic Lame constants
  // per-atom fields in the bond store (per_atom_fields(), field_id)
  enum { F_DILATATION, F_AB };
  double *state(int f) const;
  double *strain;      // per-bond strain, reused by the force pass (m != 1/2)
  bigint nstrain;

  int parse_setting(int, char **, int) override;
  void check_coeff(int, int) override;
  int uses_weights() const override { return 1; }
  double inverse_weight_horizon() const override;
  // a bond's share of the stiffness: w V (the energy mu N sum w eps^2 V)
  bool directional_moment(int &power) const override
  {
    power = 0;
    return true;
  }
  PDFamilySpec::Weight weight_rule() const override;
  void stable_dt_sum(double *) override;
  void tangent_sum(double *, double *) override;
  double *stiffness_coefficients();
  void report_extra() override;
  // every strain order m linearizes to the same solid
  bool linear_model(int t, pd_linear_kind &kind, pd_elastic &e) const override;
  void restart_settings(PDSettingsIO &io) override;
  void setup_run() override;
  std::string family_settings() const override;
  double norm(int i) const;
  double type_norm(int t) const;
  bool surface_corrected() const override { return per_atom_norm != 0; }
  double norm_of(double m) const;
};

}    // namespace LAMMPS_NS

#endif
#endif
