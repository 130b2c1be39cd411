/* ----------------------------------------------------------------------
   PERIDYNAMICS_EXT: the compat calls that need a LAMMPS class's internals
   (pd_compat.h).
------------------------------------------------------------------------- */

#include "pd_compat.h"

#include "force.h"
#include "pair_hybrid.h"

#include <cstdint>
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

void PDCompat::advise_huge_pages(void *data, size_t bytes)
{
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  // only the whole 2 MB pages inside the array; advice is only advice, so
  // a refusal (no THP in this kernel) changes nothing
  const uintptr_t huge = 2u << 20, begin = ((uintptr_t) data + huge - 1) & ~(huge - 1);
  const uintptr_t end = ((uintptr_t) data + bytes) & ~(huge - 1);
  if (data && end > begin) madvise((void *) begin, end - begin, MADV_HUGEPAGE);
#else
  (void) data, (void) bytes;
#endif
}
