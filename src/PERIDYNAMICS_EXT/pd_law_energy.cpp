/* ----------------------------------------------------------------------
   PERIDYNAMICS_EXT: 'fail energy [Gc <Gc>] [profile opening|uniform]',
   energy-based failure of a state-based material (T14 eq. 6.1-6.5; the
   bond test and the calibration: core/pd_law_energy.{h,c}).
------------------------------------------------------------------------- */

#include "pd_failure_law.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "fix_pd_bonds.h"
#include "memory.h"
#include "neighbor.h"
#include "pair_pd.h"

#include <cmath>
#include <cstring>

extern "C" {
#include "pd_law_energy.h"
#include "pd_orientation.h"
}

using namespace LAMMPS_NS;

namespace {

enum { GC, PROFILE };
const pd_coef COEFS[] = {
    // bonds between two types without their own: the mean (none if a type has none)
    {"Gc", "fracture energy", PD_MIX_MEAN, PD_COEF_PAIR | PD_COEF_FILE, PD_CHECK_POSITIVE, 0.0, 0.0, 0.0,
     nullptr},
    // the bond-failure-energy profile (pd_energy_profile), written as a
    // word; one for all type pairs, T14's opening one where none is given
    {"profile", "bond-failure-energy profile", PD_MIX_MEAN, PD_COEF_PAIR, PD_CHECK_RANGE, PD_PROFILE_UNIFORM,
     PD_PROFILE_OPENING, 0.0, nullptr},
};
const char *const PROFILES[] = {"uniform", "opening"};    // by pd_energy_profile

class LawEnergy : public PDFailureLaw {
 public:
  LawEnergy(PairPD *pair, pd_fail_law id) : PDFailureLaw(pair, id, "energy", COEFS, 2) {}
  ~LawEnergy() override { memory->destroy(crit); }

  std::string usage() const override { return "fail energy [Gc <Gc>] [profile opening|uniform]"; }

  std::string unsupported() const override
  {
    if (pair->bond_energies()) return "";
    return "a material with per-bond energies (pd/ordinary, pd/corr with strain extended): it "
           "weighs the energy each bond end holds against G_c; bond-based bonds and classical "
           "correspondence fail by 'fail stretch'";
  }

  int parse(PDCoefLine &line, int narg, char **arg, int iarg) override
  {
    for (int next = iarg;; iarg = next) {
      next = take_keyword(line, GC, narg, arg, iarg);
      if (next == iarg && iarg < narg && strcmp(arg[iarg], "profile") == 0) {
        const char *word = iarg + 1 < narg ? arg[iarg + 1] : "(nothing)";
        const int nprofiles = sizeof(PROFILES) / sizeof(PROFILES[0]);
        int k = 0;
        while (k < nprofiles && strcmp(word, PROFILES[k]) != 0) k++;
        if (k == nprofiles)
          error->all(FLERR, "Pair {} coeff: 'fail energy profile {}': expected 'opening' or 'uniform'", style(),
                     word);
        take(line, PROFILE, std::to_string(k).c_str());    // the coefficient is the pd_energy_profile
        next = iarg + 2;
      }
      if (next == iarg) return iarg;
    }
  }

  void check(int i, int j) override
  {
    // bonds between two types without their own G_c take their types' mean (mix)
    if (i == j && !given(GC, i, j))
      error->all(FLERR, "Pair {} coeff {} {}: 'fail energy' needs 'Gc <Gc>' (here or in the material "
                 "file)", style(), i, j);
  }

  void mix(int i, int j, bool explicit_pair) override
  {
    if (std::isnan(value(GC, i, j)))
      value(GC, i, j) = pd_coef_mixed(COEFS[GC].mix, value(GC, i, i), value(GC, j, j));
    if (explicit_pair && std::isnan(value(GC, i, j)))
      error->all(FLERR, "Pair {} coeff {} {}: 'fail energy' needs 'Gc <Gc>' here, or both types' own "
                 "G_c to mix", style(), i, j);
  }

  // G_c per type pair (every bond takes its pair's: an interface has its
  // own), and beta per unit G_c calibrated on each type's lattice
  void setup_run() override
  {
    const PDBondEnergies *m = pair->bond_energies();
    const int ntypes = atom->ntypes, n = ntypes + 1;
    gc.assign(n * n, INFINITY);
    int first = 0;    // the first failing pair (ti * n + tj), whose profile all share
    for (int ti = 1; ti <= ntypes; ti++)
      for (int tj = 1; tj <= ntypes; tj++)
        if (&law_of(ti, tj) == this && std::isfinite(value(GC, ti, tj))) {
          gc[ti * n + tj] = value(GC, ti, tj);
          const int p = profile_of(ti, tj);
          if (!first) first = ti * n + tj, profile = p < 0 ? PD_PROFILE_OPENING : (pd_energy_profile) p;
          if (p != profile)
            error->all(FLERR, "Pair {}: 'fail energy' takes one profile for all type pairs: {} {} has {}, {} {} "
                       "has {} (where a line names none: opening)", style(), ti, tj,
                       p < 0 ? "two (its types differ)" : PROFILES[p], first / n, first % n, PROFILES[profile]);
        }
    // the continuum integral must exist (T14 eq. 6.1-6.2) ...
    if (first && profile == PD_PROFILE_OPENING && dim() == 2 && pd_influence_singular(m->influence_kind()))
      error->all(FLERR, "Pair {}: 'fail energy profile opening' with influence {} in 2D: the G_c integral "
                 "diverges (T14 eq. 6.2); use influence constant or tupek, or profile uniform", style(),
                 pd_influence_name(m->influence_kind()));
    // ... and beta is calibrated on each atom's family: its moment
    // sum w V |xi|^(q+1) and weighted volume, calibrated as the material's
    // (core/pd_calibration.h)
    std::vector<double> sum = pair->family_moments(pd_energy_profile_power(profile) + 1);
    const std::vector<double> moment = pair->calibrate(sum.data());
    double *b = field(BETA);
    for (int i = 0; i < atom->nlocal; i++)
      b[i] = pd_energy_failure_beta_lattice(dim(), 1.0, pair->calibrated_volume(i), sum[i]);
    beta.assign(n, 0.0);
    for (int t = 1; t <= ntypes; t++)
      beta[t] = pd_energy_failure_beta_lattice(dim(), 1.0, pair->complete_volume(t), moment[t]);
  }

  std::vector<PDField> per_atom_fields() const override
  {
    return {{BETA, 1, PDField::MIGRATE | PDField::OUTPUT}};
  }

  // beta N per atom for G_c = 1; fixed per atom, so ghosts need it again
  // only after reneighboring
  const void *evaluation() override
  {
    const PDBondEnergies *m = pair->bond_energies();
    if (atom->nmax > ncrit) {
      ncrit = atom->nmax;
      memory->destroy(crit);
      memory->create(crit, ncrit, "pd/energy:crit");
    }
    const double *b = field(BETA);
    for (int i = 0; i < atom->nlocal; i++) crit[i] = b[i] * m->family_norm(i);
    if (neighbor->ago == 0) bonds()->copy_to_ghosts(crit);
    params = {crit, pd_failure_floor(crit, atom->nlocal + atom->nghost), gc.data(), 0.0, 0.0};
    pd_law_energy_profile(&params, profile);
    return &params;
  }

  // calibrated on the family's orientation average (pd_energy_failure_beta_lattice)
  int release_kind(int t) const override
  {
    const int n = atom->ntypes + 1;
    if (!std::isfinite(gc[t * n + t])) return -1;
    return profile == PD_PROFILE_OPENING ? PD_RELEASE_ENERGY_OPENING : PD_RELEASE_ENERGY_UNIFORM;
  }

  void report() const override
  {
    const PDBondEnergies *m = pair->bond_energies();
    const int n = atom->ntypes + 1;
    std::string types;
    for (int t = 1; t < n; t++)
      if (std::isfinite(gc[t * n + t]))
        types += fmt::format(" type {} beta {:.4g} (continuum {:.4g});", t, beta[t] * gc[t * n + t],
                             pd_energy_failure_beta(m->influence_kind(), profile, dim(), pair->horizon(t, t),
                                                    gc[t * n + t]));
    utils::logmesg(lmp, "{}: fail energy, profile {}:{}\n", style(), PROFILES[profile], types);
  }

 private:
  std::vector<double> gc;      // per type pair G_c (+inf: the pair does not fail)
  static constexpr const char *BETA = "energy_failure_beta";    // per atom beta for G_c = 1
  std::vector<double> beta;    // per type beta for G_c = 1, of a complete family
  double *crit = nullptr;      // per atom beta N for G_c = 1 (owned + ghost)
  int ncrit = 0;
  pd_law_energy params;
  pd_energy_profile profile = PD_PROFILE_OPENING;    // of every failing type pair

  // a type pair's profile: given, or its types' mean (mix), or the
  // opening one; types of two profiles mix to neither
  int profile_of(int i, int j)
  {
    const double v = value(PROFILE, i, j);
    return std::isnan(v) || v == PD_PROFILE_OPENING ? PD_PROFILE_OPENING
           : v == PD_PROFILE_UNIFORM                ? PD_PROFILE_UNIFORM
                                                    : -1;
  }
};

}    // namespace

PDFailureLaw *LAMMPS_NS::pd_make_law_energy(PairPD *pair, pd_fail_law id)
{
  return new LawEnergy(pair, id);
}
