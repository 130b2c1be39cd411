/* The LAMMPS calls whose names or signatures changed between releases, in
 * one place. Which form a LAMMPS tree has is decided by CMake, which looks
 * at its headers (cmake/PDExtLammpsFeatures.cmake), not at its version:
 *   PDEXT_COMM_FIX_NAMED        comm->forward_comm_fix(fix, n) and
 *                               forward_comm_compute(compute) (before 24Mar2022;
 *                               later forward_comm(Fix *, n), forward_comm(Compute *))
 *   PDEXT_NEIGH_ADD_REQUEST     neighbor->add_request(...) with flags (24Mar2022 on;
 *                               before: neighbor->request() and public fields)
 *   PDEXT_MINIMUM_IMAGE_FLERR   domain->minimum_image(FLERR, dx, dy, dz) (12Jun2025 on)
 *   PDEXT_GET_FIX_BY_ID         modify->get_fix_by_id(id) (find_fix and fix[] are
 *                               deprecated, to be removed)
 *   PDEXT_OUTPUT_RESET_DT       output->reset_dt(): dumps by simulation time follow a
 *                               changed time step (2Aug2023 on; before, no such dumps)
 * and one access that no release offers publicly: the sub-styles of pair
 * style hybrid (PairHybrid::nstyles/styles are protected in every release
 * from 29Sep2021 on), reached through pointers to members (pair_styles).
 * Handled without a switch: the destructors of LAMMPS's classes may throw
 * from 19Nov2024 on (Pointers::~Pointers() noexcept(false)), so a style's
 * second base class must not declare a virtual destructor of its own (see
 * PDFamilySource in pd_family_spec.h).
 * Tested against 29Sep2021, 2Aug2023 and 19Nov2024. */
#ifndef LMP_PD_COMPAT_H
#define LMP_PD_COMPAT_H

#include "comm.h"
#include "domain.h"
#include "fix.h"
#include "force.h"
#include "lammps.h"
#include "lattice.h"
#include "modify.h"
#include "neigh_request.h"
#include "neighbor.h"
#include "output.h"
#include "pair.h"

#include <cmath>
#include <string>
#include <vector>

namespace LAMMPS_NS {
class Compute;
class Force;
class Pair;

namespace PDCompat {

  inline void forward_comm(Comm *comm, class Fix *fix, int size)
  {
#ifdef PDEXT_COMM_FIX_NAMED
    comm->forward_comm_fix(fix, size);
#else
    comm->forward_comm(fix, size);
#endif
  }

  inline void reverse_comm(Comm *comm, class Fix *fix, int size)
  {
#ifdef PDEXT_COMM_FIX_NAMED
    comm->reverse_comm_fix(fix, size);
#else
    comm->reverse_comm(fix, size);
#endif
  }

  /* The same for a compute (its comm_forward / comm_reverse values per atom). */
  inline void forward_comm(Comm *comm, class Compute *compute)
  {
#ifdef PDEXT_COMM_FIX_NAMED
    comm->forward_comm_compute(compute);
#else
    comm->forward_comm(compute);
#endif
  }

  inline void reverse_comm(Comm *comm, class Compute *compute)
  {
#ifdef PDEXT_COMM_FIX_NAMED
    comm->reverse_comm_compute(compute);
#else
    comm->reverse_comm(compute);
#endif
  }

  /* A half list for a pair style with its own cutoff; the list reaches
   * cutoff + skin (the newer API adds the skin itself). */
  inline void request_pair_with_cutoff(Neighbor *neighbor, class Pair *pair, int instance, double cutoff)
  {
#ifdef PDEXT_NEIGH_ADD_REQUEST
    (void) instance;
    neighbor->add_request(pair)->set_cutoff(cutoff);
#else
    int irequest = neighbor->request(pair, instance);
    neighbor->requests[irequest]->cut = 1;
    neighbor->requests[irequest]->cutoff = cutoff + neighbor->skin;
#endif
  }

  /* The shortest periodic image of a separation, in place. LAMMPS changes
   * only a component longer than half the box (orthogonal and triclinic):
   * a shorter one, most bonds, skips the call (per bond in the set-up's
   * walks, where recent LAMMPS's call made a std::string of its file name
   * each time). */
  inline void minimum_image(Domain *domain, double d[3])
  {
    const double *half = domain->prd_half;
    if (fabs(d[0]) <= half[0] && fabs(d[1]) <= half[1] && fabs(d[2]) <= half[2]) return;
#ifdef PDEXT_MINIMUM_IMAGE_FLERR
    domain->minimum_image(FLERR, d[0], d[1], d[2]);
#else
    domain->minimum_image(d[0], d[1], d[2]);
#endif
  }

  /* A fix by ID, or null. */
  inline class Fix *fix_by_id(Modify *modify, const std::string &id)
  {
#ifdef PDEXT_GET_FIX_BY_ID
    return modify->get_fix_by_id(id);
#else
    const int ifix = modify->find_fix(id);
    return ifix < 0 ? nullptr : modify->fix[ifix];
#endif
  }

  /* Every fix, in the order they were defined. */
  inline std::vector<class Fix *> fixes(Modify *modify)
  {
    return std::vector<class Fix *>(modify->fix, modify->fix + modify->nfix);
  }

  /* Every compute, in the order they were defined. */
  inline std::vector<class Compute *> computes(Modify *modify)
  {
    return std::vector<class Compute *>(modify->compute, modify->compute + modify->ncompute);
  }

  /* After a change of update->dt: what depends on it, as fix dt/reset does. */
  inline void time_step_changed(class LAMMPS *lmp)
  {
    if (lmp->force->pair) lmp->force->pair->reset_dt();
    for (int i = 0; i < lmp->modify->nfix; i++) lmp->modify->fix[i]->reset_dt();
#ifdef PDEXT_OUTPUT_RESET_DT
    lmp->output->reset_dt();
#endif
  }

  /* The lattice, or null when none was defined (recent LAMMPS keeps no
   * default lattice object). */
  inline Lattice *lattice(Domain *domain)
  {
    return domain->lattice && domain->lattice->style != Lattice::NONE ? domain->lattice : nullptr;
  }

  /* The pair styles that act now: the sub-styles of a hybrid (hybrid,
   * hybrid/overlay, hybrid/scaled ...), else the pair style itself; none
   * without a pair style. Found by type, not by style name (pd_compat.cpp,
   * which alone includes pair_hybrid.h). */
  std::vector<Pair *> pair_styles(Force *force);

}    // namespace PDCompat
}    // namespace LAMMPS_NS

#endif
