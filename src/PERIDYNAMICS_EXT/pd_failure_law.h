/* -*- c++ -*- ----------------------------------------------------------
   PERIDYNAMICS_EXT: a failure law on the LAMMPS side. The core has its test
   per bond (core/pd_law_<name>.h, listed in core/pd_laws.h); here it has
   everything else, one file per law (pd_law_<name>.cpp):
     - its syntax after 'fail <name>' and its declared coefficients,
     - validation of a type pair's values and what it needs of the material,
     - how bonds between two types get their values (init_one),
     - calibration once per run, per-atom state, the parameter struct of
       one evaluation and what follows the evaluation,
     - the properties the pair must respect, and its setup report line.
   The registry (pd_failure_law.cpp) makes one of each law for a pair
   style, from the list in core/pd_laws.h. Every call is per setup or per
   evaluation, never per bond.
------------------------------------------------------------------------- */

#ifndef LMP_PD_FAILURE_LAW_H
#define LMP_PD_FAILURE_LAW_H

#include "pd_field.h"
#include "pointers.h"

#include <memory>
#include <string>
#include <vector>

extern "C" {
#include "pd_coefs.h"
#include "pd_influence.h"
#include "pd_laws.h"
}

struct pd_failure;    // core/pd_failure.h

namespace LAMMPS_NS {

class FixPDBonds;
class PairPD;
struct PDCoefLine;

// What a state-based material offers a law that weighs each bond end's
// instantaneous energy (pd_bond_force.release_i, release_j) against G_c:
// the normalization of its force state. A material without it cannot
// give those energies (bond-based bonds have no per-end state).
class PDBondEnergies {
 public:
  virtual double family_norm(int i) const = 0;    // N = d / m of atom i, m its calibrated weighted volume
  virtual pd_influence_kind influence_kind() const = 0;
  // lambda and mu of type t's bond energy, w eps (A + B eps / 2) at each
  // end with A = lambda N theta, B = 2 mu N (pd/ordinary's lambda_bar and
  // mu_bar); false where the bond energy is not of that form
  virtual bool bond_moduli(int /*t*/, double & /*lambda*/, double & /*mu*/) const { return false; }

 protected:
  // never deleted through this base: no virtual destructor, which the
  // style's would have to override with LAMMPS's exception specification
  // (see PDFamilySource in pd_family_spec.h)
  ~PDBondEnergies() = default;
};

class PDFailureLaw : protected Pointers {
 public:
  PDFailureLaw(PairPD *pair, pd_fail_law id, const char *name, const pd_coef *coefs, int ncoefs);

  const pd_fail_law id;                // its row in core/pd_laws.h
  const char *const name;              // the word after 'fail'
  const std::vector<pd_coef> coefs;    // its coefficients (columns shared by name)
  std::vector<int> cols;               // their columns in the pair's tables (set by PairPD)

  bool declares(int col) const;
  const pd_coef *entry(int col) const;   // its declaration of a column, or null

  // --- declaration
  // 'fail <name>' may be written (the absent law may not)
  virtual bool selectable() const { return true; }
  // bonds may break under it
  virtual bool breaks() const { return true; }
  // its syntax for messages: "fail stretch <s0> | fail stretch Gc <Gc>"
  virtual std::string usage() const = 0;
  // why this pair style's material cannot use it (empty: it can)
  virtual std::string unsupported() const { return ""; }
  // broken bonds never push under it: the reason, for the report (null:
  // the pair style's recontact setting rules)
  virtual const char *no_recontact() const { return nullptr; }
  // a bond it breaks with half its force is made intact again when the
  // step is evaluated again (pd_failure.replay)
  virtual bool replays_fresh() const { return true; }

  // --- pair_coeff
  // the words after 'fail <name>', from arg[iarg]; returns the next iarg
  virtual int parse(PDCoefLine &line, int narg, char **arg, int iarg) = 0;
  // a line is read (its values and a material file's): drop the file's
  // values this law has no use for
  virtual void settle(PDCoefLine &line) const;
  // one type pair's values, after the material's check (i != j: a pair_coeff I J line)
  virtual void check(int, int) {}
  // bonds between types i != j (init_one), after their columns were mixed
  // by their rules (explicit: a pair_coeff I J line gave the pair)
  virtual void mix(int, int, bool) {}

  // per-atom state it keeps in the bond store (pd_field.h), declared with
  // the pair style's
  virtual std::vector<PDField> per_atom_fields() const { return {}; }

  // --- run
  virtual void setup_run() {}                          // all ranks, first compute of a run
  virtual const void *evaluation() { return nullptr; } // the core's parameter struct for one evaluation
  virtual double *notes() { return nullptr; }          // its per-atom notes then (pd_failure.note_atom)
  // the row of core/pd_laws.h whose kernels run that evaluation: its own,
  // or another law's that makes the same test then
  virtual pd_fail_law kernels() const { return id; }
  // after the material's force pass (all ranks): true when the pass must
  // run again with what evaluation(), notes() and kernels() give now,
  // adding no force, only the law's breaks and notes (PERI's rule, guarded)
  virtual bool again(const pd_failure &) { return false; }
  virtual void after_evaluation() {}                   // what follows it (all ranks)
  // per-atom state that evaluations deferred, made exact while the atoms'
  // indices still hold: before they migrate, and when a run ends ('run_ends':
  // then also a line on what the run deferred) (all ranks)
  virtual void catch_up(bool /*run_ends*/) {}
  virtual void report() const {}                       // its line in the setup report (rank 0)
  // which lattice sum (core/pd_orientation.h, pd_release_kind) gives the
  // energy a crack releases through type t under this law, as a share of
  // its G_c; -1: none (no G_c, or the energy of a broken bond depends on
  // more than its geometry)
  virtual int release_kind(int /*t*/) const { return -1; }
  // PD_RELEASE_ORDINARY_STRETCH: lambda / mu of type t's bond moduli, which
  // weighs the dilatation's part of the release (pd_release_ordinary)
  virtual double release_dilatation(int /*t*/) const { return 0.0; }

 protected:
  PairPD *pair;

  // the pair's values of this law's k-th coefficient
  double &value(int k, int i, int j);
  bool given(int k, int i, int j) const;
  const double *table(int k) const;   // the type-pair table, (ntypes + 1)^2
  // the law the pair (i, j) names
  const PDFailureLaw &law_of(int i, int j) const;
  // read the number 'text' into the line as this law's k-th coefficient
  void take(PDCoefLine &line, int k, const char *text) const;
  // 'Gc <Gc>' at arg[iarg], if it is there: returns the next iarg
  int take_keyword(PDCoefLine &line, int k, int narg, char **arg, int iarg) const;
  // a word that starts the next keyword/value pair of a pair_coeff line
  bool line_keyword(const char *word) const;
  int fail_column() const;   // the laws' columns follow it
  const char *column_name(int p) const;
  std::string usages_of(int p) const;   // the laws that take column p, for messages
  double &column(const char *name, int i, int j);   // any column, by name
  const char *style() const;
  int dim() const;
  bool plane_strain() const;
  bool legacy_mode() const;
  FixPDBonds *bonds() const;
  double *field(const char *name) const;    // one of per_atom_fields() in the bond store
  void check_derived(int k, int i, int j);
};

// A pair style's laws, one of each, in the order of core/pd_laws.h (the
// absent law first).
std::vector<std::unique_ptr<PDFailureLaw>> pd_failure_laws(PairPD *pair);

// One function per law, in its own file: pd_law_<name>.cpp.
#define PD_LAW_MAKER(ID, name, ...) PDFailureLaw *pd_make_law_##name(PairPD *pair, pd_fail_law id);
PD_FAILURE_LAWS(PD_LAW_MAKER, ~)
#undef PD_LAW_MAKER

}    // namespace LAMMPS_NS

#endif
