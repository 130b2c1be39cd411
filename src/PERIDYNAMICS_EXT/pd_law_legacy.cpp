/* ----------------------------------------------------------------------
   PERIDYNAMICS_EXT: 'fail legacy <s00> <alpha>', LAMMPS PERI's rule in
   legacy mode (the bond test: core/pd_law_legacy.h). Each atom carries its
   s0 (atom->s0, as PERI): the largest s00 - alpha stretch over its intact
   bonds of the previous step. With alpha 0 and one s00 for all type pairs
   that is s00 for every atom, PERI's value too: the law then takes no
   notes of the bonds, and once every atom's s0 is s00 its test is the
   critical stretch s00 applied after the force acted, so it runs the
   critical stretch's kernels (core/pd_law_stretch.h, 'after').
------------------------------------------------------------------------- */

#include "pd_failure_law.h"

#include "atom.h"
#include "error.h"
#include "fix_pd_bonds.h"
#include "memory.h"
#include "pair_pd.h"

#include <cfloat>
#include <cmath>

extern "C" {
#include "pd_law_legacy.h"
#include "pd_law_stretch.h"
}

using namespace LAMMPS_NS;

namespace {

enum { S00, ALPHA };
const pd_coef COEFS[] = {
    // kept in the s0 column: between two types, the smaller
    {"s0", "PERI's critical stretch", PD_MIX_MIN, PD_COEF_PAIR, PD_CHECK_FINITE, 0.0, 0.0, 0.0, "s00"},
    {"alpha", "PERI's stretch factor", PD_MIX_MEAN, PD_COEF_PAIR, PD_CHECK_FINITE, 0.0, 0.0, 0.0, nullptr},
};

class LawLegacy : public PDFailureLaw {
 public:
  LawLegacy(PairPD *pair, pd_fail_law id) : PDFailureLaw(pair, id, "legacy", COEFS, 2) {}
  ~LawLegacy() override { memory->destroy(s0_new); }

  std::string usage() const override { return "fail legacy <s00> <alpha>"; }
  // PERI drops broken bonds; its bonds break after their force acted, so
  // no step is evaluated again with half forces
  const char *no_recontact() const override { return "legacy PERI"; }
  bool replays_fresh() const override { return false; }

  int parse(PDCoefLine &line, int narg, char **arg, int iarg) override
  {
    if (iarg + 1 >= narg) error->all(FLERR, "Pair {} coeff: 'fail legacy' needs s00 and alpha", style());
    take(line, S00, arg[iarg]);
    take(line, ALPHA, arg[iarg + 1]);
    return iarg + 2;
  }

  void check(int i, int j) override
  {
    if (!legacy_mode())
      error->all(FLERR, "Pair {} coeff {} {}: 'fail legacy' reproduces PERI and needs the 'legacy' "
                 "pair style keyword", style(), i, j);
  }

  // alpha 0 and one s00 for all type pairs: every atom's s0 is s00 after
  // the first evaluation
  void setup_run() override
  {
    fixed = true;
    s00 = value(S00, 1, 1);
    const int ntypes = atom->ntypes;
    for (int ti = 1; ti <= ntypes; ti++)
      for (int tj = 1; tj <= ntypes; tj++)
        fixed = fixed && &law_of(ti, tj) == this && value(ALPHA, ti, tj) == 0.0 &&
            value(S00, ti, tj) == s00;
  }

  void report() const override
  {
    if (fixed)
      utils::logmesg(lmp, "{}: fail legacy: alpha 0 and s00 {} for all type pairs: every atom's s0 "
                     "is s00, no notes per bond{}\n", style(), s00,
                     s00 > 0.0 ? "; once every s0 is s00, the critical stretch s00 applied after "
                                 "the force acted" : "");
    else
      utils::logmesg(lmp, "{}: fail legacy: each atom's s0 from its bonds' stretch every step "
                     "(PERI's s00 - alpha stretch)\n", style());
  }

  const void *evaluation() override
  {
    const int nall = atom->nlocal + atom->nghost;
    // (an atom made in the run, or the first evaluation, may have another
    // s0: then this law's own kernels, without notes; the stretch's screen
    // takes s0 > 0)
    as_stretch = fixed && s00 > 0.0 && every_s0_is_s00(nall);
    if (as_stretch) {
      stretch = {table(S00), 1};
      return &stretch;
    }
    // (the force loop writes every entry, owned and ghost)
    if (!fixed && atom->nmax > nmax) {
      nmax = atom->nmax;
      memory->destroy(s0_new);
      memory->create(s0_new, nmax, "pd/legacy:s0_new");
    }
    params = {table(S00), table(ALPHA), atom->s0, pd_failure_floor(atom->s0, nall)};
    return &params;
  }
  double *notes() override { return fixed ? nullptr : s0_new; }
  pd_fail_law kernels() const override { return as_stretch ? PD_FAIL_STRETCH : id; }

  // each atom's s0 for the next step: PERI's max over its intact bonds
  void after_evaluation() override
  {
    if (fixed) {
      for (int i = 0; i < atom->nlocal; i++) atom->s0[i] = s00;
      return;
    }
    bonds()->max_to_owners(s0_new);
    for (int i = 0; i < atom->nlocal; i++) atom->s0[i] = std::isinf(s0_new[i]) ? DBL_MAX : s0_new[i];
  }

 private:
  pd_law_legacy params;
  pd_law_stretch stretch;
  bool fixed = false;          // every atom's s0 is s00 (setup_run) ...
  double s00 = 0.0;            // ... this one
  bool as_stretch = false;     // this evaluation runs the critical stretch's kernels
  double *s0_new = nullptr;    // per atom new s0 (owned + ghost)
  int nmax = 0;

  bool every_s0_is_s00(int nall) const
  {
    const double *s0 = atom->s0;
    int same = 1;
    for (int a = 0; a < nall; a++) same &= s0[a] == s00;
    return same;
  }
};

}    // namespace

PDFailureLaw *LAMMPS_NS::pd_make_law_legacy(PairPD *pair, pd_fail_law id)
{
  return new LawLegacy(pair, id);
}
