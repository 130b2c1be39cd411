/* ----------------------------------------------------------------------
   PERIDYNAMICS_EXT: no failure law (the pairs without 'fail'). Bonds
   break only by a pre-crack (fix pd/precrack).
------------------------------------------------------------------------- */

#include "pd_failure_law.h"

#include "error.h"
#include "pair_pd.h"

#include <cmath>

using namespace LAMMPS_NS;

namespace {

class LawNone : public PDFailureLaw {
 public:
  LawNone(PairPD *pair, pd_fail_law id) : PDFailureLaw(pair, id, "none", nullptr, 0) {}
  bool selectable() const override { return false; }
  bool breaks() const override { return false; }
  std::string usage() const override { return "no 'fail'"; }
  int parse(PDCoefLine &, int, char **, int iarg) override { return iarg; }

  // a line without 'fail' gives no failure coefficient (a material
  // file's G_c stays: an interface with the energy law may mix it)
  void settle(PDCoefLine &line) const override
  {
    for (size_t p = fail_column() + 1; p < line.values.size(); p++)
      if (line.seen[p])
        error->all(FLERR, "Pair {} coeff: '{}' needs a failure law: {}", style(), column_name(p),
                   usages_of(p));
  }

  // A pair that never breaks has an infinite critical stretch: bonds
  // between its type and one that fails by stretch take the other's (the
  // smaller, MS07 eq. 31), and the stretch law's table reads +inf here.
  void check(int i, int j) override { column("s0", i, j) = INFINITY; }
};

}    // namespace

PDFailureLaw *LAMMPS_NS::pd_make_law_none(PairPD *pair, pd_fail_law id)
{
  return new LawNone(pair, id);
}
