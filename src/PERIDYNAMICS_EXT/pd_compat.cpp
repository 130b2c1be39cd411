/* ----------------------------------------------------------------------
   PERIDYNAMICS_EXT: the compat calls that need a LAMMPS class's internals
   (pd_compat.h).
------------------------------------------------------------------------- */

#include "pd_compat.h"

#include "force.h"
#include "pair_hybrid.h"

using namespace LAMMPS_NS;

namespace {
// PairHybrid keeps its sub-styles in protected members (every release from
// 29Sep2021 on) and offers no accessor. A derived class may name its base's
// protected members; the pointers to members it forms then apply to any
// PairHybrid (hybrid, hybrid/overlay, hybrid/scaled ...).
struct HybridMembers : PairHybrid {
  static int PairHybrid::*count() { return &HybridMembers::nstyles; }
  static Pair **PairHybrid::*list() { return &HybridMembers::styles; }
};
}    // namespace

std::vector<Pair *> PDCompat::pair_styles(Force *force)
{
  std::vector<Pair *> found;
  if (auto *hybrid = dynamic_cast<PairHybrid *>(force->pair)) {
    Pair **styles = hybrid->*HybridMembers::list();
    const int n = hybrid->*HybridMembers::count();
    for (int m = 0; m < n; m++) found.push_back(styles[m]);
  } else if (force->pair) {
    found.push_back(force->pair);
  }
  return found;
}
