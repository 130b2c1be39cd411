/* -*- c++ -*- ----------------------------------------------------------
   PERIDYNAMICS_EXT: pair_style pd/corr, correspondence materials: a
   classical constitutive law (elastic, neo-Hookean, J2, Johnson-Cook with
   damage) from the classical nonlocal deformation gradient or from T14's
   extended (Seth-Hill) nonlocal strain.
------------------------------------------------------------------------- */

#ifdef PAIR_CLASS
// clang-format off
PairStyle(pd/corr,PairPDCorr);
// clang-format on
#else

#ifndef LMP_PAIR_PD_CORR_H
#define LMP_PAIR_PD_CORR_H

#include "pair_pd.h"
#include "pd_failure_law.h"

extern "C" {
#include "pd_corr.h"
}

namespace LAMMPS_NS {

class PairPDCorr : public PairPD, public PDBondEnergies {
 public:
  PairPDCorr(class LAMMPS *);
  ~PairPDCorr() override;
  void compute(int, int) override;
  void settings(int, char **) override;
  const char *style_name() const override { return "pd/corr"; }
  void init_style() override;
  double contact_micromodulus(int, int) const override;
  std::vector<PDField> per_atom_fields() const override;
  void fracture_elastic(int i, int j, double &E, double &nu) const override;
  // extended correspondence's bond energies for 'fail energy': d psi/d phi
  // of a bond = w eps_m (n . Sigma . n) at each end (pd_corr.h)
  const PDBondEnergies *bond_energies() const override { return extended ? this : nullptr; }
  double family_norm(int i) const override;
  pd_influence_kind influence_kind() const override { return (pd_influence_kind) influence; }

 protected:
  int extended;          // strain: 1 extended (T14 4.2), 0 classical (T14 2.2.1)
  int model;             // pd_corr_model
  int influence;         // pd_influence_kind
  double stabilization;  // coefficient of the non-affine penalty (0: none)
  double order;          // Seth-Hill order m of the strain the law works on
  std::vector<pd_corr_material> material;   // per type
  double *spring;        // per type pair: PMB micromodulus
  bool shape_stale;      // the families' shapes (field corr_shape) need recomputing
  // with damage: which atoms (owned + ghost) were beyond D_c when the
  // shapes were computed (a bond counts while neither end is)
  std::vector<char> dead_at_shapes;

  int parse_setting(int, char **, int) override;
  void check_coeff(int, int) override;
  bool uses_coefficient(int p) const override;
  int uses_weights() const override { return 1; }
  // each bond's reference vector xi, kept by the store (moves and restarts
  // with the bond): filled the first time the bond is seen
  int history_per_bond() const override { return 3; }
  // (the reference vectors never change; the plastic state is per atom)
  bool yields() const override { return plastic(); }
  void fill_reference_vectors();
  PDFamilySpec::Weight weight_rule() const override;
  void stable_dt_sum(double *) override;
  void tangent_sum(double *, double *) override;
  double *stiffness_coefficients();
  void report_extra() override;
  void restart_settings(PDSettingsIO &io) override;
  void setup_run() override;
  std::string family_settings() const override;

  // the per-atom fields of one evaluation (null: not kept in this scene)
  struct Fields {
    double *defgrad, *stress, *tensor, *sums, *shape_sums, *shape;
    double *eqps, *plastic, *work, *temperature, *damage, *increment;
  };
  Fields fields() const;
  double *field(const char *name) const;
  int plastic() const { return model == PD_CORR_J2 || model == PD_CORR_JOHNSON_COOK; }
  // Johnson-Cook options, on when a type gives their constants (known from
  // pair_coeff on, so compute pd/atom can name their fields before a run)
  bool any_type_gives(int p) const;
  bool thermal() const { return model == PD_CORR_JOHNSON_COOK && any_type_gives(PD_CORR_T_MELT); }
  bool damage() const { return model == PD_CORR_JOHNSON_COOK && any_type_gives(PD_CORR_D1); }
  pd_corr_state state(const Fields &f);
  void atom_step(int i, const pd_corr_state &st, const Fields &f, const pd_corr_kinematics &kin,
                 bool with_stress, pd_tally &t);
  void update_shapes(const pd_loop &L, pd_corr_state st, const Fields &f);
  void damage_state(const pd_corr_state &st, bool &any_dead, bool &crossed) const;
};

}    // namespace LAMMPS_NS

#endif
#endif
