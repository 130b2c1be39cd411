/* ----------------------------------------------------------------------
   PERIDYNAMICS_EXT: 'fail legacy <s00> <alpha>', LAMMPS PERI's rule in
   legacy mode (the bond test: core/pd_law_legacy.h). Each atom carries its
   s0 (atom->s0, as PERI): the largest s00 - alpha stretch over its intact
   bonds of the previous step. With alpha 0 and one s00 for all type pairs
   that is s00 for every atom, PERI's value too: the law then takes no
   notes of the bonds, and once every atom's s0 is s00 its test is the
   critical stretch s00 applied after the force acted, so it runs the
   critical stretch's kernels (core/pd_law_stretch.h, 'after').

   Guarded evaluations (alpha >= 0 for every type pair). A bond's test
   comes after its force acted, so the forces of a step never depend on
   s0; only the breaks and the next s0 do. While every stretch stays below
   every s0, no bond breaks, and the next s0 need not be known, only a
   floor under it: every atom's s0 is at least the smallest s00 - alpha s
   at the step's largest stretch s. So a guarded evaluation runs the
   elastic kernels and keeps only the largest stretch (no notes onto the
   far ends, no s0 to gather and scatter), then checks it against the
   floor of the previous s0 (one MPI_Allreduce). If it is above, some
   bond may have met PERI's test: the previous s0 are computed exactly from
   the previous positions (kept for this), and the step's bonds are tested
   and noted again with the exact kernels, adding no force. The results
   are those of exact evaluations to the bit. The deferred s0 are made
   exact before atoms migrate and at the end of each run (catch_up), and
   steps that write a restart file, setup and minimization are exact.
   After a failed guard the next evaluations are exact, twice as many
   after each further failure (at most MAX_WAIT), and half as many again
   once as many guards in a row held: a breaking run pays for few second
   passes, and an elastic spell soon guards every step again.
------------------------------------------------------------------------- */

#include "pd_failure_law.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "fix_pd_bonds.h"
#include "memory.h"
#include "neighbor.h"
#include "output.h"
#include "pair_pd.h"
#include "update.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstring>

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

constexpr int MAX_WAIT = 1024;    // exact evaluations after repeated failed guards, at most

class LawLegacy : public PDFailureLaw {
 public:
  LawLegacy(PairPD *pair, pd_fail_law id) : PDFailureLaw(pair, id, "legacy", COEFS, 2) {}
  ~LawLegacy() override
  {
    memory->destroy(s0_new);
    memory->destroy(xprev);
  }

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
    // PERI takes any number: a negative s00 breaks every bond in the first step
    if (!(value(S00, i, j) > 0.0))
      error->all(FLERR, "Pair {} coeff {} {}: 'fail legacy' s00 = {} must be positive (the critical "
                 "stretch of an unstrained bond)", style(), i, j, value(S00, i, j));
  }

  // alpha 0 and one s00 for all type pairs: every atom's s0 is s00 after
  // the first evaluation; else guarded when every alpha is at least 0
  void setup_run() override
  {
    fixed = guardable = true;
    s00 = value(S00, 1, 1);
    const int ntypes = atom->ntypes;
    for (int ti = 1; ti <= ntypes; ti++)
      for (int tj = 1; tj <= ntypes; tj++) {
        const bool mine = &law_of(ti, tj) == this;
        fixed = fixed && mine && value(ALPHA, ti, tj) == 0.0 && value(S00, ti, tj) == s00;
        guardable = guardable && mine && value(ALPHA, ti, tj) >= 0.0;
      }
    guarded = redo = false;
    wait = streak = 0;
    backoff = 1;
    nevaluations = nguarded = nagain = 0;
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
                     "(PERI's s00 - alpha stretch){}\n", style(),
                     guardable ? "; guarded: a step whose largest stretch stays below every s0 "
                                 "skips the s0 notes" : "");
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
    if (fixed) return exact_params();
    if (redo) {    // the second pass after a failed guard (again)
      redo = false;
      return exact_params();
    }
    guarded = may_guard();
    nevaluations += !update->setupflag;
    if (guarded) {
      nguarded++;
      return nullptr;    // (the guarded kernels read no parameters)
    }
    settle_s0();
    return exact_params();
  }
  double *notes() override { return fixed || guarded ? nullptr : s0_new; }
  pd_fail_law kernels() const override
  {
    return as_stretch ? PD_FAIL_STRETCH : guarded ? PD_FAIL_LEGACY_GUARDED : id;
  }

  // A guarded evaluation: were all its stretches at most every previous
  // s0? Then nothing broke, and the floor under the next s0 follows from
  // the largest stretch. Else the pass runs again, exactly.
  bool again(const pd_failure &f) override
  {
    if (!guarded) return false;
    double mine[2] = {f.note_largest, s0_exact ? -owned_floor() : -s0_floor}, all[2];
    MPI_Allreduce(mine, all, 2, MPI_DOUBLE, MPI_MAX, world);
    if (all[0] <= -all[1]) {
      s0_floor = lowest_note(all[0]);
      keep_positions();
      s0_exact = false;
      if (++streak >= backoff) {    // as many guards held as the wait was long
        backoff = std::max(1, backoff / 2);
        streak = 0;
      }
      return false;
    }
    settle_s0();
    guarded = false;
    redo = true;
    nagain++;
    wait = backoff;
    backoff = std::min(2 * backoff, MAX_WAIT);
    streak = 0;
    return true;
  }

  // each atom's s0 for the next step: PERI's max over its intact bonds
  void after_evaluation() override
  {
    if (fixed) {
      for (int i = 0; i < atom->nlocal; i++) atom->s0[i] = s00;
      return;
    }
    if (guarded) return;    // (again() kept what the next one needs)
    take_notes();
  }

  void catch_up(bool run_ends) override
  {
    settle_s0();
    if (!run_ends || nevaluations == 0) return;
    if (comm->me == 0)
      utils::logmesg(lmp, "{}: fail legacy: {} of {} evaluations guarded (no s0 notes), {} of them "
                     "tested again exactly\n", style(), nguarded, nevaluations, nagain);
    nevaluations = nguarded = nagain = 0;
  }

 private:
  pd_law_legacy params;
  pd_law_stretch stretch;
  bool fixed = false;          // every atom's s0 is s00 (setup_run) ...
  double s00 = 0.0;            // ... this one
  bool as_stretch = false;     // this evaluation runs the critical stretch's kernels
  double *s0_new = nullptr;    // per atom new s0 (owned + ghost)
  int nmax = 0;

  // guarded evaluations (see the top of this file)
  bool guardable = false;      // every type pair's law is this one, alpha >= 0
  bool guarded = false;        // this evaluation skips the exact test and the notes
  bool redo = false;           // its pass runs again, exactly (again)
  bool s0_exact = true;        // atom->s0 is every atom's s0 of the last evaluation ...
  double s0_floor = 0.0;       // ... else at least this, everywhere
  double *xprev = nullptr;     // the positions of the last evaluation (owned + ghost) ...
  int nxprev = 0, xprev_nall = 0;
  bigint xprev_builds = -1;    // ... and the neighbor build they belong to
  int wait = 0, backoff = 1;   // exact evaluations to come, and after the next failed guard
  int streak = 0;              // guards held since backoff last changed
  bigint nevaluations = 0, nguarded = 0, nagain = 0;    // this run's, for its report

  bool every_s0_is_s00(int nall) const
  {
    const double *s0 = atom->s0;
    int same = 1;
    for (int a = 0; a < nall; a++) same &= s0[a] == s00;
    return same;
  }

  const void *exact_params()
  {
    // (the force loop writes every entry, owned and ghost)
    if (!fixed && atom->nmax > nmax) {
      nmax = atom->nmax;
      memory->destroy(s0_new);
      memory->create(s0_new, nmax, "pd/legacy:s0_new");
    }
    const int nall = atom->nlocal + atom->nghost;
    params = {table(S00), table(ALPHA), atom->s0, pd_failure_floor(atom->s0, nall)};
    return &params;
  }

  // the same decision on every rank: setup, minimization and a step that
  // writes a restart file (its s0) are exact, and so are the steps after a
  // failed guard
  bool may_guard()
  {
    if (!guardable || update->setupflag || update->whichflag != 1) return false;
    if (output->restart_flag && output->next_restart == update->ntimestep) return false;
    if (wait > 0) {
      wait--;
      return false;
    }
    return true;
  }

  double owned_floor() const { return pd_failure_floor(atom->s0, atom->nlocal); }

  // the smallest s00 - alpha s over the type pairs at stretch s: with alpha
  // >= 0, at most every note of a bond stretched s or less (in the core's
  // arithmetic, which is monotonic in s), so at most every atom's s0
  double lowest_note(double s) const
  {
    if (s == -INFINITY) return INFINITY;    // no bond anywhere
    double low = INFINITY;
    const int n = atom->ntypes + 1;
    const double *s00s = table(S00), *alphas = table(ALPHA);
    for (int ti = 1; ti < n; ti++)
      for (int tj = 1; tj < n; tj++)
        low = std::min(low, pd_law_legacy_note_of(s00s[ti * n + tj], alphas[ti * n + tj], s));
    return low;
  }

  void keep_positions()
  {
    const int nall = atom->nlocal + atom->nghost;
    if (atom->nmax > nxprev) {
      nxprev = atom->nmax;
      memory->destroy(xprev);
      memory->create(xprev, 3 * nxprev, "pd/legacy:xprev");
    }
    std::memcpy(xprev, atom->x[0], 3 * sizeof(double) * nall);
    xprev_nall = nall;
    xprev_builds = neighbor->ncalls;
  }

  // every atom's s0 of the last evaluation, when it was guarded: from its
  // positions (xprev, owned and ghost), what an exact one would have noted
  void settle_s0()
  {
    if (s0_exact) return;
    if (xprev_nall != atom->nlocal + atom->nghost || xprev_builds != neighbor->ncalls)
      error->one(FLERR, "Pair {}: fail legacy: the atoms changed before the deferred s0 were "
                 "settled (internal error; please report it)", style());
    exact_params();
    const int *type = atom->ntypes == 1 ? nullptr : atom->type;
    const pd_bond_view v = bonds()->view();
    pd_law_legacy_notes_at(&v, type, atom->ntypes + 1, xprev, &params, s0_new, xprev_nall);
    take_notes();
    bonds()->copy_to_ghosts(atom->s0);    // (the exact test reads the ghosts' s0)
  }

  // the notes of an exact evaluation become each atom's s0
  void take_notes()
  {
    bonds()->max_to_owners(s0_new);
    for (int i = 0; i < atom->nlocal; i++)
      atom->s0[i] = std::isinf(s0_new[i]) ? DBL_MAX : s0_new[i];
    s0_exact = true;
  }
};

// The kernels of a guarded evaluation (core/pd_law_legacy.h), which only
// LawLegacy selects: never named after 'fail'.
class LawLegacyGuarded : public PDFailureLaw {
 public:
  LawLegacyGuarded(PairPD *pair, pd_fail_law id) :
      PDFailureLaw(pair, id, "legacy (guarded)", nullptr, 0)
  {
  }
  bool selectable() const override { return false; }
  std::string usage() const override { return "fail legacy <s00> <alpha>"; }
  int parse(PDCoefLine &, int, char **, int iarg) override { return iarg; }
};

}    // namespace

PDFailureLaw *LAMMPS_NS::pd_make_law_legacy(PairPD *pair, pd_fail_law id)
{
  return new LawLegacy(pair, id);
}

PDFailureLaw *LAMMPS_NS::pd_make_law_legacy_guarded(PairPD *pair, pd_fail_law id)
{
  return new LawLegacyGuarded(pair, id);
}
