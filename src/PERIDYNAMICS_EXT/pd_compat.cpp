/* ----------------------------------------------------------------------
   PERIDYNAMICS_EXT: the compat calls that need a LAMMPS class's internals
   (pd_compat.h).
------------------------------------------------------------------------- */

#include "pd_compat.h"

#include "force.h"
#include "pair_hybrid.h"

#include <cstdlib>
#if defined(__linux__)
#include <sys/mman.h>
#endif

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

void *PDCompat::huge_alloc(size_t bytes)
{
  constexpr size_t huge = 2u << 20;
  void *data = nullptr;
  if (bytes < huge / 2) return posix_memalign(&data, 64, bytes ? bytes : 1) ? nullptr : data;
  // whole 2 MB pages: the last one too (untouched slack costs no memory)
  const size_t rounded = (bytes + huge - 1) / huge * huge;
  if (posix_memalign(&data, huge, rounded)) return nullptr;
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  madvise(data, rounded, MADV_HUGEPAGE);    // only advice: a refusal changes nothing
#endif
  return data;
}
