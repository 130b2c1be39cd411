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

extern "C" {
#include "pd_law_energy.h"
}

namespace LAMMPS_NS {

class PairPDOrdinary : public PairPD {
 public:
  PairPDOrdinary(class LAMMPS *);
  ~PairPDOrdinary() override;
  void compute(int, int) override;
  void settings(int, char **) override;
  const char *style_name() const override { return "pd/ordinary"; }
  void init_style() override;
  void write_restart_settings(FILE *) override;
  void read_restart_settings(FILE *) override;
  void *extract(const char *, int &) override;
  double contact_micromodulus(int, int) const override;
  std::vector<PDField> per_atom_fields() const override;

 protected:
  int influence;       // pd_influence_kind
  int per_atom_norm;   // surface correction: normalize by each atom's weighted volume
  double order;        // Seth-Hill order m, the same for all types
  double *bulk_volume; // per type: weighted volume of a complete family
  double *lambda_bar, *mu_bar;    // per type: peridynamic Lame constants
  // per-atom fields in the bond store (per_atom_fields(), field_id)
  enum { F_DILATATION, F_AB, F_CRIT };
  double *state(int f) const;
  double *strain;      // per-bond strain, reused by the force pass (m != 1/2)
  bigint nstrain;
  double *beta;        // per type: energy-failure beta (T14 eq. 6.3) for G_c = 1
  double *gc_pair;     // per type pair G_c of the energy law (+inf: no failure)
  struct pd_law_energy energy_law;    // its parameters for one evaluation

  int parse_setting(int, char **, int) override;
  void check_coeff(int, int) override;
  double init_one(int, int) override;
  bool between_types(int) const override;
  int uses_weights() const override { return 1; }
  PDFamilySpec::Weight weight_rule() const override;
  void stable_dt_sum(double *) override;
  void report_extra() override;
  void setup_run() override;
  std::string family_settings() const override;
  double norm(int i) const;
};

}    // namespace LAMMPS_NS

#endif
#endif
