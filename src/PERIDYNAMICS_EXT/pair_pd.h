/* -*- c++ -*- ----------------------------------------------------------
   PERIDYNAMICS_EXT: what every pd/ material pair style shares: per type
   pair coefficients given as keyword/value pairs, the bond store (fix
   pd/bonds, which it creates and describes its families to), restart,
   energy/virial tally and the setup report.
------------------------------------------------------------------------- */

#ifndef LMP_PAIR_PD_H
#define LMP_PAIR_PD_H

#include "pair.h"
#include "pd_field.h"
#include "pd_family_spec.h"

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

extern "C" {
#include "pd_bonds.h"
#include "pd_coefs.h"
#include "pd_dispersion.h"
#include "pd_failure.h"
#include "pd_lattice.h"
#include "pd_loop.h"
#include "pd_params.h"
}

namespace LAMMPS_NS {

class FixPDBonds;
class PDBondEnergies;
class PDFailureLaw;

// One pair_coeff line as it is read: a value per coefficient column (NaN:
// not given) and whether the line itself gave it (else a material file did).
struct PDCoefLine {
  std::vector<double> values;
  std::vector<char> seen;
};

// One pass over a style's settings in a restart file: writes them, or reads
// them on rank 0 and broadcasts, in the order they are visited.
class PDSettingsIO {
 public:
  PDSettingsIO(class LAMMPS *lmp, FILE *fp, bool writing) : lmp(lmp), fp(fp), writing(writing) {}
  void operator()(int &v);
  void operator()(double &v);

 private:
  class LAMMPS *lmp;
  FILE *fp;
  bool writing;
};

class PairPD : public Pair, public PDFamilySource {
 public:
  // the material's declared coefficients (its core table), horizon first
  PairPD(class LAMMPS *, const pd_coef *material_coefs, int ncoefs);
  ~PairPD() override;

  void settings(int, char **) override;
  void coeff(int, char **) override;
  void init_style() override;
  double init_one(int, int) override;
  void write_restart(FILE *) override;
  void read_restart(FILE *) override;
  void write_restart_settings(FILE *) final;
  void read_restart_settings(FILE *) final;
  double memory_usage() override;

  double horizon(int itype, int jtype) const { return coef[0][itype][jtype]; }
  // the style's own name, also under pair_style hybrid
  virtual const char *style_name() const = 0;
  // the bond families this style asks the bond store for (PDFamilySource)
  PDFamilySpec family_spec() const override;
  void catch_up(bool run_ends) override;    // the failure law's deferred per-atom state
  double current_stable_dt() override;
  // the pd/ material style of the current pair style (alone or a hybrid
  // sub-style, found by type), or null
  static PairPD *active(class Force *);
  double legacy_spacing() const { return legacy ? lattice_spacing : 0.0; }
  double plate_thickness() const { return thickness; }
  int dimension() const { return dim(); }    // of the model: 2 or 3
  // the weighted volume atom i is calibrated on (its own family's, or a
  // complete one near a free surface: core/pd_calibration.h)
  double calibrated_volume(int i) const;
  double complete_volume(int t) const { return calibrated_reference[t]; }    // of type t's complete family
  // a per-atom sum over each owned atom's reference family, calibrated in
  // place as the weighted volume is; returns the type's complete-family
  // value it blends with
  std::vector<double> calibrate(double *q) const;
  // each atom's reference family moment sum w V |xi|^power (owned atoms;
  // core/pd_calibration.h pd_family_moment), for a calibration; unweighted:
  // sum V |xi|^power
  std::vector<double> family_moments(int power, bool weighted = true) const;
  // Per type, width sums that 'add' accumulates over a sample of the
  // type's complete reference families (mark_complete_families), each as
  // a pd_family with its partners' volumes in the bond weights: one of a
  // lattice type (its complete families agree), PD_FAMILY_SAMPLE of an
  // irregular one, chosen by tag, so that every rank count takes the same
  // ones and sums them in the same order (pair_pd_family_sample.cpp).
  // Collective; the sums are zero for a type without a complete family.
  std::vector<double> family_sample_sums(int width,
                                         const std::function<void(const pd_family &, double *)> &add) const;
  // 'quadrature partial': each bond weighted by the share of its partner's
  // cell inside the horizon (core/pd_quadrature.h)
  bool partial_volumes() const { return quadrature == QUADRATURE_PARTIAL; }
  // the quadrature without a 'quadrature' keyword: the one the accuracy
  // report measured more accurate at equal cost for the style (doc/accuracy.md)
  virtual int default_quadrature() const { return QUADRATURE_POINT; }
  // the stable time step estimate of this run's setup (0 before it)
  double stable_dt() const { return dt_estimate; }
  // Each owned atom's stiffness sum with its ghosts' share added (fix
  // pd/timestep; core/pd_tangent.h), arrays of atom->nmax: from the bonds'
  // tangents in the current configuration, with 'closing' the largest
  // relative closing rate of its bonds (1/time); and as the setup estimate
  // (MS07 eq. 43), which changes only when LAMMPS reneighbors.
  void current_stiffness_sums(double *current, double *closing);
  void reference_stiffness_sums(double *reference);
  // the ghosts' share of a per-atom sum (owned + ghost) onto their owners
  void sum_to_owners(double *a);
  void max_to_owners(double *a);    // the same, the largest of owner and ghosts
  // the stable step the bond store's blow-up guard quotes
  void note_stable_dt(double dt);
  double smallest_horizon() const;
  // micromodulus of a bond-based solid as stiff as this material: the scale
  // of the contact stiffness (pd/contact)
  virtual double contact_micromodulus(int itype, int jtype) const = 0;
  // the per-atom fields the style keeps in the bond store (pd_field.h),
  // declared with it at init; compute pd/atom lists the OUTPUT ones
  virtual std::vector<PDField> per_atom_fields() const { return {}; }
  // those, the calibration's and the failure law's: what the style
  // declares to the bond store
  std::vector<PDField> fields_to_declare() const;
  // an ON_DEMAND field: whether this evaluation computes it (at set-up, or
  // when a compute pd/atom listing it is due on this step: LAMMPS's own
  // schedule, as for per-atom energy), and the step it last did (-1: never)
  bool demanded(const std::string &name);
  bigint computed_on(const std::string &name) const;
  // a bond-based solid: a bond's energy is its own (a critical stretch
  // from G_c is then calibrated on the family, core/pd_law_stretch.h), and
  // how much type t's stiffness is scaled by its own calibration
  // (core/pd_params.h pd_pmb_moment_continuum)
  virtual bool bond_based() const { return false; }
  virtual double stiffness_scale(int) const { return 1.0; }
  // E and nu of the bonds between two types, for a critical stretch from
  // G_c (MS07 eq. 28-29)
  virtual void fracture_elastic(int i, int j, double &E, double &nu) const = 0;
  // a state-based material's per-end bond energies ('fail energy'), or null
  virtual const PDBondEnergies *bond_energies() const { return nullptr; }

 protected:
  friend class PDFailureLaw;
  // the declared coefficients: the material's, 'fail' (the law of each
  // type pair, its row in core/pd_laws.h), then the laws' (one column per
  // name); restart files hold them in this order
  std::vector<pd_coef> decl;
  int nmaterial;            // the material's are decl[0 .. nmaterial-1]
  int ifail;                // the column of 'fail'
  double ***coef;           // coef[p][i][j] for decl[p]; NaN when not given
  int legacy;               // reproduce legacy PERI (partial volumes, ...)
  enum { RECONTACT_NONE, RECONTACT_NEAR, RECONTACT_ANY };
  int recontact;            // broken bonds push in compression (T14 6.1.3): once their ends touch, at any length, or never
  enum { QUADRATURE_POINT, QUADRATURE_PARTIAL };
  int quadrature;           // point: whole partner volumes; partial: their share inside the horizon
  int directional;          // directional_correction: each family's fourth moment made isotropic
  double cell_beyond;       // partial: how far past the horizon bonds reach (half the largest cell's diagonal)
  std::vector<std::unique_ptr<PDFailureLaw>> laws;   // one of each, core/pd_laws.h order
  PDFailureLaw *law;        // the failure law of the run (one for all pairs)
  pd_dimension model_dim;   // 3D, plane stress or plane strain
  double thickness;         // plate thickness of a 2D model
  double lattice_spacing;   // legacy partial volumes need it (0: not yet known)
  FixPDBonds *bonds;
  int report_pending;       // print the setup report at the next compute
  bool had_families = false;    // a run of this style used built families
  int bond_by_bond;        // PDEXT_BOND_BY_BOND set: no row in the vectorized pass (tests)
  double timed_since;      // MPI_Wtime at the start of the evaluation the report times (< 0: none)
  double *work;             // per-atom scratch, 2 doubles per atom
  int nwork;
  std::vector<int> field_id;    // the bond store's ids of per_atom_fields(), in their order
  std::vector<PDField> declared;    // per_atom_fields() as of the last init
  std::map<std::string, bigint> demanded_on;    // ON_DEMAND fields: the step last computed
  int field_index(const std::string &name) const;    // its id in the bond store, -1 if not declared

  // style hooks
  virtual int parse_setting(int narg, char **arg, int iarg);    // returns args used, 0 if unknown
  virtual int parse_model(const char *) { return 0; }           // leading model word in pair_coeff
  virtual void check_coeff(int i, int j) = 0;                   // complete/validate one pair
  // whether the style's settings use coefficient column p (a material file
  // may hold more constants than a model needs: those are skipped, named
  // in the log)
  virtual bool uses_coefficient(int) const { return true; }
  virtual int uses_weights() const { return legacy || partial_volumes() || directional; }
  // > 0: every bond's weight is this times 1/|xi|, so that the force loops
  // compute it (pd_bond_view.weight_horizon); 0: they load the table
  virtual double inverse_weight_horizon() const { return 0.0; }
  // quadrature weight of a new bond (used only when uses_weights()), as a
  // function holding copies of the settings it needs: PERI's partial
  // volume (legacy), the cell's share inside the horizon (quadrature
  // partial) or 1; a style with an influence function multiplies it in
  virtual PDFamilySpec::Weight weight_rule() const;
  // the influence function at a bond: at its length, or at the horizon for
  // a partial cell whose centre lies beyond it (its share inside is there)
  static double influence_at(int kind, int dim, const PDBondGeometry &g);
  virtual int history_per_bond() const { return 0; }
  // whether that history evolves with the deformation (plastic bonds), so
  // that a trial state of minimize's line search would change it
  virtual bool yields() const { return history_per_bond() > 0; }
  virtual std::string family_settings() const { return ""; }         // what else shapes the bonds
  virtual void setup_run() {}                                   // first compute of a run
  virtual void stable_dt_sum(double *sum) = 0;    // add stiffness sums over nall
  // the same with the current tangents, and the bonds' relative closing
  // rates (pd_tangent.h)
  virtual void tangent_sum(double *sum, double *closing) = 0;
  double *scratch();                              // per-atom scratch (nmax), second half of work
  virtual void report_extra() {}
  // The linear model the style's constants reduce to at small strain on a
  // lattice, and type t's elastic constants: the setup report's lattice
  // error. false: none (constants exact by construction).
  virtual bool linear_model(int, pd_linear_kind &, pd_elastic &) const { return false; }
  void report_accuracy(const PDFamilySpec &spec);    // pair_pd_accuracy.cpp
  std::string site_lattice(double volume, pd_lattice &lat) const;
  // the settings kept in restart files: PairPD's, then the style's (call
  // PairPD::restart_settings first)
  virtual void restart_settings(PDSettingsIO &io);

  void allocate();
  int dim() const { return pd_dimension_count(model_dim); }
  void read_material_file(int narg, char **arg);
  int set_coeff_pairs(int ilo, int ihi, int jlo, int jhi, const std::vector<double> &values);
  std::vector<double> parse_values(int narg, char **arg, int iarg, std::vector<double> values);
  void set_on_line(PDCoefLine &line, int p, double v);
  double finite_number(const char *key, const char *text);
  void set_nobond(int i, int j);
  void check_declared(int i, int j);
  void check_value(const pd_coef &c, int p, int i, int j);
  void check_derived(int p, int i, int j);
  pd_elastic elastic(int i, int j, const char *who);   // from K,G or E,nu coefficients
  // a type's K, G, E and nu from whichever pair was given, all four written
  // back and checked (a material that declares all four)
  pd_elastic complete_elastic(int i, int j);
  // E and nu of the bonds between two types: the means of theirs
  void mean_elastic(int i, int j, double &E, double &nu) const;
  double value(int p, int i, int j) const { return coef[p][i][j]; }
  bool given(int p, int i, int j) const;
  bool failure_given(int i, int j) const { return given(ifail, i, j); }   // 'fail' on the line
  int coef_index(const std::string &name) const;
  std::string describe(const pd_coef &c) const;    // "critical stretch s0"
  PDFailureLaw *law_named(const char *name) const;
  PDFailureLaw &law_of(double id) const;           // a 'fail' column's law (NaN: none)
  std::string law_names(const char *last) const;   // "stretch, energy or legacy"
  std::string law_usages(int col) const;           // the laws that take column col, for messages
  void select_law();
  void grow_work();
  // the value of column p that every type of this style shares (a
  // material's strain order m): an ERROR if two types differ; 'none' when
  // the style has no type
  double shared_value(int p, double none);
  // Each family calibrated on itself (core/pd_calibration.h,
  // pair_pd_calibration.cpp): at each run's set-up, every atom's share of
  // its own family's sums and its calibrated weighted volume (per-atom
  // fields of the bond store, migrating with the atoms)
  void calibrate_families();
  void mark_complete_families(const std::vector<double> &complete_share, const std::vector<bool> &lattice);
  std::vector<char> complete_family;    // per owned atom: its family is certainly complete
  std::vector<bool> on_lattice;         // per type: lattice_types() at the last calibration
  // 'directional_correction yes' (core/pd_directional.h,
  // pair_pd_directional.cpp): whether the style offers it, with the power
  // of |xi| in a bond's share w V |xi|^power of the stiffness; and the
  // correction of the bond weights, once, at the run that built the families
  virtual bool directional_moment(int & /*power*/) const { return false; }
  void correct_directions(const std::vector<double> &share);
  std::vector<double> lattice_forms(int power);
  void exchange_rows(double *rows, int width, const std::vector<int> &slot, int nslots, bool to_owners);
  std::vector<bool> lattice_types() const;    // per type: its atoms sit on a lattice
  // each type's median of q over the owned atoms that take selects (NaN: none)
  std::vector<double> type_medians(const double *q, const std::function<bool(int)> &take) const;
  // every atom's calibrated weighted volume is its type's complete one
  bool calibration_uniform() const;
  // the style normalizes every atom by its own family, surfaces included
  virtual bool surface_corrected() const { return false; }
  std::vector<double> calibrated_reference;    // per type: the complete family's weighted volume
  std::vector<double> family_tolerance;        // per type: the interior families' tolerance (pd_calibration.h)
  int calibrated_field = -1;                   // the bond store's id of calibrated_volume
  void declare_fields();
  void tally(const pd_tally &t);
  void report_setup();
  double smallest_stable_dt(const double *stiffness) const;    // collective
  double family_key() const;
  void check_failure(int i, int j);   // the type pair's failure law and its values
  // What one force evaluation works on: the bonds, the tally the step asks
  // for and the failure state when bonds can break. begin_evaluation fills
  // it in place (its pd_loop points into it: never copied or moved);
  // end_evaluation books what broke and tallies, and returns whether bonds
  // broke anywhere (or were replayed).
  struct Evaluation {
    pd_bond_view view;
    pd_tally tally;
    pd_failure fail;
    bool fails;
    pd_loop L;
    Evaluation() = default;
    Evaluation(const Evaluation &) = delete;
    Evaluation &operator=(const Evaluation &) = delete;
  };
  void begin_evaluation(Evaluation &e);
  pd_bond_view loop_view() const;
  // the same for a pass that computes no force (pd_tangent.h): the
  // bonds, and which broken bonds push
  void begin_pass(Evaluation &e);
  bool end_evaluation(Evaluation &e);
  // the material's force pass over e.L; again when the failure law asks
  // (PDFailureLaw::again), adding no force then
  void force_pass(Evaluation &e, const std::function<void(const pd_loop *)> &pass);
  std::vector<double> unused_forces;    // the forces of such a second pass
  void report_cost(const pd_bond_view &v, double seconds);
  bool failing() const;
  pd_failure failure_state();
  pd_failure recontact_state();    // its part that says which broken bonds push
  bool account_failure(const pd_failure &f);
  double *zero_released();
  void book_released();
  double *released;         // per-atom released energy of one step (owned + ghost)
  int *fresh;               // len0 indices of the bonds one evaluation broke (malloc'd by the core)
  int maxfresh;
  int nreleased;
  double dt_estimate;
  double *reaction;         // the force loop's scratch (pd_loop.reaction)
  int nreaction;
  double *reactions();
  double *radius;           // per-atom contact radius (owned + ghost)
  int nradius;
  bigint radius_step;       // the reneighboring it was computed for
  const double *contact_radii();

 private:
  // the steps of init_style, in order
  void check_one_material_style();
  void mix_interfaces();
  void check_minimize();
  void check_atom_setup();
  void check_spacing();
  void check_box();
  void take_lattice_spacing();
  void attach_bond_store();
};

}    // namespace LAMMPS_NS

#endif
