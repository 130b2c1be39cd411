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

 protected:
  int influence;       // pd_influence_kind
  int per_atom_norm;   // surface correction: normalize by each atom's weighted volume
  double order;        // Seth-Hill order m, the same for all types
  double *bulk_volume; // per type: weighted volume of a complete family
  double *lambda_bar, *mu_bar;    // per type: peridynamic Lame constants
  double *theta;       // dilatation of owned atoms
  double *abstate;     // per atom A = lambda theta N, B = 2 mu N (owned + ghost)
  int nmax;
  double *strain;      // per-bond strain, reused by the force pass (m != 1/2)
  bigint nstrain;
  double *beta;        // per type: energy-failure beta (T14 eq. 6.3) for G_c = 1
  double *crit;        // per atom beta N for G_c = 1 (energy law; owned + ghost)
  double *gc_pair;     // per type pair G_c of the energy law (+inf: no failure)

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
  void grow_state();
  double norm(int i) const;
};

}    // namespace LAMMPS_NS

#endif
#endif
