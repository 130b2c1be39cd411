/* ----------------------------------------------------------------------
   PERIDYNAMICS_EXT: 'fail stretch <s0>' or 'fail stretch Gc <Gc>', the
   critical stretch (MS07 eq. 25-31; the bond test: core/pd_law_stretch.h).
------------------------------------------------------------------------- */

#include "pd_failure_law.h"

#include "error.h"
#include "pair_pd.h"

#include <cmath>

extern "C" {
#include "pd_law_stretch.h"
#include "pd_orientation.h"
}

using namespace LAMMPS_NS;

namespace {

enum { S0, GC };
const pd_coef COEFS[] = {
    // bonds between two types without their own: the smaller (MS07 eq. 31)
    {"s0", "critical stretch", PD_MIX_MIN, PD_COEF_PAIR, PD_CHECK_POSITIVE, 0.0, 0.0, 0.0, nullptr},
    {"Gc", "fracture energy", PD_MIX_MEAN, PD_COEF_PAIR | PD_COEF_FILE, PD_CHECK_POSITIVE, 0.0, 0.0, 0.0,
     nullptr},
};

class LawStretch : public PDFailureLaw {
 public:
  LawStretch(PairPD *pair, pd_fail_law id) : PDFailureLaw(pair, id, "stretch", COEFS, 2) {}

  std::string usage() const override { return "fail stretch <s0> | fail stretch Gc <Gc>"; }

  int parse(PDCoefLine &line, int narg, char **arg, int iarg) override
  {
    const int next = take_keyword(line, GC, narg, arg, iarg);
    if (next != iarg) return next;
    if (iarg < narg && utils::is_double(arg[iarg])) {
      take(line, S0, arg[iarg]);
      return iarg + 1;
    }
    return iarg;
  }

  // an s0 on the line decides the critical stretch: a material file's G_c
  // is then not used
  void settle(PDCoefLine &line) const override
  {
    PDFailureLaw::settle(line);
    if (line.seen[cols[S0]] && !line.seen[cols[GC]]) line.values[cols[GC]] = NAN;
  }

  void check(int i, int j) override
  {
    if (given(S0, i, j)) {
      if (given(GC, i, j))
        error->all(FLERR, "Pair {} coeff {} {}: 'fail stretch' takes s0 or 'Gc <Gc>', not both", style(),
                   i, j);
    } else if (given(GC, i, j)) {
      // a type's own bonds now; bonds between two types in init_one, when
      // both materials are known
      if (i == j) from_fracture_energy(i, j);
    } else if (i == j) {
      error->all(FLERR, "Pair {} coeff {} {}: 'fail stretch' needs s0 or 'Gc <Gc>' (here or in the "
                 "material file)", style(), i, j);
    }
  }

  // bonds between two types: from their own G_c and the two materials, or
  // the smaller of the two types' s0
  void mix(int i, int j, bool explicit_pair) override
  {
    if (!std::isnan(value(S0, i, j))) return;
    if (explicit_pair && given(GC, i, j)) from_fracture_energy(i, j);
    else value(S0, i, j) = pd_coef_mixed(COEFS[S0].mix, value(S0, i, i), value(S0, j, j));
  }

  // a bond-based material's bonds, broken at the critical stretch of its G_c
  int release_kind(int t, bool bond_based) const override
  {
    return bond_based && given(GC, t, t) ? PD_RELEASE_BOND_BASED : -1;
  }

  const void *evaluation() override
  {
    params = {table(S0), 0};
    return &params;
  }

 private:
  pd_law_stretch params;

  // the critical stretch of bond-based elasticity (MS07 eq. 28-29) for the
  // pair's E and nu (the material's; between two types, their means)
  void from_fracture_energy(int i, int j)
  {
    double E, nu;
    pair->fracture_elastic(i, j, E, nu);
    value(S0, i, j) = pd_critical_stretch(dim(), plane_strain(), E, nu, pair->horizon(i, j), value(GC, i, j));
    check_derived(S0, i, j);
  }
};

}    // namespace

PDFailureLaw *LAMMPS_NS::pd_make_law_stretch(PairPD *pair, pd_fail_law id)
{
  return new LawStretch(pair, id);
}
